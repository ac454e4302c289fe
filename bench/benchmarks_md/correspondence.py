"""Correspondence (issue 13): stickmorph_benchmark_correspondence's correspondence.json."""

import json
import os

from .common import COLORS, FIT_MIN_N, InputError, fit_exponent, fmt_exponent, fmt_int, fmt_ms, loglog_svg, table


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
