#!/usr/bin/env python3
"""Measure local timing (issue 31): does the delayed limb lag the body by the overlap asked for?

    /usr/bin/python3 bench/local_timing.py CORPUS --build-dir build [--overlaps 0.3,0.5]
                     [--frames 61] [--json OUT.json] [--no-exact-check] [--filmstrips NAME,...]

CORPUS is a folder bench/local_timing_corpus.py wrote: skeleton pairs where the body bends while
one limb turns about its junction, the limb's vertices listed in manifest.json. For every pair the
CLI runs (`stickmorph morph SRC TGT -o OUT --frames 61`, the rigid method):

  plain      without --timing: today's morph
  d = 0      with `--timing FILE` of overlap 0 (weight 1 on the limb): must be the plain morph
             bit for bit (frames and times)
  d          with `--timing FILE` of each overlap asked (default 0.3 and 0.5), the corpus's timing
             file when it has one for d, else one written here from the manifest's limb vertices

and measures each run:

  half time  per edge, its direction's angle unwrapped over the frames, relative to frame 0; the
             edge's turn is that angle at the last frame; its half time the first time the angle
             reaches half of the turn (in the turn's direction), interpolated linearly between
             the two frames around it (the output's `times`). An edge that turns less than 5
             degrees in all has none (undefined, left out).
  lag        the median half time over the limb's edges (the manifest's limb_edges: every edge
             with an end on the limb, the junction's edge included) minus the median over the
             other edges that have one. Issue 31's must-show: lag - d within 0.1 for d = 0.3 and
             0.5. The plain run's lag (about 0) is reported as the baseline.
  valid      the CLI verifies every frame of the rigid morph in exact arithmetic and exits 2 on
             one that fails (a refusal is recorded as a failed run); every frame is also checked
             here, independently and exactly, by bench/multipart_check.py's Topology (a plane
             graph with the source's rotation system, outer faces and nesting); --no-exact-check
             skips that
  exact      frames[0] equal to the source's vertices and the last frame to the target's, bit
             for bit; d = 0 frames and times equal to the plain run's, bit for bit
  reference  for each d > 0 also the delayed motion as issue 31 states it, built here from the
             plain run's frames (reference_delayed: every edge's direction and length those of the
             plain morph at the edge's local time, the vertices fitted to them): its lag (d, up
             to the frames' resolution) and its invalid frames (the same exact check). Where the
             engine's lag falls short of d and the reference is valid at every frame, the engine
             gave way where the figure itself did not need it to.

It prints one row per pair and a summary per overlap (median and extreme |lag - d|, pairs within
0.1, bad frames, exactness), and writes everything to --json (the local_timing.json that
bench/make_benchmarks.py reads), with a few pairs' frames for the report's filmstrips (two small
pairs and the small pair whose lag misses the largest d by most, if one does). Exits 0
when it measured (whatever it found), 2 for a bad command line or corpus.
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import multipart_check as topo  # noqa: E402  (the exact validity of a frame, independent of the engine)

REPO = pathlib.Path(__file__).resolve().parents[1]
TIMEOUT_SECONDS = 600
DEFAULT_FRAMES = 61
MIN_TURN_DEG = 5.0
TOLERANCE = 0.1
FILMSTRIP_FRAMES = 8
FILMSTRIP_MAX_VERTICES = 120


def overlap_label(d):
    """0.3 -> "0.3", 0 -> "0": the key of an overlap in file names and JSON (as the corpus)."""
    return f"{float(d):g}"


# ---------------------------------------------------------------------------
# the measurement, on frames alone

def edge_turns(frames, edges):
    """Per frame and edge, the edge direction's angle in degrees relative to frame 0, unwrapped
    over the frames (frames: N x V x 2)."""
    frames = np.asarray(frames, dtype=float)
    e = np.asarray(edges, dtype=int).reshape(-1, 2)
    v = frames[:, e[:, 1]] - frames[:, e[:, 0]]
    angle = np.unwrap(np.arctan2(v[..., 1], v[..., 0]), axis=0)
    return np.degrees(angle - angle[0])


def half_times(frames, times, edges, min_turn=MIN_TURN_DEG):
    """(turn in degrees per edge, half time per edge, NaN where the turn is below min_turn)."""
    turns = edge_turns(frames, edges)
    times = np.asarray(times, dtype=float)
    total = turns[-1]
    half = np.full(len(total), np.nan)
    for k in np.nonzero(np.abs(total) >= min_turn)[0]:
        progress = turns[:, k] * np.sign(total[k])
        goal = abs(total[k]) / 2
        reached = np.nonzero(progress >= goal)[0]
        f = int(reached[0])  # the last frame reaches the whole turn, so there is one
        if f == 0:
            half[k] = times[0]
            continue
        a, b = progress[f - 1], progress[f]
        half[k] = times[f - 1] + (goal - a) / (b - a) * (times[f] - times[f - 1])
    return total, half


def lag(frames, times, edges, limb_edges, min_turn=MIN_TURN_DEG):
    """The lag of the limb behind the rest: median half time over the limb's edges minus the
    median over the other edges (each over the edges that turn by min_turn or more; None when
    either has none)."""
    total, half = half_times(frames, times, edges, min_turn)
    limb = set(int(k) for k in limb_edges)
    mine = [half[k] for k in range(len(half)) if k in limb and not math.isnan(half[k])]
    rest = [half[k] for k in range(len(half)) if k not in limb and not math.isnan(half[k])]
    out = {"limb_edges": len(limb), "limb_edges_measured": len(mine),
           "other_edges": len(half) - len(limb), "other_edges_measured": len(rest),
           "limb_half": float(np.median(mine)) if mine else None,
           "other_half": float(np.median(rest)) if rest else None,
           "limb_turn_deg": float(np.median([abs(total[k]) for k in limb])) if limb else None}
    out["lag"] = (out["limb_half"] - out["other_half"]) if mine and rest else None
    return out


def progress_curves(frames, edges, limb_edges, min_turn=MIN_TURN_DEG):
    """Per frame, the median over the limb's edges (and over the others) of the share of its turn
    the edge has made (edges that turn by min_turn or more): the report's progress plot."""
    turns = edge_turns(frames, edges)
    total = turns[-1]
    limb = set(int(k) for k in limb_edges)
    used = np.abs(total) >= min_turn
    share = np.where(used, turns / np.where(used, total, 1.0), np.nan)
    mine = [k for k in range(len(total)) if used[k] and k in limb]
    rest = [k for k in range(len(total)) if used[k] and k not in limb]
    return {"limb": np.median(share[:, mine], axis=1).round(4).tolist() if mine else None,
            "other": np.median(share[:, rest], axis=1).round(4).tolist() if rest else None}


