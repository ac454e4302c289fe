#!/usr/bin/env bash
# Regenerates BENCHMARKS.md and its plots (docs/benchmarks/*.svg) in one run.
#
#   bash bench/benchmarks.sh [--quick] [--working-tree]
#
# Measures exactly the committed HEAD: a detached git worktree of it in
# build-bench/source (git rewrites only the files that changed, so rebuilds
# stay incremental), built in Release in build-bench/release. Uncommitted
# edits in the working tree, which other people may be in the middle of, are
# not measured, so the commit that BENCHMARKS.md names is the code measured.
# --working-tree measures the working tree instead (build-bench/working-tree),
# and the report then says that the commit had uncommitted changes.
#
# Runs the benchmark programs with machine-readable output into
# out/benchmarks/ (gitignored):
#   polygon_pairs.json  stickmorph_benchmark on tests/data/polygon_pairs
#   morph.jsonl         stickmorph_benchmark_morph on the generated corpus
#   correspondence.json stickmorph_benchmark_correspondence (issue 13): automatic
#                       correspondence against size (correspondence.md: its table)
#   scrub.jsonl         stickmorph_benchmark_scrub (issue 15): frames per second of
#                       the stateful solvers at 10^3 and 10^4 vertices in every
#                       family, and at 10^5 (polyline and triangulation) with
#                       fewer frames, barycentric only (scrub.md,
#                       scrub_large.md: their tables)
#   motion_corpus/      bench/motion_corpus.py: the motion-quality corpus
#   motion.json         bench/motion_quality.py on it (issue 12, docs/MOTION.md):
#                       rigid (if `stickmorph morph --help` lists it),
#                       barycentric, linear and arap; filmstrips of the worst
#                       pairs go to docs/benchmarks/motion/
#   motion_before.json  not written here: an earlier run's motion.json on the same
#                       corpus, copied in by hand with a "label" (its commit), shown
#                       as the "before" rows of issue 30's table when present
#   key_pose_corpus/    bench/key_pose_corpus.py --redrawn: key-pose sequences
#   sequences.json      bench/sequence_motion.py on it (issue 28): the sequence
#                       morph against chained pair morphs and straight-line
#                       (shape-key) blending, and keys drawn separately
#   local_timing_corpus/ bench/local_timing_corpus.py --seed 31: skeleton pairs where
#                       the body bends while one limb turns about its junction
#   local_timing.json   bench/local_timing.py on it (issue 31): the lag of the limb
#                       delayed by `--timing` against the overlap asked (0.3, 0.5),
#                       validity, exact ends, d = 0 against the plain morph; skipped,
#                       and the report says so, when `stickmorph morph --help` lists
#                       no --timing
#   drawing_corpus/     bench/drawing_corpus.py --seed 32: hand-drawn-like drawings
#                       with gaps, touches, crossings and pen pauses planted
#   cleaning.json       bench/cleaning.py on it (issue 32): `stickmorph clean`
#                       checked (valid, every change reported, the defects found,
#                       idempotent, pairs morphed); skipped, and the report says
#                       so, when the CLI has no clean command
#   blender.json        bench/blender_bake.py (issue 29): the bake and playback
#                       in headless Blender at 10^3, 10^4 and 10^5 vertices,
#                       with the add-on package built from the measured commit
#                       (build-bench/addon, build-bench/dist); skipped, and the
#                       report says so, when no blender is on PATH
#   run.json            machine, date, commit, command, runtime
# and then bench/make_benchmarks.py (Debian's /usr/bin/python3 with
# python3-matplotlib) writes BENCHMARKS.md and the SVG plots from those files.
# --quick runs sizes 10 to 300 only (the scrubbing benchmark at 1000 with 60
# frames), to try the pipeline in a minute; the report gives the command it
# was made with.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
start=$(date +%s)
command="bash bench/benchmarks.sh"
sizes=10,30,100,300,1000,3000,10000
scrub_sizes=1000,10000
scrub_frames=240
scrub_large=100000
scrub_large_frames=24
# Every family at 10^3 and 10^4: the blended frames of the rigid morph
# (polygon, spiral, thinned, rings) cost more than the exact ones, and the
# 60 frames per second are asked of any 10^4-vertex figure.
scrub_families=polyline,spiral,polygon,tree,triangulation,thinned,rings
blender_sizes=1000,10000,100000
local_timing_count=36
drawing_count=40
working_tree=0
for argument in "$@"; do
  case "$argument" in
    --quick) sizes=10,30,100,300; scrub_sizes=1000; scrub_frames=60; scrub_large= ; blender_sizes=1000
             local_timing_count=10; drawing_count=10 ;;
    --working-tree) working_tree=1 ;;
    *) echo "usage: bash bench/benchmarks.sh [--quick] [--working-tree]" >&2; exit 2 ;;
  esac
  command+=" $argument"
