#!/usr/bin/env bash
# Sets up, builds and runs the stickmorph demo on bundled sample figures.
#
# The demo decides compatibility (paper, section 2.1) of two poses of a
# stick-figure letter A and of the letter A and its mirror image, then morphs
# the paper's S into U (Figure 8c) and writes, to out/: the morph (FORMAT.md
# JSON), its filmstrip, the straight-line morph's filmstrip (Figure 8d, which
# self-intersects) and the compatible triangulation drawn side by side.
# The headless Blender bake and render comes with the add-on.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
section() { printf '\n==== %s ====\n' "$*"; }

section "Dependencies"
bash scripts/install_deps.sh
echo "all Debian packages present"

section "Build"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build build -j2 --target stickmorph

# Runs `stickmorph check` and fails the demo unless its exit status is the
# expected one (0 compatible, 1 incompatible).
check() {
  local expected=$1 source=$2 target=$3 status=0
  echo "\$ build/stickmorph check $source $target"
  build/stickmorph check "$source" "$target" || status=$?
  if [[ $status -ne $expected ]]; then
    echo "demo: expected exit status $expected, got $status" >&2
    exit 1
  fi
}

pairs=tests/data/pairs

section "Compatible: letter A, two poses"
check 0 $pairs/compatible/letter_a.source.json $pairs/compatible/letter_a.target.json

section "Not compatible: letter A and its mirror image"
check 1 $pairs/incompatible/mirror_image.source.json $pairs/incompatible/mirror_image.target.json

section "Morph: S to U (Figure 8c) and the straight-line morph (Figure 8d)"
mkdir -p out
paper=tests/data/paper
run() { echo "\$ $*"; "$@"; }
run build/stickmorph morph $paper/s_to_u.source.json $paper/s_to_u.target.json -o out/s_to_u.json --frames 49 --svg out/s_to_u.svg
run build/stickmorph morph $paper/s_to_u.source.json $paper/s_to_u.target.json -o out/s_to_u_linear.json --frames 49 --method linear --svg out/s_to_u_linear.svg
run build/stickmorph triangulate $paper/s_to_u.source.json $paper/s_to_u.target.json -o out/s_to_u_triangulation.json --svg out/s_to_u_triangulation.svg
/usr/bin/python3 - <<'PY'
import json
ours = json.load(open("out/s_to_u.json"))["stats"]
linear = json.load(open("out/s_to_u_linear.json"))["stats"]
print(f"our morph: {ours['steiner_vertices']} Steiner vertices, every frame verified valid")
print(f"straight-line morph: frames {linear['invalid_frames']} self-intersect")
PY
ls -l out/

section "Demo finished"