def local_times(times, weights, overlap):
    """Issue 31's local time clamp((t - d w) / (1 - d), 0, 1), per time (rows) and vertex."""
    t = np.asarray(times, dtype=float)[:, None]
    w = np.asarray(weights, dtype=float)[None, :]
    return np.clip((t - overlap * w) / (1.0 - overlap), 0.0, 1.0)


def reference_delayed(plain_frames, plain_times, edges, weights, overlap):
    """The delayed motion as issue 31 states it, built here from the plain morph's frames: at
    every time of the plain run each edge has the direction and length the plain morph gives it
    at the edge's local time (the mean of its ends' local times; angles unwrapped, both
    interpolated linearly between the plain frames), and the vertices are the least-squares fit
    to those edge vectors with the plain frame's centroid. Not the engine's motion: the motion it
    would follow if nothing were in the way; its frames are checked like the engine's, so that a
    lag short of d can be told apart from a delayed motion that is itself invalid."""
    plain_frames = np.asarray(plain_frames, dtype=float)
    times = np.asarray(plain_times, dtype=float)
    e = np.asarray(edges, dtype=int).reshape(-1, 2)
    vec = plain_frames[:, e[:, 1]] - plain_frames[:, e[:, 0]]
    angle = np.unwrap(np.arctan2(vec[..., 1], vec[..., 0]), axis=0)
    length = np.linalg.norm(vec, axis=2)
    tau_v = local_times(times, weights, overlap)
    tau_e = (tau_v[:, e[:, 0]] + tau_v[:, e[:, 1]]) / 2
    n, count = plain_frames.shape[1], len(e)
    incidence = np.zeros((count + 1, n))
    incidence[np.arange(count), e[:, 1]] = 1.0
    incidence[np.arange(count), e[:, 0]] = -1.0
    incidence[count, :] = 1.0 / n  # the centroid
    solve = np.linalg.pinv(incidence)
    out = np.empty_like(plain_frames)
    for f in range(len(times)):
        a = np.array([np.interp(tau_e[f, k], times, angle[:, k]) for k in range(count)])
        r = np.array([np.interp(tau_e[f, k], times, length[:, k]) for k in range(count)])
        rhs = np.vstack([np.stack([r * np.cos(a), r * np.sin(a)], axis=1), plain_frames[f].mean(axis=0)])
        out[f] = solve @ rhs
    return out


