"""Drawing cleaning (issue 32): bench/cleaning.py's cleaning.json, `stickmorph clean` on the
hand-drawn-like drawings of bench/drawing_corpus.py (planted defects found, validity, every
change reported, idempotence, pairs morphed), with one drawing before and after."""

import json
import math
import os

from matplotlib.collections import LineCollection

from .common import COLORS, InputError, plt, table

AFTER_COLOR = "#2b3f63"
BEFORE_COLOR = "#9aa5b8"
# change kind: (marker, colour, label)
MARKS = {"crossing": ("o", "#e4572e", "crossing"), "touch": ("s", "#2ca02c", "touch"),
         "snap": ("^", "#9467bd", "end snapped"), "merge": ("D", "#ff7f0e", "strokes' points merged")}


def read_cleaning(data_dir):
    """cleaning.json (bench/cleaning.py --json), or None when the run did not measure cleaning."""
    path = os.path.join(data_dir, "cleaning.json")
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
        summary = doc["summary"]
        for block in list(summary["by_kind"].values()) + [summary["all"]]:
            block["drawings"], block["planted"]["gaps"], block["found"]["gaps"], block["changes"]["merge"]  # noqa: B018
        summary["pairs"]["pairs"], summary["failures"]  # noqa: B018
        for row in doc["drawings"]:
            row["name"], row["kind"], row["points"]  # noqa: B018
    except (OSError, ValueError, KeyError, TypeError, AttributeError) as error:
        raise InputError(f"{path}: {error!r}") from error
    return doc


def _ratio(a, b):
    return f"{a}/{b}"


def _row(label, s):
    p, f, c = s["planted"], s["found"], s["changes"]
    return [label, str(s["drawings"]), str(s["points"]), str(s["strokes"]),
            f"{f['gaps']}/{p['gaps']}", f"{f['touches']}/{p['touches']}",
            f"{f['crossings']}/{p['crossings']}", f"{f['duplicates']}/{p['duplicates']}",
            f"{c['merge']} / {c['snap']} / {c['crossing']} / {c['touch']}",
            _ratio(s["valid"], s["drawings"]), _ratio(s["accounted"], s["drawings"]),
            _ratio(s["idempotent"], s["drawings"]), f"{s['seconds']:.2f}"]


def _bounds(points, pad=0.04):
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    w, h = max(xs) - min(xs), max(ys) - min(ys)
    m = pad * max(w, h)
    return min(xs) - m, max(xs) + m, min(ys) - m, max(ys) + m


def _draw_strokes(axes, strokes, color, width, by_stroke=False):
    for k, s in enumerate(strokes):
        pts = [tuple(p) for p in s["points"]] + ([tuple(s["points"][0])] if s.get("cyclic") else [])
        axes.add_collection(LineCollection(list(zip(pts, pts[1:])), colors=COLORS[k % len(COLORS)] if by_stroke
                                           else color, linewidths=width, capstyle="round"))


def _draw_figure(axes, vertices, edges, color, width):
    axes.add_collection(LineCollection([[tuple(vertices[u]), tuple(vertices[v])] for u, v in edges], colors=color,
                                       linewidths=width, capstyle="round"))


def _joins_strokes(c):
    """A change that joins two strokes (a merge of one stroke's own duplicates does not)."""
    return c["kind"] != "merge" or c.get("other_stroke") not in (None, c["stroke"])


def _marks(axes, changes, kinds, size):
    for kind in kinds:
        # one mark per place (two legs drawn from the body's end: two merges, one junction)
        at = sorted({tuple(c["at"]) for c in changes if c["kind"] == kind and _joins_strokes(c)})
        if not at:
            continue
        marker, color, label = MARKS[kind]
        axes.scatter([p[0] for p in at], [p[1] for p in at], s=size, marker=marker, facecolors="none",
                     edgecolors=color, linewidths=0.9, label=f"{label} ({len(at)})", zorder=3)


def _snap_zoom(show):
    """The snap to zoom on: the one that moved an end furthest (the most visible gap), its
    original point and where it went."""
    snaps = [c for c in show["changes"] if c["kind"] == "snap" and c.get("point") is not None]
    if not snaps:
        return None
    c = max(snaps, key=lambda c: c["distance"])
    drawn = show["strokes"][c["stroke"]]["points"][c["point"]]
    return c, drawn


