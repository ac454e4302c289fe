#!/usr/bin/env python3
"""Measure how natural a morph looks, on every pair of a corpus folder (issue 12).

    /usr/bin/python3 bench/motion_quality.py out/motion_corpus --build-dir build \
        [--frames 30] [--ours-args "--weights uniform"] [--json FILE] [--filmstrip DIR]
    /usr/bin/python3 bench/motion_quality.py out/motion_corpus --build-dir build \
        --cli-method rigid="--method rigid" --cli-method barycentric="--method barycentric"

For every pair (NAME.source.json / NAME.target.json, as bench/motion_corpus.py writes
them) it runs `stickmorph morph` (our morph, the CLI's default method, once per --weights
kind, with --ours-args passed through; or, with --cli-method LABEL=ARGS, once per such
labelled variant), `stickmorph morph --method linear` (straight lines) and an
as-rigid-as-possible reference computed here (ARAP on the figure's own edges), and
measures each morph: edge-length deviation, joint-angle deviation, minimum size, speed
unevenness, turning beyond the needed rotation, frames that are not valid stick figures
compatible with the source, and the CLI's own time per frame. docs/MOTION.md defines
every number; the metric functions below are the definitions.

It prints Markdown: one row per pair and method, then per-method medians and 90th
percentiles, then the issue's targets as pass/fail per method.
"""
import argparse
import json
import math
import os
import pathlib
import shlex
import subprocess
import sys
import tempfile
import time

import numpy as np

REPO = pathlib.Path(__file__).resolve().parents[1]
TIMEOUT_SECONDS = 300

# Issue 12's targets (docs/MOTION.md restates them).
EDGE_MEDIAN, EDGE_P90 = 0.02, 0.08
JOINT_MEDIAN_DEG = 2.0
MIN_SIZE, MIN_SIZE_SHARE = 0.9, 0.9
UNEVEN_MEDIAN, UNEVEN_P90 = 1.2, 1.6
BEYOND_MAX_DEG = 45.0
SELF_TURN_DEG, SELF_TURN_EDGE, SELF_TURN_SIZE = 178.0, 0.01, 0.99
THRESHOLDS = {"edge_dev_median": EDGE_MEDIAN, "edge_dev_p90": EDGE_P90, "joint_dev_median_deg": JOINT_MEDIAN_DEG,
              "min_size": MIN_SIZE, "min_size_share": MIN_SIZE_SHARE, "unevenness_median": UNEVEN_MEDIAN,
              "unevenness_p90": UNEVEN_P90, "beyond_max_deg": BEYOND_MAX_DEG, "self_turn_deg": SELF_TURN_DEG,
              "self_turn_edge_dev": SELF_TURN_EDGE, "self_turn_min_size": SELF_TURN_SIZE}
# keys of the JSON's per-pair and per-target objects, next to the method labels
RESERVED_LABELS = {"kind", "vertices", "tags", "target", "key"}
# The metrics a filmstrip can be the worst pair of, and which end is bad (+1: the largest)
WORST_KEYS = [("edge_dev", 1), ("joint_dev_deg", 1), ("min_size", -1), ("unevenness", 1), ("beyond_deg", 1)]
WORST_NAMES = {"edge_dev": "edge-length deviation", "joint_dev_deg": "joint-angle deviation",
               "min_size": "minimum size", "unevenness": "speed unevenness", "beyond_deg": "turning beyond the need"}


# ---------------------------------------------------------------------------
# metrics: frames is an (N, n, 2) array, times the N values of t from 0 to 1

def _interior(frames):
    """Interior frames only: the first and last are the source and target themselves, so
    they deviate by nothing and would dilute every average."""
    return slice(1, max(1, len(frames) - 1))


def edge_lengths(frames, edges):
    e = np.asarray(edges, dtype=int).reshape(-1, 2)
    return np.linalg.norm(frames[:, e[:, 1]] - frames[:, e[:, 0]], axis=2)  # (N, m)


def edge_length_deviation(frames, edges, times):
    """Mean over edges and interior frames of |L(t) - ((1-t)L0 + tL1)| / max(L0, L1): how far
    the edges stretch away from changing their length linearly."""
    if len(edges) == 0 or len(frames) < 3:
        return 0.0
    lengths = edge_lengths(frames, edges)
    t = np.asarray(times)[:, None]
    linear = (1 - t) * lengths[0] + t * lengths[-1]
    dev = np.abs(lengths - linear) / np.maximum(lengths[0], lengths[-1])
    return float(dev[_interior(frames)].mean())


def joint_angles(points, edges):
    """The joints: (vertex, neighbour a, neighbour b) for every two consecutive edges around a
    vertex of degree >= 2, in counter-clockwise order in `points` (the source). A vertex of
    degree d has d of them (degree 2: the angle on each side)."""
    nbrs = {}
    for i, j in edges:
        nbrs.setdefault(i, []).append(j)
        nbrs.setdefault(j, []).append(i)
    out = []
    for v, ns in sorted(nbrs.items()):
        if len(ns) < 2:
            continue
        ns = sorted(ns, key=lambda u: math.atan2(points[u][1] - points[v][1], points[u][0] - points[v][0]))
        out += [(v, ns[k], ns[(k + 1) % len(ns)]) for k in range(len(ns))]
    return np.asarray(out, dtype=int).reshape(-1, 3)


def _ccw_angle(frames, joints):
    """Counter-clockwise angle from edge (v, a) to edge (v, b), in [0, 2pi), per frame."""
    u = frames[:, joints[:, 1]] - frames[:, joints[:, 0]]
    w = frames[:, joints[:, 2]] - frames[:, joints[:, 0]]
    cross = u[..., 0] * w[..., 1] - u[..., 1] * w[..., 0]
    dot = (u * w).sum(axis=2)
    return np.mod(np.arctan2(cross, dot), 2 * np.pi)