# ---------------------------------------------------------------------------
# running the CLI

def read_figure(path):
    doc = json.loads(pathlib.Path(path).read_text())
    return np.asarray(doc["vertices"], dtype=float).reshape(-1, 2), [tuple(e) for e in doc["edges"]]


def run_morph(cli, src, tgt, out, frames, timing=None):
    """(frames, times, stats, seconds), or raises RuntimeError with the CLI's error line."""
    cmd = [str(cli), "morph", str(src), str(tgt), "-o", str(out), "--frames", str(frames)]
    if timing is not None:
        cmd += ["--timing", str(timing)]
    start = time.monotonic()
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    seconds = time.monotonic() - start
    if r.returncode != 0:
        raise RuntimeError(f"exit {r.returncode}: " + (r.stderr.strip().splitlines() or [""])[0])
    doc = json.loads(pathlib.Path(out).read_text())
    return (np.asarray(doc["frames"], dtype=float), np.asarray(doc["times"], dtype=float), doc.get("stats", {}),
            seconds)


def timing_file(corpus, entry, d, tmp):
    """The corpus's timing file for overlap d, or one written into tmp from the limb's vertices."""
    listed = (entry.get("timing") or {}).get(overlap_label(d))
    if listed and (corpus / listed).exists():
        return corpus / listed
    weights = [0.0] * entry["vertices"]
    for v in entry["limb_vertices"]:
        weights[v] = 1.0
    path = pathlib.Path(tmp) / f"{entry['name']}.timing_{overlap_label(d)}.json"
    path.write_text(json.dumps({"delay": weights, "overlap": float(d)}) + "\n")
    return path


def check_frames(topology, frames):
    """Frames that the independent exact check refuses, with the first reason."""
    bad, why = [], None
    for f in range(len(frames)):
        problems = topology.frame_problems(frames[f], limit=1)
        if problems:
            bad.append(f)
            why = why or f"frame {f}: {problems[0]}"
    return bad, why


def measure_run(frames, times, stats, seconds, src, tgt, edges, limb_edges, topology):
    row = {"seconds": round(seconds, 3), "first_exact": bool(np.array_equal(frames[0], src)),
           "last_exact": bool(np.array_equal(frames[-1], tgt)), "verified": stats.get("verified", True),
           "guide_frames": (stats.get("rigid") or {}).get("guide_frames")}
    if "timing" in stats:
        row["stats_timing"] = stats["timing"]
    row.update(lag(frames, times, edges, limb_edges))
    if topology is not None:
        row["bad_frames"], why = check_frames(topology, frames)
        if why:
            row["bad_frame_reason"] = why
    return row


