#!/usr/bin/env python3
"""The reference's path tracer against Blender's Cycles on one scene: do they agree, and how long
does each take to reach the same error? docs/measurements/cycles.md keeps the figures.

    scripts/measure-cycles.py [--raystep build/release/bin/raystep] [--scene SCENE]
                              [--spp 1024] [--threads 2]

Needs Blender (Debian's `blender`; Cycles on the CPU) and oiiotool (`openimageio-tools`).

1. Agreement. Each renderer renders the scene twice at --spp, at two seeds. The image is cut into
   blocks of 10 x 10 pixels; in each block and channel the two renderers' means differ by z of
   their standard errors, each estimated from its own two renders (the variance of a pixel is
   half the square of its two renders' difference). Pixels that see the light, and their
   neighbours, are left out: the light's outline is an edge of radiance 30 against 0.3, where a
   hundredth of a pixel between the two cameras' pixel filters outweighs the lighting (the
   measurement found Cycles' edges a few hundredths of a pixel from the analytic ones, and
   raystep's on them). A right pair gives z of a standard normal:
   the script prints the share of |z| above 2 and 3 (5% and 0.3% expected) and the mean of z^2
   (1 expected), and the whole image's mean radiance in each.
2. Time to an error. The converged image is the mean of those four renders. Each renderer renders
   at 4 to 256 samples, timed (raystep's own figure, Cycles' render alone, both on --threads),
   and the RMSE against the converged image taken, over the same pixels. The script prints each
   renderer's time * RMSE^2 (constant where the error falls as 1 / sqrt(time), as independent
   samples' does) and the time each needs to reach the RMSE raystep reaches at 64 samples,
   interpolated between the measurements that bracket it (a line in log time against log RMSE),
   and their ratio.
"""

import argparse
import math
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def pixels(path):
    """The image's pixels, row by row, each an (r, g, b) triple."""
    out = subprocess.run(["oiiotool", "--dumpdata", str(path)], check=True, capture_output=True,
                         text=True).stdout
    values = []
    for line in out.splitlines():
        m = re.match(r"\s*Pixel \((\d+), (\d+)\): (\S+) (\S+) (\S+)", line)
        if m:
            values.append((float(m.group(3)), float(m.group(4)), float(m.group(5))))
    return values


def render_raystep(args, spp, seed, output):
    out = subprocess.run([args.raystep, "render", args.scene, "-o", str(output), "--spp",
                          str(spp), "--seed", str(seed), "--threads", str(args.threads)],
                         check=True, capture_output=True, text=True).stdout
    return float(re.search(r", ([0-9.]+) s on", out).group(1))


def render_cycles(args, spp, seed, output):
    out = subprocess.run(["blender", "-b", "--factory-startup", "--python",
                          str(ROOT / "scripts" / "cycles-render.py"), "--", args.scene,
                          str(output), str(spp), str(seed), str(args.threads)],
                         check=True, capture_output=True, text=True).stdout
    return float(re.search(r"render_seconds ([0-9.]+)", out).group(1))


def image_size(path):
    out = subprocess.run(["oiiotool", "--info", str(path)], check=True, capture_output=True,
                         text=True).stdout
    m = re.search(r"(\d+) x\s+(\d+)", out)
    return int(m.group(1)), int(m.group(2))


def lit_pixels(reference, width, height):
    """The pixels that see a light (radiance above 1 in a channel) and their eight neighbours."""
    bright = {k for k, p in enumerate(reference) if max(p) > 1.0}
    near = set()
    for k in bright:
        x, y = k % width, k // width
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                if 0 <= x + dx < width and 0 <= y + dy < height:
                    near.add((y + dy) * width + x + dx)
    return near


def agreement(a1, a2, b1, b2, width, height, left_out, block=10):
    zs = []
    for by in range(0, height - block + 1, block):
        for bx in range(0, width - block + 1, block):
            index = [y * width + x for y in range(by, by + block) for x in range(bx, bx + block)
                     if y * width + x not in left_out]
            n = len(index)
            if n == 0:
                continue
            for c in range(3):
                mean_a = sum(a1[k][c] + a2[k][c] for k in index) / (2 * n)
                mean_b = sum(b1[k][c] + b2[k][c] for k in index) / (2 * n)
                # Var(pixel) ~ (x1 - x2)^2 / 2; the block mean of 2n pixel samples.
                var_a = sum((a1[k][c] - a2[k][c]) ** 2 / 2 for k in index) / (2 * n * n)
                var_b = sum((b1[k][c] - b2[k][c]) ** 2 / 2 for k in index) / (2 * n * n)
                if var_a + var_b == 0:
                    continue
                zs.append((mean_a - mean_b) / math.sqrt(var_a + var_b))
    return zs


