#!/usr/bin/env bash
# Compares two run.sh outputs (a before and an after): prints their summaries
# side by side, the clean frames with excluded tets of each, every frame (and
# corpus pose) whose excluded/inverted count or clean flag differs, and each
# model's prepare seconds and excluded tets.
# Usage: bash tools/prepare_sets/compare.sh OUT_A OUT_B
set -euo pipefail
A=${1:?usage: compare.sh OUT_A OUT_B}; B=${2:?usage: compare.sh OUT_A OUT_B}
echo "### summaries: $1 | $2"
table() { awk '/^$/{exit} !/^#/' "$1/summary"; }
paste -d'|' <(table "$A" | awk '{printf "%-74s\n", $0}') <(table "$B")
echo
echo "### clean frames with excluded tets"
echo "--- $1"; sed -n '/^clean frames with excluded tets/,/^$/p' "$A/summary" | sed '1d;$d'
echo "--- $2"; sed -n '/^clean frames with excluded tets/,/^$/p' "$B/summary" | sed '1d;$d'
echo
echo "### frames whose counts differ (set model frame: clean excluded $1 -> clean excluded $2)"
/usr/bin/python3 - "$A/detail" "$B/detail" <<'PY'
import sys
def load(p):
    d = {}
    for line in open(p):
        if line.startswith("#"): continue
        s, m, f, c, e = line.rstrip("\n").split("\t")
        d[(s, m, f)] = (c, int(e))
    return d
a, b = load(sys.argv[1]), load(sys.argv[2])
keys = list(a) + [k for k in b if k not in a]
n = 0
for k in keys:
    x, y = a.get(k, ("absent", 0)), b.get(k, ("absent", 0))
    if x[1] != y[1] or (x[1] and y[1] and x[0] != y[0]):
        n += 1
        print(f"{k[0]:<10} {k[1]:<22} {k[2]:<14} {x[0]:>3} {x[1]:>6} -> {y[0]:>3} {y[1]:>6}"
              f"  ({y[1]-x[1]:+d})")
print(f"{n} frames differ")
PY
echo
echo "### per model (prepare s, excluded): $1 -> $2"
join -j1 <(sed -n '/^per model:/,$p' "$A/summary" | awk 'NF>=12 && $1!="per"{print $1"/"$2, $10, $6}' | sort) \
         <(sed -n '/^per model:/,$p' "$B/summary" | awk 'NF>=12 && $1!="per"{print $1"/"$2, $10, $6}' | sort) |
  awk '{printf "%-28s %8s -> %-8s %7s -> %s\n", $1, $2, $4, $3, $5}'
