#!/usr/bin/env python3
"""Punches holes into a closed OFF mesh, as a scan has them, for the
rehearsals of `tetblend prepare` (issue 10): --holes N seeded faces are
removed, each with its neighbours out to --rings edge rings; every other
hole gets a partner hole that touches it at one corner only (one vertex
where two fans of faces meet, as where a scan's holes run into each other).
With --split-rims, such a corner is written twice, once per fan (two
vertices at one position, no edge between their copies: not a seam).
The vertices keep their order and positions; only faces are removed (and,
with --split-rims, vertices appended).

Only the Python standard library is needed. Usage:
  tools/punch_holes.py MESH.off OUT.off [--holes 6] [--rings 1]
      [--split-rims] [--seed 3]
"""
import argparse
import random
from collections import defaultdict

from off_file import read_off, write_off


def faces_at(triangles):
    at = defaultdict(list)
    for f, tri in enumerate(triangles):
        for v in tri:
            at[v].append(f)
    return at


def grown(seed_faces, triangles, at, rings):
    """The faces within `rings` vertex rings of `seed_faces`."""
    faces = set(seed_faces)
    for _ in range(rings):
        faces |= {g for f in list(faces) for v in triangles[f] for g in at[v]}
    return faces


def touching_partner(hole, removed, triangles, at):
    """A face sharing exactly one vertex with `hole` and none of whose
    vertices' other faces are removed, or None."""
    hole_vertices = {v for f in hole for v in triangles[f]}
    for f in sorted(hole):
        for v in triangles[f]:
            for g in at[v]:
                shared = hole_vertices & set(triangles[g])
                if g in removed or len(shared) != 1:
                    continue
                others = {h for w in triangles[g] if w != v for h in at[w]}
                if not others & removed:
                    return g, v
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("out")
    parser.add_argument("--holes", type=int, default=6)
    parser.add_argument("--rings", type=int, default=1)
    parser.add_argument("--split-rims", action="store_true")
    parser.add_argument("--seed", type=int, default=3)
    args = parser.parse_args()
    rows, triangles = read_off(args.mesh)
    at = faces_at(triangles)
    rng = random.Random(args.seed)
    removed = set()
    corners = []  # (vertex, faces of the partner's fan there)
    for k in range(args.holes):
        start = rng.randrange(len(triangles))
        hole = grown([start], triangles, at, args.rings)
        removed_vertices = {w for f in removed for w in triangles[f]}
        if any(v in removed_vertices for f in hole for v in triangles[f]):
            continue  # keep holes apart unless they are made to touch
        removed |= hole
        if k % 2 == 1:
            partner = touching_partner(hole, removed, triangles, at)
            if partner is not None:
                g, v = partner
                removed |= {g}
                corners.append(v)
    kept = [tri for f, tri in enumerate(triangles) if f not in removed]
    if args.split_rims:
        # Per touching corner, the faces of one fan (faces joined to the
        # first kept face there through edges at the corner) take a copy.
        for v in corners:
            fan_faces = [i for i, tri in enumerate(kept) if v in tri]
            fan = {fan_faces[0]}
            grew = True
            while grew:
                grew = False
                for i in fan_faces:
                    if i in fan:
                        continue
                    if any(len(set(kept[i]) & set(kept[j])) == 2 for j in fan):
                        fan.add(i)
                        grew = True
            if len(fan) == len(fan_faces):
                continue  # one fan only: not pinched after all
            rows.append(rows[v])
            copy = len(rows) - 1
            kept = [tuple(copy if (i in fan and w == v) else w for w in tri) if i in fan else tri
                    for i, tri in enumerate(kept)]
    write_off(args.out, rows, kept)
    print(f"{args.out}: {len(triangles) - len(kept)} faces removed, "
          f"{len(corners)} touching corners{' split' if args.split_rims else ''}")


if __name__ == "__main__":
    main()
