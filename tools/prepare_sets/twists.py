#!/usr/bin/env python3
"""6 meshes x 4 twists about the longest bounding-box axis (two kaji handles):
handle 'fixed_end' at the box centre moved to the low end of that axis
(rotation 0), handle 'turned_end' at the high end, rotation vector
angle * axis (angle 180, 360, 540, 720 degrees); `tetblend deform --method
kaji` with distance weights (deform's default falloff).
Usage: twists.py TETBLEND OUT_DIR MESH.off..."""
import json, math, os, subprocess, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from off_file import read_off_positions

tb, out = sys.argv[1], sys.argv[2]
for mesh in sys.argv[3:]:
    name = os.path.splitext(os.path.basename(mesh))[0]
    pts = read_off_positions(mesh)[0]
    lo = [min(p[a] for p in pts) for a in range(3)]
    hi = [max(p[a] for p in pts) for a in range(3)]
    axis = max(range(3), key=lambda a: hi[a] - lo[a])
    centre = [(l + h) / 2 for l, h in zip(lo, hi)]
    a_end, b_end = list(centre), list(centre)
    a_end[axis], b_end[axis] = lo[axis], hi[axis]
    folder = os.path.join(out, name)
    os.makedirs(folder, exist_ok=True)
    for deg in (180, 360, 540, 720):
        rot = [0.0, 0.0, 0.0]
        rot[axis] = math.radians(deg)
        spec = os.path.join(folder, f"handles{deg}.json")
        with open(spec, "w") as f:
            json.dump({"handles": [{"name": "fixed_end", "centre": a_end, "rotation": [0, 0, 0]},
                                   {"name": "turned_end", "centre": b_end, "rotation": rot}]}, f)
        path = os.path.join(folder, f"twist{deg}.obj")
        subprocess.run([tb, "deform", mesh, "--handles", spec, "-o", path, "--method", "kaji"],
                       check=True, stdout=subprocess.DEVNULL)
    print(f"{mesh}: 4 twists about axis {'xyz'[axis]} in {folder}", flush=True)
