#!/usr/bin/env python3
"""`raystep demo --size`: the image is the size asked for, and its captions grow with its height.

    demo_size_test.py RAYSTEP WORK_FOLDER

Writes the ray-directions demo (two panels side by side, a caption under each) at 640x480 and at
1920x1080 as binary PPM, and measures in each the height of the captions' ink: the rows of the
strip under the panels that hold anything but the strip's colour. A caption is drawn at a 26th of
the image's height (app/demo/demo_figure.cpp); its ink, from the top of a 'd' to the foot of a
'p', is about that, so it must be from a 30th to a 20th of the height at both sizes: 36 to 54
rows at 1080, where a caption sized for 480 lines alone (15 pixels) fails. Exits 77 (skipped)
where the demo finds no font to draw the labels with.
"""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "view", "tests"))
from view_process import read_ppm  # noqa: E402

RAYSTEP, WORK = sys.argv[1:3]
SKIPPED = 77


def pixel(rgb, width, x, y):
    k = 3 * (y * width + x)
    return rgb[k:k + 3]


def caption_ink(path):
    """(width, height, rows of the bottom strip, rows of ink in it)."""
    width, height, rgb = read_ppm(path)
    strip = pixel(rgb, width, 0, 0)  # the title strip's corner: the title is centred

    # The strip under the panels: the rows at the bottom whose ends are the strip's colour (a
    # caption is centred under its panel, with a margin).
    def in_strip(y):
        return pixel(rgb, width, 0, y) == strip and pixel(rgb, width, width - 1, y) == strip

    top = height
    while top > 0 and in_strip(top - 1):
        top -= 1
    ink = [y for y in range(top, height)
           if any(pixel(rgb, width, x, y) != strip for x in range(width))]
    assert ink, "%s: no caption in the strip under the panels (rows %d to %d)" % (
        path, top, height - 1)
    return width, height, height - top, ink[-1] - ink[0] + 1


def main():
    os.makedirs(WORK, exist_ok=True)
    for size in ("640x480", "1920x1080"):
        path = os.path.join(WORK, "ray-directions-%s.ppm" % size)
        result = subprocess.run([RAYSTEP, "demo", "ray-directions", "--size", size, "-o", path],
                                capture_output=True, text=True, timeout=300)
        assert result.returncode == 0, "demo --size %s exited %d: %s" % (
            size, result.returncode, result.stderr)
        if "labels left out" in result.stderr:
            print("skipped: no font for the labels: " + result.stderr.strip())
            return SKIPPED
        width, height, strip, ink = caption_ink(path)
        print("%s: %d x %d, caption strip %d rows, caption ink %d rows (1/%.1f of the height)"
              % (size, width, height, strip, ink, height / ink))
        assert "%dx%d" % (width, height) == size, "asked for %s, got %d x %d" % (size, width,
                                                                                 height)
        assert height / 30 <= ink <= height / 20, (
            "%s: captions %d rows high; for the back of a lecture hall they need a 30th to a "
            "20th of the image's height, %.0f to %.0f" % (size, ink, height / 30, height / 20))
    return 0


if __name__ == "__main__":
    sys.exit(main())
