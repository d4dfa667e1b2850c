#!/usr/bin/env bash
# Runs `tetblend prepare REST FRAMES...` on every model of DATA_DIR's
# manifest.tsv (written by generate.sh), one at a time, then the hard-pose
# corpus test (meshing_tests' CgalDemoMeshes/PoseCorpus.*); writes
# OUT_DIR/{SET_MODEL.log,corpus.log,info} and, through summarise.py,
# OUT_DIR/summary and OUT_DIR/detail.
# Usage: bash tools/prepare_sets/run.sh DATA_DIR OUT_DIR [TETBLEND]
#   TETBLEND defaults to the repository's build/release/apps/tetblend.
#   MESHING_TESTS=path  the meshing_tests binary of the same build (default:
#                       in TETBLEND's build tree)
#   EVAL_SETS="twists harsh"  only these sets; EVAL_CORPUS=0 skips the corpus
set -uo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO=$(cd "$HERE/../.." && pwd)
USAGE="usage: run.sh DATA_DIR OUT_DIR [TETBLEND]"
MAN=${1:?$USAGE}/manifest.tsv
OUT=${2:?$USAGE}
TB=${3:-$REPO/build/release/apps/tetblend}
[ -x "$TB" ] || { echo "no tetblend binary: $TB" >&2; exit 1; }
TB=$(readlink -f "$TB")
[ -f "$MAN" ] || { echo "no $MAN: run generate.sh first" >&2; exit 1; }
# TB is BUILD/apps/tetblend; the corpus test is BUILD/tests/meshing/meshing_tests.
MESHING_TESTS=${MESHING_TESTS:-$(dirname "$(dirname "$TB")")/tests/meshing/meshing_tests}
[ -x "$MESHING_TESTS" ] || MESHING_TESTS=
mkdir -p "$OUT"
rm -f "$OUT"/*.log "$OUT"/*.inspect "$OUT"/*.tbm "$OUT"/info "$OUT"/summary "$OUT"/detail
{
  echo "label $(basename "$OUT")"; echo "tetblend $TB ($(stat -c '%y %s' "$TB"))"
  echo "meshing_tests ${MESHING_TESTS:-none}"; echo "start $(date -Is)"
  echo "git $(git -C "$REPO" rev-parse --short HEAD 2>/dev/null) $(git -C "$REPO" status --porcelain 2>/dev/null | wc -l) changed files"
  echo "load $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$OUT/info"
SETS=${EVAL_SETS:-twists harsh lion anim100 openholed}
t0=$(date +%s.%N)
while IFS=$'\t' read -r set model rest dir; do
  case " $SETS " in *" $set "*) ;; *) continue ;; esac
  mapfile -t frames < <(ls "$dir"/*.obj | sort)
  log=$OUT/${set}_$model.log
  echo "== $set $model: ${#frames[@]} frames" >&2
  /usr/bin/time -f '%e s %M KB' "$TB" prepare "$rest" "${frames[@]}" \
      -o "$OUT/${set}_$model.tbm" > "$log" 2>&1 < /dev/null
  tail -n 1 "$log" >&2
  # A rest prepared part by part prints no whole-model "N tets excluded" note:
  # the model's own count of excluded tets then comes from inspect (untimed).
  if ! grep -Eq 'tets? excluded\)' "$log" && [ -f "$OUT/${set}_$model.tbm" ]; then
    "$TB" inspect "$OUT/${set}_$model.tbm" > "$OUT/${set}_$model.inspect" 2>&1 < /dev/null
  fi
  rm -f "$OUT/${set}_$model.tbm"   # models are large; the logs hold what is measured
done < "$MAN"
if [ "${EVAL_CORPUS:-1}" != 0 ] && [ -n "${MESHING_TESTS:-}" ]; then
  echo "== corpus ($MESHING_TESTS)" >&2
  /usr/bin/time -f '%e s %M KB' "$MESHING_TESTS" --gtest_filter='CgalDemoMeshes/PoseCorpus.*' \
      > "$OUT/corpus.log" 2>&1 < /dev/null
  tail -n 1 "$OUT/corpus.log" >&2
fi
t1=$(date +%s.%N)
echo "end $(date -Is); whole run $(echo "$t1 - $t0" | bc) s" >> "$OUT/info"
/usr/bin/python3 "$HERE/summarise.py" "$OUT" "$MAN"
echo "whole run (prepares + corpus, wall): $(echo "$t1 - $t0" | bc) s" | tee -a "$OUT/summary"