def rmse(image, reference, left_out):
    kept = [k for k in range(len(reference)) if k not in left_out]
    total = sum((image[k][c] - reference[k][c]) ** 2 for k in kept for c in range(3))
    return math.sqrt(total / (3 * len(kept)))


def time_to_error(points, target):
    """The time at which a renderer's RMSE is `target`: a straight line in log time against log
    RMSE between the two measurements that bracket it (the nearest two where none does)."""
    points = sorted(points, key=lambda p: -p[1])  # falling error
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if e1 <= target <= e0 or (t1, e1) == points[-1]:
            slope = math.log(t1 / t0) / math.log(e1 / e0)
            return t0 * math.exp(slope * math.log(target / e0))
    return points[0][0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--raystep", default=str(ROOT / "build/release/bin/raystep"))
    parser.add_argument("--scene", default=str(ROOT / "scenes/stage10/cornell-box.test"))
    parser.add_argument("--spp", type=int, default=1024)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()

    work = pathlib.Path(tempfile.mkdtemp(prefix="raystep-cycles-"))
    print(f"scene {args.scene}, {args.threads} threads, images in {work}")
    converged = {}
    for name, render in (("raystep", render_raystep), ("cycles", render_cycles)):
        for seed in (1, 2):
            path = work / f"{name}-{args.spp}-{seed}.exr"
            seconds = render(args, args.spp, seed, path)
            converged[(name, seed)] = pixels(path)
            print(f"{name} {args.spp} spp seed {seed}: {seconds:.2f} s")
    width, height = image_size(work / f"raystep-{args.spp}-1.exr")

    a1, a2 = converged[("raystep", 1)], converged[("raystep", 2)]
    b1, b2 = converged[("cycles", 1)], converged[("cycles", 2)]
    reference = [tuple((a1[k][c] + a2[k][c] + b1[k][c] + b2[k][c]) / 4 for c in range(3))
                 for k in range(len(a1))]
    left_out = lit_pixels(reference, width, height)
    zs = agreement(a1, a2, b1, b2, width, height, left_out)
    share = lambda bound: sum(abs(z) > bound for z in zs) / len(zs)
    print(f"\n1. agreement at {args.spp} spp: {len(zs)} block means (10 x 10 pixels, 3 channels; "
          f"{len(left_out)} pixels on and around the light left out)")
    print(f"   |z| > 2: {share(2):.3f} (0.046 expected), |z| > 3: {share(3):.4f} (0.0027), "
          f"mean z^2 {sum(z * z for z in zs) / len(zs):.3f} (1), largest |z| "
          f"{max(abs(z) for z in zs):.2f}")
    for c, channel in enumerate("rgb"):
        kept = [k for k in range(len(a1)) if k not in left_out]
        mean_a = sum(a1[k][c] + a2[k][c] for k in kept) / (2 * len(kept))
        mean_b = sum(b1[k][c] + b2[k][c] for k in kept) / (2 * len(kept))
        print(f"   mean {channel}: raystep {mean_a:.5f}, cycles {mean_b:.5f}, "
              f"ratio {mean_a / mean_b:.4f}")

    print(f"\n2. time to an error: RMSE against the mean of the four {args.spp}-spp renders")
    measured = {}
    for name, render in (("raystep", render_raystep), ("cycles", render_cycles)):
        measured[name] = []
        for spp in (4, 16, 64, 256):
            path = work / f"{name}-{spp}.exr"
            seconds = render(args, spp, 7, path)
            error = rmse(pixels(path), reference, left_out)
            measured[name].append((seconds, error))
            print(f"   {name:8} {spp:4} spp: {seconds:7.3f} s, RMSE {error:.5f}, "
                  f"time * RMSE^2 {seconds * error * error:.6f}")
    target = measured["raystep"][2][1]
    times = {name: time_to_error(points, target) for name, points in measured.items()}
    print(f"   to reach RMSE {target:.5f} (raystep at 64 spp): raystep {times['raystep']:.2f} s, "
          f"cycles {times['cycles']:.2f} s; raystep takes {times['raystep'] / times['cycles']:.2f} "
          f"times Cycles' time")


if __name__ == "__main__":
    sys.exit(main())
