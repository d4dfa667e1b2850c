#!/usr/bin/env python3
"""Reads OUT_DIR/*.log and *.inspect (written by run.sh) for the models of
MANIFEST (written by generate.sh) and writes OUT_DIR/summary (per-set table,
clean frames with excluded tets, per-model rows; also printed) and
OUT_DIR/detail (one row per frame and corpus pose). run.sh calls it.
Usage: summarise.py OUT_DIR MANIFEST"""
import glob, os, re, sys
from collections import OrderedDict

out, manifest = sys.argv[1], sys.argv[2]
SETS = ["twists", "harsh", "lion", "anim100", "openholed"]

EX = re.compile(r"^tetblend: warning: (?P<name>.+?): (?P<n>\d+) tets? cannot be embedded "
                r"\(worst volume ratio [^)]*\); (?P<why>its surface does not intersect itself|"
                r"its surface intersects itself)")
REST = re.compile(r"^tetblend: warning: (?P<name>.+?): its surface intersects itself at .*?; "
                  r"(?P<n>\d+) tets? of the rest cannot be embedded")
NOTE = re.compile(r"^tetblend: .*?: (?P<tets>\S+(?: [kM])?) tets, \d+ vertices \((?P<steiner>\d+) "
                  r"Steiner points? added .*?; (?P<union>\d+) tets? excluded\)")
ALL = re.compile(r"\((?P<tets>\S+(?: [kM])?) tets in all\)")
TIMELINE = re.compile(r"^(?P<s>[\d.]+) s (?P<kb>\d+) KB$")


def frame_name(path):
    return os.path.splitext(os.path.basename(path))[0]


models = []
with open(manifest) as f:
    for line in f:
        if line.strip():
            s, m, rest, d = line.rstrip("\n").split("\t")
            models.append((s, m, rest, d))

detail = []
per_set = OrderedDict((s, dict(models=0, frames=0, clean_tets=0, si_tets=0, excluded=0, union=0,
                               rest=0, time=0.0, failed=0, clean_list=[])) for s in SETS)
model_rows = []
for s, m, rest, d in models:
    log = os.path.join(out, f"{s}_{m}.log")
    if not os.path.exists(log):
        continue  # set not run (EVAL_SETS)
    frames = sorted(glob.glob(os.path.join(d, "*.obj")))
    names = [frame_name(p) for p in frames]
    per = OrderedDict((n, [0, True, False]) for n in names)  # excluded, clean, warned
    union, tets, steiner, seconds, kb, rc = None, "?", "?", None, None, 0
    text = open(log).read().splitlines()
    for line in text:
        g = EX.match(line)
        if g:
            n = frame_name(g["name"])
            e = per.setdefault(n, [0, True, False])
            e[0] += int(g["n"])
            e[2] = True
            if "does not" not in g["why"]:
                e[1] = False
            continue
        g = REST.match(line)
        if g:
            per.setdefault("REST", [0, False, True])[0] += int(g["n"])
            continue
        g = NOTE.match(line)
        if g:
            union, tets, steiner = int(g["union"]), g["tets"], g["steiner"]
            continue
        g = ALL.search(line)
        if g and line.startswith("tetblend: "):
            tets = g["tets"]
        g = TIMELINE.match(line)
        if g:
            seconds, kb = float(g["s"]), int(g["kb"])
        if line.startswith("Command exited with non-zero status"):
            rc = int(line.split()[-1])
    if not text:
        rc = -1
    union_src = "note"
    insp = log[:-4] + ".inspect"
    if union is None and os.path.exists(insp):  # parts prepared on their own: no whole-model note
        g = re.search(r"excluded from the stitch: (\d+) tets", open(insp).read())
        union, union_src = (int(g[1]), "inspect") if g else (0, "inspect")
    if union is None:
        union, union_src = sum(e[0] for e in per.values()), "warnings"
    st = per_set[s]
    st["models"] += 1
    st["frames"] += len(names)
    st["failed"] += rc != 0
    st["time"] += seconds or 0.0
    st["union"] += union
    mex = mclean = msi = 0
    for n, (ex, clean, warned) in per.items():
        detail.append((s, m, n, ("yes" if clean else "no") if warned else "-", ex))
        if n == "REST":  # a self-intersecting rest embedded like a pose: counted apart
            st["rest"] += ex
            continue
        st["excluded"] += ex
        mex += ex
        if ex > 0 and clean:
            st["clean_tets"] += 1
            mclean += 1
            st["clean_list"].append(f"{m}/{n}:{ex}")
        elif ex > 0:
            st["si_tets"] += 1
            msi += 1
    model_rows.append((s, m, len(names), tets.replace(" ", ""), steiner, mex, union, msi, mclean,
                       f"{seconds:.1f}" if seconds is not None else "?", kb or "?", rc,
                       per.get("REST", [0])[0], union_src))

