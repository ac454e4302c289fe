"""Local timing (issue 31): bench/local_timing.py's local_timing.json, the measured lag of a
delayed limb against the overlap asked, with a scatter of every pair and filmstrips."""

import json
import os

from matplotlib.collections import LineCollection

from .common import COLORS, InputError, plt, table
from .common import optional_number as _optional_number

BODY_COLOR = "#2b3f63"
LIMB_COLOR = "#e4572e"
TOLERANCE = 0.1


def _num(value, spec=".3f"):
    """A table number; a lag that rounds to zero is 0.000, not -0.000."""
    text = _optional_number(value, spec)
    return text[1:] if text.startswith("-") and float(text) == 0 else text


def read_local_timing(data_dir):
    """local_timing.json (bench/local_timing.py --json), or None when the run did not measure
    local timing."""
    path = os.path.join(data_dir, "local_timing.json")
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
        doc["overlaps"], doc["frames"]  # noqa: B018 - only the KeyError matters
        for row in doc["summary"].values():
            row["measured"], row["pairs"], row["within"]  # noqa: B018
        for pair in doc["pairs"]:
            pair["name"], pair["kind"], pair["vertices"], pair["runs"]  # noqa: B018
    except (OSError, ValueError, KeyError, TypeError, AttributeError) as error:
        raise InputError(f"{path}: {error!r}") from error
    return doc


def _labels(doc):
    """The runs in the table's order: plain, d = 0, then the overlaps asked."""
    return [x for x in ["plain", "0"] + [f"{float(d):g}" for d in doc["overlaps"] if float(d) != 0.0]
            if x in doc["summary"]]


def _row(doc, label):
    s = doc["summary"][label]
    d = 0.0 if label == "plain" else float(label)
    invalid = s["bad_frames"]
    checked = s.get("frames_checked", 0)
    validity = (f"{invalid} ({s['pairs_with_bad_frames']} pairs)" if checked else "not checked")
    if s["failed"]:
        validity += f"; {s['failed']} runs refused"
    done = s["pairs"] - s["failed"]
    if label == "plain":
        same = "–"
    else:
        same = f"{s.get('same_as_plain', 0)}/{s.get('compared_with_plain', 0)}" if label == "0" else "–"
    return ["none (no `--timing`)" if label == "plain" else f"{d:g}", f"{s['measured']}/{s['pairs']}",
            _num(s["lag_median"]), _num(s["lag_p10"]), _num(s["lag_p90"]), _num(s["abs_error_median"]),
            _num(s["abs_error_max"]), f"{s['within']}/{s['measured']}", validity,
            f"{s['first_last_exact']}/{done}", same]


def _kind_rows(doc, labels):
    kinds = sorted({p["kind"] for p in doc["pairs"]})
    rows = []
    for kind in kinds:
        mine = [p for p in doc["pairs"] if p["kind"] == kind]
        row = [kind, str(len(mine)), f"{min(p['vertices'] for p in mine)}–{max(p['vertices'] for p in mine)}"]
        for label in labels:
            d = 0.0 if label == "plain" else float(label)
            lags = sorted(r["lag"] for p in mine for r in [p["runs"].get(label) or {}]
                          if "error" not in r and r.get("lag") is not None)
            within = sum(1 for x in lags if abs(x - d) <= TOLERANCE)
            median = (lags[len(lags) // 2] if len(lags) % 2 else (lags[len(lags) // 2 - 1] + lags[len(lags) // 2]) / 2
                      ) if lags else None
            row.append(f"{_num(median)} ({within}/{len(lags)})")
        rows.append(row)
    return rows


def _lag_svg(path, doc, labels):
    """Every pair's measured lag against the overlap asked: the line lag = d and its ±0.1 band."""
    figure = plt.figure(figsize=(5.2, 3.6), dpi=100)
    axes = figure.add_axes([0.13, 0.14, 0.6, 0.76])
    overlaps = [0.0] + [float(x) for x in labels if x not in ("plain", "0")]
    top = max(overlaps) + 0.15
    axes.fill_between([-0.05, top], [-0.05 - TOLERANCE, top - TOLERANCE], [-0.05 + TOLERANCE, top + TOLERANCE],
                      color="#ddd", linewidth=0, label=f"within {TOLERANCE} of d")
    axes.plot([-0.05, top], [-0.05, top], color="#777", linewidth=0.8, label="lag = d")
    kinds = sorted({p["kind"] for p in doc["pairs"]})
    for i, kind in enumerate(kinds):
        xs, ys = [], []
        for p in doc["pairs"]:
            if p["kind"] != kind:
                continue
            for j, label in enumerate(x for x in labels if x != "plain"):
                r = p["runs"].get(label) or {}
                if "error" in r or r.get("lag") is None:
                    continue
                # spread the kinds a little apart along d, so that the points do not hide each other
                xs.append(float(label) + (i - (len(kinds) - 1) / 2) * 0.012)
                ys.append(r["lag"])
        axes.scatter(xs, ys, s=10, color=COLORS[i % len(COLORS)], label=kind, linewidths=0)
    axes.set_xlim(-0.05, top)
    axes.set_xlabel("overlap d asked (timing file)")
    axes.set_ylabel("measured lag")
    axes.set_title("Measured lag of the delayed limb, every pair", fontsize=9)
    axes.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False, fontsize=7)
    figure.savefig(path, format="svg", metadata={"Date": None})
    plt.close(figure)