def filmstrip(frames, count=FILMSTRIP_FRAMES):
    index = np.linspace(0, len(frames) - 1, count).round().astype(int).tolist()
    return index, [np.round(frames[f], 5).tolist() for f in index]


def measure_pair(cli, corpus, entry, overlaps, frame_count, exact_check, keep_strip, tmp):
    src_path, tgt_path = corpus / entry["source"], corpus / entry["target"]
    src, edges = read_figure(src_path)
    tgt, _ = read_figure(tgt_path)
    limb_edges = entry["limb_edges"]
    topology = topo.Topology(src, edges) if exact_check else None
    pair = {"name": entry["name"], "kind": entry["kind"], "vertices": len(src), "edges": len(edges),
            "limb": entry.get("limb"), "turn_deg": entry.get("turn_deg"), "bend_deg": entry.get("bend_deg"),
            "limb_edge_count": len(limb_edges), "delayed_clear": entry.get("delayed_clear", {}), "runs": {}}
    out = pathlib.Path(tmp) / "out.json"
    plain = None
    try:
        plain = run_morph(cli, src_path, tgt_path, out, frame_count)
        pair["runs"]["plain"] = measure_run(*plain, src, tgt, edges, limb_edges, topology)
    except (RuntimeError, subprocess.TimeoutExpired) as error:
        pair["runs"]["plain"] = {"error": str(error)}
    strips = {}
    if keep_strip and plain is not None:
        strips["plain"] = plain[0]
    for d in [0.0] + [d for d in overlaps if d != 0.0]:
        label = overlap_label(d)
        try:
            run = run_morph(cli, src_path, tgt_path, out, frame_count, timing_file(corpus, entry, d, tmp))
        except (RuntimeError, subprocess.TimeoutExpired) as error:
            pair["runs"][label] = {"error": str(error)}
            continue
        row = measure_run(*run, src, tgt, edges, limb_edges, topology)
        if row["lag"] is not None:
            row["lag_error"] = row["lag"] - d
        if plain is not None and d > 0.0:
            weights = np.zeros(len(src))
            weights[list(entry["limb_vertices"])] = 1.0
            reference = reference_delayed(plain[0], plain[1], edges, weights, d)
            row["reference_lag"] = lag(reference, plain[1], edges, limb_edges)["lag"]
            # how far the engine's frames are from it: the largest vertex distance over the frames,
            # over the figure's size (the diagonal of the source's bounding box)
            size = float(np.hypot(*np.ptp(src, axis=0))) or 1.0
            if len(run[0]) == len(reference):
                row["reference_departure"] = float(np.abs(run[0] - reference).max() / size)
            if topology is not None:
                row["reference_bad_frames"], _ = check_frames(topology, reference)
        if plain is not None:
            row["same_as_plain"] = bool(np.array_equal(run[0], plain[0]) and np.array_equal(run[1], plain[1]))
        pair["runs"][label] = row
        if keep_strip:
            strips[label] = run[0]
    if keep_strip and strips:
        frames_any = next(iter(strips.values()))
        index, _ = filmstrip(frames_any)
        pair["filmstrip"] = {"edges": [list(e) for e in edges], "limb_edges": list(limb_edges),
                             "frame_indices": index, "frames": len(frames_any),
                             "rows": {k: filmstrip(v)[1] for k, v in strips.items()},
                             "progress": {k: progress_curves(v, edges, limb_edges) for k, v in strips.items()}}
    return pair


# ---------------------------------------------------------------------------
# summary and printing

def percentile(values, q):
    return float(np.percentile(values, q)) if values else None


