#!/usr/bin/python3
"""Writes BENCHMARKS.md and its SVG plots from the raw benchmark output.

Input (written by bench/benchmarks.sh under out/benchmarks/):
  morph.jsonl         stickmorph_benchmark_morph --json: one object per (case, method)
  polygon_pairs.json  stickmorph_benchmark --json: the polygon-pair corpus
  run.json            machine, date, commit, command and runtime of the run
  motion.json         bench/motion_quality.py --json on the motion corpus
                      (optional: without it the report says that motion
                      quality was not measured)
  correspondence.json stickmorph_benchmark_correspondence --json: automatic
                      correspondence against size (optional, likewise)
  scrub.jsonl         stickmorph_benchmark_scrub --json: frames per second of
                      the stateful solvers (issue 15; optional, likewise)

Output: BENCHMARKS.md and docs/benchmarks/*.svg. Every number in them comes
from the input files; the text around them only explains. Runs with Debian's
/usr/bin/python3; the plots are drawn with matplotlib (Debian
python3-matplotlib).
"""

import argparse
import json
import math
import os
import shlex
import subprocess
import sys

try:
    import matplotlib
    matplotlib.use("svg")  # files only: no display, no GUI toolkit
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FixedLocator, NullFormatter
except ImportError as error:  # say which package, rather than a traceback
    sys.exit(f"error: make_benchmarks: needs matplotlib (Debian: apt-get install python3-matplotlib): {error}")

# Plots that change only when their data does: no date in the file, and ids
# derived from a fixed salt instead of a random one, so that regenerating
# the report without new numbers leaves the committed SVGs unchanged.
matplotlib.rcParams.update({
    "svg.hashsalt": "stickmorph-benchmarks",
    "svg.fonttype": "none",  # text stays text, as in a hand-written SVG
    "font.family": "sans-serif",
    "font.size": 9,
})

METHODS = ["aronov", "sg2001", "improved"]
# Stages of one improved case, in pipeline order: (key, label, per frame?).
STAGES = [
    ("validate_ms", "validation", False),
    ("decompose_ms", "decomposition + compatibility", False),
    ("interior_faces_ms", "interior faces (section 4)", False),
    ("cut_ms", "enclosure + annulus cut", False),
    ("exterior_face_ms", "exterior face (section 4)", False),
    ("verify_triangulation_ms", "verify triangulation", False),
    ("morph_setup_ms", "morph setup + factorizations", False),
    ("solve_frame_ms", "solve per frame", True),
    ("verify_frame_ms", "verify per frame", True),
]
# Exponents are fitted over these sizes only: below them fixed costs dominate.
FIT_MIN_N = 100
# Issue 15: the total time (triangulate + morph) grows at most as n^1.2 from
# FIT_MIN_N to TOTAL_FIT_MAX_N vertices; a frame costs at most FRAME_LU_TARGET
# times a fresh LU factorize-and-solve at FRAME_LU_N (requested) vertices;
# a figure of SCRUB_FPS_N vertices plays back at SCRUB_FPS_TARGET frames per
# second or more.
TOTAL_FIT_MAX_N = 1000
TOTAL_EXPONENT_TARGET = 1.2
FRAME_LU_N = 1000
FRAME_LU_TARGET = 0.1
SCRUB_FPS_N = 10000
SCRUB_FPS_TARGET = 60
COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf", "#7f7f7f"]
DASHES = {"aronov": "2,3", "sg2001": "7,3", "improved": ""}


class InputError(Exception):
    """Raw data missing or malformed: the run did not complete."""


def read_inputs(data_dir):
    def load(name):
        path = os.path.join(data_dir, name)
        try:
            with open(path, encoding="utf-8") as f:
                if name.endswith(".jsonl"):
                    return [json.loads(line) for line in f if line.strip()]
                return json.load(f)
        except (OSError, ValueError) as error:
            raise InputError(f"{path}: {error}") from error

    return load("morph.jsonl"), load("polygon_pairs.json"), load("run.json")


def read_scrub(data_dir):
    """scrub.jsonl (stickmorph_benchmark_scrub --json), or None when the run did not measure it."""
    path = os.path.join(data_dir, "scrub.jsonl")
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            records = [json.loads(line) for line in f if line.strip()]
        for record in records:
            record["family"], record["requested_n"], record["status"]  # noqa: B018 - only the KeyError matters
    except (OSError, ValueError, KeyError) as error:
        raise InputError(f"{path}: {error}") from error
    return records


def read_motion(data_dir):
    """motion.json (bench/motion_quality.py --json), or None when the run did not measure
    motion quality."""
    path = os.path.join(data_dir, "motion.json")
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            motion = json.load(f)
        for key in ("methods", "pairs", "summary", "targets"):
            motion[key]  # noqa: B018 - only the KeyError matters
    except (OSError, ValueError, KeyError) as error:
        raise InputError(f"{path}: {error}") from error
    return motion


# ---------------------------------------------------------------------------
# Data


class Cell:
    """One (family, requested size, method) record of morph.jsonl."""

    def __init__(self, record):
        self.family = record["family"]
        self.requested = record["requested_n"]
        self.method = record["method"]
        self.status = record["status"]
        self.reason = record.get("reason", "")
        self.peak_mib = record.get("peak_kib", 0) / 1024
        self.wall_ms = record.get("wall_ms")
        self.result = record.get("result", {})
        if self.ok and self.method == "improved":
            frames = self.result["frames"]
            self.result["solve_frame_ms"] = self.result["solve_ms"] / frames
            self.result["verify_frame_ms"] = self.result["verify_frames_ms"] / frames

    @property
    def ok(self):
        return self.status == "ok"

    @property
    def n(self):
        return int(self.result["n"]) if self.ok else None

    def why_not(self):
        """Text for a cell without a result."""
        if self.status == "not_run":
            return f"not run: {self.reason}"
        return {"timeout": "timed out", "out_of_memory": "out of memory", "crashed": "crashed",
                "failed": "FAILED"}.get(self.status, self.status) + f": {self.reason}"


def index_cells(records):
    cells = {}
    families, sizes = [], []
    for record in records:
        cell = Cell(record)
        cells[(cell.family, cell.requested, cell.method)] = cell
        if cell.family not in families:
            families.append(cell.family)
        if cell.requested not in sizes:
            sizes.append(cell.requested)
    return cells, families, sorted(sizes)


def fit_exponent(points, min_n=FIT_MIN_N):
    """Least-squares slope of log t against log n over n >= min_n with t >
    0; None when fewer than three such sizes."""
    used = [(math.log(n), math.log(t)) for n, t in points if n >= min_n and t and t > 0]
    if len(used) < 3:
        return None, len(used)
    mx = sum(x for x, _ in used) / len(used)
    my = sum(y for _, y in used) / len(used)
    sxx = sum((x - mx) ** 2 for x, _ in used)
    sxy = sum((x - mx) * (y - my) for x, y in used)
    return sxy / sxx, len(used)


# ---------------------------------------------------------------------------
# Formatting


def fmt_ms(ms):
    if ms is None:
        return "–"
    if ms >= 1000:
        return f"{ms / 1000:.2f} s"
    if ms >= 10:
        return f"{ms:.0f} ms"
    if ms >= 1:
        return f"{ms:.1f} ms"
    if ms < 0.01:
        return "<0.01 ms"
    return f"{ms:.2f} ms"


def fmt_int(value):
    return f"{int(value):,}".replace(",", " ")


def fmt_ratio(value):
    if value == 0:
        return "0"
    return f"{value:.3f}" if value < 1 else f"{value:.2f}" if value < 100 else f"{value:.0f}"


def fmt_exponent(fit):
    slope, count = fit
    return f"{slope:.2f} ({count})" if slope is not None else f"n/a (only {count})"


def cell_text(text):
    return text.replace("|", "\\|").replace("\n", " ")


def table(header, rows, align=None):
    align = align or ["---"] + ["--:"] * (len(header) - 1)
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    lines += ["| " + " | ".join(cell_text(str(c)) for c in row) + " |" for row in rows]
    return "\n".join(lines)


# ---------------------------------------------------------------------------
# Log-log plots


def nice_label(value):
    if value >= 1:
        return f"{value:,.0f}".replace(",", " ") if value < 1e6 else f"1e{round(math.log10(value))}"
    return f"{value:g}"


def dash_pattern(dash):
    """'7,3' (on, off lengths in pixels, as in SVG) as a matplotlib linestyle."""
    if not dash:
        return "-"
    return (0, tuple(float(length) for length in dash.split(",")))