# The hard-pose corpus (meshing_tests' PoseCorpus).
corpus = dict(clean_tets=0, list=[], embed=0.0, wall=None, meshes=0, poses=0, result="?")
clog = os.path.join(out, "corpus.log")
if os.path.exists(clog):
    mesh = None
    for line in open(clog).read().splitlines():
        g = re.match(r"^(\S+)\.off: .*embedding (\S+) s$", line)
        if g:
            mesh = g[1]
            corpus["meshes"] += 1
            corpus["embed"] += float(g[2])
            continue
        g = re.match(r"^  (\w+)( \(self-intersecting\))?: (\d+) inverted,", line)
        if g and mesh:
            corpus["poses"] += 1
            n = int(g[3])
            clean = g[2] is None
            detail.append(("corpus", mesh, g[1], "yes" if clean else "no", n))
            if clean and n > 0:
                corpus["clean_tets"] += 1
                corpus["list"].append(f"{mesh}/{g[1]}:{n}")
        g = TIMELINE.match(line)
        if g:
            corpus["wall"] = float(g["s"])
        g = re.match(r"^\[  (PASSED|FAILED)  \] (\d+) tests?", line)
        if g:
            corpus["result"] = (corpus["result"] + " " if corpus["result"] != "?" else "") + \
                f"{g[1].lower()} {g[2]}"

with open(os.path.join(out, "detail"), "w") as f:
    f.write("# set\tmodel\tframe\tclean\texcluded\n")
    f.write("# clean: yes = prepare said the frame's surface does not intersect itself, no = it "
            "intersects itself (REST = a self-intersecting rest embedded like a pose), - = no tets "
            "excluded (prepare says nothing about the frame)\n")
    for row in detail:
        f.write("\t".join(map(str, row)) + "\n")

L = []
L.append(f"# {out}")
L.append("# clean = frames whose surface does not intersect itself but keep excluded (inverted) tets;")
L.append("# SI = self-intersecting frames with excluded tets; excluded = tets each frame cannot embed,")
L.append("# summed over frames; union = sum over models of the model's excluded tets (prepare's note,")
L.append("# or `tetblend inspect` for rests prepared part by part); rest = tets a self-intersecting")
L.append("# rest cannot embed (not in excluded); time = sum of the prepares' wall seconds (/usr/bin/time)")
L.append("# corpus row: meshes, poses, clean poses with inverted tets, embedding s summed over meshes")
L.append("# README convention (The untangler's 21a437b table): the five prepare sets' clean frames,")
L.append("# excluded tets summed over frames but per model (union) for openholed, and time")
L.append(f"{'set':<10} {'models':>6} {'frames':>6} {'clean':>5} {'SI':>4} {'excluded':>9} "
         f"{'union':>7} {'rest':>4} {'time_s':>8} {'failed':>6}")
tot = dict(models=0, frames=0, clean_tets=0, si_tets=0, excluded=0, union=0, rest=0, time=0.0,
           failed=0)
def row(name, st):
    return (f"{name:<10} {st['models']:>6} {st['frames']:>6} {st['clean_tets']:>5} "
            f"{st['si_tets']:>4} {st['excluded']:>9} {st['union']:>7} {st['rest']:>4} "
            f"{st['time']:>8.1f} {st['failed']:>6}")
for s, st in per_set.items():
    L.append(row(s, st))
    for k in tot:
        tot[k] += st[k]
L.append(row("TOTAL", tot))
L.append(f"{'corpus':<10} {corpus['meshes']:>6} {corpus['poses']:>6} {corpus['clean_tets']:>5} "
         f"{'':>4} {'':>9} {'':>7} {'':>4} {corpus['embed']:>8.1f}")
wall = corpus["wall"]
L.append(f"corpus test wall {wall if wall is not None else '?'} s; gtest {corpus['result']}")
readme = sum(st["excluded"] for s, st in per_set.items() if s != "openholed") + \
    per_set["openholed"]["union"]
L.append(f"README convention: clean {tot['clean_tets']}, excluded {readme}, time {tot['time']:.1f} s")
L.append("")
L.append("clean frames with excluded tets (model/frame:tets):")
for s, st in per_set.items():
    L.append(f"  {s}: {' '.join(st['clean_list']) or '-'}")
L.append(f"  corpus: {' '.join(corpus['list']) or '-'}")
L.append("")
L.append("per model: set model frames tets steiner excluded union SI_frames clean_frames "
         "prepare_s peak_KB exit rest union_from")
for r in model_rows:
    L.append("  " + " ".join(map(str, r)))
with open(os.path.join(out, "summary"), "w") as f:
    f.write("\n".join(L) + "\n")
print("\n".join(L))
