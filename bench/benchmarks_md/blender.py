"""Blender at scale (issue 29): bench/blender_bake.py's blender.json, the bake split into the
engine and the Blender side, playback with and without the tubes, the render, file size and peak
memory at 10^3 to 10^5 vertices."""

import json
import os

from .common import InputError, table
from .common import optional_number as _num

# Issue 29's targets.
BAKE_OVER_CLI_BOUND = 1.5
PLAYBACK_FPS_BOUND = 24.0
TARGET_N = 10000


def read_blender(data_dir):
    """blender.json (bench/blender_bake.py --json), or None when the run did not measure Blender."""
    path = os.path.join(data_dir, "blender.json")
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            rows = json.load(f)
        for row in rows:
            row["shape"], row["n"], row["frames"]  # noqa: B018 - only the KeyError matters
            if "error" not in row:
                row["bake_s"], row["playback_fps_tubes"], row["playback_fps_plain"]  # noqa: B018
                row["blend_mib"], row["peak_mib"]  # noqa: B018
    except (OSError, ValueError, KeyError, TypeError) as error:
        raise InputError(f"{path}: {error!r}") from error
    return rows


def _render_cell(row):
    if row.get("render_visible") is None:
        return "not rendered"
    return f"{'visible' if row['render_visible'] else 'EMPTY'} ({100 * row['render_coverage']:.1f} % of pixels)"


def blender_headline(rows):
    """One line for the report's headline: issue 29's two Blender targets at 10^4 vertices."""
    done = [r for r in rows if "error" not in r and r["n"] == TARGET_N and r.get("bake_over_cli") is not None]
    if not done:
        return f"Blender at scale ([below](#blender-at-scale)): no {TARGET_N}-vertex case was measured."
    worst_ratio = max(r["bake_over_cli"] for r in done)
    worst_fps = min(r["playback_fps_tubes"] for r in done)
    largest = max((r for r in rows if "error" not in r), key=lambda r: r["n"])
    return (f"Blender at scale ([below](#blender-at-scale)): at {TARGET_N} vertices and {done[0]['frames']} frames "
            f"the bake takes at most {worst_ratio:.2f}× the CLI's morph of the same pair (issue 29 asks ≤ "
            f"{BAKE_OVER_CLI_BOUND}) and the result with its tubes plays at {worst_fps:.0f} fps or more (asks ≥ "
            f"{PLAYBACK_FPS_BOUND:.0f}); the largest bake, {largest['n']} vertices, took {largest['bake_s']:.0f} s "
            f"and {largest['peak_mib']:.0f} MiB.")


def blender_section(rows):
    """The Blender section: one row per (shape, n)."""
    if rows is None:
        return ["\n## Blender at scale\n", "Not measured in this run (out/benchmarks/blender.json is missing: "
                "bench/benchmarks.sh runs bench/blender_bake.py).\n"]
    version = next((r["blender"] for r in rows if "blender" in r), "?")
    commits = sorted({r.get("commit", "?") for r in rows})
    md = ["\n## Blender at scale\n",
          f"`bench/blender_bake.py` (issue 29) at commit {', '.join(commits)}, headless Blender {version} with the "
          "add-on package, one Blender process per case. Each pair is drawn in numpy (`wavy`: issue 29's wavy polyline bent into "
          "an arc; the others are `bench/speed_corpus.py`'s hand-drawn families: `coral` branches at every "
          "junction), morphed first by the CLI (`stickmorph morph SOURCE TARGET -o OUT --frames F`, the "
          "default rigid motion, its wall time including writing the JSON; up to 10⁴ vertices: at 10⁵ its JSON "
          "is over a gigabyte and the bake's engine column is the same work) and then baked by "
          "`object.stick_morph_bake` with the same defaults in a new Blender. The bake's time is split into "
          "the engine's call (the module's `morph`, the same work as the CLI's) and the Blender side (reading "
          "the meshes, the checks, shape keys and keyframes, the tubes). Playback is `scene.frame_set(f)` and "
          "the result's evaluated mesh at every frame in order, with the tubes (the viewport's quality: a "
          "6-sided tube, spheres only at ends and junctions) and with the tubes' modifier off. The render is "
          "the middle frame, final Workbench render at 480 × 270 (the tubes' render quality: 12 sides, a "
          "sphere at every vertex); 'visible' counts the pixels that differ from the background. Peak memory "
          "is the Blender process's `ru_maxrss` (Blender itself included: 'before' is before the bake) and "
          "the CLI's.\n"]
    body = []
    for r in rows:
        if "error" in r:
            body.append([r["shape"], r["n"], r["frames"], "error: " + r["error"].splitlines()[-1]] + [""] * 11)
            continue
        body.append([r["shape"], r["n"], r["frames"], _num(r.get("cli_s"), ".2f"), f"{r['bake_s']:.2f}",
                     _num(r.get("bake_over_cli"), ".2f"), _num(r.get("engine_s"), ".2f"), _num(r.get("blender_side_s"), ".2f"),
                     f"{r['playback_fps_tubes']:.1f}", f"{r['playback_fps_plain']:.0f}", _render_cell(r),
                     f"{r['blend_mib']:.1f}", f"{r['peak_before_mib']:.0f}", f"{r['peak_mib']:.0f}",
                     _num(r.get("cli_peak_mib"), ".0f")])
    md.append(table(["shape", "n", "frames", "CLI s", "bake s", "bake / CLI", "engine s", "Blender side s",
                     "playback fps (tubes)", "playback fps (no tubes)", "render", ".blend MiB",
                     "Blender MiB before", "Blender peak MiB", "CLI peak MiB"],
                    body, ["---", "--:", "--:", "--:", "--:", "--:", "--:", "--:", "--:", "--:", "---", "--:", "--:",
                           "--:", "--:"]) + "\n")
    playback = sorted({r.get("playback_frames", r["frames"]) for r in rows if "error" not in r})
    md.append(f"Playback frames per case: {', '.join(map(str, playback))}. Issue 29's targets at {TARGET_N} "
              f"vertices: bake ≤ {BAKE_OVER_CLI_BOUND}× the CLI, playback with the tubes ≥ "
              f"{PLAYBACK_FPS_BOUND:.0f} fps, a render with visible geometry.\n")
    return md
