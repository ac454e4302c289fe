"""Steiner vertices per method (Algorithm 3, the three triangulation methods) and the
polygon-pair corpus (section 4 alone)."""

import os

from .common import COLORS, DASHES, METHODS, fmt_int, fmt_ms, fmt_ratio, loglog_svg, table


def steiner_section(cells, families, sizes, run, plot_dir, plot_rel):
    """Steiner vertices of every case and method, with the plot steiner.svg."""
    md = []
    add = md.append

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
    return md


def polygon_pairs_section(polygon_pairs):
    """Section 4 alone on the polygon pairs of tests/data/polygon_pairs."""
    md = []
    add = md.append

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
    return md
