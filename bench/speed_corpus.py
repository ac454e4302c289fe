#!/usr/bin/env python3
"""Time the whole morph on drawn-looking figures of 10^3 to 10^5 vertices (issue 15).

    /usr/bin/python3 bench/speed_corpus.py [--build DIR] [--sizes 1000,10000] [--shapes LIST]
                                             [--frames N] [--playback K] [--seed S] [--json FILE]

The benchmark families (native/bench/bench_figures.h) are regular on purpose; these are drawn by
a wobbly hand, at the sizes a tablet stroke or a traced outline reaches:

  coil      a hand-drawn spiral stroke (the turns 1.5 to 2.5 strokes apart) uncoiled into a
            wavy line: the spiral's exterior face is one long thin corridor.
  meander   a snake of switchbacks wound into a coil (the issue's spiral into meander).
  band      a closed band along a spiral (a polygon 1.5 % of its length wide) straightened
            into a shallow arc: a long thin interior face.
  outline   the outline of a glyph ("S", DejaVu Sans) resampled to n points, bent, turned by
            100 degrees and scaled.
  coral     a branching coral (a tree of curly branches) twisted about its root.

Each (shape, n) runs in a child process of its own (peak memory is that child's ru_maxrss):
triangulate_figures (timed), morph() with the default rigid method and 50 frames (its stats),
then the scrubbing solvers built once and played back over K evenly spaced times
(MorphSolver for the paper's barycentric morph, RigidMorphSolver for the rigid one), each frame
solved and certified exactly (the default frame check). Prints a Markdown table; --json writes
the raw rows. Targets are drawn so that source and target are valid figures with the same
numbering; a shape whose warp breaks validity is warped less (the row says how much).
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys
import time

import numpy as np

REPO = pathlib.Path(__file__).resolve().parent.parent
SHAPES = ("coil", "meander", "band", "outline", "coral")


def wobble(rng, count, amplitude, waves=6):
    """A smooth random function on [0, 1] sampled at `count` points: a hand's unsteadiness."""
    s = np.linspace(0.0, 1.0, count)
    out = np.zeros(count)
    for k in range(1, waves + 1):
        out += rng.normal(0.0, amplitude / k) * np.sin(2 * math.pi * k * s + rng.uniform(0, 2 * math.pi))
    return out


def polyline_edges(n):
    return [[i, i + 1] for i in range(n - 1)]


def polygon_edges(n):
    return [[i, (i + 1) % n] for i in range(n)]


def spiral_points(n, rng, turns, start_radius=2.0):
    """A hand-drawn Archimedean spiral: radius grows by 1 per turn, points evenly spaced in arc."""
    theta_end = 2 * math.pi * turns
    fine = np.linspace(0.0, theta_end, 40 * n)
    radius = start_radius + fine / (2 * math.pi) + wobble(rng, fine.size, 0.08)
    xy = np.stack([radius * np.cos(fine), radius * np.sin(fine)], axis=1)
    return resample(xy, n)


def resample(xy, n, closed=False):
    """n points evenly spaced in arc length along the polyline xy (closed: round the loop)."""
    if closed:
        xy = np.vstack([xy, xy[:1]])
    step = np.linalg.norm(np.diff(xy, axis=0), axis=1)
    arc = np.concatenate([[0.0], np.cumsum(step)])
    at = np.linspace(0.0, arc[-1], n + 1 if closed else n)
    if closed:
        at = at[:-1]
    return np.stack([np.interp(at, arc, xy[:, 0]), np.interp(at, arc, xy[:, 1])], axis=1)


def coil(n, rng):
    turns = max(3.0, math.sqrt(n) / 3)
    source = spiral_points(n, rng, turns)
    length = np.sum(np.linalg.norm(np.diff(source, axis=0), axis=1))
    s = np.linspace(0.0, 1.0, n)
    target = np.stack([s * length * 0.6, 0.03 * length * np.sin(9 * math.pi * s) + wobble(rng, n, 0.01 * length)],
                      axis=1)
    return source, target, polyline_edges(n), "uncoiled"