def summarize(pairs, overlaps):
    """Per overlap (and the plain run, "plain"): counts, lag statistics, validity, exactness."""
    out = {}
    for label in ["plain", "0"] + [overlap_label(d) for d in overlaps if d != 0.0]:
        d = 0.0 if label == "plain" else float(label)
        runs = [(p, p["runs"].get(label)) for p in pairs if p["runs"].get(label) is not None]
        done = [(p, r) for p, r in runs if "error" not in r]
        lags = [r["lag"] for _, r in done if r.get("lag") is not None]
        errors = [abs(x - d) for x in lags]
        s = {"overlap": d, "pairs": len(runs), "failed": len(runs) - len(done), "measured": len(lags),
             "failures": [f"{p['name']}: {r['error']}" for p, r in runs if "error" in r][:20],
             "lag_median": percentile(lags, 50), "lag_p10": percentile(lags, 10), "lag_p90": percentile(lags, 90),
             "abs_error_median": percentile(errors, 50), "abs_error_max": max(errors) if errors else None,
             "within": sum(1 for e in errors if e <= TOLERANCE),
             "bad_frames": sum(len(r.get("bad_frames", [])) for _, r in done),
             "pairs_with_bad_frames": sum(1 for _, r in done if r.get("bad_frames")),
             "frames_checked": sum(1 for _, r in done if "bad_frames" in r),
             "first_last_exact": sum(1 for _, r in done if r["first_exact"] and r["last_exact"]),
             "misses": [{"name": p["name"], "lag": r["lag"], "limb": p.get("limb"),
                         "reference_lag": r.get("reference_lag"),
                         "reference_valid": (not r["reference_bad_frames"]) if "reference_bad_frames" in r else None,
                         "guide_frames": r.get("guide_frames")}
                        for p, r in done if r.get("lag") is not None and abs(r["lag"] - d) > TOLERANCE]}
        if label != "plain":
            s["same_as_plain"] = sum(1 for _, r in done if r.get("same_as_plain"))
            s["compared_with_plain"] = sum(1 for _, r in done if "same_as_plain" in r)
            clear = [abs(r["lag"] - d) for p, r in done if r.get("lag") is not None
                     and p["delayed_clear"].get(label, True)]
            s["clear_pairs"] = len(clear)
            s["clear_within"] = sum(1 for e in clear if e <= TOLERANCE)
        if label not in ("plain", "0"):
            reference = [r["reference_lag"] for _, r in done if r.get("reference_lag") is not None]
            s["reference_measured"] = len(reference)
            s["reference_lag_median"] = percentile(reference, 50)
            s["reference_within"] = sum(1 for x in reference if abs(x - d) <= TOLERANCE)
            s["reference_bad_frames"] = sum(len(r.get("reference_bad_frames", [])) for _, r in done)
            s["reference_pairs_with_bad_frames"] = sum(1 for _, r in done if r.get("reference_bad_frames"))
            s["reference_checked"] = sum(1 for _, r in done if "reference_bad_frames" in r)
        out[label] = s
    return out


def fmt(value, spec="{:.3f}"):
    return "-" if value is None else spec.format(value)


