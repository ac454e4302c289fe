#!/usr/bin/env bash
# The demo's bake and render, small: builds the package for the Blender on
# PATH, bakes monkey -> basketball player with scripts/render_demo.py (12
# frames at 320x180) and the waving stick man through its four key poses
# (issue 28: object.stick_morph_bake_sequence, 97 frames at 320x180) and the
# stick man whose hand lags (issue 31: the sample scene's Delay Group), and
# the Grease Pencil stick figure (issue 32: cleaned, baked into Grease Pencil,
# one drawing per frame), and checks that the PNG frames and the MP4s were
# written.
# scripts/blender_matrix.sh runs it in every tested Blender, so the README
# demo's render is known to work in 3.4, 4.3 and 5.2 alike.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${STICKMORPH_BUILD_DIR:-build-addon}"
out=$(mktemp -d "${TMPDIR:-/tmp}/stickmorph-render-smoke.XXXXXX")
trap 'rm -rf "$out"' EXIT

/usr/bin/python3 build_addon.py --build-dir "$BUILD_DIR" > "$out/build.log"
package=$(sed -n 's/^wrote \(dist\/stick_morph-[^ ]*\.zip\).*$/\1/p' "$out/build.log" | tail -n 1)
if [[ -z "$package" || ! -f "$package" ]]; then
  cat "$out/build.log" >&2
  echo "render_smoke.sh: build_addon.py wrote no package" >&2
  exit 1
fi
frames=12
if ! blender -b --factory-startup --python-exit-code 1 --python scripts/render_demo.py -- \
    --sample blend_samples/monkey_to_player.blend --zip "$package" --out "$out/render" \
    --frames "$frames" --resolution 320 180 > "$out/render.log" 2>&1; then
  tail -n 40 "$out/render.log" >&2
  echo "render_smoke.sh: the demo's bake and render failed" >&2
  exit 1
fi
pngs=$(find "$out/render/frames" -name 'frame_*.png' | wc -l)
mp4="$out/render/morph.mp4"
[[ "$pngs" -eq "$frames" ]] || { echo "render_smoke.sh: $pngs PNG frames, expected $frames" >&2; exit 1; }
[[ -s "$mp4" ]] || { echo "render_smoke.sh: no morph.mp4 was written" >&2; exit 1; }
# An MP4 file starts with an ftyp box: bytes 4..7 spell "ftyp".
[[ "$(head -c 8 "$mp4" | tail -c 4)" == "ftyp" ]] || { echo "render_smoke.sh: morph.mp4 is not an MP4 file" >&2; exit 1; }
echo "render smoke: $package baked and rendered $pngs frames and a $(stat -c %s "$mp4")-byte MP4 in $(blender --version 2>/dev/null | head -n 1)"

# The key-pose sample: the collection's four keys at their own key frames
# 1, 25, 49 and 73, so the sequence is frames 1..73.
if ! blender -b --factory-startup --python-exit-code 1 --python scripts/render_demo.py -- \
    --sample blend_samples/key_poses/stick_man_wave.blend --key-poses wave_keys --zip "$package" \
    --out "$out/key_poses" --resolution 320 180 > "$out/key_poses.log" 2>&1; then
  tail -n 40 "$out/key_poses.log" >&2
  echo "render_smoke.sh: the key-pose bake and render failed" >&2
  exit 1
fi
key_pngs=$(find "$out/key_poses/frames" -name 'frame_*.png' | wc -l)
[[ "$key_pngs" -eq 73 ]] || { echo "render_smoke.sh: $key_pngs PNG frames of the key poses, expected 73" >&2; exit 1; }
[[ "$(head -c 8 "$out/key_poses/morph.mp4" | tail -c 4)" == "ftyp" ]] || { echo "render_smoke.sh: the key poses' morph.mp4 is not an MP4 file" >&2; exit 1; }
echo "render smoke: key poses of wave_keys baked and rendered $key_pngs frames and an MP4"

# The local-timing sample (issue 31): the scene's settings name the pair,
# its Delay Group and Overlap; the log says the group lagged.
if ! blender -b --factory-startup --python-exit-code 1 --python scripts/render_demo.py -- \
    --sample blend_samples/local_timing/stick_man_lag.blend --zip "$package" --out "$out/local_timing" \
    --frames "$frames" --resolution 320 180 > "$out/local_timing.log" 2>&1; then
  tail -n 40 "$out/local_timing.log" >&2
  echo "render_smoke.sh: the local-timing bake and render failed" >&2
  exit 1
fi
grep -q "'lag' lagging by 0.3" "$out/local_timing.log" || { echo "render_smoke.sh: the local-timing bake did not use its Delay Group" >&2; exit 1; }
lag_pngs=$(find "$out/local_timing/frames" -name 'frame_*.png' | wc -l)
[[ "$lag_pngs" -eq "$frames" ]] || { echo "render_smoke.sh: $lag_pngs PNG frames of the local-timing sample, expected $frames" >&2; exit 1; }
echo "render smoke: the local-timing sample baked with its Delay Group and rendered $lag_pngs frames"

# The Grease Pencil sample (issue 32): two hand-drawn poses whose strokes
# cross and stop short, cleaned and baked into a Grease Pencil object with
# one drawing per frame, rendered with its own materials.
if ! blender -b --factory-startup --python-exit-code 1 --python scripts/render_demo.py -- \
    --sample blend_samples/drawings/stick_figure_gp.blend --zip "$package" --out "$out/drawing" \
    --frames "$frames" --resolution 320 180 > "$out/drawing.log" 2>&1; then
  tail -n 40 "$out/drawing.log" >&2
  echo "render_smoke.sh: the Grease Pencil bake and render failed" >&2
  exit 1
fi
grep -q "Grease Pencil, $frames drawings" "$out/drawing.log" || { echo "render_smoke.sh: the Grease Pencil sample did not bake into $frames drawings" >&2; exit 1; }
gp_pngs=$(find "$out/drawing/frames" -name 'frame_*.png' | wc -l)
[[ "$gp_pngs" -eq "$frames" ]] || { echo "render_smoke.sh: $gp_pngs PNG frames of the Grease Pencil sample, expected $frames" >&2; exit 1; }
[[ "$(head -c 8 "$out/drawing/morph.mp4" | tail -c 4)" == "ftyp" ]] || { echo "render_smoke.sh: the Grease Pencil sample's morph.mp4 is not an MP4 file" >&2; exit 1; }
echo "render smoke: the Grease Pencil sample baked into $frames drawings and rendered $gp_pngs frames and an MP4"
