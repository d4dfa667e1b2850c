#!/usr/bin/env python3
"""Writes the skinned frames of tools/pose_rehearsal.py (its own write_frames,
so the frames are byte for byte the rehearsal's) without running prepare.
Usage: frames.py TETBLEND OUT_DIR MESH... [--frames N] [--handles N]
       [--amplitude DEG] [--falloff P] [--method dqs] [--seed S]
Frames go to OUT_DIR/<mesh name>/frameNNN.obj, as the rehearsal writes them."""
import argparse, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import pose_rehearsal

p = argparse.ArgumentParser()
p.add_argument("tetblend"); p.add_argument("out_dir"); p.add_argument("meshes", nargs="+")
p.add_argument("--frames", type=int, default=16)
p.add_argument("--handles", type=int, default=6)
p.add_argument("--amplitude", type=float, default=60.0)
p.add_argument("--falloff", type=float, default=4.0)
p.add_argument("--method", default="dqs")
p.add_argument("--seed", type=int, default=1)
a = p.parse_args()
for mesh in a.meshes:
    name = os.path.splitext(os.path.basename(mesh))[0]
    folder = os.path.join(a.out_dir, name)
    os.makedirs(folder, exist_ok=True)
    paths = pose_rehearsal.write_frames(a, mesh, folder)
    print(f"{mesh}: {len(paths)} frames in {folder}", flush=True)
