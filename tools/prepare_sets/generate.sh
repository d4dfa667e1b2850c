#!/usr/bin/env bash
# Generates the five prepare sets that The untangler's figures are measured
# on (README: "Rehearsal of prepare on skinned animations", "Long animations:
# 48 frames", "Open rest surfaces", "The untangler") into DATA_DIR, with
# DATA_DIR/manifest.tsv (set, model, rest, frame folder) for run.sh. Skinned
# frames come from tools/pose_rehearsal.py's own write_frames (frames.py),
# without the rehearsal's prepare run. The CGAL demo meshes are unpacked from
# /usr/share/doc/libcgal-demo/data.tar.gz into DATA_DIR/cgal once.
# The README never named the holed sets' meshes; these lists fix them: the 4-holes
# set = the 10 meshes of the corpus, the twists and the harsh set (cactus
# eight knot1 elephant hand handle dino femur homer triceratops) + armadillo
# ("now with the holed armadillo"); the 3-large-holes set = the same 11 +
# blobby (blobby, handle, knot1 and dino are named in that section and in
# The untangler's "hc2's dino frame 7").
# Usage: bash tools/prepare_sets/generate.sh DATA_DIR [TETBLEND]
#   TETBLEND defaults to the repository's build/release/apps/tetblend.
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO=$(cd "$HERE/../.." && pwd)
mkdir -p "${1:?usage: generate.sh DATA_DIR [TETBLEND]}"
D=$(cd "$1" && pwd)
TB=${2:-$REPO/build/release/apps/tetblend}
[ -x "$TB" ] || { echo "no tetblend binary" >&2; exit 1; }
M=$D/cgal/data/meshes
if [ ! -d "$M" ]; then
  mkdir -p "$D/cgal" && tar xzf /usr/share/doc/libcgal-demo/data.tar.gz -C "$D/cgal"
fi
PY=/usr/bin/python3
cd "$D"
rm -rf twists harsh lion anim100 openholed manifest.tsv
MAN=$D/manifest.tsv
: > "$MAN"
add() { # add SET MODEL REST DIR   (frames: DIR/*.obj, sorted)
  printf '%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" >> "$MAN"
}

# 1. twists: 6 meshes x 4 twists of 180-720 deg about the longest bounding-box
#    axis, two kaji handles (README, The untangler, "Faster placement").
for m in cactus eight knot1 hand handle femur; do
  $PY "$HERE/twists.py" "$TB" "$D/twists" "$M/$m.off"
  add twists "$m" "$M/$m.off" "$D/twists/$m"
done

# 2. harsh: 6 meshes x 16 harsh skinned frames (60 deg, falloff 4, 6 handles:
#    pose_rehearsal.py's defaults).
for m in knot1 eight femur hand homer triceratops; do
  $PY "$HERE/frames.py" "$TB" "$D/harsh" "$M/$m.off" --frames 16 --handles 6 --amplitude 60 --falloff 4
  add harsh "$m" "$M/$m.off" "$D/harsh/$m"
done

# 3. lion: 48 gallop-like frames (Long animations, "Quadrupeds in a
#    gallop-like cycle").
$PY "$HERE/frames.py" "$TB" "$D/lion" "$M/lion.off" --frames 48 --handles 8 --amplitude 40 --falloff 3
add lion lion "$M/lion.off" "$D/lion/lion"

# 4. anim100: dino, elephant, homer, elk x 48 frames at 100 deg, falloff 3.
for m in dino elephant homer elk; do
  $PY "$HERE/frames.py" "$TB" "$D/anim100" "$M/$m.off" --frames 48 --handles 8 --amplitude 100 --falloff 3
  add anim100 "$m" "$M/$m.off" "$D/anim100/$m"
done

# 5. openholed: the open rests gentle (45 deg, falloff 2) and harsh (60, 4),
#    16 frames, 6 handles; 4 punched holes of 3 rings (seed 7) rehearsed with
#    8 handles, 60 deg, falloff 4; 3 large holes of 5 rings (seed 11) with
#    8 handles, 60 deg, falloff 3, seed 2 (mesh lists: see the header).
O=$D/openholed
for m in mushroom nefertiti lion lion-head; do
  $PY "$HERE/frames.py" "$TB" "$O/gentle" "$M/$m.off" --frames 16 --amplitude 45 --falloff 2
  add openholed "gentle-$m" "$M/$m.off" "$O/gentle/$m"
  $PY "$HERE/frames.py" "$TB" "$O/harsh" "$M/$m.off" --frames 16 --amplitude 60 --falloff 4
  add openholed "harsh-$m" "$M/$m.off" "$O/harsh/$m"
done
TEN="cactus eight knot1 elephant hand handle dino femur homer triceratops"
H4="$TEN armadillo"
H3="$TEN armadillo blobby"
mkdir -p "$O/h4mesh" "$O/h3mesh"
for m in $H4; do
  $PY "$REPO/tools/punch_holes.py" "$M/$m.off" "$O/h4mesh/$m.off" --holes 4 --rings 3 --seed 7
  $PY "$HERE/frames.py" "$TB" "$O/h4" "$O/h4mesh/$m.off" --frames 16 --handles 8 --amplitude 60 --falloff 4
  add openholed "h4-$m" "$O/h4mesh/$m.off" "$O/h4/$m"
done
for m in $H3; do
  $PY "$REPO/tools/punch_holes.py" "$M/$m.off" "$O/h3mesh/$m.off" --holes 3 --rings 5 --seed 11
  $PY "$HERE/frames.py" "$TB" "$O/h3" "$O/h3mesh/$m.off" --frames 16 --handles 8 --amplitude 60 --falloff 3 --seed 2
  add openholed "h3-$m" "$O/h3mesh/$m.off" "$O/h3/$m"
done

echo "manifest: $MAN ($(wc -l < "$MAN") models)"