def loglog_svg(path, title, x_label, y_label, series, note=None, least=0.0):
    """series: list of dicts {label, points [(x, y)], color, dash}. Points with
    y <= least (at least those y <= 0, which a log axis cannot show) are left
    out; the caller says so in the note."""
    series = [dict(s, points=[(x, y) for x, y in s["points"] if y > least]) for s in series]
    series = [s for s in series if s["points"]]  # nothing to draw, nothing to list
    xs = [x for s in series for x, y in s["points"] if y > 0]
    ys = [y for s in series for x, y in s["points"] if y > 0]
    if not xs:
        xs, ys = [10, 10000], [1, 10]

    def axis_range(values):
        # Whole decades, except that a value just below a decade (n = 9)
        # does not stretch the axis by a whole empty decade.
        lo, hi = math.log10(min(values)), math.log10(max(values))
        lo = math.floor(lo) if lo - math.floor(lo) < 0.9 else lo - 0.03
        hi = math.ceil(hi) if math.ceil(hi) - hi < 0.9 else hi + 0.03
        return lo, max(hi, lo + 1)

    def decades(lo, hi):
        exponents = range(math.floor(lo), math.ceil(hi) + 1)
        major = [10.0 ** e for e in exponents if lo - 1e-9 <= e <= hi + 1e-9]
        minor = [m * 10.0 ** e for e in exponents for m in (2, 5) if lo - 1e-9 <= e + math.log10(m) <= hi + 1e-9]
        return major, minor

    # 800 by 460 pixels, as before: the plot on the left, the legend in a
    # column on its right.
    figure = plt.figure(figsize=(8.0, 4.6), dpi=100)
    axes = figure.add_axes([78 / 800, 58 / 460, (800 - 78 - 250) / 800, (460 - 40 - 58) / 460])
    axes.set_xscale("log")
    axes.set_yscale("log")
    for set_limits, set_ticks, set_minor_ticks, set_labels, (lo, hi), axis in (
            (axes.set_xlim, axes.set_xticks, axes.xaxis.set_minor_locator, axes.set_xticklabels,
             axis_range(xs), axes.xaxis),
            (axes.set_ylim, axes.set_yticks, axes.yaxis.set_minor_locator, axes.set_yticklabels,
             axis_range(ys), axes.yaxis)):
        major, minor = decades(lo, hi)
        set_limits(10.0 ** lo, 10.0 ** hi)
        set_ticks(major)
        set_labels([nice_label(v) for v in major])
        set_minor_ticks(FixedLocator(minor))
        axis.set_minor_formatter(NullFormatter())
    # Grid: decades darker, 2 and 5 light.
    axes.grid(True, which="major", color="#ccc", linewidth=0.8)
    axes.grid(True, which="minor", color="#eee", linewidth=0.8)
    axes.set_axisbelow(True)
    for side in axes.spines.values():
        side.set_color("#333")
    for s in series:
        points = sorted((x, y) for x, y in s["points"] if y > 0)
        axes.plot([x for x, _ in points], [y for _, y in points], color=s["color"], linewidth=1.4,
                  linestyle=dash_pattern(s.get("dash")), marker="o", markersize=4, label=s["label"])
    axes.set_title(title, fontsize=12)
    axes.set_xlabel(x_label)
    axes.set_ylabel(y_label)
    if series:
        axes.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False, handlelength=2.6, fontsize=8,
                    borderaxespad=0.0)
    if note:
        figure.text(78 / 800, 2 / 460, note, fontsize=8, color="#555", va="bottom")
    figure.savefig(path, format="svg", metadata={"Date": None})
    plt.close(figure)


# ---------------------------------------------------------------------------
# The report


def improved_cells(cells, family, sizes):
    return [cells[(family, s, "improved")] for s in sizes if (family, s, "improved") in cells]