def meander(n, rng):
    rows = max(4, int(math.sqrt(n) / 2))
    width = 40.0
    path = []
    for r in range(rows):
        xs = np.linspace(0.0, width, 200)
        if r % 2:
            xs = xs[::-1]
        path.extend((x, 2.0 * r) for x in xs)
        # a rounded turn at the row's end
        cx = xs[-1]
        side = 1.0 if r % 2 == 0 else -1.0
        for a in np.linspace(-math.pi / 2, math.pi / 2, 20)[1:-1]:
            path.append((cx + side * math.cos(a), 2.0 * r + 1.0 + math.sin(a)))
    xy = np.asarray(path)
    xy[:, 1] += wobble(rng, len(xy), 0.05)
    source = resample(xy, n)
    target = spiral_points(n, rng, max(3.0, math.sqrt(n) / 3))
    return source, target, polyline_edges(n), "coiled"


def band(n, rng):
    half = n // 2
    turns = max(2.0, math.sqrt(n) / 6)
    theta = np.linspace(2 * math.pi, 2 * math.pi * (1 + turns), 30 * half)
    radius = 3.0 * theta / (2 * math.pi) + wobble(rng, theta.size, 0.05)
    centre = np.stack([radius * np.cos(theta), radius * np.sin(theta)], axis=1)
    tangent = np.gradient(centre, axis=0)
    normal = np.stack([-tangent[:, 1], tangent[:, 0]], axis=1)
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    length = np.sum(np.linalg.norm(np.diff(centre, axis=0), axis=1))
    w = min(0.015 * length, 0.6)
    outer = resample(centre + w * normal, half)
    inner = resample(centre - w * normal, n - half)
    source = np.vstack([outer, inner[::-1]])
    # Straightened into a shallow arc of the same length, the same width.
    s_outer = np.linspace(0.0, 1.0, half)
    s_inner = np.linspace(0.0, 1.0, n - half)[::-1]
    bend = 0.4

    def arc(s, offset):
        a = bend * (s - 0.5)
        r = length / bend
        return np.stack([(r + offset) * np.sin(a), r - (r + offset) * np.cos(a)], axis=1)

    target = np.vstack([arc(s_outer, w), arc(s_inner, -w)])
    if signed_area(source) < 0:
        source = source[::-1].copy()
        target = target[::-1].copy()
    if signed_area(target) < 0:  # the straightened band must keep the orientation
        target[:, 0] = -target[:, 0]
    return source, target, polygon_edges(n), "straightened"


def signed_area(xy):
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def outline(n, rng):
    sys.path.insert(0, str(REPO / "bench"))
    import correspondence_corpus as outlines  # the font outlines of the correspondence corpus
    contours, _ = outlines.glyph_contours("DejaVuSans.ttf", "S")
    dense = []
    for beziers in contours[:1]:
        for cp in beziers:
            for u in np.linspace(0.0, 1.0, 60, endpoint=False):
                dense.append(bezier_point(cp, u))
    source = resample(np.asarray(dense) * 100.0, n, closed=True)
    if signed_area(source) < 0:
        source = source[::-1].copy()
    return source, None, polygon_edges(n), "bent, turned 100 degrees"


def bezier_point(cp, u):
    pts = np.asarray(cp, dtype=float)
    while len(pts) > 1:
        pts = (1 - u) * pts[:-1] + u * pts[1:]
    return pts[0]


