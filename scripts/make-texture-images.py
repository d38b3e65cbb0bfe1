#!/usr/bin/env python3
"""Writes the images of scenes/textures/, which stage 11's scenes look up, from nothing but
arithmetic: made here, under the repository's licence.

    scripts/make-texture-images.py [FOLDER]     (default: scenes/textures)

- uv-grid.png: a test grid for texture coordinates, red growing with u and green with v, with a
  checker of 8 x 8 squares and a white cross at (0.25, 0.75): a v flipped or u mirrored shows.
- checker.png: a grey checker of 8 x 8 squares, for a floor repeated by its uvs.
- bricks-height.png: a height map of bricks in rows offset by half a brick, mortar 0, brick faces
  1 with bevelled edges.
- bricks-normal.png: the tangent-space normal map of the same bricks, from the height map's
  central differences, scaled so that a bevel tilts the normal by about 45 degrees, as
  normal-map tools make them from a height map.

Pure Python (zlib): no imaging library needed."""

import math
import pathlib
import struct
import sys
import zlib

SIZE = 256


def write_png(path: pathlib.Path, width: int, height: int, pixel) -> None:
    """An 8-bit RGB PNG whose pixel (i, j), row j from the top, is pixel(i, j), each in [0, 1]."""
    rows = bytearray()
    for j in range(height):
        rows.append(0)  # filter: none
        for i in range(width):
            for channel in pixel(i, j):
                rows.append(max(0, min(255, round(255 * channel))))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                     chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b""))


def uv_grid(i: int, j: int):
    u = (i + 0.5) / SIZE
    v = 1.0 - (j + 0.5) / SIZE
    dark = (int(u * 8) + int(v * 8)) % 2 == 0
    if abs(u - 0.25) < 0.01 and abs(v - 0.75) < 0.06 or abs(v - 0.75) < 0.01 and abs(u - 0.25) < 0.06:
        return (1.0, 1.0, 1.0)
    shade = 0.55 if dark else 1.0
    return (shade * u, shade * v, shade * 0.35)


def checker(i: int, j: int):
    grey = 0.25 if (i * 8 // SIZE + j * 8 // SIZE) % 2 == 0 else 0.85
    return (grey, grey, grey)


BRICK_ROWS = 8
BRICK_COLUMNS = 4
MORTAR = 0.06   # of a brick's height
BEVEL = 0.12    # of a brick's height


def brick_height(u: float, v: float) -> float:
    """1 on a brick's face, 0 in the mortar, a slope across the bevel; the rows offset by half."""
    row = v * BRICK_ROWS
    column = u * BRICK_COLUMNS + (0.5 if int(math.floor(row)) % 2 else 0.0)
    # Distances to the nearest mortar line, in units of a brick's height.
    dv = min(row % 1.0, 1.0 - row % 1.0)
    du = min(column % 1.0, 1.0 - column % 1.0) * BRICK_ROWS / BRICK_COLUMNS
    edge = min(du, dv) - MORTAR / 2
    if edge <= 0.0:
        return 0.0
    return min(1.0, edge / BEVEL)


def height_at(i: int, j: int) -> float:
    return brick_height(((i % SIZE) + 0.5) / SIZE, 1.0 - ((j % SIZE) + 0.5) / SIZE)


def bricks_height(i: int, j: int):
    h = height_at(i, j)
    return (h, h, h)


def bricks_normal(i: int, j: int):
    # Slopes in height per texel, scaled so that a bevel tilts the normal by about 45 degrees;
    # v grows upwards, rows downwards.
    strength = 0.5 * SIZE / BRICK_ROWS * BEVEL
    dh_du = (height_at(i + 1, j) - height_at(i - 1, j)) / 2 * strength
    dh_dv = (height_at(i, j - 1) - height_at(i, j + 1)) / 2 * strength
    n = (-dh_du, -dh_dv, 1.0)
    length = math.sqrt(sum(c * c for c in n))
    return tuple(0.5 * c / length + 0.5 for c in n)


def main() -> int:
    folder = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "scenes/textures")
    folder.mkdir(parents=True, exist_ok=True)
    for name, pixel in [("uv-grid.png", uv_grid), ("checker.png", checker),
                        ("bricks-height.png", bricks_height), ("bricks-normal.png", bricks_normal)]:
        write_png(folder / name, SIZE, SIZE, pixel)
        print(f"wrote {folder / name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
