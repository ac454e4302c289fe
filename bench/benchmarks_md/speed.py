"""Speed (issue 15): a frame against a fresh LU, scrubbing, the total's growth."""

from .common import (FIT_MIN_N, FRAME_LU_N, FRAME_LU_TARGET, SCRUB_FPS_N, SCRUB_FPS_TARGET, TOTAL_EXPONENT_TARGET,
                     TOTAL_FIT_MAX_N, fit_exponent, fmt_int, fmt_ms, fmt_ratio, improved_cells, table)


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