def write_report(records, polygon_pairs, run, out_path, plot_dir, motion=None, correspondence=None, scrub=None):
    cells, families, sizes = index_cells(records)
    os.makedirs(plot_dir, exist_ok=True)
    plot_rel = os.path.relpath(plot_dir, os.path.dirname(os.path.abspath(out_path)))
    md = []
    add = md.append

    add("# Benchmarks\n")
    add("Generated by `" + run["command"] + "` (bench/benchmarks.sh runs the benchmark programs, then "
        "bench/make_benchmarks.py writes this file and the plots). Do not edit by hand: every number "
        "below comes from that run.\n")
    add(table(["", ""], [
        ["date", run["date"]],
        ["commit", run["commit"]],
        ["machine", run["machine"]],
        ["compiler", run["compiler"]],
        ["build", run["build"]],
        ["frames per morph", str(run["frames"])],
        ["runtime of the whole command", f"{run['runtime_s']:.0f} s ({run['runtime_s'] / 60:.1f} min)"],
    ], ["---", "---"]))
    repeat = run.get("repeat", 1)
    repeated = (f"Each (case, method) runs in a child process of its own (peak memory is that process's "
                f"`ru_maxrss`), with an address-space limit of {run['memory_limit_mib']} MiB and a time limit; "
                + (f"the improved method's cases of at most {run.get('repeat_max_n')} requested vertices run "
                   f"{repeat} times and the run of median total time (triangulate + morph) is reported (the "
                   "growth exponents rest on them), the rest once. " if repeat > 1 else "once. "))
    add("\n" + repeated + "Times are wall-clock measurements on a 2-core machine that other jobs may share: "
        "read them to within tens of percent, the small ones (below a millisecond) only as orders of "
        "magnitude.\n")

    # Headline.
    ok_improved = [c for c in cells.values() if c.method == "improved" and c.ok]
    add("## Headline\n")
    headline = []
    largest = max(ok_improved, key=lambda c: (c.n, c.family)) if ok_improved else None
    total_frames = sum(c.result["frames"] for c in ok_improved)
    invalid_ours = sum(c.result["invalid_frames"] for c in ok_improved)
    invalid_linear = sum(c.result["linear_invalid_frames"] for c in ok_improved)
    cases_linear_bad = sum(1 for c in ok_improved if c.result["linear_invalid_frames"] > 0)
    headline.append(f"Our morph: {invalid_ours} invalid frames out of {fmt_int(total_frames)} on "
                    f"{len(ok_improved)} cases (every frame re-checked exactly). The straight-line morph: "
                    f"{fmt_int(invalid_linear)} self-intersecting or incompatible frames, in {cases_linear_bad} of "
                    f"the same {len(ok_improved)} cases.")
    ratios = [(c.result["steiner"] / c.n, c) for c in ok_improved if c.n >= FIT_MIN_N]
    if ratios:
        worst = max(ratios, key=lambda rc: rc[0])
        headline.append(f"Improved Steiner vertices per input vertex, n ≥ {FIT_MIN_N}: at most "
                        f"{fmt_ratio(worst[0])} ({worst[1].family}, n = {worst[1].n}); the paper's bound is 11.")
    all_three = [c for c in ok_improved
                 if all(cells.get((c.family, c.requested, m)) and cells[(c.family, c.requested, m)].ok
                        for m in METHODS)]
    if all_three:
        total = {m: sum(cells[(c.family, c.requested, m)].result["steiner"] for c in all_three) for m in METHODS}
        headline.append(f"Steiner vertices in total over the {len(all_three)} cases where all three methods ran "
                        f"(n ≤ {max(c.n for c in all_three)}): aronov {fmt_int(total['aronov'])}, sg2001 "
                        f"{fmt_int(total['sg2001'])}, improved {fmt_int(total['improved'])}.")
    if largest:
        big = [c for c in ok_improved if c.requested == largest.requested]
        headline.append(f"At n ≈ {largest.requested}, improved compatible triangulation takes " +
                        ", ".join(f"{fmt_ms(c.result['triangulate_ms'])} ({c.family})" for c in big) +
                        "; a frame then costs " +
                        ", ".join(f"{fmt_ms(c.result['solve_frame_ms'] + c.result['verify_frame_ms'])}"
                                  for c in big) +
                        " (solve and exact verification), in the same order; peak memory at most "
                        f"{max(c.peak_mib for c in big):.0f} MiB.")
    unfinished = [c for c in cells.values() if c.method == "improved" and not c.ok]
    if unfinished:
        headline.append("Improved cases without a result: " +
                        "; ".join(f"{c.family} n ≈ {c.requested} ({c.why_not()})" for c in unfinished) + ".")
    headline += speed_headline(cells, families, sizes, scrub)
    if motion is not None:
        met = motion_targets_met(motion)
        headline.append("Motion quality ([below](#motion-quality)), issue 12's targets met: "
                        + ", ".join(f"{m} {met[m]}" for m in motion["methods"]) + ".")
    add("\n".join(f"- {h}" for h in headline) + "\n")

    # Corpus.
    add("## Corpus\n")
    add("Pairs from `native/bench/bench_figures.h`, deterministic (fixed seeds, raw `std::mt19937` output) and "
        "compatible by construction: polylines and simple polygons with the same vertex order always are; the "
        "other targets are the source under a smooth twist of the plane (rotation growing with the distance "
        "from the centre, up to the stated angle in radians at the rim), halved until the exact check "
        "accepts the pair.\n")
    add("- **polyline**: a sine-shaped path; target another sine wave.\n"
        "- **spiral**: the same path; target wound into an Archimedean spiral (adversarial: one long, thin "
        "exterior face that changes completely).\n"
        "- **polygon**: a star-shaped polygon with random radii; target another one turned by 135°.\n"
        "- **tree**: a spine with alternating two-edge branches; target twisted.\n"
        "- **triangulation**: a k×k grid with one diagonal per cell; target twisted.\n"
        "- **thinned**: the Delaunay triangulation of a jittered triangular lattice, thinned to a random "
        "spanning tree plus a third of the other edges (faces of many sizes, dangling trees); target twisted.\n"
        "- **rings**: figures of several parts (issue 14): a grid of cells, each a ring of 16 vertices round a "
        "ring of 8 round a dot (a lone vertex); in the target every inner ring is turned by 120° inside its "
        "ring and the whole is twisted, so the bridges that join the parts into one triangulation must bend.\n")
    rows = []
    for family in families:
        for c in improved_cells(cells, family, sizes):
            if c.ok:
                r = c.result
                rows.append([family, c.requested, r["n"], r["edges"], r["interior_faces"],
                             f"{r['twist']:g}" if r["twist"] else "–"])
            else:
                rows.append([family, c.requested, c.why_not(), "", "", ""])
    add(table(["family", "requested n", "n", "edges", "interior faces", "twist"], rows))
    add("")

    # Steiner vertices.
    add("## Steiner vertices per method\n")
    add("Steiner vertices of the whole compatible triangulation (Algorithm 3: every face, the annulus cut's "
        "bends included), and in brackets their ratio to the input vertices n. `aronov` and `sg2001` build the "
        "paper's spiderwebs, which grow quadratically on long thin faces; they are run only up to "
        f"{run['aronov_max']} and {run['sg2001_max']} requested vertices (the size cap), and no method is run "
        "past a size where it hit the time or memory limit. Each cell that was not run says why.\n")
    for method, cap in (("aronov", run["aronov_max"]), ("sg2001", run["sg2001_max"])):
        at_cap = [c for c in cells.values() if c.method == method and c.ok and c.requested == cap]
        if at_cap:
            c = max(at_cap, key=lambda c: c.result["steiner"])
            add(f"- Why {method} stops at {cap}: its largest case there, {c.family} (n = {c.n}), took "
                f"{fmt_ms(c.result['triangulate_ms'])} and {c.peak_mib:.0f} MiB for "
                f"{fmt_int(c.result['steiner'])} Steiner vertices; the next size is 3.3 times larger, so growing "
                "quadratically it would need about 11 times as much, beyond this run's time and memory budget.")
    add("")
    rows = []
    for family in families:
        for size in sizes:
            row = [family, size]
            base = cells.get((family, size, "improved"))
            n = base.n if base and base.ok else None
            row.append(n if n is not None else "–")
            for method in METHODS:
                c = cells.get((family, size, method))
                if c is None:
                    row.append("–")
                elif c.ok:
                    s = c.result["steiner"]
                    row.append(f"{fmt_int(s)} ({fmt_ratio(s / c.n)})")
                else:
                    row.append(c.why_not())
            rows.append(row)
    add(table(["family", "requested n", "n", "aronov (/n)", "sg2001 (/n)", "improved (/n)"], rows,
              ["---", "--:", "--:", "--:", "--:", "--:"]))
    series = []
    for fi, family in enumerate(families):
        for method in METHODS:
            pts = [(c.n, c.result["steiner"]) for s in sizes
                   for c in [cells.get((family, s, method))] if c and c.ok]
            if pts:
                series.append({"label": f"{family} {method}", "points": pts, "color": COLORS[fi % len(COLORS)],
                               "dash": DASHES[method]})
    loglog_svg(os.path.join(plot_dir, "steiner.svg"), "Steiner vertices against size", "input vertices n",
               "Steiner vertices", series, "solid: improved, long dashes: sg2001, short dashes: aronov; "
               "zero counts cannot be drawn on a log axis")
    add(f"\n![Steiner vertices against n]({plot_rel}/steiner.svg)\n")

    # Stages.
    add("## Time per stage\n")
    add("Stages of the improved pipeline, as the engine measures them (`FigureTriangulationStats`, "
        "`MorphStats`): validation is `make_stick_figure` on both figures (exact planarity checks); "
        "decomposition is Algorithm 1 on both and the compatibility check; interior and exterior faces are "
        "section 4's compatible triangulation of each face; the enclosure and annulus cut are Algorithm 3, "
        "step 3; verification is the exact check of the glued triangulation. Morph setup is the weights of "
        "both embeddings, assembly, symbolic analysis and every numeric LU factorization (the count is "
        "given); per frame are the solves (including iterative refinement) and the exact check of each "
        "frame, divided by the number of frames. The pipeline is the default, rigid method (issue 12): its "
        "morph setup is the weights and the rigid guide sampled at 17 times, the LU count that of its own "
        "systems (the Steiner vertices' and the blended one, each iterated on its latest factorization "
        "like the barycentric solver's), its solve per frame the guide, the Steiner vertices and the "
        "blended system where the guide is left. The last two columns compare its whole morph with the paper's barycentric morph "
        "of the same pair and frames (on that method's own triangulation): the cost per frame the issue "
        "asks to stay within 2x.\n")
    for family in families:
        rows = []
        for c in improved_cells(cells, family, sizes):
            if not c.ok:
                rows.append([c.requested, c.why_not()] + [""] * (len(STAGES) + 2))
                continue
            r = c.result
            paper = r.get("barycentric_morph_ms")
            ratio = f"{r['morph_ms'] / paper:.2f}" if paper else "—"
            rows.append([r["n"], fmt_ms(r["triangulate_ms"])] + [fmt_ms(r[key]) for key, _, _ in STAGES] +
                        [r["factorizations"], fmt_ms(r["morph_ms"]),
                         fmt_ms(paper) if paper is not None else "—", ratio])
        add(f"### {family}\n")
        add(table(["n", "triangulate (total)"] + [label for _, label, _ in STAGES] +
                  ["LU count", "morph (total)", "barycentric morph (total)", "rigid / barycentric"], rows))
        add("")
        series = []
        for si, (key, label, _) in enumerate(STAGES):
            pts = [(c.n, c.result[key]) for c in improved_cells(cells, family, sizes) if c.ok]
            series.append({"label": label, "points": pts, "color": COLORS[si % len(COLORS)], "dash": ""})
        loglog_svg(os.path.join(plot_dir, f"stages_{family}.svg"), f"Time per stage: {family}",
                   "input vertices n", "milliseconds", series, "times below 1 µs (stages that had nothing to do) are not drawn",
                   least=1e-3)
        add(f"![Time per stage, {family}]({plot_rel}/stages_{family}.svg)\n")

    add(f"### Fitted growth exponents\n")
    add(f"Least-squares slope of log(time) against log(n) over the completed sizes with n ≥ {FIT_MIN_N}, "
        "in brackets how many sizes (at least three needed): 1 is linear growth, 2 quadratic. Stages that "
        "took under 1 µs are left out of the fit.\n")
    per_family = {f: [c for c in improved_cells(cells, f, sizes) if c.ok] for f in families}

    def exponent_row(label, value):
        return [label] + [fmt_exponent(fit_exponent([(c.n, value(c)) for c in per_family[f]
                                                     if value(c) >= 1e-3])) for f in families]

    rows = [exponent_row("triangulate (total)", lambda c: c.result["triangulate_ms"])]
    rows += [exponent_row(label, lambda c, key=key: c.result[key]) for key, label, _ in STAGES]
    rows.append(exponent_row("peak memory (MiB)", lambda c: c.peak_mib))
    rows.append([f"total (triangulate + morph), n = {FIT_MIN_N} to {TOTAL_FIT_MAX_N}"] +
                [fmt_exponent(total_exponent(per_family[f])) for f in families])
    add(table(["stage"] + families, rows))
    add(f"\nThe last row is issue 15's: the whole pipeline's time (triangulation and the {run['frames']}-frame "
        f"morph, the default rigid method) against the actual n, fitted over the cases requested at "
        f"{FIT_MIN_N} to {TOTAL_FIT_MAX_N} vertices only; the target is at most {TOTAL_EXPONENT_TARGET}.\n")

    # Where the time goes.
    add("### Where the triangulation time goes\n")
    notes = []
    for family in families:
        cs = [c for c in improved_cells(cells, family, sizes) if c.ok]
        if not cs:
            continue
        c = max(cs, key=lambda c: c.n)
        r = c.result
        parts = [(r[key], label) for key, label, per_frame in STAGES[1:6]]
        top_ms, top_label = max(parts)
        share = top_ms / r["triangulate_ms"] if r["triangulate_ms"] > 0 else 0
        note = f"{family}, n = {c.n}: {top_label} takes {share:.0%} of {fmt_ms(r['triangulate_ms'])}"
        sg = cells.get((family, c.requested, "sg2001"))
        if sg and sg.ok:
            note += (f"; the sg2001 spiderweb of the same pair has {fmt_int(sg.result['steiner'])} Steiner "
                     f"vertices, improved keeps {fmt_int(r['steiner'])}")
        notes.append(note + ".")
    add("\n".join(f"- {n}" for n in notes) + "\n")
    add("The exterior face is where the figures differ most: for trees and polylines it is the only face, "
        "a weakly simple polygon of 2(n−1) corners. The improved method first cuts it along diagonals "
        "valid in both figures, then builds the reduced spiderweb of section 4.1 on what is left, embeds it "
        "in both polygons and removes every Steiner vertex that is redundant in both (a dynamic programme "
        "over each star, repeated in passes until nothing changes). Its cost therefore follows the size of "
        "the spiderweb it builds — compare the sg2001 column above — rather than the few vertices that "
        "remain.\n")
    add("Profile notes, taken by hand (perf) and not regenerated by the command. At commit 39851c3 the "
        "10⁴-vertex polygon's exterior face took 52 s: 30% of a 5000-vertex run was `hypot` in the "
        "embedding's clearance (every spiderweb node scanned for every corner), and at 10⁴ vertices "
        "remove_redundant_steiner took 38 of the 43 s, re-running its O(d³) dynamic programme on the "
        "links of hub vertices (up to d = 2321) after every neighbour's removal. Commit ec6c964 sweeps "
        "the nodes in x order for the clearance and retries a vertex only after its star changed, long "
        "links last; the same polygon then takes about 7 s with 10 199 Steiner vertices instead of "
        "10 208, and the polygon-pair corpus's counts are unchanged.\n")

    # Per frame.
    series = []
    for fi, family in enumerate(families):
        cs = [c for c in improved_cells(cells, family, sizes) if c.ok]
        series.append({"label": f"{family} solve", "points": [(c.n, c.result["solve_frame_ms"]) for c in cs],
                       "color": COLORS[fi % len(COLORS)], "dash": ""})
        series.append({"label": f"{family} verify", "points": [(c.n, c.result["verify_frame_ms"]) for c in cs],
                       "color": COLORS[fi % len(COLORS)], "dash": "5,3"})
    loglog_svg(os.path.join(plot_dir, "per_frame.svg"), "Time per frame", "input vertices n", "milliseconds",
               series, "solid: solve (amortised, with refinement), dashed: exact verification of the frame")
    series = [{"label": family, "points": [(c.n, c.result["triangulate_ms"]) for c in
                                          improved_cells(cells, family, sizes) if c.ok],
               "color": COLORS[fi % len(COLORS)], "dash": ""} for fi, family in enumerate(families)]
    loglog_svg(os.path.join(plot_dir, "triangulate.svg"), "Compatible triangulation (improved), total",
               "input vertices n", "milliseconds", series)
    add(f"![Triangulation time]({plot_rel}/triangulate.svg)\n")
    add(f"![Time per frame]({plot_rel}/per_frame.svg)\n")

    md += frame_cost_section(cells, families, sizes)
    md += scrub_section(scrub)

    # Memory.
    add("## Peak memory\n")
    add("Peak resident memory (`ru_maxrss`) of the child process that ran the case: for improved, the whole "
        "pipeline including the stored frames, the re-check and the straight-line morph; for aronov and "
        "sg2001, the triangulation alone. A process that does nothing measures about 3–4 MiB here.\n")
    rows = []
    for family in families:
        for size in sizes:
            row = [family, size]
            for method in METHODS:
                c = cells.get((family, size, method))
                row.append("–" if c is None else f"{c.peak_mib:.0f}" if c.ok else c.why_not())
            rows.append(row)
    add(table(["family", "requested n", "aronov MiB", "sg2001 MiB", "improved MiB"], rows))
    series = []
    for fi, family in enumerate(families):
        for method in METHODS:
            pts = [(c.n, c.peak_mib) for s in sizes for c in [cells.get((family, s, method))] if c and c.ok]
            if pts:
                series.append({"label": f"{family} {method}", "points": pts, "color": COLORS[fi % len(COLORS)],
                               "dash": DASHES[method]})
    loglog_svg(os.path.join(plot_dir, "memory.svg"), "Peak memory against size", "input vertices n", "MiB",
               series, "solid: improved (whole morph), long dashes: sg2001, short dashes: aronov (triangulation)")
    add(f"\n![Peak memory]({plot_rel}/memory.svg)\n")

    # Linear morph.
    add("## Straight-line morph against ours\n")
    add(f"Frames (of {run['frames']}, both endpoints included) that are not a stick figure compatible with the "
        "source — crossing, touching or overlapping edges, or a changed rotation system — by the same exact "
        "check (`is_frame_valid`). Ours are counted again independently of the morph's own verification.\n")
    rows = []
    for family in families:
        for c in improved_cells(cells, family, sizes):
            if not c.ok:
                rows.append([family, c.requested, c.why_not(), "", ""])
                continue
            r = c.result
            first = r["linear_first_invalid"]
            rows.append([family, r["n"], r["invalid_frames"], r["linear_invalid_frames"],
                         "–" if first < 0 else first])
    add(table(["family", "n", "ours: invalid frames", "straight line: invalid frames", "first invalid frame"],
              rows))
    add("")

    # Polygon pairs.
    add("## Polygon-pair corpus\n")
    add("Section 4 alone on the polygon pairs of `tests/data/polygon_pairs` (`stickmorph_benchmark`, best of "
        f"{polygon_pairs['repeat']} runs). Steiner vertices, in brackets per corner.\n")
    rows = []
    totals = {m: 0 for m in METHODS}
    common = {m: 0 for m in METHODS}
    corners_total = 0
    for pair in polygon_pairs["pairs"]:
        if pair["skipped"]:
            rows.append([pair["name"], "–", "skipped: " + pair["skipped"], "", ""])
            continue
        by_method = {m["method"]: m for m in pair["methods"]}
        row = [pair["name"], pair["corners"]]
        all_ok = all(by_method.get(m, {}).get("ok") for m in METHODS)
        for method in METHODS:
            m = by_method.get(method)
            if m is None:
                row.append("not run")
            elif m["ok"]:
                row.append(f"{m['steiner']} ({m['steiner'] / pair['corners']:.2f}), {fmt_ms(m['ms'])}")
                totals[method] += m["steiner"]
                if all_ok:
                    common[method] += m["steiner"]
            else:
                row.append("FAILED: " + m["failure"][:80])
        if all_ok:
            corners_total += pair["corners"]
        rows.append(row)
    add(table(["pair", "corners", "aronov", "sg2001", "improved"], rows))
    add("")
    if common["sg2001"] and common["aronov"]:
        add(f"Over the pairs where all three succeeded ({corners_total} corners): aronov {common['aronov']}, "
            f"sg2001 {common['sg2001']}, improved {common['improved']} Steiner vertices; improved/sg2001 = "
            f"{common['improved'] / common['sg2001']:.2f} and improved/aronov = "
            f"{common['improved'] / common['aronov']:.2f}, against the paper's Figure 7 ratios of "
            f"{153 / 334:.2f} and {153 / 575:.2f} for its one pair of 38-gons.\n")

    md += motion_section(motion, out_path, plot_dir)
    md += correspondence_section(correspondence, out_path, plot_dir)

    with open(out_path, "w", encoding="utf-8") as f:
        f.write("\n".join(md).rstrip() + "\n")