def print_report(pairs, summary, overlaps, stream=sys.stdout):
    labels = ["plain", "0"] + [overlap_label(d) for d in overlaps if d != 0.0]
    print("| pair | V | limb | turn | " + " | ".join(f"lag {x}" for x in labels) + " | bad frames | exact |",
          file=stream)
    print("|---|--:|---|--:|" + "--:|" * len(labels) + "--:|---|", file=stream)
    for p in pairs:
        cells, bad, exact = [], 0, []
        for label in labels:
            r = p["runs"].get(label, {})
            if "error" in r:
                cells.append("FAILED")
                continue
            cells.append(fmt(r.get("lag")))
            bad += len(r.get("bad_frames", []))
            if r and not (r["first_exact"] and r["last_exact"]):
                exact.append(f"{label}: ends not exact")
            if label == "0" and r and r.get("same_as_plain") is False:
                exact.append("d=0 differs from plain")
        print(f"| {p['name']} | {p['vertices']} | {p['limb']} | {fmt(p['turn_deg'], '{:+.0f}')} | "
              + " | ".join(cells) + f" | {bad} | {'; '.join(exact) or 'yes'} |", file=stream)
    print("", file=stream)
    for label in labels:
        s = summary[label]
        name = "plain (no --timing)" if label == "plain" else f"d = {label}"
        line = (f"{name:20s} {s['measured']}/{s['pairs']} measured, {s['failed']} failed; lag median "
                f"{fmt(s['lag_median'])} (P10 {fmt(s['lag_p10'])}, P90 {fmt(s['lag_p90'])}); |lag - d| median "
                f"{fmt(s['abs_error_median'])}, max {fmt(s['abs_error_max'])}; within {TOLERANCE}: {s['within']}/"
                f"{s['measured']}; bad frames {s['bad_frames']} (in {s['pairs_with_bad_frames']} pairs, "
                f"{s['frames_checked']} runs checked); first/last exact {s['first_last_exact']}")
        if label != "plain":
            line += (f"; same as plain {s['same_as_plain']}/{s['compared_with_plain']}; delayed path clear: "
                     f"within {s['clear_within']}/{s['clear_pairs']}")
        if "reference_measured" in s:
            line += (f"; reference (issue 31's delayed motion from the plain frames): lag median "
                     f"{fmt(s['reference_lag_median'])}, within {s['reference_within']}/{s['reference_measured']}, "
                     + (f"invalid frames {s['reference_bad_frames']} (in {s['reference_pairs_with_bad_frames']} pairs)"
                        if s["reference_checked"] else "frames not checked"))
        print(line, file=stream)
        for m in s["misses"] if label not in ("plain", "0") else []:
            valid = {True: "valid", False: "INVALID", None: "not checked"}[m["reference_valid"]]
            guide = m.get("guide_frames") or {}
            print(f"    misses: {m['name']} (limb {m['limb']}): lag {m['lag']:.3f}; the reference: lag "
                  f"{fmt(m['reference_lag'])}, {valid}; the morph's interior frames: {guide.get('exact', '?')} on its "
                  f"guide, {guide.get('blended', '?')} blended", file=stream)
        for f in s["failures"]:
            print(f"    failed: {f}", file=stream)


def pick_filmstrips(entries, names, count=2):
    """The pairs whose frames go to the report: those named, else the first small humanoid (or
    stick man) and the first small quadruped (or lizard, or tree)."""
    if names:
        return list(names)
    chosen = []
    for kinds in (("humanoid", "stickman"), ("quadruped", "lizard", "tree")):
        for e in entries:
            if e["kind"] in kinds and e["vertices"] <= FILMSTRIP_MAX_VERTICES and e["name"] not in chosen:
                chosen.append(e["name"])
                break
    return chosen[:count]


def worst_miss(pairs, overlaps):
    """The small pair whose lag misses the largest overlap by most (more than the tolerance), or
    None: its filmstrip shows the report where the morph gave way."""
    if not overlaps:
        return None
    label = overlap_label(max(overlaps))
    worst, name = TOLERANCE, None
    for p in pairs:
        r = p["runs"].get(label) or {}
        if p["vertices"] <= FILMSTRIP_MAX_VERTICES and r.get("lag") is not None and abs(r["lag"] - float(label)) > worst:
            worst, name = abs(r["lag"] - float(label)), p["name"]
    return name


