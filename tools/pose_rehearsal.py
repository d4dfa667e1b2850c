#!/usr/bin/env python3
"""Skinned-animation rehearsal of `tetblend prepare` (issue 10).

Stands in for the real animation data nobody here has: for each closed mesh
it picks handles by farthest-point sampling (the extremities: feet, head,
tail, fingers, horns), turns each about its centre by a seeded periodic angle
(amplitude AMPLITUDE degrees, random axis and phase per handle), skins every
frame with `tetblend deform` (distance weights, falloff exponent FALLOFF),
then times `tetblend prepare REST FRAMES...` and reports, per mesh, what
prepare printed: tets, Steiner points, excluded tets, and how many frames
had tets that could not be embedded, split by whether the frame's surface
intersects itself.

Only the Python standard library is needed. Usage:
  tools/pose_rehearsal.py TETBLEND OUT_DIR MESH.off [MESH.off ...]
      [--frames 16] [--handles 6] [--amplitude 60] [--falloff 4]
      [--method dqs] [--seed 1] [--rest-frame N]
With --rest-frame N, frame N is the rest and the other frames are the
examples (a posed rest, as when a user picks an animation's first frame).
"""
import argparse
import json
import math
import os
import random
import re
import subprocess
import sys
import time

from off_file import read_off_positions


def squared_distance(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b))


def farthest_points(points, count):
    """The centroid and `count` points chosen by farthest-point sampling,
    starting from the point farthest from the centroid."""
    centroid = tuple(sum(p[a] for p in points) / len(points) for a in range(3))
    first = max(range(len(points)), key=lambda i: squared_distance(points[i], centroid))
    chosen = [first]
    distance = [squared_distance(p, points[first]) for p in points]
    while len(chosen) < count:
        i = max(range(len(points)), key=lambda j: distance[j])
        chosen.append(i)
        distance = [min(d, squared_distance(p, points[i])) for d, p in zip(distance, points)]
    return centroid, [points[i] for i in chosen]


def rotation_matrix(axis, angle):
    """Rodrigues' formula for a unit axis."""
    x, y, z = axis
    c, s = math.cos(angle), math.sin(angle)
    t = 1 - c
    return [[c + x * x * t, x * y * t - z * s, x * z * t + y * s],
            [y * x * t + z * s, c + y * y * t, y * z * t - x * s],
            [z * x * t - y * s, z * y * t + x * s, c + z * z * t]]


def handle(name, centre, rotation):
    """A handle turning by `rotation` about `centre`, as deform's JSON wants."""
    moved = [sum(rotation[r][c] * centre[c] for c in range(3)) for r in range(3)]
    matrix = [rotation[r] + [centre[r] - moved[r]] for r in range(3)] + [[0, 0, 0, 1]]
    return {"name": name, "centre": list(centre), "matrix": matrix}


def write_frames(args, mesh, folder):
    """Writes the skinned frames of `mesh` into `folder`; returns their paths."""
    rng = random.Random(args.seed)
    centroid, ends = farthest_points(read_off_positions(mesh)[0], args.handles)
    axes = []
    for _ in ends:
        v = [rng.gauss(0, 1) for _ in range(3)]
        norm = math.sqrt(sum(x * x for x in v))
        axes.append([x / norm for x in v])
    phases = [rng.uniform(0, 2 * math.pi) for _ in ends]
    paths = []
    for frame in range(args.frames):
        handles = [handle("body", centroid, rotation_matrix([1, 0, 0], 0.0))]
        for i, end in enumerate(ends):
            angle = math.radians(args.amplitude) * math.sin(
                2 * math.pi * frame / args.frames + phases[i])
            handles.append(handle(f"end{i}", end, rotation_matrix(axes[i], angle)))
        spec = os.path.join(folder, f"handles{frame:03d}.json")
        with open(spec, "w") as f:
            json.dump({"handles": handles}, f)
        path = os.path.join(folder, f"frame{frame:03d}.obj")
        subprocess.run([args.tetblend, "deform", mesh, "--handles", spec, "-o", path,
                        "--method", args.method, "--falloff", str(args.falloff)],
                       check=True, stdout=subprocess.DEVNULL)
        paths.append(path)
    return paths


def rehearse(args, mesh):
    """One table row for `mesh`."""
    name = os.path.splitext(os.path.basename(mesh))[0]
    folder = os.path.join(args.out_dir, name)
    os.makedirs(folder, exist_ok=True)
    frames = write_frames(args, mesh, folder)
    rest = mesh
    if args.rest_frame is not None:
        rest = frames.pop(args.rest_frame)
    start = time.monotonic()
    run = subprocess.run([args.tetblend, "prepare", rest, *frames, "-o",
                          os.path.join(folder, "model.tbm")], capture_output=True, text=True)
    seconds = time.monotonic() - start
    lines = run.stderr.splitlines() + run.stdout.splitlines()
    if run.returncode != 0:
        error = next((l for l in lines if "error" in l), "?")
        return f"| {name} | refused: {error[:120]} |"
    warnings = [l for l in lines if re.search(r"\d+ tets? cannot be embedded", l)]
    clean = sum("does not intersect itself" in l for l in warnings)
    note = next((l for l in lines if "Steiner points" in l), None)
    if note is not None:
        tets, steiner, excluded = re.search(
            r": (\S+(?: [kM])?) tets, .*\((\d+) Steiner points?.*; (\d+) tets? excluded",
            note).groups()
    else:  # components prepared each on its own: no summary of the whole
        whole = next((l for l in lines if "tets in all)" in l), "")
        found = re.search(r"\((\S+(?: [kM])?) tets in all\)", whole)
        tets = found.group(1) if found else "?"
        steiner = "—"
        excluded = sum(int(re.search(r"(\d+) tets? cannot be embedded", l).group(1))
                       for l in warnings)
    return (f"| {name} | {tets} | {steiner} | {excluded} | {len(warnings) - clean} | {clean} "
            f"| {seconds:.1f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("tetblend")
    parser.add_argument("out_dir")
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--frames", type=int, default=16)
    parser.add_argument("--handles", type=int, default=6)
    parser.add_argument("--amplitude", type=float, default=60.0, help="degrees")
    parser.add_argument("--falloff", type=float, default=4.0)
    parser.add_argument("--method", default="dqs")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--rest-frame", type=int, default=None,
                        help="use this frame (0-based) as the rest and the others as examples "
                             "(default: the mesh itself is the rest)")
    args = parser.parse_args()
    if args.rest_frame is not None and not 0 <= args.rest_frame < args.frames:
        parser.error(f"--rest-frame must be in [0, {args.frames - 1}]")
    rest = "the mesh" if args.rest_frame is None else f"frame {args.rest_frame}"
    print(f"{args.frames} frames, {args.handles} handles, {args.amplitude:g} degrees, "
          f"{args.method}, falloff {args.falloff:g}, seed {args.seed}, rest: {rest}")
    print("| mesh | tets | Steiner points | excluded tets | frames self-intersecting "
          "with excluded tets | clean frames with excluded tets | prepare s |")
    print("|---|---|---|---|---|---|---|")
    for mesh in args.meshes:
        print(rehearse(args, mesh), flush=True)


if __name__ == "__main__":
    sys.exit(main())