# ---------------------------------------------------------------------------
# Speed (issue 15): a frame against a fresh LU, scrubbing, the total's growth


def total_exponent(cells):
    """Fitted exponent of triangulate + morph against the actual n, over the cases requested at
    FIT_MIN_N to TOTAL_FIT_MAX_N vertices (a family's actual n may be a little off: 99, 1024)."""
    chosen = [c for c in cells if FIT_MIN_N <= c.requested <= TOTAL_FIT_MAX_N and "morph_ms" in c.result]
    return fit_exponent([(c.n, c.result["triangulate_ms"] + c.result["morph_ms"]) for c in chosen], min_n=1)


def _frame_cells(cells, families, sizes, requested):
    return [(f, cells[(f, requested, "improved")]) for f in families if (f, requested, "improved") in cells]


def speed_headline(cells, families, sizes, scrub):
    lines = []
    at = _frame_cells(cells, families, sizes, FRAME_LU_N)
    if at:
        for key, name in (("frame_lu_ratio", "barycentric (MorphSolver::solve + certificate)"),
                          ("frame_after_setup_lu_ratio", "barycentric once its solver is set up (the first "
                           "solve's moment space left out)"),
                          ("rigid_frame_lu_ratio", "rigid, the default (GuidedMorph::frame with the certificate)")):
            have = [(f, c.result.get(key)) for f, c in at if c.ok and c.result.get(key) is not None]
            missing = [f for f, c in at if not (c.ok and c.result.get(key) is not None)]
            if not have:
                continue
            bad = [(f, r) for f, r in have if r > FRAME_LU_TARGET]
            worst = max(have, key=lambda fr: fr[1])
            verdict = "holds in every family" if not bad and not missing else \
                "does not hold in every family"
            text = (f"A frame at n ≈ {FRAME_LU_N} against a fresh sparse LU factorize-and-solve of the same system "
                    f"(issue 15's ≤ {FRAME_LU_TARGET:g}x), {name}: {verdict}; worst {fmt_ratio(worst[1])}x "
                    f"({worst[0]})")
            if bad:
                text += "; above the target: " + ", ".join(f"{f} {fmt_ratio(r)}x" for f, r in bad)
            if missing:
                text += "; no measurement: " + ", ".join(missing)
            lines.append(text + " ([below](#a-frame-against-a-fresh-lu)).")
    per_family = {f: [c for c in improved_cells(cells, f, sizes) if c.ok] for f in families}
    fits = [(f, total_exponent(per_family[f])) for f in families]
    fitted = [(f, slope) for f, (slope, _) in fits if slope is not None]
    if fitted:
        bad = [(f, e) for f, e in fitted if e > TOTAL_EXPONENT_TARGET]
        unfitted = [f for f, (slope, _) in fits if slope is None]
        text = (f"Total time (triangulate + morph) from n = {FIT_MIN_N} to {TOTAL_FIT_MAX_N}, target growth at most "
                f"n^{TOTAL_EXPONENT_TARGET}: " +
                ("met in every family" if not bad and not unfitted else
                 f"met in {len(fitted) - len(bad)} of {len(fits)} families") +
                " (" + ", ".join(f"{f} {e:.2f}" for f, e in fitted) + ")")
        if bad:
            text += "; above: " + ", ".join(f"{f}" for f, _ in bad)
        if unfitted:
            text += "; too few sizes: " + ", ".join(unfitted)
        lines.append(text + ".")
    if scrub is not None:
        at = [r for r in scrub if r["requested_n"] == SCRUB_FPS_N]
        if at:
            parts = []
            for r in at:
                if r["status"] != "ok":
                    parts.append(f"{r['family']}: {r['status']}")
                    continue
                res = r["result"]
                fps = [(name, res.get(f"{key}_fps")) for name, key in
                       (("barycentric in order", "barycentric_in_order"), ("barycentric scrub", "barycentric_scrub"),
                        ("rigid in order", "rigid_in_order"), ("rigid scrub", "rigid_scrub"))
                       if res.get(f"{key}_fps") is not None]
                parts.append(f"{r['family']} " + ", ".join(f"{name} {v:.0f}" for name, v in fps))
            reached = all(r["status"] == "ok" and all(
                r["result"].get(f"{k}_fps", SCRUB_FPS_TARGET) >= SCRUB_FPS_TARGET
                for k in ("barycentric_in_order", "barycentric_scrub", "rigid_in_order", "rigid_scrub"))
                for r in at)
            lines.append(f"Playback once triangulated at n ≈ {SCRUB_FPS_N} (target ≥ {SCRUB_FPS_TARGET} frames per "
                         f"second, solve and certificate per frame): " +
                         ("reached in every case" if reached else "not reached in every case") +
                         " (frames per second: " + "; ".join(parts) + ") ([below](#scrubbing)).")
        largest = max((r["requested_n"] for r in scrub), default=None)
        if largest and largest > SCRUB_FPS_N:
            big = [r for r in scrub if r["requested_n"] == largest]
            lines.append(f"At n ≈ {largest}: " + "; ".join(
                f"{r['family']} " + (f"triangulated in {fmt_ms(r['result']['triangulate_ms'])} and morphs at "
                                     f"{r['result']['barycentric_in_order_fps']:.1f} frames per second (barycentric)"
                                     if r["status"] == "ok" else f"no result ({r['status']}: {r.get('reason', '')})")
                for r in big) + ".")
    return lines