def _filmstrip_svg(path, pair, labels):
    """The pair's frames in rows, one row per run (d = 0 and the largest overlap), the limb's
    edges in their own colour; below, the share of its turn each made over time."""
    strip = pair["filmstrip"]
    edges, limb = strip["edges"], set(strip["limb_edges"])
    rows = [x for x in labels if x in strip["rows"] and x != "plain"]
    rows = [rows[0], rows[-1]] if len(rows) > 1 else rows
    if not rows and "plain" in strip["rows"]:
        rows = ["plain"]
    frames_all = [f for x in rows for f in strip["rows"][x]]
    width = max(max(p[0] for p in f) - min(p[0] for p in f) for f in frames_all)
    height = max(max(p[1] for p in f) - min(p[1] for p in f) for f in frames_all)
    count = len(strip["frame_indices"])
    step_x, step_y = 1.15 * width, 1.3 * height
    # inches: the strip as wide as the page allows at its own aspect, then the progress plot
    strip_w = 7.2
    strip_h = min(5.0, max(0.8, strip_w * (len(rows) * step_y) / (count * step_x)))
    plot_h, gap, top = 1.7, 0.75, 0.35
    fig_h = top + strip_h + gap + plot_h + 0.45
    figure = plt.figure(figsize=(8.0, fig_h), dpi=100)
    strip_axes = figure.add_axes([0.7 / 8.0, (fig_h - top - strip_h) / fig_h, strip_w / 8.0, strip_h / fig_h])
    strip_axes.set_aspect("equal")
    strip_axes.axis("off")
    strip_axes.set_xlim(-0.6 * step_x, (count - 0.4) * step_x)
    strip_axes.set_ylim(-(len(rows) - 0.4) * step_y, 0.6 * step_y)
    for r, label in enumerate(rows):
        y0 = -r * step_y
        for i, points in enumerate(strip["rows"][label]):
            cx = (max(p[0] for p in points) + min(p[0] for p in points)) / 2
            cy = (max(p[1] for p in points) + min(p[1] for p in points)) / 2
            dx = i * step_x - cx
            for in_limb, color, width in ((False, BODY_COLOR, 0.9), (True, LIMB_COLOR, 1.4)):
                segments = [[(points[a][0] + dx, points[a][1] - cy + y0), (points[b][0] + dx, points[b][1] - cy + y0)]
                            for k, (a, b) in enumerate(edges) if (k in limb) == in_limb]
                strip_axes.add_collection(LineCollection(segments, colors=color, linewidths=width, capstyle="round"))
            if r == len(rows) - 1:
                t = strip["frame_indices"][i] / max(1, strip["frames"] - 1)
                strip_axes.text(i * step_x, y0 - 0.62 * height, f"t = {t:.2f}", ha="center", va="top", fontsize=7,
                                color="#555")
        name = "no timing" if label == "plain" else f"d = {label}"
        measured = (pair["runs"].get(label) or {}).get("lag")
        if measured is not None:
            name += f"\nlag {_num(measured, '.2f')}"
        strip_axes.text(-0.62 * step_x, y0, name, ha="right", va="center", fontsize=8)
    strip_axes.set_title(f"{pair['name']} ({pair['vertices']} vertices): the limb ({pair.get('limb')}, orange) "
                         f"turns {pair.get('turn_deg', 0):+.0f}° about its junction while the body bends", fontsize=9)
    plot = figure.add_axes([0.8 / 8.0, 0.45 / fig_h, 4.4 / 8.0, plot_h / fig_h])
    times = [k / max(1, strip["frames"] - 1) for k in range(strip["frames"])]
    for label, dash in zip(rows, ["-", "--"]):
        progress = strip.get("progress", {}).get(label) or {}
        for part, color in (("limb", LIMB_COLOR), ("other", BODY_COLOR)):
            if progress.get(part):
                name = "no timing" if label == "plain" else f"d = {label}"
                plot.plot(times, progress[part], linestyle=dash, color=color, linewidth=1.1,
                          label=f"{'limb' if part == 'limb' else 'rest'}, {name}")
    plot.axhline(0.5, color="#bbb", linewidth=0.6)
    plot.set_xlim(0, 1)
    plot.set_xlabel("t", fontsize=8)
    plot.set_ylabel("share of turn", fontsize=8)
    plot.tick_params(labelsize=7)
    plot.legend(loc="upper left", bbox_to_anchor=(1.02, 1.05), frameon=False, fontsize=7)
    figure.savefig(path, format="svg", metadata={"Date": None})
    plt.close(figure)


