"""Shared by every section of BENCHMARKS.md: matplotlib set-up, constants, reading the
raw output, the cells of morph.jsonl, number formats, Markdown tables and log-log plots."""

import json
import math
import os
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


def median(values):
    """The median of the values that are not None, or None when there are none."""
    values = sorted(v for v in values if v is not None)
    if not values:
        return None
    mid = len(values) // 2
    return values[mid] if len(values) % 2 else (values[mid - 1] + values[mid]) / 2


def optional_number(value, spec=".3f"):
    """A number for a table cell, an en dash for None."""
    return "–" if value is None else format(value, spec)


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