def frame_cost_section(cells, families, sizes):
    md = []
    add = md.append
    rows = []
    for family in families:
        for c in improved_cells(cells, family, sizes):
            r = c.result
            if not c.ok or r.get("frame_lu_ratio") is None:
                continue
            rows.append([family, r["n"], fmt_int(r["frame_unknowns"]), fmt_ms(r["fresh_lu_ms"]),
                         fmt_ms(r["frame_solve_ms"]), fmt_ms(r["frame_certificate_ms"]), fmt_ms(r["frame_mean_ms"]),
                         fmt_ms(r["frame_median_ms"]), f"{r['frame_factorizations']}",
                         f"{r['frame_iterations']}", f"**{fmt_ratio(r['frame_lu_ratio'])}**"
                         if c.requested == FRAME_LU_N else fmt_ratio(r["frame_lu_ratio"]),
                         fmt_ms(r.get("frame_setup_ms")),
                         fmt_ratio(r["frame_after_setup_lu_ratio"])
                         if r.get("frame_after_setup_lu_ratio") is not None else "–",
                         fmt_ms(r.get("rigid_fresh_lu_ms")), fmt_ms(r.get("rigid_frame_mean_ms")),
                         fmt_ms(r.get("rigid_frame_median_ms")),
                         fmt_ratio(r["rigid_frame_lu_ratio"]) if r.get("rigid_frame_lu_ratio") is not None else "–"])
    add("## A frame against a fresh LU\n")
    if not rows:
        add("Not measured in this run (no `frame_lu_ratio` in morph.jsonl).\n")
        return md
    add(f"Issue 15: at {FRAME_LU_N} vertices a frame (the solve and the per-frame certificate) should cost at most "
        f"{FRAME_LU_TARGET:g} times a fresh sparse LU factorize-and-solve of the same system, measured in the same "
        "run (the same child process). The fresh LU is MorphSolver's: `Eigen::SparseLU` on the system permuted "
        "symmetrically by AMD (`SymmetricOrderedLU`): the ordering, symbolic analysis, numeric factorization and the solve of both coordinates of the system at t = 0.5 "
        "(median of three; the weights and the assembly are not counted). Barycentric: a new `MorphSolver` on the "
        "barycentric method's triangulation solves the morph's interior times f / (N − 1) in order, each result "
        "followed by `certificate_defect`, as `morph_triangulation` makes a frame; mean (amortised: the first "
        "frame factorizes, as in a morph) and median per frame, its factorizations and its refinement steps "
        "(pairs of triangular solves) over the whole morph. Rigid, the default: `prepare_rigid_morph`, then "
        "`GuidedMorph::frame` with verification (the certificate included) at the same times, against the fresh "
        "LU of the barycentric system on the rigid triangulation (the sparsity of its blended system). The "
        "ratio is the mean frame over the fresh LU. Set-up is the barycentric solver's one-time work in its first "
        "solve (the moment space: three factorizations and their moments); after set-up is the mean frame "
        "without it, over the fresh LU, what a frame costs once the stateful solver exists (later "
        "factorizations stay in). The rigid morph's set-up is `prepare_rigid_morph`, not in its frames.\n")
    add(table(["family", "n", "unknowns", "fresh LU", "solve", "certificate", "frame (mean)", "frame (median)",
               "LUs", "steps", "frame / LU", "set-up", "after set-up / LU", "rigid: fresh LU", "rigid frame (mean)", "rigid frame (median)",
               "rigid frame / LU"], rows))
    add("")
    return md