done
frames=50
# Each improved case up to 1000 vertices three times, the median kept (the
# fitted growth over 100 to 1000 vertices rests on cases of milliseconds).
repeat=3
repeat_max_n=1000
aronov_max=300
sg2001_max=1000
memory_limit_mib=4096
data=out/benchmarks
commit=$(git rev-parse --short=12 HEAD)

bash scripts/install_deps.sh

if [[ $working_tree -eq 1 ]]; then
  source_dir=.
  build=build-bench/working-tree
  if [[ -n "$(git status --porcelain --untracked-files=no)" ]]; then
    commit+=" with uncommitted changes"
  fi
else
  source_dir=build-bench/source
  build=build-bench/release
  head=$(git rev-parse HEAD)
  if [[ ! -e "$source_dir/.git" ]]; then
    mkdir -p build-bench
    git worktree add --quiet --detach "$source_dir" "$head"
  else
    git -C "$source_dir" checkout --quiet --detach "$head"
  fi
fi

echo "==== build ($build from $source_dir at $commit, Release) ===="
# Configured every run, not only the first: a build directory configured
# at an older commit has no Makefile rule for a target added since, and
# naming several targets at once does not regenerate it first.
if [[ -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$source_dir" -B "$build" >/dev/null
else
  cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 \
    -DSTICKMORPH_BUILD_PYTHON=OFF -DSTICKMORPH_BUILD_TESTS=OFF
fi
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$build/CMakeCache.txt")
if [[ "$build_type" != "Release" ]]; then
  echo "error: $build is configured as '$build_type', not Release; remove it or reconfigure" >&2
  exit 2
fi
cmake --build "$build" -j2 --target stickmorph_benchmark stickmorph_benchmark_morph \
  stickmorph_benchmark_correspondence stickmorph_benchmark_scrub stickmorph

mkdir -p "$data"
rm -rf "$data/polygon_pairs.json" "$data/morph.jsonl" "$data/correspondence.json" "$data/motion.json" \
  "$data/scrub.jsonl" "$data/scrub_large.jsonl" "$data/run.json" "$data/sequences.json" "$data/key_pose_corpus" "$data/blender.json" \
  "$data/local_timing.json" "$data/local_timing_corpus" "$data/cleaning.json" "$data/drawing_corpus"

echo "==== polygon-pair corpus (tests/data/polygon_pairs) ===="
"$build/stickmorph_benchmark" --json "$data/polygon_pairs.json" "$source_dir/tests/data/polygon_pairs" \
  > "$data/polygon_pairs.md"

echo "==== morph corpus (sizes $sizes, $frames frames; progress below) ===="
"$build/stickmorph_benchmark_morph" --sizes "$sizes" --frames "$frames" --aronov-max "$aronov_max" \
  --sg2001-max "$sg2001_max" --memory-limit-mib "$memory_limit_mib" --repeat "$repeat" \
  --repeat-max-n "$repeat_max_n" --json "$data/morph.jsonl" \
  > "$data/morph.md"

echo "==== scrubbing (issue 15: stickmorph_benchmark_scrub, sizes $scrub_sizes, $scrub_frames frames; progress below) ===="
"$build/stickmorph_benchmark_scrub" --sizes "$scrub_sizes" --frames "$scrub_frames" --families "$scrub_families" \
  --json "$data/scrub.jsonl" > "$data/scrub.md"
if [[ -n "$scrub_large" ]]; then
  # 10^5 vertices: triangulating takes minutes there (the rigid setup would
  # triangulate again) and a frame up to a second, so fewer frames and the
  # barycentric solver only, to keep the whole command near a quarter hour.
  "$build/stickmorph_benchmark_scrub" --sizes "$scrub_large" --frames "$scrub_large_frames" --no-rigid \
    --families polyline,triangulation --json "$data/scrub_large.jsonl" > "$data/scrub_large.md"
  cat "$data/scrub_large.jsonl" >> "$data/scrub.jsonl"
fi

echo "==== correspondence (issue 13: stickmorph_benchmark_correspondence, sizes $sizes; progress below) ===="
"$build/stickmorph_benchmark_correspondence" --sizes "$sizes" --memory-limit-mib "$memory_limit_mib" \
  --json "$data/correspondence.json" > "$data/correspondence.md"
tail -1 "$data/correspondence.md"  # whether the 1000-vertex pairs match in under a second

echo "==== motion quality (issue 12: bench/motion_corpus.py, bench/motion_quality.py) ===="
# The rigid method is measured once the CLI has it: `stickmorph morph --help`
# lists it under --method (or, if the help has no --method entry, anywhere).
morph_help=$("$build/stickmorph" morph --help 2>&1 || true)
method_help=$(printf '%s\n' "$morph_help" | awk '/^ *--method/ {on = 1; print; next} on && /^ *-/ {on = 0} on')
[[ -n "$method_help" ]] || method_help=$morph_help
motion_methods=()
if [[ "$method_help" == *rigid* ]]; then
  motion_methods+=(--cli-method "rigid=--method rigid" --filmstrip-method rigid --filmstrip-rows rigid,barycentric)
else
  echo "note: stickmorph morph --help lists no rigid method: the motion table has no rigid row"
  motion_methods+=(--note "no rigid row: \`stickmorph morph --help\` at $commit lists no rigid method"
                   --filmstrip-method barycentric --filmstrip-rows barycentric)
fi
/usr/bin/python3 bench/motion_corpus.py "$data/motion_corpus" --build-dir "$build" > "$data/motion_corpus.log"
tail -1 "$data/motion_corpus.log"
/usr/bin/python3 bench/motion_quality.py "$data/motion_corpus" --build-dir "$build" \
  "${motion_methods[@]}" --cli-method "barycentric=--method barycentric" \
  --filmstrip docs/benchmarks/motion --filmstrip-worst 1 --filmstrip-pairs special_self_turn_180 \
  --json "$data/motion.json" > "$data/motion.md" 2> "$data/motion.log" \
  || { tail -20 "$data/motion.log" >&2; exit 1; }

echo "==== key poses (issue 28: bench/key_pose_corpus.py --redrawn, bench/sequence_motion.py) ===="
/usr/bin/python3 bench/key_pose_corpus.py "$data/key_pose_corpus" --build-dir "$build" --redrawn \
  > "$data/key_pose_corpus.log"
tail -1 "$data/key_pose_corpus.log"
/usr/bin/python3 bench/sequence_motion.py "$data/key_pose_corpus" --build-dir "$build" \
  --json "$data/sequences.json" > "$data/sequences.md"
sed -n '/^medians/,$p' "$data/sequences.md"

# morph_help: `stickmorph morph --help`, read for the motion step above.
if [[ "$morph_help" == *--timing* ]]; then
  echo "==== local timing (issue 31: bench/local_timing_corpus.py, bench/local_timing.py) ===="
  /usr/bin/python3 bench/local_timing_corpus.py "$data/local_timing_corpus" --seed 31 --count "$local_timing_count" \
    --build-dir "$build" > "$data/local_timing_corpus.log"
  tail -1 "$data/local_timing_corpus.log"
  /usr/bin/python3 bench/local_timing.py "$data/local_timing_corpus" --build-dir "$build" --overlaps 0.3,0.5 \
    --json "$data/local_timing.json" > "$data/local_timing.md" 2> "$data/local_timing.log" \
    || { tail -20 "$data/local_timing.log" >&2; exit 1; }
  sed -n '/^plain (no --timing)/,$p' "$data/local_timing.md"
else
  echo "==== local timing: not measured (\`stickmorph morph --help\` lists no --timing) ===="
fi

if "$build/stickmorph" clean --help >/dev/null 2>&1; then
  echo "==== drawing cleaning (issue 32: bench/drawing_corpus.py, bench/cleaning.py) ===="
  /usr/bin/python3 bench/drawing_corpus.py "$data/drawing_corpus" --seed 32 --count "$drawing_count" \
    > "$data/drawing_corpus.log"
  tail -1 "$data/drawing_corpus.log"
  /usr/bin/python3 bench/cleaning.py "$data/drawing_corpus" --build-dir "$build" --json "$data/cleaning.json" \
    > "$data/cleaning.md" 2> "$data/cleaning.log" || { tail -20 "$data/cleaning.log" >&2; exit 1; }
  sed -n '/^kind /,$p' "$data/cleaning.md"
else
  echo "==== drawing cleaning: not measured (\`stickmorph clean --help\` fails) ===="
fi

if command -v "${BLENDER:-blender}" >/dev/null; then
  echo "==== Blender (issue 29: bench/blender_bake.py, sizes $blender_sizes; progress below) ===="
  # The package of the measured commit, for the Blender on PATH (its module
  # built for Blender's Python, which also draws the pairs here).
  /usr/bin/python3 "$source_dir/build_addon.py" --blender "${BLENDER:-blender}" --build-dir build-bench/addon \
    --dist build-bench/dist > "$data/blender_build.log" 2>&1 || { tail -20 "$data/blender_build.log" >&2; exit 1; }
  /usr/bin/python3 bench/blender_bake.py --cli "$build/stickmorph" --module build-bench/addon/python \
    --dist build-bench/dist --sizes "$blender_sizes" --json "$data/blender.json" > "$data/blender.md" \
    || echo "bench/blender_bake.py: some cases failed; their rows in BENCHMARKS.md say why"
  cat "$data/blender.md"
else
  echo "==== Blender: not measured (no blender on PATH) ===="
fi

runtime=$(( $(date +%s) - start ))
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
memory=$(awk '/^MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)
os=$(. /etc/os-release && echo "$PRETTY_NAME")
compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
compiler_version=$("${compiler:-c++}" --version | head -1)
flags=$(sed -n 's/^CMAKE_CXX_FLAGS_RELEASE:STRING=//p' "$build/CMakeCache.txt")

# Passed through the environment, not spliced into Python source, so that no
# character in a CPU name or path can break the JSON.
BENCH_COMMAND="$command" BENCH_DATE="$(date -u '+%Y-%m-%d %H:%M UTC')" BENCH_COMMIT="$commit" \
BENCH_MACHINE="$cpu, $(nproc) cores, $memory, $os" BENCH_COMPILER="$compiler_version" \
BENCH_BUILD="CMake Release ($flags), $build/" BENCH_FRAMES="$frames" BENCH_ARONOV_MAX="$aronov_max" \
BENCH_SG2001_MAX="$sg2001_max" BENCH_MEMORY_LIMIT_MIB="$memory_limit_mib" BENCH_RUNTIME_S="$runtime" \
BENCH_REPEAT="$repeat" BENCH_REPEAT_MAX_N="$repeat_max_n" \
  /usr/bin/python3 -c '
import json, os, sys
e = os.environ
json.dump({"command": e["BENCH_COMMAND"], "date": e["BENCH_DATE"], "commit": e["BENCH_COMMIT"],
           "machine": e["BENCH_MACHINE"], "compiler": e["BENCH_COMPILER"], "build": e["BENCH_BUILD"],
           "frames": int(e["BENCH_FRAMES"]), "aronov_max": int(e["BENCH_ARONOV_MAX"]),
           "sg2001_max": int(e["BENCH_SG2001_MAX"]), "memory_limit_mib": int(e["BENCH_MEMORY_LIMIT_MIB"]),
           "runtime_s": int(e["BENCH_RUNTIME_S"]), "repeat": int(e["BENCH_REPEAT"]),
           "repeat_max_n": int(e["BENCH_REPEAT_MAX_N"])}, open(sys.argv[1], "w"), indent=1)
' "$data/run.json"

echo "==== report ===="
/usr/bin/python3 bench/make_benchmarks.py --data "$data" --output BENCHMARKS.md --plots docs/benchmarks
echo "benchmarks: done in $(( $(date +%s) - start )) s"
