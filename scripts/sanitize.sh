#!/usr/bin/env bash
# The sanitizer suite (docs/TESTING.md): builds build-sanitize with clang,
# AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer coverage, runs
# every Catch2 test under the sanitizers, then runs each fuzz target on its
# seed corpus for a fixed time. Stops at the first failure.
#
#   scripts/sanitize.sh                    build, Catch2 tests, 60 s per fuzz target
#   scripts/sanitize.sh --fuzz-time N      N seconds per fuzz target
#   scripts/sanitize.sh --build-only       only configure and build
#
# One build directory serves both: every object is compiled with
# -fsanitize=address,undefined and -fsanitize=fuzzer-no-link, the Catch2
# tests link normally and only the fuzz targets link libFuzzer.
set -euo pipefail

usage() {
  echo "usage: scripts/sanitize.sh [--fuzz-time SECONDS] [--build-only]" >&2
}

fuzz_seconds=60 build_only=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --fuzz-time) fuzz_seconds="${2:-}"; shift 2 ;;
    --build-only) build_only=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "scripts/sanitize.sh: unknown argument: $1" >&2; usage; exit 2 ;;
  esac
done
if ! [[ "$fuzz_seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "scripts/sanitize.sh: --fuzz-time needs a whole number of seconds, got '$fuzz_seconds'" >&2; exit 2
fi

cd "$(dirname "${BASH_SOURCE[0]}")/.."
section() { printf '\n==== %s ====\n' "$*"; }
build_dir=build-sanitize

section "Dependencies"
bash scripts/install_deps.sh
echo "all Debian packages present"

# clang++-14 on Debian 12 (scripts/install_deps.sh), the default clang++ on
# later releases, which package no clang 14.
clang=$(command -v clang++-14 || command -v clang++ || true)
[[ -n "$clang" ]] || { echo "sanitize.sh: no clang++ found (scripts/install_deps.sh installs it)" >&2; exit 2; }

section "Configure ($build_dir: $(basename "$clang"), ASan + UBSan, libFuzzer)"
# RelWithDebInfo: optimised like the release build (so the suite runs in
# reasonable time) with line numbers in sanitizer stack traces.
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER="$clang" \
  -DSTICKMORPH_SANITIZE=ON -DSTICKMORPH_BUILD_FUZZERS=ON \
  -DSTICKMORPH_BUILD_PYTHON=OFF -DSTICKMORPH_BUILD_TESTS=ON

section "Build"
# Everything, not only the targets run here: ctest runs every executable
# the test tree registers, and the CLI and benchmarks at least compile
# under the sanitizers' flags.
cmake --build "$build_dir" -j2
if [[ $build_only -eq 1 ]]; then
  exit 0
fi

# Any report aborts the process with a stack trace, so ctest and the
# fuzzers see a failure. LeakSanitizer works in this sandbox (it needs
# ptrace-like access to the process, which some containers deny; if it did
# not, every test would fail with "LeakSanitizer has encountered a fatal
# error" rather than pass unchecked).
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:print_stacktrace=1:symbolize=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:symbolize=1"

section "C++ tests under ASan + UBSan (ctest)"
ctest --test-dir "$build_dir" -j2 --output-on-failure

for target in figure_reader morph_pair correspond_pair clean_drawing; do
  section "Fuzz $target for ${fuzz_seconds}s"
  bash scripts/fuzz.sh --target "$target" --time "$fuzz_seconds" --build-dir "$build_dir"
done

section "Sanitizer suite passed"