def scrub_section(scrub):
    md = []
    add = md.append
    add("## Scrubbing\n")
    if scrub is None:
        add("Not measured in this run (no scrub.jsonl: `stickmorph_benchmark_scrub` was not run).\n")
        return md
    add("`stickmorph_benchmark_scrub`: each pair triangulated once (timed), then a stateful solver built once and "
        "N frames (the frames column) played back in order (t = k / (N − 1)), then as many at seeded "
        "random times (a scrub back and forth); every frame is the solve and the certificate (`certificate_defect` "
        "for MorphSolver, `GuidedMorph::frame` with verification for the rigid method). Frames per second are "
        "frames over the playback's wall time; the worst frame is the slowest single one (a refactorization). "
        "The rigid method's setup is `prepare_rigid_morph`, which triangulates again in the guide's enclosure. "
        "One child process per case; a rigid column left empty was not measured (at 10⁵ vertices "
        "bench/benchmarks.sh runs the barycentric solver only, with fewer frames, for time).\n")
    rows = []
    for r in scrub:
        if r["status"] != "ok":
            rows.append([r["family"], r["requested_n"], f"{r['status']}: {r.get('reason', '')}"] + [""] * 12)
            continue
        res = r["result"]

        def fps(key):
            v = res.get(f"{key}_fps")
            return "–" if v is None else f"{v:.1f}" if v < 100 else f"{v:.0f}"

        def worst(key):
            return fmt_ms(res.get(f"{key}_worst_ms"))

        rows.append([r["family"], r["requested_n"], fmt_int(res["n"]), r.get("frames", "–"), fmt_ms(res["triangulate_ms"]),
                     fmt_ms(res["fresh_lu_ms"]), fmt_ms(res["solver_setup_ms"]),
                     fps("barycentric_in_order"), worst("barycentric_in_order"), fps("barycentric_scrub"),
                     worst("barycentric_scrub"),
                     fmt_ms(res.get("rigid_setup_ms")), fps("rigid_in_order"), fps("rigid_scrub"),
                     f"{r.get('peak_kib', 0) / 1024:.0f}"])
    add(table(["family", "requested n", "n", "frames", "triangulate", "fresh LU", "solver setup", "barycentric fps (in order)",
               "worst frame", "barycentric fps (scrub)", "worst frame", "rigid setup", "rigid fps (in order)",
               "rigid fps (scrub)", "peak MiB"], rows))
    defects = sum(r["result"].get(k, 0) for r in scrub if r["status"] == "ok"
                  for k in ("barycentric_in_order_defects", "barycentric_scrub_defects"))
    add(f"\nFrames that failed their certificate: {defects}.\n")
    return md


# ---------------------------------------------------------------------------
# Motion quality (issue 12): bench/motion_quality.py's motion.json

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
KIND_ORDER = ["glyph", "skeleton", "polygon", "triangulation", "special", "sample"]
REFERENCES = {"linear", "arap"}
DEFAULT_THRESHOLDS = {"edge_dev_median": 0.02, "edge_dev_p90": 0.08, "joint_dev_median_deg": 2.0, "min_size": 0.9,
                      "min_size_share": 0.9, "unevenness_median": 1.2, "unevenness_p90": 1.6, "beyond_max_deg": 45.0,
                      "self_turn_deg": 178.0, "self_turn_edge_dev": 0.01, "self_turn_min_size": 0.99}
METRIC_NAMES = {"edge_dev": "edge-length deviation", "joint_dev_deg": "joint-angle deviation",
                "min_size": "minimum size", "unevenness": "speed unevenness", "beyond_deg": "turning beyond the need"}


def motion_targets_met(motion):
    """'k of n' targets passed, per method."""
    return {m: f"{sum(1 for t in motion['targets'] if (t.get(m) or {}).get('pass') is True)}"
               f"/{len(motion['targets'])}" for m in motion["methods"]}


def _num(value, spec):
    return "–" if value is None else format(value, spec)


def _motion_rows(motion, method):
    """The per-pair results of one method that did not fail: (name, pair, result)."""
    return [(name, pair, pair[method]) for name, pair in motion["pairs"].items()
            if isinstance(pair.get(method), dict) and "error" not in pair[method]]


def _median(values):
    values = sorted(v for v in values if v is not None)
    if not values:
        return None
    mid = len(values) // 2
    return values[mid] if len(values) % 2 else (values[mid - 1] + values[mid]) / 2


def _git_ignored(path):
    """Whether git ignores the path (out/, build/): such a file is never committed, so the
    report must not link it. False where git cannot tell."""
    try:
        return subprocess.run(["git", "-C", REPO, "check-ignore", "-q", path], stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL, timeout=60).returncode == 0
    except (OSError, subprocess.SubprocessError):
        return False


def _link(path, out_path, text):
    """A Markdown link to a file of the repository, relative to the report; a path outside
    the repository is named in a code span instead (the report links only its own files)."""
    absolute = os.path.abspath(path if os.path.isabs(path) else os.path.join(REPO, path))
    if os.path.commonpath([absolute, REPO]) != REPO or _git_ignored(absolute):
        return f"`{path}` (not a file of the repository, so not linked)", None
    rel = os.path.relpath(absolute, os.path.dirname(os.path.abspath(out_path))).replace(os.sep, "/")
    return f"[{text}]({rel})", rel


def motion_plot(path, motion):
    """Per-pair edge-length deviation and speed unevenness per method, each sorted: where the
    tails are, at a glance."""
    figure, axes = plt.subplots(1, 2, figsize=(8.0, 3.6), dpi=100)
    for mi, method in enumerate(motion["methods"]):
        rows = _motion_rows(motion, method)
        style = {"color": COLORS[mi % len(COLORS)], "linewidth": 1.4, "label": method,
                 "linestyle": "--" if method in REFERENCES else "-"}
        for ax, key in ((axes[0], "edge_dev"), (axes[1], "unevenness")):
            values = sorted(r[key] for _, _, r in rows)
            ax.plot(range(1, len(values) + 1), values, **style)
    t = dict(DEFAULT_THRESHOLDS, **motion.get("thresholds", {}))
    for ax, key, title, lines in ((axes[0], "edge_dev", "edge-length deviation per pair, sorted",
                                   (t["edge_dev_median"], t["edge_dev_p90"])),
                                  (axes[1], "unevenness", "speed unevenness per pair, sorted",
                                   (t["unevenness_median"], t["unevenness_p90"]))):
        for y in lines:
            ax.axhline(y, color="#999", linewidth=0.8, linestyle=":")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("pairs, best to worst")
        ax.grid(True, color="#eee", linewidth=0.8)
        ax.set_axisbelow(True)
    # edge deviation: logarithmic down to 0.001, linear below (ARAP's zeros); unevenness from 1 up
    top = max([r["edge_dev"] for m in motion["methods"] for _, _, r in _motion_rows(motion, m)] + [0.1])
    axes[0].set_yscale("symlog", linthresh=0.001, linscale=0.5)
    axes[0].set_ylim(0, top * 1.5)
    axes[0].set_yticks([v for v in (0, 0.001, 0.01, 0.1, 1) if v <= top * 1.5])
    axes[0].set_yticklabels([f"{v:g}" for v in (0, 0.001, 0.01, 0.1, 1) if v <= top * 1.5])
    axes[0].yaxis.set_minor_formatter(NullFormatter())
    highest = max([r["unevenness"] for m in motion["methods"] for _, _, r in _motion_rows(motion, m)] + [2])
    axes[1].set_yscale("log")
    axes[1].set_ylim(0.95, highest * 1.2)
    ticks = [v for v in (1, 1.2, 1.6, 2, 3, 5, 10, 20, 50, 100) if v <= highest * 1.2]
    axes[1].set_yticks(ticks)
    axes[1].set_yticklabels([f"{v:g}" for v in ticks])
    axes[1].yaxis.set_minor_locator(FixedLocator([]))
    axes[0].legend(loc="upper left", frameon=False, fontsize=8)
    figure.text(0.01, 0.01, "dotted: the targets for the median and the 90th percentile; dashed: references "
                "(straight lines, ARAP); edge axis linear below 0.001", fontsize=8, color="#555")
    figure.subplots_adjust(left=0.07, right=0.98, top=0.9, bottom=0.22, wspace=0.25)
    figure.savefig(path, format="svg", metadata={"Date": None})
    plt.close(figure)


