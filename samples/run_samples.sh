#!/usr/bin/env bash
# Runs the whole tetblend pipeline on the samples, end to end:
#   run_samples.sh BUILD_DIR OUT_DIR          (./dev.sh demo calls it)
#
# The sample surfaces are generated at run time by tetblend-make-samples
# (apps/src/make_samples.cpp, from procedural_shapes.h) into OUT_DIR/surfaces,
# so no mesh files are committed: a 4 pi twisted bar, a cylinder bent into an L
# and a U, a two-bone limb posed by dual-quaternion and by linear-blend
# skinning (at 170 degrees LBS folds the elbow into itself: prepare reports
# the tets that pose cannot embed and leaves them out of the stitch).
# Committed here: batch.json (the batch spec, copied beside the model because
# its paths are relative to the spec), probe_handles.json (the deformer's
# handles), show_quality.py (pvpython: colour a .pvd by quality) and
# compare_methods.py (pvpython: every method in one PNG; run here through
# tools/run_pvpython.py, skipped with the reason when pvpython cannot be had).
set -euo pipefail
if [ $# -ne 2 ]; then
  sed -n '2,3p' "$0"
  exit 2
fi
build=$(cd "$1" && pwd)
mkdir -p "$2"
out=$(cd "$2" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
tb="$build/apps/tetblend"
s="$out/surfaces"

step() { echo "== $*"; }

step "sample surfaces -> $s"
"$build/apps/tetblend-make-samples" "$s"

step "prepare: validate, tetrahedralise (TetGen), compatible tet meshes"
"$tb" prepare "$s/bar_rest.obj" "$s/bar_twist4pi.obj" "$s/bar_bend.obj" -o "$out/bar.tbm"
"$tb" prepare "$s/cyl_rest.off" "$s/cyl_bend90.off" "$s/cyl_bend180.off" -o "$out/cyl.tbm"
"$tb" prepare "$s/limb_rest.obj" "$s/limb_dqs.obj" "$s/limb_lbs.obj" -o "$out/limb.tbm"
"$tb" prepare --tetrise "$s/bar_rest.obj" "$s/bar_twist4pi.obj" "$s/bar_bend.obj" \
  -o "$out/bar_tetrised.tbm"

step "prepare a pose that intersects itself (warning, excluded tets)"
"$tb" prepare "$s/limb_rest.obj" "$s/limb_dqs.obj" "$s/limb_lbs170.obj" -o "$out/limb_folded.tbm"

step "inspect"
"$tb" inspect "$out/bar.tbm" "$out/cyl.tbm" "$out/limb.tbm" "$out/limb_folded.tbm" "$s/bar_rest.obj"

step "blend: half of the 4 pi twist (kaji and dq), the U-bent cylinder halfway"
mkdir -p "$out/blend"
"$tb" blend "$out/bar.tbm" --weights 0.5,0 -o "$out/blend/bar_half_twist_kaji.vtu" \
  --surface-format obj
"$tb" blend "$out/bar.tbm" --weights 0.5,0 --method dq -o "$out/blend/bar_half_twist_dq.vtu"
"$tb" blend "$out/cyl.tbm" --weights 0,0.5 -o "$out/blend/cyl_half_u.vtu"

step "batch: every method at half the twist (resumable; see $out/batch/summary.csv)"
cp "$here/batch.json" "$out/batch.json"
"$tb" batch "$out/batch.json"

step "variations: 8 random cylinders, and principal components of the limb"
"$tb" variations "$out/cyl.tbm" --count 8 --seed 42 -o "$out/variations"
"$tb" variations "$out/limb.tbm" --pca --count 5 -o "$out/pca"

step "animate: rest -> twist -> bend -> rest (Catmull-Rom in weight space)"
"$tb" animate "$out/bar.tbm" --keys "0,0;1,0;0,1;0,0" --frames 24 -o "$out/animation"

step "deform: probe turned by 2 pi (kaji swirls, dq does not move; Kaji-Ochiai Fig. 2)"
mkdir -p "$out/deform"
for m in kaji dq; do
  "$tb" deform "$s/bar_rest.obj" --handles "$here/probe_handles.json" --method "$m" \
    -o "$out/deform/bar_probe_$m.vtp"
done

step "every method at half the twist, one picture (pvpython; README figure)"
status=0
/usr/bin/python3 "$here/../tools/run_pvpython.py" "$build/pvpython" "$here/compare_methods.py" \
  "$out/bar.tbm" --weights 0.5,0 -o "$out/compare_methods.png" \
  --plugin "$build/python/tetblend_plugin.py" 2> "$out/compare_methods.log" || status=$?
case $status in
  0) echo "   $out/compare_methods.png" ;;
  77) echo "   skipped: $(tail -n 1 "$out/compare_methods.log")" ;;
  *) cat "$out/compare_methods.log" >&2; exit "$status" ;;
esac

step "done: open $out/batch/batch.pvd or $out/animation/animation.pvd in ParaView"
echo "   (pvpython $here/show_quality.py $out/batch/batch.pvd volume_ratio)"
cat "$out/batch/summary.csv"