def _wrap(a):
    """Angle(s) into (-pi, pi]."""
    return np.pi - np.mod(np.pi - np.asarray(a, dtype=float), 2 * np.pi)


def joint_angle_deviation(frames, edges, times):
    """Mean over joints and interior frames, in degrees, of how far the angle between two
    consecutive edges at a vertex is from its linear interpolation. Both end angles are in
    (0, 360) in the same rotation order (the pair is compatible), so the linear interpolation
    is the way that never folds the two edges onto each other; the difference is taken the
    short way, so a frame whose edges did swap order still counts a bounded error."""
    joints = joint_angles(frames[0], edges)
    if len(joints) == 0 or len(frames) < 3:
        return 0.0
    ang = _ccw_angle(frames, joints)
    t = np.asarray(times)[:, None]
    linear = (1 - t) * ang[0] + t * ang[-1]
    dev = np.abs(_wrap(ang - linear))
    return float(np.degrees(dev[_interior(frames)].mean()))


def rms_radius(frames):
    c = frames.mean(axis=1, keepdims=True)
    return np.sqrt(((frames - c) ** 2).sum(axis=2).mean(axis=1))


def min_size(frames, times):
    """Minimum over frames of the RMS radius about the centroid divided by its linear
    interpolation between the two ends' RMS radii: below 1 the figure shrinks on the way
    (the collapse the issue saw: 0.77 in a self-turn)."""
    r = rms_radius(frames)
    t = np.asarray(times)
    linear = (1 - t) * r[0] + t * r[-1]
    if linear.min() <= 0:
        return 1.0  # a single vertex has no size to lose
    return float((r / linear).min())


def steps(frames):
    """RMS vertex displacement between consecutive frames."""
    return np.sqrt(((frames[1:] - frames[:-1]) ** 2).sum(axis=2).mean(axis=1))


def speed_unevenness(frames):
    """Largest step over the mean step: 1 for constant speed (times are equally spaced). A
    morph whose motion bunches into its first or last step scores high."""
    s = steps(frames)
    if len(s) == 0 or s.mean() <= 1e-300:
        return 1.0  # nothing moves: no unevenness
    return float(s.max() / s.mean())


def procrustes_angle(a, b):
    """The rotation angle (radians, in (-pi, pi]) that best maps a onto b after both are
    centred (least squares; a uniform scale does not change the best angle)."""
    a = a - a.mean(axis=0)
    b = b - b.mean(axis=0)
    cross = float((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]).sum())
    dot = float((a * b).sum())
    return math.atan2(cross, dot)


def turning(frames):
    """Rotation the eye sees: the best-fit (Procrustes) rotation from each frame to the next,
    accumulated over the frames (the angle track, unwrapped by construction since each step
    is taken the short way). Returns degrees:
      net     the accumulated angle at the end (signed),
      path    the sum of |steps| (a turn there and back counts both ways),
      needed  the Procrustes rotation from source to target, the short way,
      beyond  path - |needed|: turning that the pair did not ask for.
    Accumulating steps rather than taking each frame's angle relative to frame 0 matters for
    a deforming figure: the end angle relative to frame 0 is the needed one by definition,
    so a self-turn by 180 degrees would always "turn 180" however much of the way it got
    there by collapsing and re-growing instead of turning."""
    inc = np.array([procrustes_angle(frames[k], frames[k + 1]) for k in range(len(frames) - 1)])
    needed = procrustes_angle(frames[0], frames[-1])
    net = float(inc.sum()) if len(inc) else 0.0
    path = float(np.abs(inc).sum()) if len(inc) else 0.0
    return {"net": math.degrees(net), "path": math.degrees(path), "needed": math.degrees(needed),
            "beyond": math.degrees(path - abs(needed)), "track": np.degrees(np.cumsum(inc)).tolist()}


def measure(frames, edges, times):
    frames = np.asarray(frames, dtype=float)
    turn = turning(frames)
    return {"edge_dev": edge_length_deviation(frames, edges, times),
            "joint_dev_deg": joint_angle_deviation(frames, edges, times),
            "min_size": min_size(frames, times),
            "unevenness": speed_unevenness(frames),
            "turn_deg": turn["net"], "turn_path_deg": turn["path"], "needed_deg": turn["needed"],
            "beyond_deg": turn["beyond"],
            "series": {"steps": steps(frames).tolist(), "rms_radius": rms_radius(frames).tolist(),
                       "angle_track_deg": turn["track"]}}


# ---------------------------------------------------------------------------
# the ARAP reference