def motion_section(motion, out_path, plot_dir):
    """The 'Motion quality' section: a list of Markdown blocks."""
    md = ["## Motion quality\n"]
    add = md.append
    if motion is None:
        add("Not measured in this run: the data folder has no `motion.json` (bench/benchmarks.sh writes it with "
            "bench/motion_corpus.py and bench/motion_quality.py; see docs/MOTION.md).\n")
        return md
    methods = motion["methods"]
    summary = motion["summary"]
    t = dict(DEFAULT_THRESHOLDS, **motion.get("thresholds", {}))
    cli_methods = motion.get("cli_methods", {})
    pairs = motion["pairs"]
    kinds = sorted({p["kind"] for p in pairs.values()},
                   key=lambda k: (KIND_ORDER.index(k) if k in KIND_ORDER else len(KIND_ORDER), k))
    counts = ", ".join(f"{sum(1 for p in pairs.values() if p['kind'] == k)} {k}" for k in kinds)
    sizes = [p["vertices"] for p in pairs.values()]
    seed = motion.get("corpus_seed")
    add(f"How natural the motion looks (issue 12). {_link('docs/MOTION.md', out_path, 'docs/MOTION.md')[0]} defines the corpus, every "
        f"metric and the targets. {len(pairs)} pairs from `bench/motion_corpus.py`"
        + (f" (seed {seed})" if seed is not None else "") + f": {counts}; {min(sizes)}–{max(sizes)} vertices"
        f", {motion['frames']} frames per morph. Each method other than `arap` is `stickmorph morph SRC TGT "
        f"--frames {motion['frames']}` with the options given below. `linear` (straight lines) and `arap` "
        "(as rigid as possible on the figure's own edges, computed by bench/motion_quality.py, which keeps "
        "nothing valid) are references for what the metrics give, not candidates. Invalid frames are counted "
        "by `stickmorph check` on every interior frame"
        + ("" if motion.get("check_frames", "all") == "all" else f" (`--check-frames {motion['check_frames']}`)")
        + ". The time per frame is the CLI's own `stats.milliseconds.morph` divided by the frames (the "
        "solves and the exact check of every frame; not the triangulation, not the process start).\n")
    notes = list(motion.get("notes", []))
    if "rigid" not in methods and not any("rigid" in n for n in notes):
        notes.append("no `rigid` row: this run did not measure a rigid method.")
    if notes:
        add("\n".join(f"- Note: {n}" for n in notes) + "\n")

    def options(m):
        if m not in cli_methods:
            return "–"
        if cli_methods[m] is None:
            return "computed in the script"
        return f"`{cli_methods[m]}`" if cli_methods[m] else "(the CLI's default)"

    rows = []
    for m in methods:
        s = summary[m]
        ms = (s.get("ms_per_frame") or {}).get("median")
        share = s.get("min_size_share_ok")
        ok_pairs = s["pairs"]
        rows.append([f"**{m}**" if m not in REFERENCES else m, options(m),
                     f"{ok_pairs}" + (f" (+{s['failed']} failed)" if s.get("failed") else ""),
                     _num(s["edge_dev"]["median"], ".3f"), _num(s["edge_dev"]["p90"], ".3f"),
                     _num(s["joint_dev_deg"]["median"], ".2f"),
                     "–" if share is None else f"{share:.0%} ({round(share * ok_pairs)}/{ok_pairs})",
                     _num(s["unevenness"]["median"], ".2f"), _num(s["unevenness"]["p90"], ".2f"),
                     _num(s["beyond_deg"]["max"], ".1f"),
                     (f"{s['bad_frames']} ({s['pairs_with_bad_frames']})" if s.get("bad_frames_checked", True)
                      else "not checked"),
                     "–" if ms is None else fmt_ms(ms)])
    rows.append(["*must show*", "", "", f"≤ {t['edge_dev_median']:g}", f"≤ {t['edge_dev_p90']:g}",
                 f"≤ {t['joint_dev_median_deg']:g}", f"≥ {t['min_size_share']:.0%}",
                 f"≤ {t['unevenness_median']:g}", f"≤ {t['unevenness_p90']:g}", f"≤ {t['beyond_max_deg']:g}",
                 "0", ""])
    add(table(["method", "options", "pairs", "edge dev median", "edge dev p90", "joint dev ° median",
               f"min size ≥ {t['min_size']:g}", "unevenness median", "unevenness p90", "max beyond °",
               "invalid frames (pairs)", "per frame"], rows,
              ["---", "---"] + ["--:"] * 10))
    add("")

    # The targets, pass or fail.
    rows = []
    for target in motion["targets"]:
        cells = []
        for m in methods:
            cell = target.get(m) or {}
            verdict = {True: "PASS", False: "FAIL"}.get(cell.get("pass"), "n/a")
            cells.append(f"{verdict} ({cell.get('value', '')})")
        rows.append([target["target"]] + cells)
    met = motion_targets_met(motion)
    rows.append(["**targets met**"] + [f"**{met[m]}**" for m in methods])
    add("Issue 12's targets (\"must show\"), per method, with the measured values:\n")
    add(table(["target"] + methods, rows, ["---"] + ["---"] * len(methods)))
    add("")

    # Per kind of pair.
    rows = []
    for kind in kinds:
        row = [kind, sum(1 for p in pairs.values() if p["kind"] == kind)]
        for key, spec in (("edge_dev", ".3f"), ("unevenness", ".2f"), ("min_size", ".2f")):
            for m in methods:
                values = [r[key] for _, p, r in _motion_rows(motion, m) if p["kind"] == kind]
                if key == "min_size":
                    row.append(_num(min(values) if values else None, spec))
                else:
                    row.append(_num(_median(values), spec))
        rows.append(row)
    add("By kind of pair: medians of the edge-length deviation and the speed unevenness, and the smallest "
        "minimum size:\n")
    add(table(["kind", "pairs"] + [f"edge dev {m}" for m in methods] + [f"uneven {m}" for m in methods]
              + [f"min size {m}" for m in methods], rows))
    add("")

    # Self-turns.
    turns = sorted(((name, p) for name, p in pairs.items()
                    if "self_turn_deg" in p.get("tags", {}) or "self_turn" in name),
                   key=lambda item: (item[1].get("tags", {}).get("self_turn_deg") != 180,
                                     -(item[1].get("tags", {}).get("self_turn_deg") or 0), item[0]))
    if turns:
        rows = []
        for name, p in turns:
            for m in methods:
                r = p.get(m)
                if r is None:
                    continue
                if "error" in r:
                    rows.append([name, m, "failed: " + r["error"][:80]] + [""] * 6)
                    continue
                rows.append([name, m, f"{r['turn_deg']:.1f}", f"{r['needed_deg']:.1f}", f"{r['beyond_deg']:.1f}",
                             f"{r['edge_dev']:.3f}", f"{r['min_size']:.3f}", f"{r['unevenness']:.2f}",
                             len(r["bad_frames"]) if r.get("bad_frames") is not None else "not checked"])
        add(f"A figure into itself turned (the 180° pair is the target: turns ≥ {t['self_turn_deg']:g}°, edge "
            f"dev ≤ {t['self_turn_edge_dev']:g}, min size ≥ {t['self_turn_min_size']:g}):\n")
        add(table(["pair", "method", "turns °", "needed °", "beyond °", "edge dev", "min size", "unevenness",
                   "invalid frames"], rows, ["---", "---"] + ["--:"] * 7))
        add("")

    # The plot.
    os.makedirs(plot_dir, exist_ok=True)
    plot_path = os.path.join(plot_dir, "motion_quality.svg")
    motion_plot(plot_path, motion)
    plot_rel = os.path.relpath(os.path.abspath(plot_path), os.path.dirname(os.path.abspath(out_path)))
    add(f"![Edge-length deviation and speed unevenness per pair]({plot_rel.replace(os.sep, '/')})\n")

    # Filmstrips.
    strips = motion.get("filmstrips") or []
    if strips:
        method = strips[0].get("method", methods[0])
        rows_drawn = strips[0].get("rows", [method])
        add(f"### Filmstrips of the worst `{method}` pairs\n")
        add(f"The worst `{method}` pairs by each metric" + (" and the pairs asked for by name" if any(
            not s.get("worst") for s in strips) else "") + f"; each filmstrip has one row per method "
            f"({', '.join(rows_drawn)}): seven of the {motion['frames']} frames, source blue to target red, all "
            "rows at one scale, an invalid frame dashed.\n")
        for strip in strips:
            why = ", ".join(f"{METRIC_NAMES.get(w['metric'], w['metric'])} {w['value']:.3g}"
                            + ("°" if w["metric"].endswith("_deg") else "") for w in strip.get("worst", []))
            link, rel = _link(strip["file"], out_path, strip["pair"])
            add(f"- {link}: " + (f"worst by {why}" if why else "asked for") + "\n"
                + (f"\n  ![{strip['pair']}]({rel})\n" if rel else ""))
    else:
        add("No filmstrips were drawn in this run.\n")

    # How it was made.
    build = motion.get("build_dir", "build")
    corpus_cmd = (f"/usr/bin/python3 bench/motion_corpus.py {shlex.quote(motion['corpus'])}"
                  + (f" --seed {seed}" if seed is not None else "") + f" --build-dir {shlex.quote(build)}")
    add("Made by these commands (bench/benchmarks.sh runs them"
        + (f"; the measuring took {motion['runtime_s']:.0f} s" if motion.get("runtime_s") is not None else "")
        + (f"; {motion['cli_version']}" if motion.get("cli_version") else "") + "):\n")
    add("```\n" + corpus_cmd + "\n" + motion.get("command", "/usr/bin/python3 bench/motion_quality.py ...")
        + "\n```\n")
    return md


# ---------------------------------------------------------------------------
# Correspondence (issue 13): stickmorph_benchmark_correspondence's correspondence.json

CORRESPONDENCE_FAMILIES = {
    "polygon": "a star-shaped blob sampled at n points; target the same curve sampled at 1.37 n other points, "
               "turned, scaled and renumbered (two loops: the cyclic-shift search)",
    "spiral": "an open polyline on an Archimedean spiral; target the same spiral resampled at 0.8 n points, turned "
              "and renumbered",
    "tree": "a random spanning tree of a grid (junctions of degree 3 and 4, bends, ends), every edge subdivided "
            "0–2 times; target the same tree subdivided otherwise, turned and renumbered",
    "mesh": "a jittered grid with one diagonal per cell: nearly every vertex is a junction, so the skeleton is the "
            "whole figure (the worst case for the isomorphism search); target a renumbered, turned copy",
    "wheel": "a hub with k = n/3 spokes and a rim with 2 vertices per arc; target the same wheel with 3 per arc, "
             "turned by 0.3 of a spoke and renumbered: k symmetric isomorphisms, every one compared",
}