def build_source(build_dir):
    """What the CLI was built from: the build's source folder (its CMakeCache.txt), that
    folder's commit and whether its engine (native/) had uncommitted changes; None where unknown."""
    try:
        cache = (pathlib.Path(build_dir) / "CMakeCache.txt").read_text()
        source = next(line.split("=", 1)[1] for line in cache.splitlines()
                      if line.startswith("CMAKE_HOME_DIRECTORY:"))
        commit = subprocess.run(["git", "-C", source, "rev-parse", "--short=12", "HEAD"], capture_output=True,
                                text=True, check=True).stdout.strip()
        status = subprocess.run(["git", "-C", source, "status", "--porcelain", "--untracked-files=no", "--",
                                 "native"], capture_output=True, text=True, check=True).stdout
    except (OSError, StopIteration, subprocess.CalledProcessError):
        return None
    return {"commit": commit, "uncommitted_native": bool(status.strip())}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("corpus", type=pathlib.Path, help="folder with manifest.json (bench/local_timing_corpus.py)")
    ap.add_argument("--build-dir", type=pathlib.Path, default=REPO / "build")
    ap.add_argument("--overlaps", default="0.3,0.5", help="overlaps to measure (default 0.3,0.5); 0 always runs")
    ap.add_argument("--frames", type=int, default=DEFAULT_FRAMES, help=f"frames per morph (default {DEFAULT_FRAMES})")
    ap.add_argument("--json", type=pathlib.Path, help="write the results here")
    ap.add_argument("--no-exact-check", action="store_true",
                    help="skip the independent exact check of every frame (the CLI still verifies them)")
    ap.add_argument("--filmstrips", default="",
                    help="pairs whose frames the JSON keeps (default: two small ones and the worst small miss)")
    ap.add_argument("--only", action="append", help="measure only this pair (repeatable)")
    args = ap.parse_args(argv)
    cli = args.build_dir / "stickmorph"
    manifest_path = args.corpus / "manifest.json"
    for path in (cli, manifest_path):
        if not path.exists():
            print(f"error: {path} does not exist", file=sys.stderr)
            return 2
    try:
        overlaps = sorted({float(x) for x in args.overlaps.split(",") if x.strip()})
    except ValueError:
        print(f"error: --overlaps {args.overlaps!r}: expected numbers like 0.3,0.5", file=sys.stderr)
        return 2
    if any(not 0.0 <= d < 1.0 for d in overlaps) or args.frames < 3:
        print("error: every overlap must be in [0, 1) and --frames at least 3", file=sys.stderr)
        return 2
    manifest = json.loads(manifest_path.read_text())
    entries = [e for e in manifest["pairs"] if not args.only or e["name"] in args.only]
    strips = pick_filmstrips(entries, [n for n in args.filmstrips.split(",") if n])
    help_text = subprocess.run([str(cli), "morph", "--help"], capture_output=True, text=True).stdout
    pairs = []
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="local_timing_") as tmp:
        for entry in entries:
            keep = entry["name"] in strips or (not args.filmstrips and entry["vertices"] <= FILMSTRIP_MAX_VERTICES)
            pair = measure_pair(cli, args.corpus, entry, overlaps, args.frames, not args.no_exact_check, keep, tmp)
            pairs.append(pair)
            print(f"{entry['name']}: " + ", ".join(
                f"{k} " + ("FAILED" if "error" in r else f"lag {fmt(r.get('lag'))}") for k, r in pair["runs"].items()),
                file=sys.stderr)
    # Frames are kept for the pairs picked and, unless pairs were named, for the worst miss too.
    miss = None if args.filmstrips else worst_miss(pairs, overlaps)
    for p in pairs:
        if p.get("filmstrip") and p["name"] not in strips and p["name"] != miss:
            del p["filmstrip"]
        elif p.get("filmstrip"):
            p["filmstrip"]["why"] = "picked" if p["name"] in strips else "worst miss"
    pairs_order = {name: i for i, name in enumerate(strips + ([miss] if miss else []))}
    summary = summarize(pairs, overlaps)
    print_report(pairs, summary, overlaps)
    if args.json:
        doc = {"command": "/usr/bin/python3 bench/local_timing.py " + " ".join(argv if argv is not None else sys.argv[1:]),
               "build": build_source(args.build_dir),
               "corpus": str(args.corpus), "seed": manifest.get("seed"), "frames": args.frames,
               "overlaps": overlaps, "tolerance": TOLERANCE, "min_turn_deg": MIN_TURN_DEG,
               "timing_in_help": "--timing" in help_text, "exact_check": not args.no_exact_check,
               "seconds": round(time.monotonic() - started, 1), "summary": summary, "pairs": pairs,
               "filmstrips": sorted((p["name"] for p in pairs if p.get("filmstrip")), key=pairs_order.get)}
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(json.dumps(doc, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
