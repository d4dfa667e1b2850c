#!/usr/bin/env python3
"""Adds caps to a closed OFF mesh, as exporters and welding tools leave
them, for the rehearsals of `tetblend prepare` (issue 10): --caps N seeded
faces (a, b, c) become (a, m, c) and (m, b, c), m a new vertex at the
midpoint of the edge from the first corner, and the T-junction against the
neighbour (b, a, d) is closed by the cap (a, b, m). With --height=H, m is
then moved H times the edge's length towards c (H < 0: away from c, over
the neighbour, so the rest itself folds there). No two caps share a face.
The other vertices keep their order and positions; m is appended.

Only the Python standard library is needed. Usage:
  tools/add_caps.py MESH.off OUT.off [--caps 30] [--height=0] [--seed 2]
"""
import argparse
import math
import random

from off_file import read_off_positions, write_off


def directed_edges(triangles):
    """The face running each directed edge (a, b)."""
    return {(t[k], t[(k + 1) % 3]): f for f, t in enumerate(triangles) for k in range(3)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("out")
    parser.add_argument("--caps", type=int, default=30)
    parser.add_argument("--height", type=float, default=0.0)
    parser.add_argument("--seed", type=int, default=2)
    args = parser.parse_args()
    vertices, triangles = read_off_positions(args.mesh)
    vertices = [list(v) for v in vertices]
    triangles = [list(t) for t in triangles]
    edges = directed_edges(triangles)
    rng = random.Random(args.seed)
    used = set()
    for _ in range(args.caps):
        for _attempt in range(100 * len(triangles)):
            f = rng.randrange(len(triangles))
            a, b, c = triangles[f]
            g = edges.get((b, a))
            if f not in used and g is not None and g not in used:
                break
        else:
            raise SystemExit(f"{args.mesh}: no room for {args.caps} caps")
        length = math.dist(vertices[a], vertices[b])
        midpoint = [(p + q) / 2 for p, q in zip(vertices[a], vertices[b])]
        towards = [p - q for p, q in zip(vertices[c], midpoint)]
        norm = math.hypot(*towards)
        m = len(vertices)
        vertices.append([x + args.height * length * t / norm for x, t in zip(midpoint, towards)])
        triangles[f] = [a, m, c]
        triangles.extend([[m, b, c], [a, b, m]])
        used |= {f, g, len(triangles) - 2, len(triangles) - 1}
    write_off(args.out, vertices, [tuple(t) for t in triangles])


if __name__ == "__main__":
    main()