def arap_frames(src, tgt, edges, times):
    """As-rigid-as-possible interpolation on the figure's own edges: every edge vector turns
    by its own rotation (taken within 180 degrees of the figure's Procrustes rotation, so all
    edges of a figure turned by 180 degrees turn the same way) while its length changes
    linearly; each frame's vertices are the least-squares fit to those edge vectors (exact on
    a tree), with the centroid moving on a straight line. Nothing keeps it from
    self-intersecting, which is what it is measured for."""
    src = np.asarray(src, dtype=float)
    tgt = np.asarray(tgt, dtype=float)
    n = len(src)
    e = np.asarray(edges, dtype=int).reshape(-1, 2)
    times = np.asarray(times, dtype=float)
    c0, c1 = src.mean(axis=0), tgt.mean(axis=0)
    out = np.empty((len(times), n, 2))
    if len(e) == 0:
        for k, t in enumerate(times):
            out[k] = src + t * (c1 - c0)
    else:
        d0 = src[e[:, 1]] - src[e[:, 0]]
        d1 = tgt[e[:, 1]] - tgt[e[:, 0]]
        a0 = np.arctan2(d0[:, 1], d0[:, 0])
        a1 = np.arctan2(d1[:, 1], d1[:, 0])
        whole = procrustes_angle(src, tgt)
        turn = whole + _wrap(a1 - a0 - whole)
        l0, l1 = np.linalg.norm(d0, axis=1), np.linalg.norm(d1, axis=1)
        incidence = np.zeros((len(e), n))
        incidence[np.arange(len(e)), e[:, 0]] = -1
        incidence[np.arange(len(e)), e[:, 1]] = 1
        # minimum-norm least squares: for a connected figure its solution has mean 0, so
        # adding the centroid places it
        pinv = np.linalg.pinv(incidence)
        for k, t in enumerate(times):
            ang = a0 + t * turn
            length = (1 - t) * l0 + t * l1
            d = np.stack([length * np.cos(ang), length * np.sin(ang)], axis=1)
            out[k] = pinv @ d + ((1 - t) * c0 + t * c1)
    out[0], out[-1] = src, tgt  # exactly, as the engine's frames are
    return out


# ---------------------------------------------------------------------------
# running the engine

def read_figure(path):
    doc = json.loads(pathlib.Path(path).read_text())
    return np.asarray(doc["vertices"], dtype=float).reshape(-1, 2), [tuple(x) for x in doc["edges"]]


def write_figure(path, points, edges, name="frame"):
    doc = {"name": name, "vertices": [[float(x), float(y)] for x, y in points],
           "edges": [[int(i), int(j)] for i, j in edges]}
    pathlib.Path(path).write_text(json.dumps(doc))


def run_morph(cli, src, tgt, out, frames, extra):
    """Returns (frames, times, stats) or raises RuntimeError with the CLI's error line."""
    cmd = [str(cli), "morph", str(src), str(tgt), "-o", str(out), "--frames", str(frames)] + list(extra)
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    if r.returncode != 0:
        raise RuntimeError((r.stderr.strip() or f"exit {r.returncode}") + " [" + " ".join(cmd[1:]) + "]")
    doc = json.loads(pathlib.Path(out).read_text())
    stats = dict(doc.get("stats", {}))
    stats["_shape"] = triangulation_shape(doc)
    return np.asarray(doc["frames"], dtype=float), np.asarray(doc["times"], dtype=float), stats


def triangulation_shape(doc):
    """Issue 30's shape of the compatible triangulation a morph used (the output's
    "triangulation"; a key-pose output's "triangulations" are all taken): the smallest angle in
    degrees over every triangle in both embeddings, and Steiner vertices per figure vertex.
    None when the output has no triangulation (the straight-line morph's is null)."""
    triangulations = [t for t in (doc.get("triangulations") or [doc.get("triangulation")])
                      if isinstance(t, dict) and t.get("triangles")]
    if not triangulations:
        return None
    least, steiner = 180.0, 0.0
    for tri in triangulations:
        triangles = np.asarray(tri["triangles"], dtype=int)
        for embedding in ("source", "target"):
            p = np.asarray(tri[embedding], dtype=float)[triangles]  # #T by 3 by 2
            for j in range(3):
                u = p[:, (j + 1) % 3] - p[:, j]
                v = p[:, (j + 2) % 3] - p[:, j]
                cross = np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
                dot = u[:, 0] * v[:, 0] + u[:, 1] * v[:, 1]
                least = min(least, float(np.degrees(np.arctan2(cross, dot)).min()))
        steiner = max(steiner, tri["steiner_vertices"] / max(1, tri["figure_vertices"]))
    return {"min_angle_deg": least, "steiner_per_vertex": steiner}


def bad_frames(cli, src_path, frames, edges, tmp):
    """Interior frames that are not stick figures compatible with the source, decided by the
    engine's own exact test: `stickmorph check SRC FRAME` exits 1 (incompatible: an edge
    order or the outside changed) or 2 (not a figure: edges cross, vertices coincide)."""
    bad = []
    frame_path = pathlib.Path(tmp) / "frame.json"
    for k in range(1, len(frames) - 1):
        write_figure(frame_path, frames[k], edges)
        r = subprocess.run([str(cli), "check", str(src_path), str(frame_path)], capture_output=True,
                           text=True, timeout=TIMEOUT_SECONDS)
        if r.returncode != 0:
            bad.append(k)
    return bad


def corpus_pairs(folder):
    """(name, kind, tags) of every pair in the folder, in manifest order when there is one."""
    folder = pathlib.Path(folder)
    manifest = folder / "manifest.json"
    if manifest.exists():
        pairs = json.loads(manifest.read_text())["pairs"]
        listed = [(p["name"], p.get("kind", ""), p) for p in pairs]
        if all((folder / f"{name}.source.json").exists() for name, _, _ in listed):
            return listed
    names = sorted(p.name[:-len(".source.json")] for p in folder.glob("*.source.json")
                   if (folder / p.name.replace(".source.json", ".target.json")).exists())
    return [(name, name.split("_")[0], {}) for name in names]


def self_turn_180(name, tags):
    return tags.get("self_turn_deg") == 180 or "self_turn_180" in name


# ---------------------------------------------------------------------------
# reporting

COLUMNS = [("edge_dev", "edge dev", "{:.3f}"), ("joint_dev_deg", "joint dev °", "{:.2f}"),
           ("min_size", "min size", "{:.3f}"), ("unevenness", "unevenness", "{:.2f}"),
           ("turn_deg", "turn °", "{:.1f}"), ("needed_deg", "needed °", "{:.1f}"),
           ("beyond_deg", "beyond °", "{:.1f}")]


def fmt(v, spec="{:.3f}"):
    return "—" if v is None or (isinstance(v, float) and math.isnan(v)) else spec.format(v)


