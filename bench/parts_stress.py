#!/usr/bin/env python3
"""Stress `stickmorph morph` with large, harsh figures of several parts, checked exactly.

    /usr/bin/python3 bench/parts_stress.py [--stickmorph build/stickmorph] [--seed S] [--count N]
        [--max-vertices V] [--min-vertices V] [--frames F] [--offset D] [--methods rigid,barycentric]
        [--timeout S] [--keep DIR] [--json REPORT]

Much harsher than bench/multipart_corpus.py. Each pair is a random scene of *clusters*: rings
(polygons inscribed in circles, some star-shaped, some squares with exactly collinear vertices on
their sides) nested 2-5 deep around one centre with gaps of 1-5% of the radius; in every annulus
bands of dots (lone vertices), arc strokes, radial strokes of collinear vertices and tiny
satellite clusters of their own; a tree or a grid of dots in the innermost ring. Clusters have
scales spread over 1e4 (a tiny cluster next to a huge one) and are packed with their
circumcircles 0.1-2% apart (parts near each other's convex hull), dots sit between clusters,
and the whole figure is 1e6 away from the origin. Figures have min-vertices..max-vertices
vertices and 50-500 parts (default 300..700 vertices, so that the default run stays within about
two minutes; the harsh sizes are --min-vertices 1000 --max-vertices 10000).

The target turns every ring, band and satellite independently about its cluster's centre by up
to +-180 degrees (some by exact quarter turns, which keep collinear vertices collinear), turns
every cluster as a whole, and turns, scales and moves the whole figure. Every turned piece stays
in its annulus, so the target keeps every vertex's order of neighbours, every part's outer face
and the nesting; that is checked anyway, exactly, with bench/multipart_check.py's functions
(a target that fails is regenerated, and reported if it keeps failing).

For each pair and each method (`--methods`, default the rigid default and barycentric) the
script runs `stickmorph morph SRC TGT -o OUT --frames F [--method M]` and checks the output with
multipart_check.check_index_morph: F frames of n points, the input's edges, first and last frame
the source and target bit for bit, and every frame a plane graph with the source's rotation
system, outer faces and nesting, in exact integer arithmetic. It prints a table (parts,
vertices, bridge_vertices and steiner_vertices from stats, the engine's triangulate and morph
milliseconds, wall seconds, peak RSS of the CLI) and lists failures, runs slower than 10 s and
runs above 2 GB; each CLI run is limited to --memory-mb of address space (default 4096) and
--timeout seconds (default 300). Exit 1 on any failure, 2 on bad usage.

The pairs are written to --keep DIR (default a temporary folder, removed unless a pair failed).
The default run (10 pairs of 300-700 vertices, 2 methods) is meant to take under two minutes on
2 cores.
"""
import argparse
import json
import math
import os
import pathlib
import random
import resource
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import multipart_check as mc  # noqa: E402  (the exact checker, shared on purpose)

SLOW_SECONDS = 10.0
BIG_RSS_KB = 2 * 1024 * 1024


class Figure:
    """Source and target positions on one edge set, built part by part."""

    def __init__(self):
        self.source, self.target, self.edges = [], [], []
        self.parts = 0

    def add(self, source, target, edges=()):
        base = len(self.source)
        self.source += source
        self.target += target
        self.edges += [(base + a, base + b) for a, b in edges]
        self.parts += 1


def rot(p, angle):
    """p turned by angle; multiples of a quarter turn exactly (coordinate swaps)."""
    q = angle / (math.pi / 2)
    if abs(q - round(q)) < 1e-12:
        k = int(round(q)) % 4
        x, y = p
        return [(x, y), (-y, x), (-x, -y), (y, -x)][k]
    c, s = math.cos(angle), math.sin(angle)
    return (c * p[0] - s * p[1], s * p[0] + c * p[1])


def random_turn(rng):
    """Up to +-180 degrees; one in five an exact quarter turn (or a half turn, or none)."""
    if rng.random() < 0.2:
        return rng.choice([-2, -1, 0, 1, 2]) * math.pi / 2
    return rng.uniform(-math.pi, math.pi)


