#!/usr/bin/env python3
"""Adds parts to a closed OFF mesh, as game characters have them, for the
rehearsals of `tetblend prepare` (issue 10):
  --spheres N   N icospheres (320 faces) of radius R x the bounding-box
                diagonal, centred on seeded surface vertices: half in, half
                out, so they go through the surface (eyes, studs, a weapon
                through a hand);
  --sheet N     an open flat sheet of N x N squares just above the bounding
                box (spheres included), over its whole length and the middle
                40 % of its depth (a cape, a hair card): no fill closes it.
The mesh's own vertices and faces come first, unchanged.

Only the Python standard library is needed. Usage:
  tools/add_parts.py MESH.off OUT.off [--spheres 4] [--radius 0.03]
      [--sheet 0] [--seed 7]
"""
import argparse
import math
import random

from off_file import read_off_positions, write_off


def icosphere(levels):
    """Unit icosphere: 12 vertices, 20 faces, each level splits every face
    into 4 (outward, counter-clockwise)."""
    t = (1 + 5 ** 0.5) / 2
    vertices = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                vertices.append(tuple((vertices[a][i] + vertices[b][i]) / 2 for i in range(3)))
                middle[key] = len(vertices) - 1
            return middle[key]

        split = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = split
    unit = [tuple(x / math.sqrt(sum(y * y for y in v)) for x in v) for v in vertices]
    return unit, faces


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("out")
    parser.add_argument("--spheres", type=int, default=4)
    parser.add_argument("--radius", type=float, default=0.03)
    parser.add_argument("--sheet", type=int, default=0)
    parser.add_argument("--seed", type=int, default=7)
    args = parser.parse_args()
    vertices, faces = read_off_positions(args.mesh)
    lo = [min(v[a] for v in vertices) for a in range(3)]
    hi = [max(v[a] for v in vertices) for a in range(3)]
    diagonal = math.dist(lo, hi)
    rng = random.Random(args.seed)
    sphere_vertices, sphere_faces = icosphere(2)
    surface_count = len(vertices)
    for _ in range(args.spheres):
        centre = vertices[rng.randrange(surface_count)]
        base = len(vertices)
        vertices += [tuple(centre[i] + args.radius * diagonal * v[i] for i in range(3))
                     for v in sphere_vertices]
        faces += [(a + base, b + base, c + base) for a, b, c in sphere_faces]
    n = args.sheet
    if n > 0:
        lo = [min(v[a] for v in vertices) for a in range(3)]  # spheres included
        hi = [max(v[a] for v in vertices) for a in range(3)]
        base = len(vertices)
        for j in range(n + 1):
            for i in range(n + 1):
                vertices.append((lo[0] + (hi[0] - lo[0]) * i / n,
                                 lo[1] + (hi[1] - lo[1]) * (0.3 + 0.4 * j / n),
                                 hi[2] + 0.05 * (hi[2] - lo[2])))
        for j in range(n):
            for i in range(n):
                a = base + j * (n + 1) + i
                faces += [(a, a + 1, a + n + 2), (a, a + n + 2, a + n + 1)]
    write_off(args.out, vertices, faces)


if __name__ == "__main__":
    main()