def percentile(values, q):
    v = [x for x in values if x is not None and not math.isnan(x)]
    return float(np.percentile(v, q)) if v else float("nan")


def summarize(results, methods):
    """Per method: median and 90th percentile of every metric over the pairs it morphed (for
    the minimum size the bad tail is the low one, so its 10th percentile), plus the counts."""
    summary = {}
    for m in methods:
        rows = [r[m] for r in results.values() if m in r and "error" not in r[m]]
        s = {"pairs": len(rows), "failed": sum(1 for r in results.values() if m in r and "error" in r[m])}
        for key, _, _ in COLUMNS:
            vals = [row[key] for row in rows]
            s[key] = {"median": percentile(vals, 50), "p90": percentile(vals, 90), "p10": percentile(vals, 10),
                      "max": max(vals) if vals else float("nan")}
        s["bad_frames"] = sum(len(row["bad_frames"]) for row in rows if row["bad_frames"] is not None)
        s["pairs_with_bad_frames"] = sum(1 for row in rows if row["bad_frames"])
        s["bad_frames_checked"] = all(row["bad_frames"] is not None for row in rows)
        s["min_size_share_ok"] = (sum(1 for row in rows if row["min_size"] >= MIN_SIZE) / len(rows)
                                  if rows else float("nan"))
        # the CLI's own time per frame (stats.milliseconds.morph / frames); ARAP has none
        ms = [row["ms_per_frame"] for row in rows if row.get("ms_per_frame") is not None]
        if ms:
            s["ms_per_frame"] = {"median": percentile(ms, 50), "p90": percentile(ms, 90), "max": max(ms)}
        summary[m] = s
    return summary


def targets(results, summary, methods, corpus):
    """Issue 12's targets, per method: (target text, {method: (passed, shown value)}, key)."""
    out = []

    def add(key, text, fn):
        out.append((text, {m: fn(m, summary[m]) for m in methods}, key))

    add("edge_dev", f"edge dev median ≤ {EDGE_MEDIAN} and p90 ≤ {EDGE_P90}",
        lambda m, s: (s["edge_dev"]["median"] <= EDGE_MEDIAN and s["edge_dev"]["p90"] <= EDGE_P90,
                      f"{s['edge_dev']['median']:.3f} / {s['edge_dev']['p90']:.3f}"))
    add("joint_dev", f"joint dev median ≤ {JOINT_MEDIAN_DEG:g}°",
        lambda m, s: (s["joint_dev_deg"]["median"] <= JOINT_MEDIAN_DEG, f"{s['joint_dev_deg']['median']:.2f}°"))
    add("min_size", f"min size ≥ {MIN_SIZE} in {MIN_SIZE_SHARE:.0%} of pairs",
        lambda m, s: (s["min_size_share_ok"] >= MIN_SIZE_SHARE, f"{s['min_size_share_ok']:.0%}"))
    add("unevenness", f"unevenness median ≤ {UNEVEN_MEDIAN} and p90 ≤ {UNEVEN_P90}",
        lambda m, s: (s["unevenness"]["median"] <= UNEVEN_MEDIAN and s["unevenness"]["p90"] <= UNEVEN_P90,
                      f"{s['unevenness']['median']:.2f} / {s['unevenness']['p90']:.2f}"))
    add("beyond", f"no pair turns > {BEYOND_MAX_DEG:g}° beyond the needed rotation",
        lambda m, s: (s["beyond_deg"]["max"] <= BEYOND_MAX_DEG, f"max {s['beyond_deg']['max']:.1f}°"))

    def self_turn(m, s):
        rows = [(name, results[name][m]) for name, _, tags in corpus
                if self_turn_180(name, tags) and m in results[name]]
        if not rows:
            return (None, "no 180° pair")
        ok, shown = True, []
        for name, r in rows:
            if "error" in r:
                return (False, "failed")
            ok &= (abs(r["turn_deg"]) >= SELF_TURN_DEG and r["edge_dev"] <= SELF_TURN_EDGE
                   and r["min_size"] >= SELF_TURN_SIZE)
            shown.append(f"{abs(r['turn_deg']):.1f}°, {r['edge_dev']:.3f}, {r['min_size']:.2f}")
        return (ok, "; ".join(shown))
    add("self_turn", f"180° self-turn: turns ≥ {SELF_TURN_DEG:g}°, edge dev ≤ {SELF_TURN_EDGE}, min size ≥ {SELF_TURN_SIZE}",
        self_turn)
    add("invalid_frames", "0 invalid frames (and every morph succeeds)",
        lambda m, s: ((s["bad_frames"] == 0 and s["failed"] == 0) if s["bad_frames_checked"] else None,
                      f"{s['bad_frames']} in {s['pairs_with_bad_frames']} pairs"
                      + (f", {s['failed']} failed" if s["failed"] else "")
                      + ("" if s["bad_frames_checked"] else " (not checked)")))
    return out


