#!/usr/bin/env python3
"""Writes scenes/demos/watertight.test: a closed icosphere far from the origin, for
`raystep demo watertight`. Rerun it after changing the centre or the subdivision:

    scripts/make-watertight-scene.py > scenes/demos/watertight.test
"""
import math

# The mesh's centre: far enough that a double's spacing there (2^-6 = 0.0156 at 1e14) is a few
# percent of a pixel's footprint on the mesh, so that the lecture's plane-based triangle tests
# leak at hundreds of pixels of the demo's 320 x 424 panel (at 1e12 only a handful, at 1e15 the
# vertices themselves snap to a visibly coarse grid). docs/measurements/watertight-demo.md has
# the counts. The image size is the demo's panel, so that the demo frames the mesh as written.
CENTRE = (1e14, 5e13, -7.5e13)
RADIUS = 1.0
SUBDIVISIONS = 2  # 320 triangles: few enough to test every one at every pixel


def icosphere(subdivisions):
    t = (1 + math.sqrt(5)) / 2
    vertices = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]

    def unit(v):
        length = math.sqrt(sum(c * c for c in v))
        return tuple(c / length for c in v)

    vertices = [unit(v) for v in vertices]
    for _ in range(subdivisions):
        midpoints = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoints:
                vertices.append(unit(tuple((p + q) / 2 for p, q in zip(vertices[a], vertices[b]))))
                midpoints[key] = len(vertices) - 1
            return midpoints[key]

        finer = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = finer
    return vertices, faces


def main():
    vertices, faces = icosphere(SUBDIVISIONS)
    at = lambda offset: " ".join(repr(c + RADIUS * o) for c, o in zip(CENTRE, offset))
    centre = ", ".join(f"{c:g}" for c in CENTRE)
    print(f"""# raystep demo watertight: a closed icosphere ({len(faces)} triangles, every edge shared by
# two) of radius {RADIUS:g} around ({centre}), seen from {3.3 * RADIUS:.1f} units from its centre.
# Every coordinate is near 1e14, where doubles are 0.0156 apart: the triangle tests that first
# find the hit point on the plane (projection, half-spaces) round it by that much and let rays
# through the shared edges, which then see the inside of the sphere. The watertight test of the
# reference renderer lets none through. Written by scripts/make-watertight-scene.py.
# views: normal full
size 320 424
camera {at((1.2, 1.6, 2.6))} {at((0, 0, 0))} 0 1 0 45
point {at((4, 6, 8))} 1 1 1
ambient 0.1 0.1 0.12
diffuse 0.7 0.7 0.7
maxverts {len(vertices)}""")
    for v in vertices:
        print(f"vertex {at(v)}")
    for a, b, c in faces:
        print(f"tri {a} {b} {c}")


main()
