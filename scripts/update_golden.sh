#!/usr/bin/env bash
# Regenerates the golden results in tests/data/golden/ from the current
# engine, for a change that is meant to alter them (docs/TESTING.md,
# "Golden results"):
#
#   tests/data/golden/steiner_counts.json   by the Catch2 test [golden]
#   tests/data/golden/morphs/*.json         by tests/python/test_golden_morphs.py
#
#   bash scripts/update_golden.sh [--build-dir DIR]   (default: build)
#
# It builds the two targets it runs (in DIR, configured if needed), runs both
# tests with STICKMORPH_UPDATE_GOLDEN=1, which makes them write their file
# before comparing, and lists the golden files that changed (git status). Review the
# diff and commit it with the change that explains it: the normal test runs
# never write these files, so drift is never silent.
set -euo pipefail

usage() { echo "usage: scripts/update_golden.sh [--build-dir DIR]" >&2; }

build_dir=build
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build-dir) build_dir="${2:-}"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "scripts/update_golden.sh: unknown argument: $1" >&2; usage; exit 2 ;;
  esac
done
if [[ -z "$build_dir" ]]; then echo "scripts/update_golden.sh: --build-dir needs a directory" >&2; exit 2; fi

cd "$(dirname "${BASH_SOURCE[0]}")/.."
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
fi
cmake --build "$build_dir" -j2 --target stickmorph stickmorph_tests

export STICKMORPH_UPDATE_GOLDEN=1
"$build_dir/stickmorph_tests" "[golden]"
STICKMORPH_BUILD_DIR="$build_dir" /usr/bin/python3 -m pytest -q tests/python/test_golden_morphs.py

# status, not diff --stat: a golden file for a new case is untracked.
git status --short -- tests/data/golden
echo "golden files regenerated; review 'git diff tests/data/golden' before committing"