def print_report(corpus, results, methods, summary, target_rows, per_pair=True, file=sys.stdout):
    def line(cells):
        print("| " + " | ".join(cells) + " |", file=file)
    if per_pair:
        line(["pair", "n", "method"] + [c[1] for c in COLUMNS] + ["bad frames"])
        line(["---"] * (len(COLUMNS) + 4))
        for name, _, _ in corpus:
            for m in methods:
                r = results[name].get(m)
                if r is None:
                    continue
                if "error" in r:
                    line([name, str(results[name]["_n"]), m] + ["—"] * len(COLUMNS) + ["failed: " + r["error"][:80]])
                    continue
                bad = "not checked" if r["bad_frames"] is None else str(len(r["bad_frames"]))
                line([name, str(results[name]["_n"]), m] + [fmt(r[k], f) for k, _, f in COLUMNS] + [bad])
        print(file=file)
    line(["method", "pairs", "edge dev med / p90", "joint dev ° med / p90", "min size med / p10",
          "unevenness med / p90", "beyond ° med / p90 / max", "bad frames (pairs)", "ms/frame med"])
    line(["---"] * 9)
    for m in methods:
        s = summary[m]
        line([m, f"{s['pairs']}" + (f" (+{s['failed']} failed)" if s["failed"] else ""),
              f"{s['edge_dev']['median']:.3f} / {s['edge_dev']['p90']:.3f}",
              f"{s['joint_dev_deg']['median']:.2f} / {s['joint_dev_deg']['p90']:.2f}",
              f"{s['min_size']['median']:.3f} / {s['min_size']['p10']:.3f}",
              f"{s['unevenness']['median']:.2f} / {s['unevenness']['p90']:.2f}",
              f"{s['beyond_deg']['median']:.1f} / {s['beyond_deg']['p90']:.1f} / {s['beyond_deg']['max']:.1f}",
              f"{s['bad_frames']} ({s['pairs_with_bad_frames']})" + ("" if s["bad_frames_checked"] else " unchecked"),
              f"{s['ms_per_frame']['median']:.3f}" if "ms_per_frame" in s else "—"])
    print(file=file)
    # medians per kind of pair: where a method's motion goes wrong
    kinds = sorted({results[name]["_kind"] for name, _, _ in corpus})
    if len(kinds) > 1:
        line(["kind", "method", "pairs", "edge dev med", "joint dev ° med", "min size min", "unevenness med",
              "beyond ° max", "bad frames"])
        line(["---"] * 9)
        for kind in kinds:
            for m in methods:
                rows = [results[name][m] for name, k, _ in corpus if k == kind and m in results[name]
                        and "error" not in results[name][m]]
                if not rows:
                    continue
                line([kind, m, str(len(rows)), f"{np.median([r['edge_dev'] for r in rows]):.3f}",
                      f"{np.median([r['joint_dev_deg'] for r in rows]):.2f}",
                      f"{min(r['min_size'] for r in rows):.3f}", f"{np.median([r['unevenness'] for r in rows]):.2f}",
                      f"{max(r['beyond_deg'] for r in rows):.1f}",
                      str(sum(len(r["bad_frames"] or []) for r in rows))])
        print(file=file)
    line(["target"] + methods)
    line(["---"] * (len(methods) + 1))
    for text, per, _ in target_rows:
        cells = []
        for m in methods:
            ok, shown = per[m]
            cells.append(("n/a" if ok is None else "PASS" if ok else "FAIL") + f" ({shown})")
        line([text] + cells)


