#!/usr/bin/env bash
# Sets up, builds and runs every test: the Catch2 tests of the engine and CLI
# (through ctest), the pytest tests of the Python module and the CLI, and the
# Blender add-on's tests in Blender 3.4, 4.3 and 5.2 (scripts/blender_matrix.sh).
#
# Then the sanitizer suite (scripts/sanitize.sh, docs/TESTING.md): the Catch2
# tests again under AddressSanitizer + UndefinedBehaviorSanitizer (clang), and
# each libFuzzer target on its seed corpus.
#
#   scripts/test.sh           the regular suite, 60 s per fuzz target
#   scripts/test.sh --long    also the long modes: 10,000 random compatible
#                             pairs with a random seed (failures saved to
#                             tests/data/regressions), 10 minutes per fuzz target
set -euo pipefail

usage() {
  echo "usage: scripts/test.sh [--long]" >&2
}

fuzz_seconds=60
for argument in "$@"; do
  case "$argument" in
    --long) export STICKMORPH_LONG=1; fuzz_seconds=600 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "scripts/test.sh: unknown argument: $argument" >&2; usage; exit 2 ;;
  esac
done

cd "$(dirname "${BASH_SOURCE[0]}")/.."
section() { printf '\n==== %s ====\n' "$*"; }

section "Dependencies"
bash scripts/install_deps.sh
echo "all Debian packages present"

# Debian's Python, the one Blender embeds and the one with python3-numpy;
# a python3 earlier on PATH (pyenv, venv) would build an unusable module.
PYTHON=/usr/bin/python3

section "Configure"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE="$PYTHON" \
  -DSTICKMORPH_BUILD_TESTS=ON -DSTICKMORPH_BUILD_PYTHON=ON

section "Build"
cmake --build build -j2

# Every suite is a CTest test (CMakeLists.txt), by label: this script only
# sets up, builds and runs them in order, stopping at the first failing one.
section "C++ tests (ctest -L cpp)"
ctest --test-dir build --output-on-failure -L cpp

section "Python tests: module and CLI (ctest -L python: pytest tests/python)"
ctest --test-dir build --output-on-failure --verbose -L python

section "Blender add-on tests: 3.4 (host), 4.3 (Debian 13 chroot), 5.2 (sid chroot) (ctest -L blender)"
# The headless suite, the GUI test and a demo render in each Blender users
# run; the chroots are created when missing and cached outside the
# repository (docs/BLENDER.md).
ctest --test-dir build --output-on-failure --verbose -L blender

section "Sanitizer suite (ASan + UBSan, libFuzzer)"
# The random-pair long mode already ran above; under the sanitizers it would
# only repeat it ten times slower.
env -u STICKMORPH_LONG bash scripts/sanitize.sh --fuzz-time "$fuzz_seconds"

section "All tests passed"
