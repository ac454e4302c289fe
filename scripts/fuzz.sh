#!/usr/bin/env bash
# Runs one libFuzzer target of native/fuzz for a fixed time (docs/TESTING.md).
#
#   scripts/fuzz.sh --target NAME --time SECONDS [--build-dir DIR]
#
# NAME is figure_reader, morph_pair or correspond_pair (the executable is
# DIR/fuzz/fuzz_NAME, DIR defaults to build-sanitize, which
# scripts/sanitize.sh builds). The committed seeds (tests/data/fuzz/NAME)
# and regression inputs (tests/data/fuzz/regressions/NAME) are read but
# never written: inputs the fuzzer finds interesting go to
# out/fuzz/NAME/corpus, crash, timeout and out-of-memory inputs to
# out/fuzz/NAME/. Exits 0 when the time ran out with
# no finding, 1 on a finding (printing how to reproduce it), 2 on bad usage.
set -euo pipefail

usage() {
  echo "usage: scripts/fuzz.sh --target figure_reader|morph_pair|correspond_pair|clean_drawing --time SECONDS [--build-dir DIR]" >&2
}

target="" seconds="" build_dir=build-sanitize
while [[ $# -gt 0 ]]; do
  case "$1" in
    --target) target="${2:-}"; shift 2 ;;
    --time) seconds="${2:-}"; shift 2 ;;
    --build-dir) build_dir="${2:-}"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "scripts/fuzz.sh: unknown argument: $1" >&2; usage; exit 2 ;;
  esac
done
case "$target" in
  figure_reader|morph_pair|correspond_pair|clean_drawing) ;;
  *) echo "scripts/fuzz.sh: --target must be figure_reader, morph_pair, correspond_pair or clean_drawing, got '$target'" >&2; usage; exit 2 ;;
esac
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "scripts/fuzz.sh: --time needs a whole number of seconds, got '$seconds'" >&2; usage; exit 2
fi

cd "$(dirname "${BASH_SOURCE[0]}")/.."
fuzzer="$build_dir/fuzz/fuzz_$target"
if [[ ! -x "$fuzzer" ]]; then
  echo "scripts/fuzz.sh: $fuzzer not found; build it with scripts/sanitize.sh --build-only" >&2
  exit 2
fi
out="out/fuzz/$target"
mkdir -p "$out/corpus"

# Every sanitizer report is fatal; leaks are reported too (LeakSanitizer runs
# in this sandbox, checked when this script was written).
export ASAN_OPTIONS="${ASAN_OPTIONS:-halt_on_error=1:abort_on_error=1:detect_leaks=1:print_stacktrace=1:symbolize=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1:symbolize=1}"

# -max_len 4096: the seeds fit (tests/data/fuzz/make_seeds.py); longer
# inputs would only spend the time on legitimately large figures.
# -timeout 30: one input of at most 4096 bytes takes milliseconds; 30 s
# means the engine is stuck, not busy.
echo "fuzz: $fuzzer for ${seconds}s, seeds tests/data/fuzz/$target, findings under $out/"
corpora=("$out/corpus" "tests/data/fuzz/$target")
if [[ -d "tests/data/fuzz/regressions/$target" ]]; then
  corpora+=("tests/data/fuzz/regressions/$target")
fi
status=0
"$fuzzer" "${corpora[@]}" \
  -dict=native/fuzz/json.dict -max_len=4096 -timeout=30 -rss_limit_mb=2048 \
  -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$out/" \
  2>"$out/fuzz.log" || status=$?
tail -n 25 "$out/fuzz.log"
if [[ $status -ne 0 ]]; then
  echo
  echo "fuzz: FINDING in $target (exit $status); full log: $out/fuzz.log"
  for artifact in "$out"/crash-* "$out"/timeout-* "$out"/oom-* "$out"/leak-*; do
    [[ -e "$artifact" ]] || continue
    echo "  input: $artifact"
    echo "  reproduce: $fuzzer $artifact"
    echo "  see the outcome of each stage: STICKMORPH_FUZZ_TRACE=1 $fuzzer $artifact"
  done
  exit 1
fi
echo "fuzz: $target: no finding in ${seconds}s"