def _finite(value):
    """NaN (a summary over no pairs) as null: JSON has no NaN."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    return value


def svg_filmstrip(path, frames, edges, title, count=7):
    """A plain filmstrip for the references the CLI cannot draw (ARAP): `count` frames side by
    side at one scale, source blue to target red, like `stickmorph morph --svg`."""
    idx = np.linspace(0, len(frames) - 1, count).round().astype(int)
    lo, hi = frames.reshape(-1, 2).min(axis=0), frames.reshape(-1, 2).max(axis=0)
    span = float(max(hi - lo)) or 1.0
    cell, pad = 160.0, 10.0
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{count * cell}" height="{cell + 20}">',
             f'<text x="4" y="14" font-size="12">{title}</text>']
    for c, k in enumerate(idx):
        t = k / max(1, len(frames) - 1)
        color = f"rgb({int(255 * t)},0,{int(255 * (1 - t))})"
        p = (frames[k] - lo) / span * (cell - 2 * pad)
        pts = [(c * cell + pad + x, 20 + cell - pad - y) for x, y in p]
        for i, j in edges:
            parts.append(f'<line x1="{pts[i][0]:.2f}" y1="{pts[i][1]:.2f}" x2="{pts[j][0]:.2f}" '
                         f'y2="{pts[j][1]:.2f}" stroke="{color}" stroke-width="1"/>')
    parts.append("</svg>")
    pathlib.Path(path).write_text("\n".join(parts) + "\n")


def _path_d(points, edges):
    """One SVG path for all edges of a frame: M x y L x y per edge, one decimal (small files)."""
    return " ".join(f"M{points[i][0]:.1f} {points[i][1]:.1f}L{points[j][0]:.1f} {points[j][1]:.1f}"
                    for i, j in edges)


def svg_filmstrip_rows(path, rows, edges, title, count=7):
    """A filmstrip with one row per method, drawn from frames already computed (no second
    morph): `count` frames per row at t = 0 ... 1, all rows at one scale so that sizes compare,
    source blue to target red. rows: (label, caption, frames or None, bad frame indices or None).
    A drawn frame that is invalid is dashed and marked; a method that failed shows its caption."""
    drawn = [f for _, _, f, _ in rows if f is not None]
    cell, pad, left, head, row_head = 130.0, 8.0, 96.0, 22.0, 16.0
    if drawn:
        everything = np.concatenate([f.reshape(-1, 2) for f in drawn])
        lo, hi = everything.min(axis=0), everything.max(axis=0)
    else:
        lo, hi = np.zeros(2), np.ones(2)
    span = float(max(hi - lo)) or 1.0
    scale = (cell - 2 * pad) / span
    # keep the aspect ratio, centre the figure's box in its cell
    off = (cell - 2 * pad - (hi - lo) * scale) / 2
    width = left + count * cell
    row_h = row_head + cell + 14
    height = head + len(rows) * row_h
    esc = lambda text: str(text).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")  # noqa: E731
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" height="{height:.0f}" '
             f'viewBox="0 0 {width:.0f} {height:.0f}" font-family="sans-serif">',
             '<rect width="100%" height="100%" fill="white"/>',
             f'<text x="4" y="15" font-size="13">{esc(title)}</text>']
    for r, (label, caption, frames, bad) in enumerate(rows):
        top = head + r * row_h
        parts.append(f'<text x="4" y="{top + row_head + cell / 2:.0f}" font-size="12" font-weight="bold">'
                     f'{esc(label)}</text>')
        parts.append(f'<text x="{left:.0f}" y="{top + 12:.0f}" font-size="10" fill="#444">{esc(caption)}</text>')
        if frames is None:
            continue
        idx = np.linspace(0, len(frames) - 1, count).round().astype(int)
        for c, k in enumerate(idx):
            t = k / max(1, len(frames) - 1)
            color = f"rgb({int(40 + 180 * t)},{int(90 - 50 * t)},{int(200 - 160 * t)})"
            x0, y0 = left + c * cell + pad + off[0], top + row_head + cell - pad - off[1]
            pts = [(x0 + (x - lo[0]) * scale, y0 - (y - lo[1]) * scale) for x, y in frames[k]]
            invalid = bad is not None and k in bad
            dash = ' stroke-dasharray="3,2"' if invalid else ""
            parts.append(f'<path d="{_path_d(pts, edges)}" fill="none" stroke="{color}" stroke-width="1.3" '
                         f'stroke-linecap="round"{dash}/>')
            mark = " invalid" if invalid else ""
            parts.append(f'<text x="{left + c * cell + cell / 2:.0f}" y="{top + row_head + cell + 10:.0f}" '
                         f'font-size="9" text-anchor="middle" fill="{"#c00" if invalid else "#666"}">'
                         f'frame {k}{mark}</text>')
    parts.append("</svg>")
    pathlib.Path(path).write_text("\n".join(parts) + "\n")


def _caption(r):
    if "error" in r:
        return "failed: " + r["error"][:120]
    text = (f"edge dev {r['edge_dev']:.3f}, joint dev {r['joint_dev_deg']:.1f}°, min size {r['min_size']:.2f}, "
            f"unevenness {r['unevenness']:.2f}, turns {r['turn_deg']:.1f}° of {r['needed_deg']:.1f}° "
            f"(beyond {r['beyond_deg']:.1f}°)")
    if r.get("bad_frames"):
        text += ", invalid frames " + ", ".join(str(k) for k in r["bad_frames"])
    return text


def straight_lines(extra):
    """Whether CLI options ask for the straight-line morph (a reference, like `linear`)."""
    extra = list(extra or [])
    return "--method=linear" in extra or any(a == "--method" and b == "linear" for a, b in zip(extra, extra[1:]))


def cli_method(text):
    """--cli-method LABEL=ARGS: (label, ARGS split like a shell would)."""
    label, sep, rest = text.partition("=")
    label = label.strip()
    if not sep or not label:
        raise argparse.ArgumentTypeError(f"{text!r}: expected LABEL=ARGS, e.g. rigid=\"--method rigid\"")
    try:
        return label, shlex.split(rest)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(f"{text!r}: {exc}")


def _repo_relative(path):
    """A path as the JSON records it: relative to the repository when inside it."""
    path = pathlib.Path(path).resolve()
    try:
        return path.relative_to(REPO).as_posix()
    except ValueError:
        return str(path)


# ---------------------------------------------------------------------------

def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    started = time.monotonic()
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("corpus", nargs="?", default="out/motion_corpus", help="corpus folder (motion_corpus.py)")
    ap.add_argument("--build-dir", default=os.environ.get("STICKMORPH_BUILD_DIR", str(REPO / "build")),
                    help="folder with the stickmorph CLI (default $STICKMORPH_BUILD_DIR or build)")
    ap.add_argument("--frames", type=int, default=30, help="frames per morph (default 30, as in the issue)")
    ap.add_argument("--ours-args", default="",
                    help='extra `stickmorph morph` options for our method, e.g. "--weights uniform" '
                         '(given --weights, the method runs once with them instead of once per --weights kind)')
    ap.add_argument("--weights", default="mvc,uniform,floater",
                    help="weight kinds our method runs with, comma-separated (default mvc,uniform,floater)")
    ap.add_argument("--cli-method", type=cli_method, action="append", default=[], metavar="LABEL=ARGS",
                    help='a `stickmorph morph` variant labelled LABEL, with ARGS passed through (empty: the '
                         'CLI\'s default), e.g. rigid="--method rigid"; repeatable. Given any, --methods '
                         'defaults to linear,arap (the references)')
    ap.add_argument("--methods", default=None,
                    help="which of ours,linear,arap to run (default ours,linear,arap; linear,arap with --cli-method)")
    ap.add_argument("--check-frames", choices=["all", "references", "none"], default="all",
                    help="count invalid frames with `stickmorph check` for every method (all), only for "
                         "straight lines and ARAP (references; ours verifies its own frames), or not at all")
    ap.add_argument("--json", help="write every number (per pair, per method, per frame series) to this file")
    ap.add_argument("--filmstrip", help="write SVG filmstrips of the worst pairs per metric into this folder")
    ap.add_argument("--filmstrip-method", help="the method whose worst pairs are drawn (default: the first)")
    ap.add_argument("--filmstrip-worst", type=int, default=3, metavar="K",
                    help="the K worst pairs per metric get a filmstrip (default 3)")
    ap.add_argument("--filmstrip-rows", metavar="M1,M2,...",
                    help="draw each filmstrip here, one row per listed method, from the frames already "
                         "measured (no second CLI run); one file strip_PAIR.svg per pair, however many "
                         "metrics it is worst in")
    ap.add_argument("--filmstrip-pairs", default="", metavar="NAME,...",
                    help="with --filmstrip-rows: also draw these pairs (e.g. special_self_turn_180)")
    ap.add_argument("--note", action="append", default=[], help="a line of text kept in the JSON (repeatable)")
    ap.add_argument("--summary-only", action="store_true", help="print the summary tables without per-pair rows")
    args = ap.parse_args(argv)

    cli = pathlib.Path(args.build_dir) / "stickmorph"
    if not cli.exists():
        sys.exit(f"error: {cli} is missing (cmake --build build --target stickmorph)")
    folder = pathlib.Path(args.corpus)
    corpus = corpus_pairs(folder)
    if not corpus:
        sys.exit(f"error: no NAME.source.json / NAME.target.json pairs in {folder} "
                 "(make them with bench/motion_corpus.py)")
    if args.methods is None:
        args.methods = "linear,arap" if args.cli_method else "ours,linear,arap"
    families = [f.strip() for f in args.methods.split(",") if f.strip()]
    unknown = [f for f in families if f not in ("ours", "linear", "arap")]
    if unknown:
        sys.exit(f"error: --methods {','.join(unknown)}: not one of ours, linear, arap (use --cli-method for others)")
    ours_args = shlex.split(args.ours_args)
    methods = {}  # label -> extra CLI args, or None for ARAP

    def add_method(label, extra):
        if label in methods:
            sys.exit(f"error: two methods are labelled {label!r}")
        if label in RESERVED_LABELS or label.startswith("_"):
            sys.exit(f"error: {label!r} cannot label a method (the JSON uses it for something else)")
        methods[label] = extra
    if "ours" in families:
        if "--weights" in ours_args or any(a.startswith("--weights=") for a in ours_args):
            add_method("ours", ours_args)
        else:
            for w in [w.strip() for w in args.weights.split(",") if w.strip()]:
                add_method(f"ours[{w}]", ours_args + ["--weights", w])
    for label, extra in args.cli_method:
        add_method(label, extra)
    if "linear" in families:
        add_method("linear", ["--method", "linear"])
    if "arap" in families:
        add_method("arap", None)
    labels = list(methods)
    if not labels:
        sys.exit("error: no method to run")
    strip_method = args.filmstrip_method or labels[0]
    if args.filmstrip and strip_method not in methods:
        sys.exit(f"error: --filmstrip-method {strip_method}: not one of {', '.join(labels)}")
    strip_rows = None
    if args.filmstrip_rows:
        strip_rows = [m.strip() for m in args.filmstrip_rows.split(",") if m.strip()]
        missing = [m for m in strip_rows if m not in methods]
        if missing or not strip_rows:
            sys.exit(f"error: --filmstrip-rows {','.join(missing)}: not among the methods {', '.join(labels)}")

    results = {}
    frames_kept = {}
    with tempfile.TemporaryDirectory(prefix="motion_quality_") as tmp:
        for name, kind, tags in corpus:
            src_path, tgt_path = folder / f"{name}.source.json", folder / f"{name}.target.json"
            src, edges = read_figure(src_path)
            tgt, _ = read_figure(tgt_path)
            results[name] = {"_n": len(src), "_kind": kind}
            for label, extra in methods.items():
                try:
                    if extra is None:
                        times = np.linspace(0.0, 1.0, args.frames)
                        frames, stats = arap_frames(src, tgt, edges, times), {}
                    else:
                        frames, times, stats = run_morph(cli, src_path, tgt_path, pathlib.Path(tmp) / "morph.json",
                                                         args.frames, extra)
                except RuntimeError as exc:
                    results[name][label] = {"error": str(exc)}
                    print(f"warning: {name} {label}: {exc}", file=sys.stderr)
                    continue
                r = measure(frames, edges, times)
                linear = extra is not None and straight_lines(extra)
                reference = extra is None or linear
                if args.check_frames == "all" or (args.check_frames == "references" and reference):
                    r["bad_frames"] = bad_frames(cli, src_path, frames, edges, tmp)
                elif not reference:
                    # ours verifies every frame exactly or fails (docs/CLI.md): 0 by construction
                    r["bad_frames"] = [] if stats.get("verified", False) else None
                else:
                    r["bad_frames"] = None
                if extra is not None:
                    # what the CLI says it ran, and its own wall time (the checks above not included)
                    ms = stats.get("milliseconds", {})
                    r["engine_method"] = stats.get("method")
                    if "weights" in stats:
                        r["engine_weights"] = stats["weights"]
                    if isinstance(ms.get("morph"), (int, float)):
                        r["morph_ms"] = float(ms["morph"])
                        r["ms_per_frame"] = float(ms["morph"]) / len(frames)
                    if isinstance(ms.get("triangulate"), (int, float)):
                        r["triangulate_ms"] = float(ms["triangulate"])
                    # Issue 30: the triangulation's shape, and the share of interior frames
                    # that are the rigid guide itself.
                    if stats.get("_shape"):
                        r["triangle_min_angle_deg"] = stats["_shape"]["min_angle_deg"]
                        r["steiner_per_vertex"] = stats["_shape"]["steiner_per_vertex"]
                    guide = (stats.get("rigid") or {}).get("guide_frames")
                    if isinstance(guide, dict) and sum(guide.values()) > 0:
                        r["exact_frame_share"] = guide.get("exact", 0) / sum(guide.values())
                if linear and "invalid_frames" in stats:
                    r["engine_invalid_frames"] = stats["invalid_frames"]
                    if r["bad_frames"] is not None and sorted(r["bad_frames"]) != sorted(
                            k for k in stats["invalid_frames"] if 0 < k < len(frames) - 1):
                        print(f"warning: {name}: check finds bad frames {r['bad_frames']}, the linear morph "
                              f"reports {stats['invalid_frames']}", file=sys.stderr)
                results[name][label] = r
                frames_kept[(name, label)] = (frames, edges) if args.filmstrip else None
            print(f"measured {name}", file=sys.stderr)

        summary = summarize(results, labels)
        target_rows = targets(results, summary, labels, corpus)
        for note in args.note:
            print(f"Note: {note}\n")
        print(f"Motion quality of {len(corpus)} pairs in {folder}, {args.frames} frames"
              + (f", ours with `{args.ours_args}`" if args.ours_args else "") + "\n")
        print_report(corpus, results, labels, summary, target_rows, per_pair=not args.summary_only)

        filmstrips = []
        if args.filmstrip:
            out = pathlib.Path(args.filmstrip)
            out.mkdir(parents=True, exist_ok=True)
            m = strip_method
            ok = [name for name, _, _ in corpus if m in results[name] and "error" not in results[name][m]]
            worst_k = max(0, args.filmstrip_worst)
            # an earlier run's worst pairs are other files: remove them (only names this
            # script writes) so the folder shows one run
            for key, _ in WORST_KEYS:
                for old in out.glob(f"{key}_[0-9]*_*.svg"):
                    old.unlink()
            for old in out.glob("strip_*.svg"):
                old.unlink()
            # worst = largest value, except the minimum size (smallest)
            worst = {key: sorted(ok, key=lambda n: -sign * results[n][m][key])[:worst_k] for key, sign in WORST_KEYS}
            if strip_rows is None:
                for key, _ in WORST_KEYS:
                    for rank, name in enumerate(worst[key], 1):
                        svg = out / f"{key}_{rank}_{name}.svg"
                        if methods[m] is None:
                            frames, edges = frames_kept[(name, m)]
                            svg_filmstrip(svg, frames, edges, f"{name} {m}: {key} = {results[name][m][key]:.3f}")
                        else:
                            extra = methods[m] + (["--svg-compare-linear"] if not straight_lines(methods[m]) else [])
                            run_morph(cli, folder / f"{name}.source.json", folder / f"{name}.target.json",
                                      pathlib.Path(tmp) / "morph.json", args.frames, extra + ["--svg", str(svg)])
                        filmstrips.append({"file": _repo_relative(svg), "pair": name, "method": m, "rows": [m],
                                           "worst": [{"metric": key, "rank": rank,
                                                      "value": results[name][m][key]}]})
            else:
                chosen = {}  # pair -> the metrics it is among the worst in (insertion order)
                for key, _ in WORST_KEYS:
                    for rank, name in enumerate(worst[key], 1):
                        chosen.setdefault(name, []).append({"metric": key, "rank": rank,
                                                            "value": results[name][m][key]})
                for name in [n.strip() for n in args.filmstrip_pairs.split(",") if n.strip()]:
                    if name not in results:
                        print(f"warning: --filmstrip-pairs {name}: no such pair", file=sys.stderr)
                        continue
                    chosen.setdefault(name, [])
                for name, why in chosen.items():
                    svg = out / f"strip_{name}.svg"
                    rows, edges = [], None
                    for label in strip_rows:
                        r = results[name].get(label, {"error": "not run"})
                        kept = frames_kept.get((name, label))
                        if kept is not None:
                            edges = kept[1]
                        rows.append((label, _caption(r), kept[0] if kept is not None and "error" not in r else None,
                                     set(r.get("bad_frames") or [])))
                    if edges is None:
                        edges = read_figure(folder / f"{name}.source.json")[1]
                    title = f"{name} ({results[name]['_n']} vertices, {args.frames} frames)"
                    if why:
                        title += f": worst {m} pair by " + ", ".join(WORST_NAMES[w["metric"]] for w in why)
                    svg_filmstrip_rows(svg, rows, edges, title)
                    filmstrips.append({"file": _repo_relative(svg), "pair": name, "method": m, "rows": strip_rows,
                                       "worst": why})
            print(f"\n{len(filmstrips)} filmstrips of the worst {worst_k} pairs per metric ({m}) in {out}",
                  file=sys.stderr)

        if args.json:
            manifest = folder / "manifest.json"
            seed = json.loads(manifest.read_text()).get("seed") if manifest.exists() else None
            version = subprocess.run([str(cli), "--version"], capture_output=True, text=True,
                                     timeout=TIMEOUT_SECONDS).stdout.strip()
            skip = {"name", "kind", "vertices", "edges", "attempts"}
            doc = {"command": "/usr/bin/python3 bench/motion_quality.py " + shlex.join(argv),
                   "corpus": str(folder), "corpus_seed": seed, "build_dir": str(args.build_dir),
                   "cli_version": version, "frames": args.frames, "ours_args": args.ours_args,
                   "check_frames": args.check_frames, "methods": labels,
                   "cli_methods": {m: (None if e is None else shlex.join(e)) for m, e in methods.items()},
                   "notes": args.note, "thresholds": THRESHOLDS,
                   "pairs": {name: {"kind": results[name]["_kind"], "vertices": results[name]["_n"],
                                    "tags": {k: v for k, v in tags.items() if k not in skip},
                                    **{m: results[name][m] for m in labels if m in results[name]}}
                             for name, _, tags in corpus},
                   "summary": summary,
                   "targets": [{"target": text, "key": key,
                                **{m: {"pass": ok, "value": shown} for m, (ok, shown) in per.items()}}
                               for text, per, key in target_rows],
                   "filmstrips": filmstrips,
                   "runtime_s": round(time.monotonic() - started, 1)}
            pathlib.Path(args.json).write_text(json.dumps(_finite(doc), indent=1, allow_nan=False) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