def read_correspondence(data_dir):
    """correspondence.json (stickmorph_benchmark_correspondence --json), or None when the run
    did not measure the correspondence."""
    path = os.path.join(data_dir, "correspondence.json")
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        data["repeat"]  # noqa: B018 - only the KeyError matters
        for case in data["cases"]:
            case["family"], case["requested_n"], case["status"]  # noqa: B018
            if case["status"] == "ok":
                for key in ("n_source", "n_target", "m", "nodes", "chains", "candidates", "ms"):
                    case["result"][key]  # noqa: B018
    except (OSError, ValueError, KeyError, TypeError) as error:
        raise InputError(f"{path}: {error!r}") from error
    return data


def _correspondence_why_not(case):
    if case["status"] == "not_run":
        return f"not run: {case.get('reason', '')}"
    return {"timeout": "timed out", "out_of_memory": "out of memory", "crashed": "crashed",
            "failed": "FAILED"}.get(case["status"], case["status"]) + f": {case.get('reason', '')}"


def correspondence_requirement(data):
    """Issue 13's "matching a 1000-vertex pair takes under a second": (met or None when not
    measured, the slowest finished case at that size or None, cases at that size, unfinished)."""
    requirement = data.get("requirement") or {}
    size, limit = requirement.get("requested_n", 1000), requirement.get("limit_ms", 1000)
    at_size = [c for c in data["cases"] if c["requested_n"] == size]
    if not at_size:
        return None, None, 0, 0
    done = [c for c in at_size if c["status"] == "ok"]
    worst = max(done, key=lambda c: c["result"]["ms"]) if done else None
    met = worst is not None and len(done) == len(at_size) and worst["result"]["ms"] < limit
    return met, worst, len(at_size), len(at_size) - len(done)


def correspondence_section(data, out_path, plot_dir):
    """The 'Correspondence' section: a list of Markdown blocks."""
    md = ["## Correspondence\n"]
    add = md.append
    if data is None:
        add("Not measured in this run: the data folder has no `correspondence.json` (bench/benchmarks.sh writes "
            "it with stickmorph_benchmark_correspondence).\n")
        return md
    cases = data["cases"]
    families = []
    for case in cases:
        if case["family"] not in families:
            families.append(case["family"])
    repeat = data["repeat"]
    add("Automatic correspondence (issue 13): `correspond_figures` matches two figures drawn separately (other "
        "vertex counts, numbering and subdivision) as skeletons, plane maps that keep the rotation system and the "
        "exterior face, chosen by similarity fit, and resamples the chains by arc length with dummy vertices. "
        "Pairs from `native/bench/benchmark_correspondence.cpp`, deterministic:\n")
    add("\n".join(f"- **{f}**: {CORRESPONDENCE_FAMILIES.get(f, 'a family of this run')}." for f in families) + "\n")
    limits = [f"address-space limit {data['memory_limit_mib']} MiB"] if "memory_limit_mib" in data else []
    limits += [f"time limit {data['time_limit_s']} s"] if "time_limit_s" in data else []
    add("Each case runs in a child process of its own (peak memory is its `ru_maxrss`"
        + "".join(f", {text}" for text in limits)
        + f"); the time is the best of {repeat} runs of the match alone (a single run where one took over 10 s). "
        "`m` is the matched figure's vertex count: every vertex of both figures once, a vertex of one with no "
        "partner in the other standing with a dummy on the other's edge. Nodes and chains are each figure's "
        "skeleton; candidates the isomorphisms (for two loops, the cyclic shifts) whose fit was compared. "
        "Valid: the matched pair passes `is_valid` and `check_compatibility`. Partners: of the source vertices "
        "whose true partner the generator knows, how many were matched to it.\n")

    met, worst, at_size, unfinished = correspondence_requirement(data)
    if met is None:
        add("Issue 13's requirement (a 1000-vertex pair matched in under a second) was not measured: this run has "
            "no size 1000.\n")
    else:
        text = ("Issue 13's requirement, \"matching a 1000-vertex pair takes under a second\": **"
                + ("met" if met else "not met") + "**")
        if worst:
            r = worst["result"]
            text += (f"; the slowest of the {at_size} pairs at n ≈ {worst['requested_n']} is {worst['family']} "
                     f"({fmt_int(r['n_source'])} against {fmt_int(r['n_target'])} vertices, "
                     f"{fmt_int(r['candidates'])} candidates): {fmt_ms(r['ms'])}")
        if unfinished:
            text += f"; {unfinished} of them did not finish"
        add(text + ".\n")

    rows = []
    for family in families:
        for case in [c for c in cases if c["family"] == family]:
            if case["status"] != "ok":
                rows.append([family, case["requested_n"], _correspondence_why_not(case)] + [""] * 9)
                continue
            r = case["result"]
            known = r.get("known_partners", 0)
            single = r.get("runs", repeat) == 1 and repeat > 1
            rows.append([family, case["requested_n"], fmt_int(r["n_source"]), fmt_int(r["n_target"]), fmt_int(r["m"]),
                         fmt_int(r["nodes"]), fmt_int(r["chains"]), fmt_int(r["candidates"]),
                         fmt_ms(r["ms"]) + (" (1 run)" if single else ""),
                         f"{case.get('peak_kib', 0) / 1024:.0f}", "yes" if r.get("valid") else "**NO**",
                         f"{r.get('correct_partners', 0)}/{known}" if known else "–"])
    add(table(["family", "requested n", "n source", "n target", "m", "nodes", "chains", "candidates", "time",
               "peak MiB", "valid", "partners"], rows, ["---", "--:", "--:", "--:", "--:", "--:", "--:", "--:", "--:",
                                                          "--:", "---", "--:"]))
    add("")

    # Growth: the program's own fit (over the requested sizes, since a
    # generated n may fall just short of the requested one), else one here.
    rows = []
    for family in families:
        fit = (data.get("exponents") or {}).get(family)
        if fit is not None:
            slope, count = fit.get("exponent"), fit.get("sizes", 0)
        else:
            slope, count = fit_exponent([(c["result"]["n_source"], c["result"]["ms"]) for c in cases
                                         if c["family"] == family and c["status"] == "ok"])
        rows.append([family, fmt_exponent((slope, count))])
    min_n = data.get("fit_min_n", FIT_MIN_N)
    add(f"Fitted growth exponent of the time: the least-squares slope of log(time) against log(n) over the "
        f"requested sizes ≥ {min_n}, in brackets how many (at least three needed); 1 is linear, 2 quadratic.\n")
    add(table(["family", "exponent"], rows))
    add("")

    os.makedirs(plot_dir, exist_ok=True)
    plot_path = os.path.join(plot_dir, "correspondence.svg")
    series = [{"label": family, "color": COLORS[fi % len(COLORS)], "dash": "",
               "points": [(c["result"]["n_source"], c["result"]["ms"]) for c in cases
                          if c["family"] == family and c["status"] == "ok"]}
              for fi, family in enumerate(families)]
    loglog_svg(plot_path, "Automatic correspondence against size", "source vertices n", "milliseconds", series,
               f"best of {repeat} runs of correspond_figures per pair; times of 0 cannot be drawn on a log axis")
    plot_rel = os.path.relpath(os.path.abspath(plot_path), os.path.dirname(os.path.abspath(out_path)))
    add(f"![Correspondence time against n]({plot_rel.replace(os.sep, '/')})\n")
    if data.get("command"):
        add("Made by this command (bench/benchmarks.sh runs it):\n")
        add("```\n" + data["command"] + "\n```\n")
    return md


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", default="out/benchmarks", help="directory of the raw output")
    parser.add_argument("--output", default="BENCHMARKS.md")
    parser.add_argument("--plots", default="docs/benchmarks", help="directory for the SVG plots")
    args = parser.parse_args()
    try:
        records, polygon_pairs, run = read_inputs(args.data)
        if not records:
            raise InputError(f"{args.data}/morph.jsonl holds no results")
        motion = read_motion(args.data)
        correspondence = read_correspondence(args.data)
        scrub = read_scrub(args.data)
        write_report(records, polygon_pairs, run, args.output, args.plots, motion, correspondence, scrub)
    except (InputError, KeyError) as error:
        print(f"error: make_benchmarks: incomplete benchmark data: {error}", file=sys.stderr)
        return 2
    print(f"wrote {args.output} and {args.plots}/*.svg")
    return 0


if __name__ == "__main__":
    sys.exit(main())