def coral(n, rng):
    """Curly branches grown from the root; a step that would come within 0.3 of the drawing
    (other than the branch's own last point) ends the branch, so no two strokes meet."""
    step, clearance = 0.5, 0.3
    points = [(0.0, 0.0)]
    edges = []
    grid = {}

    def cell(p):
        return (int(math.floor(p[0])), int(math.floor(p[1])))

    def near(p, skip):
        cx, cy = cell(p)
        for gx in range(cx - 1, cx + 2):
            for gy in range(cy - 1, cy + 2):
                for j in grid.get((gx, gy), ()):
                    if j != skip and math.dist(points[j], p) < clearance + step * 0.5:
                        return True
        return False

    grid.setdefault(cell(points[0]), []).append(0)
    tips = [(0, math.pi / 2)]
    stalls = 0
    while len(points) < n and tips and stalls < 50 * n:
        v, heading = tips.pop(int(rng.integers(len(tips))))
        grown = 0
        for _ in range(int(rng.integers(8, 20))):
            if len(points) >= n:
                break
            heading += rng.normal(0.0, 0.12)
            x, y = points[v]
            p = (x + step * math.cos(heading), y + step * math.sin(heading))
            if near(p, v):
                stalls += 1
                break
            points.append(p)
            edges.append([v, len(points) - 1])
            v = len(points) - 1
            grid.setdefault(cell(p), []).append(v)
            grown += 1
        if grown and len(points) < n:
            tips.append((v, heading + rng.uniform(0.3, 0.7)))
            tips.append((v, heading - rng.uniform(0.3, 0.7)))
    if len(points) < n:
        raise RuntimeError(f"coral: grew only {len(points)} of {n} points")
    return np.asarray(points), None, edges, "twisted about its root"


def warp(points, kind, strength):
    """A smooth orientation-preserving map of the plane, then a similarity."""
    c = points.mean(axis=0)
    d = points - c
    reach = np.max(np.linalg.norm(d, axis=1))
    if kind == "outline":  # bend about a far centre, then turn by 100 degrees
        x, y = d[:, 0] / reach, d[:, 1] / reach
        a = strength * 0.8 * x
        bent = np.stack([(1 + y * 0.3 * strength) * np.sin(a) / max(1e-9, 0.8 * strength) if strength else x,
                         y + (1 - np.cos(a)) * 0.5], axis=1) * reach
        turn = math.radians(100) * min(1.0, strength)
    else:  # a twist growing with the distance from the root
        r = np.linalg.norm(d, axis=1) / reach
        a = strength * 1.2 * r
        bent = np.stack([np.cos(a) * d[:, 0] - np.sin(a) * d[:, 1], np.sin(a) * d[:, 0] + np.cos(a) * d[:, 1]],
                        axis=1)
        turn = math.radians(30) * strength
    rot = np.array([[math.cos(turn), -math.sin(turn)], [math.sin(turn), math.cos(turn)]])
    return (bent @ rot.T) * 0.7 + c + np.array([0.2 * reach, -0.1 * reach])


def make_pair(shape, n, seed, stickmorph):
    rng = np.random.default_rng(seed + 1000 * SHAPES.index(shape) + n)
    source, target, edges, how = globals()[shape](n, rng)
    if target is None:
        strength = 1.0
        for _ in range(12):
            target = warp(source, shape, strength)
            if stickmorph.check_compatibility(source.tolist(), target.tolist(), edges).compatible:
                break
            strength *= 0.5
        else:
            raise RuntimeError(f"{shape} n={n}: no warp keeps the figure valid")
        how += f" (warp strength {strength:g})"
    for which, xy in (("source", source), ("target", target)):
        stickmorph.validate(xy.tolist(), edges)
    report = stickmorph.check_compatibility(source.tolist(), target.tolist(), edges)
    if not report.compatible:
        raise RuntimeError(f"{shape} n={n}: the drawn pair is not compatible: {report.reason}")
    return source, target, edges, how