class Cluster:
    """Rings nested around the origin (local units, core radius 1), with bands of dots and
    strokes between them. Pieces: (source points, edges, turn) in local coordinates; a piece's
    target is its source turned about the centre. Satellites: nested clusters in a band."""

    def __init__(self, rng, vertex_budget, part_budget, depth, allow_satellites, scale_ratio):
        self.pieces = []      # (points, edges, turn): each one part
        self.satellites = []  # (Cluster, centre (local), scale, band turn, its own turn)
        self.radius = 1.0
        self.vertex_count = 0
        self.part_count = 0
        self._core(rng, vertex_budget, part_budget)
        ring_vertices = max(3, int(vertex_budget * 0.6 / depth))
        item_parts = max(0, part_budget - depth - self.part_count)
        for level in range(depth):
            gap = rng.uniform(0.01, 0.05)
            inner = self.radius * (1 + gap)
            band = (self.radius, inner)
            shape = rng.random()
            if shape < 0.25:
                sides, pull, phase = 4, 0.0, math.pi / 4  # a square: axis-parallel sides
            else:
                sides = max(3, int(ring_vertices * rng.uniform(0.3, 1.0)))
                pull = rng.uniform(0.0, 0.08) if shape < 0.5 else 0.0
                phase = rng.uniform(0, 2 * math.pi)
            radius = inner / ((1 - pull) * math.cos(math.pi / sides))
            self._bands(rng, band, item_parts // (4 * depth) + (1 if rng.random() < 0.5 else 0),
                        int(vertex_budget * 0.3 / depth), allow_satellites, scale_ratio)
            self._ring(rng, sides, radius, pull, phase, ring_vertices if sides == 4 else 0)
            self.radius = radius

    # -- pieces -------------------------------------------------------------------------------
    def _piece(self, points, edges, turn):
        self.pieces.append((points, edges, turn))
        self.vertex_count += len(points)
        self.part_count += 1

    def _core(self, rng, vertex_budget, part_budget):
        kind = rng.choice(["tree", "dots", "both", "none"])
        if kind in ("tree", "both"):
            arms = rng.randint(3, 7)
            per_arm = max(1, min(12, vertex_budget // 40))
            pts, edges = [(0.0, 0.0)], []
            for a in range(arms):
                angle = 2 * math.pi * a / arms + rng.uniform(-0.2, 0.2)
                prev = 0
                for k in range(1, per_arm + 1):
                    r = 0.5 * k / per_arm
                    pts.append((r * math.cos(angle), r * math.sin(angle)))  # collinear along the arm
                    edges.append((prev, len(pts) - 1))
                    prev = len(pts) - 1
            self._piece(pts, edges, random_turn(rng))
        if kind in ("dots", "both"):
            count = rng.randint(1, max(1, min(30, part_budget // 4)))
            r0 = 0.6 if kind == "dots" else 0.75  # beyond the tree's reach (0.5) when both
            ring_dots = [(r0 * math.cos(2 * math.pi * k / count), r0 * math.sin(2 * math.pi * k / count))
                         for k in range(count)]
            turn = random_turn(rng)
            for p in ring_dots:
                self._piece([p], [], turn)

    def _bands(self, rng, band, items, vertex_budget, allow_satellites, scale_ratio):
        lo0, hi0 = band
        items = max(1, min(items, 6))
        width = (hi0 - lo0) / items
        for j in range(items):
            lo, hi = lo0 + width * (j + 0.2), lo0 + width * (j + 0.8)
            turn = random_turn(rng)
            kind = rng.random()
            if allow_satellites and kind < 0.15:
                # A tiny cluster of its own in this band, turned with it.
                scale = min((hi - lo) * 0.4, scale_ratio)
                sub = Cluster(rng, 40, 6, rng.randint(1, 2), False, scale_ratio)
                s = scale / sub.radius
                rho = (lo + hi) / 2
                angle = rng.uniform(0, 2 * math.pi)
                self.satellites.append((sub, (rho * math.cos(angle), rho * math.sin(angle)), s, turn,
                                        random_turn(rng)))
                self.vertex_count += sub.vertex_count
                self.part_count += sub.part_count
            elif kind < 0.55:
                count = rng.randint(1, 12)
                rho = (lo + hi) / 2
                start = rng.uniform(0, 2 * math.pi)
                for k in range(count):
                    a = start + 2 * math.pi * k / count
                    self._piece([(rho * math.cos(a), rho * math.sin(a))], [], turn)
            elif kind < 0.85:
                step = 2 * math.acos(lo / hi) * 0.9
                m = max(2, min(int(vertex_budget / items) or 2, int(1.8 * math.pi / step) + 1, 400))
                start = rng.uniform(0, 2 * math.pi)
                pts = [(hi * math.cos(start + step * k), hi * math.sin(start + step * k)) for k in range(m)]
                self._piece(pts, [(k, k + 1) for k in range(m - 1)], turn)
            else:
                # Collinear vertices on a ray; exactly collinear on an axis.
                angle = rng.choice([0.0, math.pi / 2, math.pi, rng.uniform(0, 2 * math.pi)])
                m = rng.randint(3, 8)
                c, s = (1.0, 0.0) if angle == 0.0 else (math.cos(angle), math.sin(angle))
                pts = []
                for k in range(m):
                    r = lo + (hi - lo) * k / (m - 1)
                    pts.append((r * c, r * s) if angle not in (math.pi / 2, math.pi) else
                               ((0.0, r) if angle == math.pi / 2 else (-r, 0.0)))
                self._piece(pts, [(k, k + 1) for k in range(m - 1)], turn)

    def _ring(self, rng, sides, radius, pull, phase, square_vertices):
        if sides == 4:
            # Axis-parallel square with exactly collinear vertices along its sides.
            a = radius * math.cos(math.pi / 4)
            per_side = max(1, min(square_vertices // 4, 200))
            corners = [(a, a), (-a, a), (-a, -a), (a, -a)]
            pts = []
            for k in range(4):
                (x0, y0), (x1, y1) = corners[k], corners[(k + 1) % 4]
                for t in range(per_side):
                    f = t / per_side
                    # one coordinate stays exactly x0 or y0 along the side
                    pts.append((x0 if x0 == x1 else x0 + (x1 - x0) * f, y0 if y0 == y1 else y0 + (y1 - y0) * f))
        else:
            pts = []
            for k in range(sides):
                r = radius * (1 - pull) if k % 2 else radius
                t = phase + 2 * math.pi * k / sides
                pts.append((r * math.cos(t), r * math.sin(t)))
        n = len(pts)
        self._piece(pts, [(k, (k + 1) % n) for k in range(n)], random_turn(rng))

    # -- placement ------------------------------------------------------------------------------
    def emit(self, figure, source_map, target_map):
        """Adds every part; source_map/target_map take local points to the figure's."""
        for pts, edges, turn in self.pieces:
            figure.add([source_map(p) for p in pts], [target_map(rot(p, turn)) for p in pts], edges)
        for sub, centre, s, turn, sub_turn in self.satellites:
            def sub_source(p, centre=centre, s=s):
                return source_map((centre[0] + s * p[0], centre[1] + s * p[1]))

            def sub_target(p, centre=centre, s=s, turn=turn, sub_turn=sub_turn):
                q = rot(p, sub_turn)
                c = rot(centre, turn)
                return target_map((c[0] + s * q[0], c[1] + s * q[1]))
            sub.emit(figure, sub_source, sub_target)


def make_scene(rng, min_vertices, max_vertices, far=1e6):
    vertices = rng.randint(min_vertices, max_vertices)
    parts = rng.randint(50, max(50, min(500, vertices // 4)))
    clusters = rng.randint(3, 10)
    scale_ratio = 1e4
    placed = []  # (centre, radius)
    figure = Figure()
    offset = (far * rng.choice([1, -1]), far * rng.uniform(-1, 1))
    global_turn, global_scale = random_turn(rng), math.exp(rng.uniform(-1, 1))
    shift = (rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3))

    def to_target(p):
        q = rot(p, global_turn)
        return (global_scale * q[0] + offset[0] + shift[0], global_scale * q[1] + offset[1] + shift[1])

    for k in range(clusters):
        cluster = Cluster(rng, vertices // clusters, parts // clusters, rng.randint(2, 5), True, scale_ratio)
        # The first cluster huge, the second tiny beside it, the rest anywhere between.
        scale = 1e4 if k == 0 else 1.0 if k == 1 else math.exp(rng.uniform(0, math.log(1e4)))
        radius = cluster.radius * scale
        centre = (0.0, 0.0)
        for _ in range(200):
            if not placed:
                break
            other_centre, other_radius = rng.choice(placed)
            gap = rng.uniform(0.001, 0.02) * min(radius, other_radius)
            angle = rng.uniform(0, 2 * math.pi)
            d = other_radius + radius + gap
            centre = (other_centre[0] + d * math.cos(angle), other_centre[1] + d * math.sin(angle))
            if all(math.hypot(centre[0] - c[0], centre[1] - c[1]) > r + radius + 0.0005 * min(r, radius)
                   for c, r in placed):
                break
        else:
            continue
        placed.append((centre, radius))
        cluster_turn = random_turn(rng)

        def source_map(p, centre=centre, scale=scale):
            return (centre[0] + scale * p[0] + offset[0], centre[1] + scale * p[1] + offset[1])

        def target_map(p, centre=centre, scale=scale, cluster_turn=cluster_turn):
            q = rot(p, cluster_turn)
            return to_target((centre[0] + scale * q[0], centre[1] + scale * q[1]))
        cluster.emit(figure, source_map, target_map)
    # Dots between the clusters (outside every circumcircle), turned with the whole.
    lo = [min(c[0] - r for c, r in placed), min(c[1] - r for c, r in placed)]
    hi = [max(c[0] + r for c, r in placed), max(c[1] + r for c, r in placed)]
    for _ in range(rng.randint(5, 40)):
        p = (rng.uniform(lo[0], hi[0]), rng.uniform(lo[1], hi[1]))
        if all(math.hypot(p[0] - c[0], p[1] - c[1]) > r * 1.001 for c, r in placed):
            figure.add([(p[0] + offset[0], p[1] + offset[1])], [to_target(p)])
    # Renumber so that parts interleave in index order.
    n = len(figure.source)
    order = list(range(n))
    rng.shuffle(order)  # order[new] = old
    image = [0] * n
    for new, old in enumerate(order):
        image[old] = new
    source = [figure.source[old] for old in order]
    target = [figure.target[old] for old in order]
    edges = [(image[a], image[b]) for a, b in figure.edges]
    return source, target, edges


def part_count(n, edges):
    return max(mc.parts_of(n, edges)) + 1 if n else 0


def figure_json(points, edges, name):
    return {"name": name, "vertices": [[float(x), float(y)] for x, y in points], "edges": [list(e) for e in edges]}


def run_cli(cmd, timeout, memory_mb):
    """(returncode, stdout, stderr, seconds, peak RSS KB) of one CLI run, its address space
    limited to memory_mb (a morph that wants more fails instead of waking the OOM killer)."""
    def limit():
        if memory_mb:
            resource.setrlimit(resource.RLIMIT_AS, (memory_mb << 20, memory_mb << 20))
    start = time.monotonic()
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        proc = subprocess.Popen(cmd, stdout=out, stderr=err, stdin=subprocess.DEVNULL, preexec_fn=limit)
        try:
            deadline = start + timeout
            while True:
                pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
                if pid:
                    break
                if time.monotonic() > deadline:
                    proc.kill()
                    pid, status, usage = os.wait4(proc.pid, 0)
                    proc.returncode = -9
                    return None, "", f"timed out after {timeout} s", time.monotonic() - start, usage.ru_maxrss
                time.sleep(0.02)
        finally:
            if proc.returncode is None and proc.poll() is None:
                proc.kill()
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        return (proc.returncode, out.read().decode(errors="replace"), err.read().decode(errors="replace"),
                time.monotonic() - start, usage.ru_maxrss)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--stickmorph", default="build/stickmorph")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count", type=int, default=10)
    ap.add_argument("--min-vertices", type=int, default=300)
    ap.add_argument("--max-vertices", type=int, default=700)
    ap.add_argument("--memory-mb", type=int, default=4096,
                    help="address-space limit of each CLI run (0: none); default 4096")
    ap.add_argument("--frames", type=int, default=4)
    ap.add_argument("--offset", type=float, default=1e6,
                    help="distance of the figures from the origin (default 1e6; 0 to tell precision apart)")
    ap.add_argument("--methods", default="rigid,barycentric")
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--keep", type=pathlib.Path)
    ap.add_argument("--json", type=pathlib.Path)
    args = ap.parse_args(argv)
    if args.count < 1 or args.frames < 2 or args.min_vertices < 1 or args.max_vertices < args.min_vertices:
        ap.error("need --count >= 1, --frames >= 2 and 1 <= --min-vertices <= --max-vertices")
    cli = pathlib.Path(args.stickmorph)
    if not cli.exists():
        print(f"parts_stress: {cli} not found (build it first)", file=sys.stderr)
        return 2
    methods = [m for m in args.methods.split(",") if m]
    workdir = args.keep or pathlib.Path(tempfile.mkdtemp(prefix="parts_stress_"))
    workdir.mkdir(parents=True, exist_ok=True)
    rows, failures = [], []
    started = time.monotonic()
    for index in range(args.count):
        pair_seed = args.seed * 1000003 + index
        rng = random.Random(pair_seed)
        name = f"stress_s{args.seed}_{index}"
        gen_start = time.monotonic()
        for attempt in range(5):
            for _ in range(100):  # 50-500 parts (generating is cheap; checking is not)
                source, target, edges = make_scene(rng, args.min_vertices, args.max_vertices, args.offset)
                if 50 <= part_count(len(source), edges) <= 500:
                    break
            bad = mc.plane_problems(source, edges)
            if not bad:
                topo = mc.Topology(source, edges)
                bad = topo.frame_problems(target)
            if not bad:
                break
        else:
            failures.append(f"{name}: generator: no valid target in 5 attempts: {bad[:2]}")
            continue
        gen_seconds = time.monotonic() - gen_start
        src_path, tgt_path = workdir / f"{name}.source.json", workdir / f"{name}.target.json"
        src_path.write_text(json.dumps(figure_json(source, edges, name + " source")))
        tgt_path.write_text(json.dumps(figure_json(target, edges, name + " target")))
        for method in methods:
            out = workdir / f"{name}.{method}.morph.json"
            if out.exists():
                out.unlink()
            cmd = [str(cli), "morph", str(src_path), str(tgt_path), "-o", str(out), "--frames", str(args.frames)]
            if method != "rigid":
                cmd += ["--method", method]
            code, stdout, stderr, seconds, rss = run_cli(cmd, args.timeout, args.memory_mb)
            row = {"pair": name, "method": method, "seed": pair_seed, "vertices": len(source),
                   "parts": topo.count, "edges": len(edges), "result": "ok", "seconds": round(seconds, 2),
                   "rss_mb": round(rss / 1024, 1), "generate_seconds": round(gen_seconds, 2),
                   "command": " ".join(cmd), "problems": []}
            if code != 0:
                row["problems"].append(f"exit {code}: {stderr.strip().splitlines()[:1]}")
            else:
                doc = json.loads(out.read_text())
                stats = doc.get("stats", {})
                ms = stats.get("milliseconds", {})
                row.update(bridge_vertices=stats.get("bridge_vertices"), steiner_vertices=stats.get("steiner_vertices"),
                           stats_parts=stats.get("parts"), triangulate_ms=ms.get("triangulate"), morph_ms=ms.get("morph"),
                           verify_ms=ms.get("verify"))
                if stats.get("parts") != topo.count:
                    row["problems"].append(f"stats.parts {stats.get('parts')}, the figure has {topo.count}")
                check_start = time.monotonic()
                row["problems"] += mc.check_index_morph((source, edges), (target, edges), doc, args.frames)
                row["check_seconds"] = round(time.monotonic() - check_start, 2)
                out.unlink()  # large; the inputs and the command reproduce it
            if row["problems"]:
                row["result"] = "FAIL"
                failures.append(f"{name} {method}: {'; '.join(row['problems'])[:400]}\n    reproduce: {' '.join(cmd)}")
            if seconds > SLOW_SECONDS:
                row["slow"] = True
            if rss > BIG_RSS_KB:
                row["big"] = True
            rows.append(row)
            print(f"  {name} {method}: {row['result']} in {seconds:.1f} s", file=sys.stderr, flush=True)

    head = ["pair", "method", "parts", "vertices", "bridge_v", "steiner_v", "tri ms", "morph ms", "wall s", "RSS MB",
            "result"]

    def cell(v, fmt="{}"):
        return "-" if v is None else fmt.format(v)
    body = [[r["pair"], r["method"], cell(r["parts"]), cell(r["vertices"]), cell(r.get("bridge_vertices")),
             cell(r.get("steiner_vertices")), cell(r.get("triangulate_ms"), "{:.0f}"), cell(r.get("morph_ms"), "{:.0f}"),
             cell(r["seconds"], "{:.1f}"), cell(r["rss_mb"], "{:.0f}"),
             r["result"] + (" SLOW" if r.get("slow") else "") + (" BIG" if r.get("big") else "")] for r in rows]
    widths = [max([len(h)] + [len(b[k]) for b in body]) for k, h in enumerate(head)]
    print("  ".join(h.ljust(w) for h, w in zip(head, widths)))
    for b in body:
        print("  ".join(c.ljust(w) for c, w in zip(b, widths)))
    slow = [r for r in rows if r.get("slow")]
    big = [r for r in rows if r.get("big")]
    print(f"\n{len(rows)} runs, {sum(r['result'] == 'ok' for r in rows)} ok, {len(failures)} failures, "
          f"{len(slow)} slower than {SLOW_SECONDS:.0f} s, {len(big)} above 2 GB; "
          f"{time.monotonic() - started:.0f} s in all; pairs in {workdir}")
    for r in slow:
        print(f"slow: {r['pair']} {r['method']}: {r['seconds']:.1f} s ({r['vertices']} vertices, {r['parts']} parts)")
    for f in failures:
        print("FAIL: " + f)
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1))
    if not failures and args.keep is None:
        shutil.rmtree(workdir, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
