#!/usr/bin/env bash
# Sets up, builds and runs the stickmorph demo on bundled sample figures.
#
# Today the demo decides compatibility (paper, section 2.1) of two poses of a
# stick-figure letter A, then of the letter A and a mirror image of it, which
# is not compatible. The figures are pairs from tests/data/pairs.
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

section "Demo finished"