def _before_after_svg(path, show):
    """Three panels: the drawing as drawn (a colour per stroke), the cleaned figure with its
    junctions marked by the change that made them, and a zoom on one snapped end."""
    zoom = _snap_zoom(show)
    panels = 3 if zoom else 2
    figure = plt.figure(figsize=(3.2 * panels + 0.4, 4.2), dpi=100)
    width = 3.0 / (3.2 * panels + 0.4)
    every = [p for s in show["strokes"] for p in s["points"]]
    x0, x1, y0, y1 = _bounds(every)
    before = figure.add_axes([0.02, 0.14, width, 0.68])
    _draw_strokes(before, show["strokes"], None, 1.0, by_stroke=True)
    before.set_title(f"as drawn: {len(show['strokes'])} strokes, {len(every)} points", fontsize=8)
    after = figure.add_axes([0.04 + width, 0.14, width, 0.68])
    _draw_figure(after, show["vertices"], show["edges"], AFTER_COLOR, 0.9)
    _marks(after, show["changes"], ("crossing", "touch", "snap", "merge"), 22)
    merges = sum(1 for c in show["changes"] if not _joins_strokes(c))
    after.set_title(f"cleaned: {len(show['vertices'])} vertices, {len(show['edges'])} edges\n"
                    f"({merges} duplicate points merged)", fontsize=8)
    for axes in (before, after):
        axes.set_xlim(x0, x1)
        axes.set_ylim(y0, y1)
        axes.set_aspect("equal")
        axes.axis("off")
    handles, labels = after.get_legend_handles_labels()
    if zoom:
        c, drawn = zoom
        ax = figure.add_axes([0.06 + 2 * width, 0.14, width, 0.68])
        half = 4 * show["tolerance"]
        cx, cy = c["at"]
        _draw_strokes(ax, show["strokes"], BEFORE_COLOR, 2.4)
        _draw_figure(ax, show["vertices"], show["edges"], AFTER_COLOR, 0.9)
        ax.annotate("", xy=tuple(c["at"]), xytext=tuple(drawn),
                    arrowprops={"arrowstyle": "->", "color": MARKS["snap"][1], "linewidth": 0.9})
        ax.scatter([drawn[0]], [drawn[1]], s=14, color=BEFORE_COLOR, zorder=3)
        ax.scatter([cx], [cy], s=22, marker=MARKS["snap"][0], facecolors="none", edgecolors=MARKS["snap"][1],
                   linewidths=0.9, zorder=3)
        ax.add_patch(plt.Circle((cx, cy), show["tolerance"], fill=False, linestyle=":", color="#777", linewidth=0.7))
        ax.set_xlim(cx - half, cx + half)
        ax.set_ylim(cy - half, cy + half)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        for spine in ax.spines.values():
            spine.set_color("#bbb")
        ratio = c["distance"] / show["tolerance"] if show["tolerance"] else math.nan
        ax.set_title(f"zoom: stroke {c['stroke']}'s end snapped by {ratio:.2f} tolerance\n(drawn grey, cleaned blue; "
                     "dotted: the tolerance)", fontsize=7)
    figure.legend(handles, labels, loc="lower center", ncol=max(1, len(handles)), frameon=False, fontsize=7,
                  title="junctions made by", title_fontsize=7)
    figure.suptitle(f"{show['name']} ({show.get('subject') or show.get('kind')}) before and after `stickmorph clean`",
                    fontsize=9)
    figure.savefig(path, format="svg", metadata={"Date": None})
    plt.close(figure)