def run_case(shape, n, seed, frames, playback):
    import stickmorph
    source, target, edges, how = make_pair(shape, n, seed, stickmorph)
    row = {"shape": shape, "n": n, "how": how, "edges": len(edges)}
    start = time.perf_counter()
    tri = stickmorph.triangulate_figures(source.tolist(), target.tolist(), edges)
    row["triangulate_ms"] = 1e3 * (time.perf_counter() - start)
    row["steiner"] = tri["steiner_vertices"]
    row["nodes"] = tri["figure_vertices"] + tri["enclosure_vertices"] + tri["steiner_vertices"]
    start = time.perf_counter()
    result = stickmorph.morph(source.tolist(), target.tolist(), edges, frames=frames)
    row["morph_total_ms"] = 1e3 * (time.perf_counter() - start)
    ms = result["stats"]["milliseconds"]
    row["rigid_triangulate_ms"] = ms["triangulate"]
    row["rigid_morph_ms"] = ms["morph"]
    row["rigid_frame_ms"] = ms["morph"] / frames
    times = np.linspace(0.0, 1.0, playback)
    for name, make in (("barycentric", lambda: stickmorph.MorphSolver(tri, edges)),
                       ("rigid", lambda: stickmorph.RigidMorphSolver(source.tolist(), target.tolist(), edges))):
        start = time.perf_counter()
        solver = make()
        row[f"{name}_setup_ms"] = 1e3 * (time.perf_counter() - start)
        start = time.perf_counter()
        for t in times:
            solver.solve(float(t))
        elapsed = time.perf_counter() - start
        row[f"{name}_fps"] = playback / elapsed
    import resource
    row["peak_mib"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return row


def child(args):
    row = run_case(args.case_shape, args.case_n, args.seed, args.frames, args.playback)
    print(json.dumps(row))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(REPO / "build"), help="build directory (python/ holds the module)")
    parser.add_argument("--sizes", default="1000,10000")
    parser.add_argument("--shapes", default=",".join(SHAPES))
    parser.add_argument("--frames", type=int, default=50)
    parser.add_argument("--playback", type=int, default=240)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--json")
    parser.add_argument("--case-shape", help=argparse.SUPPRESS)
    parser.add_argument("--case-n", type=int, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    sys.path.insert(0, str(pathlib.Path(args.build).resolve() / "python"))
    if args.case_shape:
        child(args)
        return 0
    rows = []
    for n in [int(s) for s in args.sizes.split(",")]:
        for shape in args.shapes.split(","):
            if shape not in SHAPES:
                parser.error(f"unknown shape {shape!r} (choose from {', '.join(SHAPES)})")
            command = [sys.executable, __file__, "--build", args.build, "--case-shape", shape, "--case-n", str(n),
                       "--seed", str(args.seed), "--frames", str(args.frames), "--playback", str(args.playback)]
            start = time.perf_counter()
            process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
            out, err = process.communicate()
            wall = time.perf_counter() - start
            if process.returncode != 0:
                message = err.decode("utf-8", "replace").strip().splitlines()
                rows.append({"shape": shape, "n": n, "error": message[-1] if message else f"exit {process.returncode}"})
            else:
                row = json.loads(out.decode().strip().splitlines()[-1])
                row["wall_s"] = wall
                rows.append(row)
            print(json.dumps(rows[-1]), file=sys.stderr, flush=True)
    print("| shape | n | nodes | Steiner | triangulate | rigid morph, 50 frames | rigid frame | "
          "playback fps barycentric | playback fps rigid | peak MiB | how |")
    print("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|")
    for r in rows:
        if "error" in r:
            print(f"| {r['shape']} | {r['n']} | | | failed: {r['error']} | | | | | | |")
            continue
        print(f"| {r['shape']} | {r['n']} | {r['nodes']} | {r['steiner']} | {r['triangulate_ms'] / 1e3:.2f} s | "
              f"{r['rigid_morph_ms'] / 1e3:.2f} s | {r['rigid_frame_ms']:.1f} ms | {r['barycentric_fps']:.0f} | "
              f"{r['rigid_fps']:.0f} | {r['peak_mib']:.0f} | {r['how']} |")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(rows, indent=1) + "\n")
    return 0 if all("error" not in r for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