def local_timing_section(doc, out_path, plot_dir):
    """The local-timing section: the lag measured against the overlap asked, validity and
    exactness per overlap, per kind, the misses, a scatter and filmstrips."""
    if doc is None:
        return ["\n## Local timing\n", "Not measured in this run (out/benchmarks/local_timing.json is missing: "
                "bench/benchmarks.sh runs bench/local_timing_corpus.py and bench/local_timing.py).\n"]
    plot_rel = os.path.relpath(plot_dir, os.path.dirname(os.path.abspath(out_path)) or ".")
    labels = _labels(doc)
    pairs = doc["pairs"]
    kinds = sorted({p["kind"] for p in pairs})
    overlaps = [f"{float(d):g}" for d in doc["overlaps"] if float(d) != 0.0]
    md = ["\n## Local timing\n",
          f"Issue 31: `stickmorph morph SRC TGT --timing FILE.json` with `{{\"delay\": [w per vertex], \"overlap\": "
          f"d}}` moves each part at local time clamp((t − d w)/(1 − d), 0, 1). Measured by `bench/local_timing.py` on "
          f"{len(pairs)} skeleton pairs of `bench/local_timing_corpus.py` (seed {doc.get('seed')}: "
          f"{', '.join(kinds)}; {min(p['vertices'] for p in pairs) if pairs else 0}–"
          f"{max(p['vertices'] for p in pairs) if pairs else 0} vertices) where the body bends by up to 5–40° "
          "per joint while one limb turns 45–150° about its junction, weight 1 on the limb's vertices and 0 "
          f"elsewhere, {doc['frames']} frames, the rigid method.\n",
          f"The *lag* of a run is the median over the limb's edges of the time at which an edge has made half of its "
          f"turn (its angle unwrapped over the frames, interpolated between frames) minus the same median over the "
          f"other edges; edges that turn less than {doc.get('min_turn_deg', 5):g}° are left out. Issue 31 asks "
          f"lag − d within {TOLERANCE} for d = " + " and ".join(overlaps or ["–"]) + ", every frame valid, the first "
          "and last frames exact and d = 0 the plain morph bit for bit. *Invalid frames*: frames the independent "
          "exact check of `bench/multipart_check.py` refuses (the CLI verifies every frame itself and refuses a "
          "run with one that fails: *runs refused*).\n"]
    build = doc.get("build") or {}
    if doc.get("command"):
        md.append(f"Measured with `{doc['command']}`"
                  + (f", the CLI built from {build['commit']}"
                     + (" with uncommitted changes to the engine (native/)" if build.get("uncommitted_native") else "")
                     if build.get("commit") else "") + ".\n")
    if not doc.get("timing_in_help", True):
        md.append("The CLI measured lists no `--timing` in `stickmorph morph --help`: the timed runs below are its "
                  "refusals.\n")
    md.append(table(["overlap d asked", "pairs measured", "lag median", "lag P10", "lag P90", "\\|lag − d\\| median",
                     "\\|lag − d\\| max", f"within {TOLERANCE}", "invalid frames", "first and last frame exact",
                     "d = 0 bit for bit plain"],
                    [_row(doc, label) for label in labels], ["---"] + ["--:"] * 10))
    clear_notes = []
    for label in overlaps:
        s = doc["summary"].get(label)
        if s and s.get("clear_pairs", s["measured"]) != s["measured"]:
            clear_notes.append(f"d = {label}: within {TOLERANCE} on {s['clear_within']}/{s['clear_pairs']} of the "
                               "pairs whose delayed path the corpus found clear")
    if clear_notes:
        md.append("\nThe corpus makes the delayed motion of each figure itself (every edge at its local time) and checks "
                  "it exactly; one pair in five is drawn without asking it to be valid; " + "; ".join(clear_notes) + ".")
    md.append("\nPer kind of figure, the lag's median and the pairs within " + f"{TOLERANCE}:\n")
    md.append(table(["kind", "pairs", "vertices"] + [("lag, no timing" if x == "plain" else f"lag, d = {x}")
                                                     for x in labels], _kind_rows(doc, labels),
                    ["---", "--:", "--:"] + ["--:"] * len(labels)))
    references = [(label, doc["summary"][label]) for label in overlaps
                  if doc["summary"].get(label, {}).get("reference_measured")]
    if references:
        md.append("\n*Reference*: the delayed motion as issue 31 states it, built by `bench/local_timing.py` from the "
                  "plain run's frames (every edge's direction and length those of the plain morph at the edge's local "
                  "time, the vertices fitted to those edge vectors), measured and checked the same way: " + "; ".join(
                      f"d = {label}: lag median {_num(s['reference_lag_median'])}, within {TOLERANCE} on "
                      f"{s['reference_within']}/{s['reference_measured']}, "
                      + (f"invalid frames {s['reference_bad_frames']} (in {s['reference_pairs_with_bad_frames']} of the "
                         "pairs)" if s.get("reference_checked", 1) else "its frames not checked")
                      for label, s in references)
                  + ". Where the engine's lag falls short of d and the reference is valid in every frame, the morph "
                  "gave way where the figure itself did not need it.")
    misses = [(label, m) for label in overlaps for m in doc["summary"].get(label, {}).get("misses", [])]
    if misses:
        def reference(m):
            guide = m.get("guide_frames") or {}
            text = (f"; {guide['blended']} of its {sum(guide.values())} interior frames blended, off the rigid guide"
                    if guide.get("blended") is not None else "")
            if m.get("reference_valid") is None:
                return text
            return text + ("; the reference valid" if m["reference_valid"] else "; the reference has invalid frames")
        md.append("\nPairs where the lag misses d by more than " + f"{TOLERANCE}: " + "; ".join(
            f"{m['name']} (limb {m.get('limb')}, d = {label}: lag {m['lag']:.3f}{reference(m)})"
            for label, m in misses) + ".")
    failures = [f for label in labels for f in doc["summary"][label].get("failures", [])]
    if failures:
        md.append("\nRuns refused: " + "; ".join(f[:160] for f in failures[:10]) + ".")
    os.makedirs(plot_dir, exist_ok=True)
    if any(p["runs"].get(x, {}).get("lag") is not None for p in pairs for x in overlaps):
        _lag_svg(os.path.join(plot_dir, "local_timing_lag.svg"), doc, labels)
        md.append(f"\n![Measured lag against the overlap asked]({plot_rel}/local_timing_lag.svg)\n")
    by_name = {p["name"]: p for p in pairs if p.get("filmstrip")}
    strips = [by_name[n] for n in doc.get("filmstrips", []) if n in by_name] or list(by_name.values())
    for i, pair in enumerate(strips[:3], 1):
        name = f"local_timing_filmstrip_{i}.svg"
        _filmstrip_svg(os.path.join(plot_dir, name), pair, labels)
        what = ("the pair whose lag misses the largest d by most" if pair["filmstrip"].get("why") == "worst miss"
                else "filmstrip without and with the limb delayed")
        md.append(f"\n![{pair['name']}: {what}]({plot_rel}/{name})\n")
    if strips:
        md.append("Each filmstrip: evenly spaced frames (each centred), the limb in orange, one row per timing; "
                  "below, the median share of its turn the limb's edges (orange) and the other edges (blue) have "
                  "made at each time: the lag is the distance between the curves where they cross one half.\n")
    return md