def cleaning_section(doc, out_path, plot_dir):
    """The drawing-cleaning section: per kind of drawing the planted defects found, the changes
    reported, validity, accounting and idempotence; pairs morphed; refusals; failures; a figure."""
    if doc is None:
        return ["\n## Drawing cleaning\n", "Not measured in this run (out/benchmarks/cleaning.json is missing: "
                "bench/benchmarks.sh runs bench/drawing_corpus.py and bench/cleaning.py).\n"]
    plot_rel = os.path.relpath(plot_dir, os.path.dirname(os.path.abspath(out_path)) or ".")
    s = doc["summary"]
    a = s["all"]
    rows = doc["drawings"]
    kinds = sorted(s["by_kind"])
    points = [r["points"] for r in rows]
    md = ["\n## Drawing cleaning\n",
          "Issue 32: `stickmorph clean DRAWING.json -o FIGURE.json` turns a drawing (strokes that cross and touch, "
          "ends that stop short, points repeated) into a valid stick figure: crossings and touches become shared "
          "vertices, a free end within the tolerance (default 1% of the bounding-box diagonal) of a stroke snaps "
          "onto it, points within a hundredth of the tolerance merge, and the output's `cleaning` lists every "
          "change. Measured by `bench/cleaning.py` on "
          f"{a['drawings']} drawings of `bench/drawing_corpus.py` (seed {doc.get('seed')}: {', '.join(kinds)}; "
          f"{min(points) if points else 0}–{max(points) if points else 0} points, as a tablet draws them: every "
          "0.3–1% of the size, each stroke wobbling on its own, on a grid; sizes from 8 to 8000, some far from "
          "the origin) with gaps of 0.15–0.85 tolerance, touches, shared ends, overshoots of 2–4 tolerances and "
          "pen pauses planted, each listed in the corpus's manifest.\n",
          "*Found*: a planted gap counts when the end's vertex is on the stroke it stopped short of, a crossing when "
          "one vertex at its place is on both strokes, a duplicate when it became the vertex of the point before it. "
          "*Valid*: `stickmorph check OUT OUT` and an independent exact test (fractions on the doubles: no crossing, "
          "overlap or coincident vertices). *Accounted*: every input point is where it was drawn unless a merge or "
          "snap names it with the distance it moved (to 1e-12, relative), every stroke's path runs along the edges "
          "through its points in order, every vertex two strokes share (or one stroke twice) is explained by a "
          "change or a point drawn there, and the summary counts match. *Idempotent*: cleaning the cleaned figure "
          "again, with the same tolerance, changes nothing, bit for bit.\n"]
    build = doc.get("build") or {}
    if doc.get("command"):
        md.append(f"Measured with `{doc['command']}`"
                  + (f", the CLI built from {build['commit']}"
                     + (" with uncommitted changes to the engine (native/)" if build.get("uncommitted_native") else "")
                     if build.get("commit") else "") + ".\n")
    md.append(table(["kind", "drawings", "points", "strokes", "gaps found", "touches found", "crossings found",
                     "duplicates merged", "reported merge / snap / crossing / touch", "valid", "accounted",
                     "idempotent", "seconds"],
                    [_row(k, s["by_kind"][k]) for k in kinds] + [_row("**all**", a)],
                    ["---"] + ["--:"] * 12))
    notes = [f"crossings reported as crossings at their vertex: {a['found']['crossings_reported']}/"
             f"{a['found']['crossings']}",
             f"merges within the merge distance and snaps of free ends within the tolerance: "
             f"{a.get('within_limits', a['drawings'])}/{a['drawings']}",
             f"snaps of ends the manifest has as free: {a['extra_snaps']}",
             f"crossings it does not have: {a['extra_crossings']}",
             f"free ends less than the tolerance from a junction (stubs the cleaning left): {a.get('stubs', 0)}",
             f"idempotent with the default tolerance (the cleaned figure's own box): {a['idempotent_default']}/"
             f"{a['drawings']}",
             f"slowest clean {a['seconds_max'] * 1000:.0f} ms"]
    if a.get("bends"):
        notes.append(f"{a['bends']} times in {a['bent_drawings']} drawings a crossing fell within the merge distance "
                     "of another stroke's point and was put on it, the crossing stroke bending through it by at most "
                     f"{a['bend_max_of_merge']:.2f} of the merge distance (a crossing change with distance 0 says so)")
    md.append("\n" + "; ".join(notes) + ".")
    ps = s["pairs"]
    if ps["pairs"]:
        md.append(f"\nPairs (the same subject in two poses, cleaned separately): {ps['morphed']}/{ps['pairs']} morphed "
                  "by `stickmorph morph A.clean.json B.clean.json --correspond auto` (every frame verified by the "
                  f"engine), frames[0] and the last frame on the cleaned drawings in {ps['ends_on_drawings']}/"
                  f"{ps['pairs']}.")
    rs = s.get("refusals") or {}
    if rs.get("cases"):
        md.append(f"\nBad drawings (no strokes, a stroke of one point, a stroke along another, a stroke retracing "
                  f"itself): {rs['ok']}/{rs['cases']} refused with exit 2 and one `error:` line naming the stroke.")
    if s["failures"]:
        md.append("\nFailures: " + "; ".join(f"{f['name']} ({f['what']}): {f['detail'][:200]}"
                                              for f in s["failures"][:10])
                  + (f"; and {len(s['failures']) - 10} more" if len(s["failures"]) > 10 else "") + ".")
    else:
        md.append("\nNo failure.")
    show = doc.get("showcase")
    if show:
        os.makedirs(plot_dir, exist_ok=True)
        _before_after_svg(os.path.join(plot_dir, "cleaning_before_after.svg"), show)
        md.append(f"\n![{show['name']} before and after cleaning, junctions marked]({plot_rel}/cleaning_before_after.svg)"
                  "\n")
        md.append("Left, the drawing as drawn, a colour per stroke; middle, the cleaned figure, each junction marked "
                  "by the change that made it (points of two strokes drawn at one place merge); right, the end that "
                  "snapped furthest, drawn and cleaned.\n")
    return md
