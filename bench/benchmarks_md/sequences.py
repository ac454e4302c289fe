"""Key poses (issue 28): bench/sequence_motion.py's sequences.json, the sequence morph against
chained pair morphs and straight-line (shape-key) blending, with a filmstrip and the speed
profiles through the keys."""

import json
import os

from .common import COLORS, InputError, plt, table
from .common import median as _median, optional_number as _num

MODE_LABELS = {
    "sequence": "sequence morph (`morph KEY1 ... KEYK`)",
    "chained": "chained pair morphs (one `morph` per segment)",
    "linear": "straight lines key to key (Blender's shape-key blending)",
    "matched": "sequence morph, keys drawn separately (`--correspond auto`)",
}
MODE_ORDER = ["sequence", "matched", "chained", "linear"]
MODE_COLORS = {"sequence": COLORS[0], "matched": COLORS[2], "chained": COLORS[1], "linear": COLORS[8]}
JUMP_BOUND = 0.25
PASS_BOUND = 0.3
EDGE_DEV_BOUND = 0.02


def read_sequences(data_dir):
    """sequences.json (bench/sequence_motion.py --json), or None when the run did not measure
    key poses."""
    path = os.path.join(data_dir, "sequences.json")
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            rows = json.load(f)
        for row in rows:
            row["name"], row["kind"], row["mode"], row["keys"]  # noqa: B018 - only the KeyError matters
            if "error" not in row:
                row["invalid_frames"], row["key_error"], row["edge_dev_median"], row["speeds"]  # noqa: B018
    except (OSError, ValueError, KeyError, TypeError) as error:
        raise InputError(f"{path}: {error!r}") from error
    return rows


def _summary_rows(rows, modes, kinds):
    out = []
    for mode in modes:
        for kind in ["all"] + kinds:
            mine = [r for r in rows if r["mode"] == mode and (kind == "all" or r["kind"] == kind)]
            done = [r for r in mine if "error" not in r]
            if not mine:
                continue
            jumps = [r["jump_median"] for r in done]
            passes = [r["pass_speed_min"] for r in done]
            invalid = sum(len(r["invalid_frames"]) for r in done)
            frames = sum(r["frames"] for r in done)
            out.append([MODE_LABELS[mode] if kind == "all" else "", kind, f"{len(done)}/{len(mine)}",
                        f"{invalid} of {frames}", f"{max(r['key_error'] for r in done):.0e}" if done else "–",
                        _num(_median(jumps)), _num(max((j for j in jumps if j is not None), default=None)),
                        _num(_median(passes)), _num(_median(r["edge_dev_median"] for r in done), ".4f")])
    return out


def _filmstrip_svg(path, strip):
    """About a dozen frames of one sequence side by side (each centred on its own centroid, left to
    right in time), the keys drawn darker."""
    frames, edges, keys_at = strip["frames"], strip["edges"], set(strip["keys_at"])
    count = len(frames)
    shown = sorted({round(i * (count - 1) / 12) for i in range(13)} | keys_at)
    centred = []
    for f in shown:
        cx = sum(p[0] for p in frames[f]) / len(frames[f])
        cy = sum(p[1] for p in frames[f]) / len(frames[f])
        centred.append([(p[0] - cx, p[1] - cy) for p in frames[f]])
    width = max(max(p[0] for p in c) - min(p[0] for p in c) for c in centred)
    figure = plt.figure(figsize=(8.0, 1.6), dpi=100)
    axes = figure.add_axes([0.005, 0.02, 0.99, 0.8])
    axes.set_aspect("equal")
    axes.axis("off")
    for i, (f, points) in enumerate(zip(shown, centred)):
        key = f in keys_at
        dx = i * 1.1 * width
        for a, b in edges:
            axes.plot([points[a][0] + dx, points[b][0] + dx], [points[a][1], points[b][1]],
                      color="#111" if key else "#4a7fb5", linewidth=1.2 if key else 0.8)
        axes.text(dx, min(p[1] for p in points) - 0.05 * width, f"{f}", ha="center", va="top", fontsize=7,
                  color="#111" if key else "#777")
    axes.set_title(f"{strip['name']}: frames left to right (each centred), keys in black", fontsize=9)
    figure.savefig(path, format="svg", metadata={"Date": None})
    plt.close(figure)


def _velocity_change_svg(path, rows, name):
    """The change of velocity |X[f+1] - 2 X[f] + X[f-1]| / mean step at every frame of one
    sequence, every mode, keys marked: the jump of the table, everywhere."""
    figure = plt.figure(figsize=(8.0, 3.2), dpi=100)
    axes = figure.add_axes([0.08, 0.15, 0.62, 0.75])
    keys_at = None
    for mode in MODE_ORDER:
        row = next((r for r in rows if r["name"] == name and r["mode"] == mode and "error" not in r), None)
        if row is None or mode == "matched" or "velocity_changes" not in row:
            continue
        keys_at = row.get("keys_at", keys_at)
        axes.plot(range(1, len(row["velocity_changes"]) + 1), row["velocity_changes"], color=MODE_COLORS[mode],
                  linewidth=1.2, label=MODE_LABELS[mode].split(" (")[0])
    for f in keys_at or []:
        axes.axvline(f, color="#bbb", linewidth=0.8, zorder=0)
    axes.axhline(JUMP_BOUND, color="#555", linewidth=0.8, linestyle=(0, (4, 3)), label=f"issue 28's bound {JUMP_BOUND}")
    axes.set_yscale("symlog", linthresh=0.01)
    axes.set_ylim(bottom=0)
    axes.set_xlabel("frame (grey lines: keys)")
    axes.set_ylabel("change of velocity / mean step")
    axes.set_title(f"{name}: change of velocity at every frame", fontsize=10)
    axes.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False, fontsize=8)
    figure.savefig(path, format="svg", metadata={"Date": None})
    plt.close(figure)


