"""Motion quality (issue 12): bench/motion_quality.py's motion.json."""

import json
import os
import shlex
import subprocess

from .common import COLORS, FixedLocator, InputError, NullFormatter, fmt_ms, plt, table
from .common import median as _median, optional_number as _num

# The repository's root (bench/benchmarks_md/ is two folders below it).
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
KIND_ORDER = ["glyph", "skeleton", "polygon", "triangulation", "special", "sample"]
REFERENCES = {"linear", "arap"}
DEFAULT_THRESHOLDS = {"edge_dev_median": 0.02, "edge_dev_p90": 0.08, "joint_dev_median_deg": 2.0, "min_size": 0.9,
                      "min_size_share": 0.9, "unevenness_median": 1.2, "unevenness_p90": 1.6, "beyond_max_deg": 45.0,
                      "self_turn_deg": 178.0, "self_turn_edge_dev": 0.01, "self_turn_min_size": 0.99}
METRIC_NAMES = {"edge_dev": "edge-length deviation", "joint_dev_deg": "joint-angle deviation",
                "min_size": "minimum size", "unevenness": "speed unevenness", "beyond_deg": "turning beyond the need"}


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
    # An earlier run on the same corpus, kept by hand as motion_before.json with a "label" (the
    # commit it measured): issue 30's table shows it as "before".
    before_path = os.path.join(data_dir, "motion_before.json")
    if os.path.exists(before_path):
        try:
            with open(before_path, encoding="utf-8") as f:
                motion["before"] = json.load(f)
            for key in ("methods", "pairs", "label"):
                motion["before"][key]  # noqa: B018 - only the KeyError matters
        except (OSError, ValueError, KeyError) as error:
            raise InputError(f"{before_path}: {error}") from error
    return motion


def motion_targets_met(motion):
    """'k of n' targets passed, per method."""
    return {m: f"{sum(1 for t in motion['targets'] if (t.get(m) or {}).get('pass') is True)}"
               f"/{len(motion['targets'])}" for m in motion["methods"]}


def _motion_rows(motion, method):
    """The per-pair results of one method that did not fail: (name, pair, result)."""
    return [(name, pair, pair[method]) for name, pair in motion["pairs"].items()
            if isinstance(pair.get(method), dict) and "error" not in pair[method]]



# Issue 30's targets for following the guide and for the triangulation's shape.
ISSUE30 = {"within": 0.005, "within_share": 0.95, "edge_dev_p90": 0.06, "angle_median_deg": 5.0,
           "angle_p10_deg": 1.0, "steiner_median": 0.5}


def _p(values, q):
    """The q-quantile as the report's tables take it: the value at rank floor(q n), or None."""
    values = sorted(values)
    return values[min(len(values) - 1, int(q * len(values)))] if values else None


def _guide_and_shape(motion, methods):
    """Issue 30: per method run by the CLI, how closely it follows the rigid motion on the
    figure's own edges (the `arap` reference) on the pairs where that motion stays valid, the
    share of frames that are the guide itself, and the shape of the compatible triangulation.
    Markdown blocks; empty when the run measured none of it."""
    def measured_in(run):
        return [m for m in run["methods"] if m not in REFERENCES
                and any("triangle_min_angle_deg" in r for _, _, r in _motion_rows(run, m))]
    measured = [(motion, m, f"**{m}**") for m in measured_in(motion) if m in methods]
    if not measured:
        return []
    before = motion.get("before")
    if before:
        measured = [(before, m, f"{m}, before (`{before['label']}`)") for m in measured_in(before)] + measured
    valid = {name for name, p in motion["pairs"].items()
             if isinstance(p.get("arap"), dict) and p["arap"].get("bad_frames") == []}
    rows = []
    for run, m, label in measured:
        results = _motion_rows(run, m)
        close = [name for name, p, r in results
                 if name in valid and r["edge_dev"] - p["arap"]["edge_dev"] <= ISSUE30["within"]]
        judged = [name for name, _, r in results if name in valid]
        angles = [r["triangle_min_angle_deg"] for _, _, r in results if "triangle_min_angle_deg" in r]
        steiner = [r["steiner_per_vertex"] for _, _, r in results if "steiner_per_vertex" in r]
        exact = [r["exact_frame_share"] for _, _, r in results if "exact_frame_share" in r]
        rows.append([label, f"{len(close)}/{len(judged)}" + (f" ({len(close) / len(judged):.0%})" if judged else ""),
                     _num(_p([r["edge_dev"] for _, _, r in results], 0.9), ".3f"),
                     _num(_median(exact), ".0%") if exact else "–",
                     _num(_median(angles), ".2f"), _num(_p(angles, 0.1), ".2f"), _num(min(angles), ".3f"),
                     _num(_median(steiner), ".2f")])
    rows.append(["*must show*", f"≥ {ISSUE30['within_share']:.0%}", f"≤ {ISSUE30['edge_dev_p90']:g}", "",
                 f"≥ {ISSUE30['angle_median_deg']:g}", f"≥ {ISSUE30['angle_p10_deg']:g}", "",
                 f"≤ {ISSUE30['steiner_median']:g}"])
    return ["### Following the guide, and the triangulation's shape (issue 30)\n",
            f"On the {len(valid)} pairs whose `arap` motion (rigid on the figure's own edges) is valid in every "
            f"frame: how many morphs stay within {ISSUE30['within']:g} edge-length deviation of it. Exact frames: "
            "the median share of interior frames that are the rigid guide itself (`stats.rigid.guide_frames`). "
            "The smallest angle, in degrees, over every triangle of the compatible triangulation the morph used, "
            "in both embeddings, per pair; Steiner vertices per figure vertex."
            + (f" The rows marked before are the same corpus measured at `{before['label']}` "
               "(`motion_before.json`, an earlier run kept for the comparison)." if before else "") + "\n",
            table(["method", f"within {ISSUE30['within']:g} of arap", "edge dev p90", "exact frames median",
                   "smallest angle ° median", "p10", "min", "Steiner / vertex median"], rows,
                  ["---"] + ["--:"] * 7),
            ""]


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

    # The issue's targets, pass or fail.
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

    md.extend(_guide_and_shape(motion, methods))

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
