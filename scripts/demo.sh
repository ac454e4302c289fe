#!/usr/bin/env bash
# Sets up, builds and runs the stickmorph demo on bundled sample figures.
#
# The demo decides compatibility (paper, section 2.1) of two poses of a
# stick-figure letter A and of the letter A and its mirror image, then morphs
# the paper's S into U (Figure 8c) and writes, to out/: the morph (FORMAT.md
# JSON), its filmstrip, the straight-line morph's filmstrip (Figure 8d, which
# self-intersects) and the compatible triangulation drawn side by side.
# Then it builds the Blender add-on zip (dist/stick_morph-<version>-blender3.4-cp311-linux-x64.zip),
# bakes the monkey -> basketball player sample (Figure 8a) with it in headless
# Blender (scripts/render_demo.py: a temporary user config, never the real
# one) and renders PNG frames and an MP4 into out/monkey_to_player/, next to a
# filmstrip of our morph against the straight-line morph (Figure 8d). Last,
# it bakes the waving stick man of blend_samples/key_poses through its four
# key poses (object.stick_morph_bake_sequence, issue 28) and renders it into
# out/stick_man_wave/.
#
#   scripts/demo.sh                   Blender 3.4.1 of the host (Debian 12)
#   scripts/demo.sh --blender trixie  Blender 4.3.2 in the Debian 13 chroot
#   scripts/demo.sh --blender sid     Blender 5.2.2 in the Debian sid chroot
# (the chroots: scripts/blender_chroot.sh, made when missing; docs/BLENDER.md)
set -euo pipefail

blender_system=host
while [[ $# -gt 0 ]]; do
  case "$1" in
    --blender) blender_system=${2:-}; shift 2 || { echo "demo.sh: --blender needs host, trixie or sid" >&2; exit 2; } ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "demo.sh: unknown argument: $1 (usage: scripts/demo.sh [--blender host|trixie|sid])" >&2; exit 2 ;;
  esac
done
case "$blender_system" in
  host) in_blender_system=() ; addon_build_dir=build ;;
  trixie|sid)
    in_blender_system=(bash scripts/blender_chroot.sh run "$blender_system" --)
    # The chroot's own compiler and Python build the module, in its /var/tmp.
    addon_build_dir=/var/tmp/stickmorph-build ;;
  *) echo "demo.sh: --blender must be host, trixie or sid, not '$blender_system'" >&2; exit 2 ;;
esac

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
run build/stickmorph morph $paper/s_to_u.source.json $paper/s_to_u.target.json -o out/s_to_u.json --frames 49 --svg out/s_to_u.svg --svg-compare-linear
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

section "Blender add-on: build the package ($blender_system)"
if [[ $blender_system != host ]]; then bash scripts/blender_chroot.sh ensure "$blender_system"; fi
"${in_blender_system[@]}" /usr/bin/python3 build_addon.py --build-dir "$addon_build_dir" | tee out/build_addon.log
# build_addon.py names the package it wrote on its last line ("wrote dist/...").
zip=$(sed -n 's/^wrote \(dist\/stick_morph-[^ ]*\.zip\).*$/\1/p' out/build_addon.log | tail -n 1)
[[ -n "$zip" && -f "$zip" ]] || { echo "demo: build_addon.py wrote no package" >&2; exit 1; }
echo "add-on package: $zip"

section "Blender ($blender_system): bake and render monkey -> basketball player (Figure 8a)"
sample=monkey_to_player
mkdir -p out/$sample
started=$SECONDS
echo "\$ blender -b --factory-startup --python-exit-code 1 --python scripts/render_demo.py -- --sample blend_samples/$sample.blend --zip $zip --out out/$sample --frames 60 --resolution 960 540"
# Blender prints a line or two per rendered frame; those are left out here.
"${in_blender_system[@]}" blender -b --factory-startup --python-exit-code 1 --python scripts/render_demo.py -- \
  --sample blend_samples/$sample.blend --zip "$zip" --out out/$sample --frames 60 --resolution 960 540 \
  | grep --line-buffered -v -E '^[[:space:]]*(Fra:|Saved: |Append frame|Time: |$)'
echo "bake and render: $((SECONDS - started)) s"

section "Filmstrip: our morph against the straight-line morph (Figure 8d)"
figures=blend_samples/figures
run build/stickmorph morph $figures/$sample.source.json $figures/$sample.target.json \
  -o out/$sample/morph.json --svg out/$sample/filmstrip.svg --svg-compare-linear
run build/stickmorph morph $figures/$sample.source.json $figures/$sample.target.json \
  -o out/$sample/linear.json --method linear
OUT=out/$sample /usr/bin/python3 - <<'PY'
import glob, json, os
out = os.environ["OUT"]
stats = json.load(open(f"{out}/morph.json"))["stats"]
print(f"our morph: {stats['steiner_vertices']} Steiner vertices, every frame verified valid")
invalid = json.load(open(f"{out}/linear.json"))["stats"]["invalid_frames"]
print(f"straight-line morph: frames {invalid} self-intersect" if invalid else
      "straight-line morph: no frame self-intersects for this pair (S to U above has frames that do)")
mp4 = f"{out}/morph.mp4"
frames = sorted(glob.glob(f"{out}/frames/frame_*.png"))
print("\nOutputs:")
print(f"  {mp4}: {os.path.getsize(mp4) / 1024:.0f} KiB")
print(f"  {out}/frames/: {len(frames)} PNG frames")
print(f"  {out}/baked.blend: {os.path.getsize(out + '/baked.blend') / 1024:.0f} KiB (renders without the add-on)")
print(f"  {out}/filmstrip.svg: {os.path.getsize(out + '/filmstrip.svg') / 1024:.0f} KiB "
      "(top: our morph, bottom: the straight-line morph)")
PY

section "Blender ($blender_system): key poses, a stick man waving through four poses (issue 28)"
keys_out=out/stick_man_wave
mkdir -p $keys_out
started=$SECONDS
echo "\$ blender -b --factory-startup --python-exit-code 1 --python scripts/render_demo.py -- --sample blend_samples/key_poses/stick_man_wave.blend --key-poses wave_keys --zip $zip --out $keys_out --resolution 960 540"
"${in_blender_system[@]}" blender -b --factory-startup --python-exit-code 1 --python scripts/render_demo.py -- \
  --sample blend_samples/key_poses/stick_man_wave.blend --key-poses wave_keys --zip "$zip" --out $keys_out \
  --resolution 960 540 | grep --line-buffered -v -E '^[[:space:]]*(Fra:|Saved: |Append frame|Time: |$)'
echo "bake and render: $((SECONDS - started)) s"

section "Demo finished"