def sequences_headline(rows):
    """One line for the report's headline: the sequence morph's jump and validity against the
    baselines'."""
    def median_jump(mode):
        return _median(r["jump_median"] for r in rows if r["mode"] == mode and "error" not in r)

    done = [r for r in rows if r["mode"] == "sequence" and "error" not in r]
    invalid = sum(len(r["invalid_frames"]) for r in done)
    frames = sum(r["frames"] for r in done)
    return (f"Key poses ([below](#key-poses)): through {len(done)} sequences the velocity jump at the keys has "
            f"median {_num(median_jump('sequence'))} (issue 28 asks ≤ {JUMP_BOUND}; chained pair morphs "
            f"{_num(median_jump('chained'))}, straight lines {_num(median_jump('linear'))}), {invalid} invalid frames "
            f"of {frames}.")


def sequences_section(rows, out_path, plot_dir):
    """The key-pose section: smoothness at the keys, validity, rigidity per mode and kind."""
    if rows is None:
        return ["\n## Key poses\n", "Not measured in this run (out/benchmarks/sequences.json is missing: "
                "bench/benchmarks.sh runs bench/sequence_motion.py).\n"]
    plot_rel = os.path.relpath(plot_dir, os.path.dirname(os.path.abspath(out_path)) or ".")
    modes = [m for m in MODE_ORDER if any(r["mode"] == m for r in rows)]
    kinds = sorted({r["kind"] for r in rows})
    names = sorted({r["name"] for r in rows})
    md = ["\n## Key poses\n",
          f"Issue 28: {len(names)} key-pose sequences of 3 to 6 keys (`bench/key_pose_corpus.py --redrawn`: "
          "skeletons through one periodic motion (`cycle`) and through independent poses (`poses`), letters "
          "bent and moved (`glyph`)), 49 frames per segment with the keys evenly spaced, each made four ways "
          "and measured by `bench/sequence_motion.py` (every frame checked in exact arithmetic by "
          "`bench/multipart_check.py`, independently of the engine):\n"]
    md += [f"- {MODE_LABELS[m]}" for m in modes]
    md.append(f"""
*Jump* at an interior key k is |v+ − v−| / (the sequence's mean step), v− = X[F_k] − X[F_k − 1],
v+ = X[F_k + 1] − X[F_k]: the change of velocity there, issue 28's smoothness number (≤ {JUMP_BOUND} wanted;
a C1 motion gives about 0.1). *Pass speed* is min(|v−|, |v+|) / mean step at the keys the motion passes
through (≥ {PASS_BOUND}: no stop); *edge dev* the pair morph's rigidity measure per segment (median ≤
{EDGE_DEV_BOUND}). Medians are over sequences (each sequence's median over its interior keys).
""")
    md.append(table(["motion", "kind", "sequences", "invalid frames", "worst key error", "jump median",
                     "jump max", "pass speed median", "edge dev median"],
                    _summary_rows(rows, modes, kinds), ["---", "---"] + ["--:"] * 7))
    linear = [r for r in rows if r["mode"] == "linear" and "error" not in r]
    if linear and not any(r["invalid_frames"] for r in linear):
        md.append("\nOn these sequences straight lines from key to key stay valid too: their poses are gentle "
                  "enough. Where straight lines cross or fold a figure is measured on pairs (\"Straight-line morph "
                  "against ours\" above); the sequence morph is checked in exact arithmetic on every frame "
                  "either way.")
    failed = [r for r in rows if "error" in r]
    if failed:
        md.append("\nRefused: " + "; ".join(f"{r['name']} ({r['mode']}): {r['error'][:120]}" for r in failed))
    strip_row = next((r for r in rows if r.get("filmstrip")), None)
    if strip_row is not None:
        os.makedirs(plot_dir, exist_ok=True)
        strip = dict(strip_row["filmstrip"], name=strip_row["name"], keys_at=strip_row["keys_at"])
        _filmstrip_svg(os.path.join(plot_dir, "sequence_filmstrip.svg"), strip)
        _velocity_change_svg(os.path.join(plot_dir, "sequence_velocity_change.svg"), rows, strip_row["name"])
        md.append(f"""
![A sequence]({plot_rel}/sequence_filmstrip.svg)

![Change of velocity at every frame]({plot_rel}/sequence_velocity_change.svg)

The change of velocity at every frame of the same sequence: chained pair morphs and straight lines
are smooth within a segment and change velocity at once at every key (each pair's motion starts
and ends on its own), the sequence morph passes through the keys as through any other frame.
""")
    return md
