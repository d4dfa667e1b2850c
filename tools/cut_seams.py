#!/usr/bin/env python3
"""Cuts a closed OFF mesh along seams, as a UV-unwrapped export does.

The faces are split into CHARTS charts by region growing from seeded faces
(breadth first over shared edges); every vertex keeps its index in the first
chart that uses it and gets one copy, appended after the input's vertices,
for each other chart that uses it. Positions are copied exactly, so
`tetblend prepare` zips the seams back (seam_welding.h). Writes
OUT_DIR/NAME_seams.off. Only the Python standard library is needed. Usage:
  tools/cut_seams.py MESH.off OUT_DIR [--charts 12] [--seed 1]
"""
import argparse
import collections
import os
import random

from off_file import read_off, write_off


def charts_of(triangles, count, rng):
    """A chart number per face, grown from `count` random seed faces."""
    faces_of_edge = collections.defaultdict(list)
    for face, (a, b, c) in enumerate(triangles):
        for u, v in ((a, b), (b, c), (c, a)):
            faces_of_edge[(min(u, v), max(u, v))].append(face)
    chart = [-1] * len(triangles)
    queue = collections.deque()
    for number, seed in enumerate(rng.sample(range(len(triangles)), count)):
        chart[seed] = number
        queue.append(seed)
    while queue:
        face = queue.popleft()
        a, b, c = triangles[face]
        for u, v in ((a, b), (b, c), (c, a)):
            for other in faces_of_edge[(min(u, v), max(u, v))]:
                if chart[other] < 0:
                    chart[other] = chart[face]
                    queue.append(other)
    return chart


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("out_dir")
    parser.add_argument("--charts", type=int, default=12)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    vertices, triangles = read_off(args.mesh)
    chart = charts_of(triangles, args.charts, random.Random(args.seed))
    first_chart = {}
    copies = {}
    out_vertices = list(vertices)
    out_triangles = []
    for face, corners in enumerate(triangles):
        renumbered = []
        for v in corners:
            if first_chart.setdefault(v, chart[face]) == chart[face]:
                renumbered.append(v)
                continue
            if (v, chart[face]) not in copies:
                copies[(v, chart[face])] = len(out_vertices)
                out_vertices.append(vertices[v])
            renumbered.append(copies[(v, chart[face])])
        out_triangles.append(renumbered)
    name = os.path.splitext(os.path.basename(args.mesh))[0]
    os.makedirs(args.out_dir, exist_ok=True)
    out = os.path.join(args.out_dir, f"{name}_seams.off")
    write_off(out, out_vertices, out_triangles)
    print(f"{out}: {len(vertices)} -> {len(out_vertices)} vertices, {args.charts} charts")


if __name__ == "__main__":
    main()
