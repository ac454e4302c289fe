#!/usr/bin/env python3
"""Measure issue 32's drawing cleaning (`stickmorph clean`) on bench/drawing_corpus.py's drawings,
checking the contract independently.

    /usr/bin/python3 bench/cleaning.py CORPUS --build-dir build --json OUT.json
                     [--only NAME] [--keep DIR] [--frames N] [--no-refusals]

CORPUS holds the drawings and the manifest.json of bench/drawing_corpus.py (every planted gap,
touch, crossing and duplicate point listed). For every drawing the CLI runs
`stickmorph clean NAME.json -o NAME.clean.json` (the default tolerance, 1% of the drawing's
bounding-box diagonal) and this script checks:

  valid       the output is a valid stick figure: `stickmorph check OUT OUT` exits 0, and
              independently, in exact rational arithmetic on the doubles (fractions.Fraction,
              bench/correspondence_check.py's plane_problems): no two edges cross or overlap, no
              vertex lies on an edge that does not end at it, no two vertices coincide; no edge
              from a vertex to itself and none twice
  limits      docs/FORMAT.md's: a merge joins a point to one drawn within the merge distance
              (tolerance / 100) of it, or is a point of a tail (from a snapped point to its stroke's
              end, all on the snap's vertex, each drawn within the tolerance of another stroke);
              a snap moves a free end (with its pen pauses) or a tail's inner end, by at most the
              tolerance
  accounted   every change is reported: each input point lands on its vertex (point_vertices)
              exactly where it was drawn, unless a merge or snap change names that stroke and
              point with the distance it moved (within 1e-12, relative) and `at` its vertex; every
              merge and snap change says how far its point really moved; each stroke's path
              (cleaning.strokes) runs along the figure's edges and every edge lies on a path (on two
              only within the tolerance: counted, snapping makes that of strokes meeting at a
              shallow angle; a run of such edges longer than the tolerance is an overlap); the
              path passes through its points' vertices in order, and any vertex between two of
              them lies on their segment as drawn or between where they went when one of them
              moved (within 1e-9 of the size: a crossing's point rounded), or, when one of them
              moved, on a straight piece between an earlier and a later vertex of the path there
              no further from the drawn segment than the point moved (the stroke from its last
              junction to a snapped end is drawn anew, and later junctions land on it). Not a failure but
              counted, a *bend*: a vertex where a change names the stroke within the merge distance
              (tolerance / 100) of the segment, a crossing that fell that close to another stroke's
              point put on that point. Every vertex that two strokes share, or one stroke at two
              places that are not neighbours along it, is explained for each of those strokes by a
              crossing, touch, snap or merge change at that vertex naming the stroke, or by an
              input point of that stroke drawn exactly there; the summary counts are the changes'
              counts
  found       the planted defects against the manifest: a gap is closed when the end's vertex is on
              the stroke it stopped short of (however the engine did it: the end snapped, or the
              other stroke's end snapped onto it); a crossing when one vertex within 2/10000 of the
              size of the planted crossing lies on both strokes (and is reported as a crossing); a
              touch when the end's vertex is on the stroke it touched; a duplicate when it became
              the vertex of the point before it. Changes the manifest does not explain are counted
              too (snaps of ends the manifest has as free, crossings it does not have), and so are
              *stubs*: free ends of the cleaned figure less than the tolerance along it from a
              junction (the corpus draws none, so each is one the cleaning left, an end snapped next
              to another stroke's end, which then sticks out)
  idempotent  cleaning the output figure again (a figure file: stroke i = edge i) with the
              tolerance the first cleaning used reports no change and gives the same vertices and
              edges, bit for bit; also with the default tolerance (the cleaned figure's own box)
  morph       for every pair of poses: `stickmorph morph A.clean.json B.clean.json -o M.json
              --correspond auto --frames N` succeeds (the CLI verifies every frame exactly) and
              frames[0] is a subdivision of cleaned A (its vertices bit for bit, dummies on its
              edges), the last frame of cleaned B (bench/correspondence_check.py's
              subdivision_problems)
  refusals    drawings `clean` must refuse, made from the corpus's first drawing: no strokes, a
              stroke of one point, a stroke that runs along part of another, a stroke that retraces
              itself; each must exit 2 with one `error:` line naming the stroke (--no-refusals skips)

It prints a table per kind of drawing and in all, the pairs, every failure with its file, and
writes everything to --json (the cleaning.json that bench/make_benchmarks.py reads, with one
drawing before and after for the report's figure). Exits 0 when it measured (whatever it found),
2 for a bad command line or corpus.
"""
import argparse
import json
import math
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import correspondence_check as cc  # noqa: E402  (exact plane-graph test, subdivision check)

REPO = pathlib.Path(__file__).resolve().parents[1]
TIMEOUT_SECONDS = 300
RELATIVE = 1e-12  # a reported distance against the one measured here
ON_SEGMENT = 1e-9  # a vertex put between two points: off their segment by at most this, of the size
CROSSING_MATCH = 2e-4  # a planted crossing found within this of the size (twice the merge distance)
MERGE_FRACTION = 0.01  # the engine's merge distance, of the tolerance (`stickmorph clean --help`)
DEFAULT_FRAMES = 20
KINDS = ("merge", "snap", "crossing", "touch")
MAX_PROBLEMS = 12


def close(reported, measured):
    """Whether a reported distance is the measured one within RELATIVE."""
    return abs(reported - measured) <= RELATIVE * max(abs(reported), abs(measured), 1e-300)


# ---------------------------------------------------------------------------
# reading

def read_drawing(path):
    """[(points as tuples, cyclic)] of a drawing file."""
    doc = json.loads(pathlib.Path(path).read_text())
    return [([tuple(map(float, p)) for p in s["points"]], bool(s.get("cyclic", False))) for s in doc["strokes"]]


def drawing_size(drawing):
    pts = np.array([p for points, _ in drawing for p in points], dtype=float).reshape(-1, 2)
    return float(np.hypot(*(pts.max(axis=0) - pts.min(axis=0)))) if len(pts) else 0.0


def figure_of(doc):
    return [tuple(map(float, v)) for v in doc["vertices"]], [tuple(map(int, e)) for e in doc["edges"]]


# ---------------------------------------------------------------------------
# the checks, on the output document alone (no CLI)

def structure_problems(drawing, doc):
    """Whether the output has what the contract says, indices in range (other checks need it)."""
    problems = []
    for key in ("vertices", "edges", "cleaning"):
        if key not in doc:
            return [f"the output has no {key!r}"]
    c = doc["cleaning"]
    for key in ("tolerance", "junctions_made", "ends_snapped", "points_merged", "changes", "strokes",
                "point_vertices"):
        if key not in c:
            problems.append(f"cleaning has no {key!r}")
    if problems:
        return problems
    n = len(doc["vertices"])
    if len(c["strokes"]) != len(drawing) or len(c["point_vertices"]) != len(drawing):
        return [f"cleaning.strokes/point_vertices have {len(c['strokes'])}/{len(c['point_vertices'])} entries for "
                f"{len(drawing)} strokes"]
    for i, ((points, _), pv, path) in enumerate(zip(drawing, c["point_vertices"], c["strokes"])):
        if len(pv) != len(points):
            problems.append(f"stroke {i}: {len(pv)} point vertices for {len(points)} points")
        if any(not isinstance(v, int) or not 0 <= v < n for v in pv + list(path.get("vertices", []))):
            problems.append(f"stroke {i}: a vertex index outside 0..{n - 1}")
    for e in doc["edges"]:
        if len(e) != 2 or any(not isinstance(v, int) or not 0 <= v < n for v in e):
            problems.append(f"edge {e} is not two vertices of 0..{n - 1}")
            break
    for k, ch in enumerate(c["changes"]):
        if ch.get("kind") not in KINDS or not isinstance(ch.get("stroke"), int) \
                or not 0 <= ch["stroke"] < len(drawing) or "at" not in ch or "distance" not in ch:
            problems.append(f"change {k} is malformed: {ch}")
            continue
        point = ch.get("point")
        if point is not None and not 0 <= point < len(drawing[ch["stroke"]][0]):
            problems.append(f"change {k} names point {point} of stroke {ch['stroke']}, which has "
                            f"{len(drawing[ch['stroke']][0])}")
        other = ch.get("other_stroke")
        if other is not None and not 0 <= other < len(drawing):
            problems.append(f"change {k} names stroke {other}")
    return problems[:MAX_PROBLEMS]


def validity_problems(doc):
    """The exact plane-graph test of the cleaned figure (independent of the engine)."""
    vertices, edges = figure_of(doc)
    problems = []
    seen = set()
    for k, (u, v) in enumerate(edges):
        if u == v:
            problems.append(f"edge {k} joins vertex {u} to itself")
        key = frozenset((u, v))
        if key in seen:
            problems.append(f"edge {k} ({u}, {v}) is there twice")
        seen.add(key)
    if problems:
        return problems[:MAX_PROBLEMS]
    return cc.plane_problems(vertices, edges, limit=MAX_PROBLEMS)


def changes_at(changes, vertices):
    """Per vertex, the changes whose `at` is that vertex (exactly), and the changes whose `at`
    is no vertex."""
    where = {}
    for v, p in enumerate(vertices):
        where.setdefault(p, v)
    by_vertex, stray = {}, []
    for k, ch in enumerate(changes):
        at = tuple(map(float, ch["at"]))
        v = where.get(at)
        if v is None:
            stray.append(k)
        else:
            by_vertex.setdefault(v, []).append(ch)
    return by_vertex, stray


def path_steps(path, cyclic):
    steps = list(zip(path, path[1:]))
    if cyclic and len(path) > 2:
        steps.append((path[-1], path[0]))
    return steps


def accounting_problems(drawing, doc, size, bends=None, shared_edges=None):
    """Whether every change is reported (the module docstring's "accounted"). `bends` gets the
    strokes bent through a junction within the merge distance (path_order_problems), `shared_edges`
    the edges on two strokes' paths that are within the tolerance."""
    vertices, edges = figure_of(doc)
    c = doc["cleaning"]
    changes = c["changes"]
    pv = c["point_vertices"]
    problems = []
    merge = float(c["tolerance"]) * MERGE_FRACTION
    by_vertex, stray = changes_at(changes, vertices)
    named_at = {}
    for v, mine in by_vertex.items():
        for ch in mine:
            named_at.setdefault(v, set()).update(x for x in (ch["stroke"], ch.get("other_stroke")) if x is not None)

    def add(text):
        problems.append(text)
        return len(problems) >= MAX_PROBLEMS

    named = {}
    for ch in changes:
        if ch["kind"] in ("merge", "snap") and ch.get("point") is not None:
            named.setdefault((ch["stroke"], ch["point"]), []).append(ch)
    # input points where they were drawn, or a merge/snap that says how far they moved
    for i, (points, _) in enumerate(drawing):
        for j, p in enumerate(points):
            q = vertices[pv[i][j]]
            moved = math.hypot(q[0] - p[0], q[1] - p[1])
            mine = named.get((i, j), [])
            if q == p:
                continue
            if not mine:
                if add(f"point {j} of stroke {i} moved by {moved:.6g} ({moved / size:.3g} of the size) to vertex "
                       f"{pv[i][j]} at {list(q)}, and no merge or snap change names it"):
                    return problems
                continue
            if not any(close(float(ch["distance"]), moved) for ch in mine):
                if add(f"point {j} of stroke {i} moved by {moved!r}; its change says "
                       f"{[ch['distance'] for ch in mine]}"):
                    return problems
    for (i, j), mine in named.items():
        p, q = drawing[i][0][j], vertices[pv[i][j]]
        moved = math.hypot(q[0] - p[0], q[1] - p[1])
        for ch in mine:
            if not close(float(ch["distance"]), moved):
                if add(f"a {ch['kind']} change of point {j} of stroke {i} says {ch['distance']!r}, the point moved "
                       f"{moved!r}"):
                    return problems
            if tuple(map(float, ch["at"])) != q:
                if add(f"a {ch['kind']} change of point {j} of stroke {i} is at {ch['at']}, its vertex {pv[i][j]} at "
                       f"{list(q)}"):
                    return problems
    # the paths: along the edges, every edge on one, through the points' vertices in order
    edge_set = {frozenset(e) for e in edges}
    used = {}
    for i, ((points, cyclic), path) in enumerate(zip(drawing, c["strokes"])):
        verts = list(path["vertices"])
        for a, b in path_steps(verts, bool(path.get("cyclic"))):
            key = frozenset((a, b))
            if a == b or key not in edge_set:
                if add(f"stroke {i}'s path steps from vertex {a} to {b}, which is no edge"):
                    return problems
            used.setdefault(key, []).append(i)
        problems += path_order_problems(i, points, cyclic, pv[i], verts, bool(path.get("cyclic")), vertices, size,
                                        named_at, merge, bends)
        if len(problems) >= MAX_PROBLEMS:
            return problems
    unused = [e for e in edges if frozenset(e) not in used]
    if unused:
        add(f"edges {unused[:5]} ({len(unused)}) lie on no stroke's path")
    # Two strokes along one edge: an overlap, unless the edge is within the tolerance (snapping and
    # merging make that of two strokes meeting at a shallow angle; the engine keeps it, once)
    # (a run of such edges longer than the tolerance, even of short edges, is an overlap)
    tol = float(c["tolerance"])
    twice = {tuple(sorted(k)): tuple(sorted(set(v))) for k, v in used.items() if len(v) > 1}
    for strokes_pair, length, run in shared_runs(twice, vertices):
        if length > tol:
            add(f"strokes {list(strokes_pair)} run along each other for {length:.6g} ({length / tol:.3g} tolerances, "
                f"{len(run)} edges on both paths): an overlap along a length, which the contract refuses")
        elif shared_edges is not None:
            shared_edges.extend(run)
    # shared vertices explained
    if stray:
        add(f"changes {stray[:5]} are at no vertex of the figure")
    places = {}
    for i, path in enumerate(c["strokes"]):
        verts = list(path["vertices"])
        for pos, v in enumerate(verts):
            places.setdefault(v, []).append((i, pos, len(verts), bool(path.get("cyclic"))))
    exact_points = {}
    for i, (points, _) in enumerate(drawing):
        for j, p in enumerate(points):
            if vertices[pv[i][j]] == p:
                exact_points.setdefault(pv[i][j], {}).setdefault(i, []).append(j)
    for v, occ in places.items():
        strokes = sorted({i for i, *_ in occ})
        self_twice = [i for i in strokes if not_neighbours([(p, n, cyc) for s, p, n, cyc in occ if s == i])]
        if len(strokes) < 2 and not self_twice:
            continue
        named_here = set()
        for ch in by_vertex.get(v, []):
            named_here.add(ch["stroke"])
            if ch.get("other_stroke") is not None:
                named_here.add(ch["other_stroke"])
        for i in strokes:
            drawn_here = exact_points.get(v, {}).get(i, [])
            if i in self_twice:
                ok = i in named_here or len(drawn_here) >= 2
            else:
                ok = i in named_here or drawn_here
            if not ok:
                if add(f"vertex {v} at {list(vertices[v])} is shared by strokes {strokes} (stroke {i} "
                       f"{'twice' if i in self_twice else ''}), and nothing explains stroke {i} there: no change there "
                       f"names it, no point of it was drawn there"):
                    return problems
    # the summary counts
    count = {k: sum(1 for ch in changes if ch["kind"] == k) for k in KINDS}
    expected = {"junctions_made": count["crossing"] + count["touch"], "ends_snapped": count["snap"],
                "points_merged": count["merge"]}
    for key, value in expected.items():
        if c[key] != value:
            add(f"cleaning.{key} is {c[key]}, the changes have {value}")
    return problems


def limit_problems(drawing, doc):
    """The contract's limits (docs/FORMAT.md, `clean`). A merge joins a point to one drawn within
    the merge distance (tolerance / 100) of it, or is a point of a *tail*: the run from a snapped
    point to its stroke's end, every point of it on the snap's vertex, each drawn within the
    tolerance of another stroke (or of a far part of its own). A snap moves a free end (with its
    pen pauses) or a tail's inner end: every point from it to one end of its open stroke is on its
    vertex; by at most the tolerance."""
    c = doc["cleaning"]
    tol = float(c["tolerance"])
    merge = tol * MERGE_FRACTION
    slack = 1 + 1e-9
    pv = c["point_vertices"]
    on_vertex = {}
    for i, row in enumerate(pv):
        for j, v in enumerate(row):
            on_vertex.setdefault(v, []).append((i, j))
    snapped = {}
    for ch in c["changes"]:
        if ch["kind"] == "snap" and ch.get("point") is not None:
            snapped.setdefault((ch["stroke"], pv[ch["stroke"]][ch["point"]]), []).append(ch["point"])

    def run_to_end(i, j):
        """The points from j to the end of open stroke i that j's side reaches, if all are on j's
        vertex (else None): j..last or 0..j."""
        points, cyclic = drawing[i]
        if cyclic:
            return None
        v = pv[i][j]
        for run in (range(j, len(points)), range(0, j + 1)):
            if all(pv[i][k] == v for k in run):
                return run
        return None

    def tail_point(i, j):
        v = pv[i][j]
        for s in snapped.get((i, v), []):
            run = run_to_end(i, s)
            if run is not None and j in run:
                return run
        return None

    def near_elsewhere(i, j, run):
        """Whether point j of stroke i was drawn within the tolerance of another stroke, or of its
        own stroke away from its tail (the tail's segments and the one before it left out)."""
        p = np.array(drawing[i][0][j], dtype=float)
        for k, (points, cyclic) in enumerate(drawing):
            pts = np.array(points, dtype=float)
            if len(pts) < 2:
                continue
            a, b = (pts, np.roll(pts, -1, axis=0)) if cyclic else (pts[:-1], pts[1:])
            d = b - a
            dd = np.maximum(np.einsum("ij,ij->i", d, d), 1e-300)
            tt = np.clip(np.einsum("ij,ij->i", p[None, :] - a, d) / dd, 0.0, 1.0)
            dist = np.hypot(*(a + tt[:, None] * d - p[None, :]).T)
            if k == i:
                lo, hi = min(run) - 1, max(run)  # segments m with m+1 >= lo and m <= hi touch the tail
                keep = np.array([not (lo - 1 <= m <= hi) for m in range(len(a))])
                dist = np.where(keep, dist, np.inf)
            if dist.size and float(dist.min()) <= tol * slack:
                return True
        return False

    problems = []
    for ch in c["changes"]:
        i, j = ch["stroke"], ch.get("point")
        if j is None:
            continue
        v = pv[i][j]
        p = drawing[i][0][j]
        if ch["kind"] == "merge" and float(ch["distance"]) > merge * slack:
            taken = any((k, l) != (i, j) and math.dist(p, drawing[k][0][l]) <= merge * slack
                        for k, l in on_vertex.get(v, []))
            run = None if taken else tail_point(i, j)
            if not taken and run is None:
                problems.append(f"point {j} of stroke {i} merged {ch['distance']:.6g} away ({ch['distance'] / tol:.3g} "
                                f"tolerances) into the vertex at {ch['at']}: no point of that vertex was drawn within "
                                f"tolerance / 100 of it, and it is on no tail of a snapped end")
            elif run is not None and not near_elsewhere(i, j, run):
                problems.append(f"point {j} of stroke {i} merged {ch['distance']:.6g} away ({ch['distance'] / tol:.3g} "
                                f"tolerances) as the tail of a snap at {ch['at']}, but it was drawn more than the "
                                f"tolerance from every other stroke")
        if ch["kind"] == "snap":
            if float(ch["distance"]) > tol * slack:
                problems.append(f"point {j} of stroke {i} snapped {ch['distance']:.6g} ({ch['distance'] / tol:.3g} "
                                f"tolerances) onto stroke {ch.get('other_stroke')}")
            if run_to_end(i, j) is None:
                points, cyclic = drawing[i]
                kind = ", cyclic" if cyclic else ""
                problems.append(f"point {j} of stroke {i} (of {len(points)}{kind}) snapped onto stroke "
                                f"{ch.get('other_stroke')} by {ch['distance']:.6g}: it is no free end, nor a tail's "
                                "inner end (the points beyond it to the stroke's end are elsewhere)")
        if len(problems) >= MAX_PROBLEMS:
            break
    return problems


def shared_runs(twice, vertices):
    """Edges on the paths of the same strokes, joined into runs where they share a vertex:
    [(strokes, total length, [edges])]."""
    by_strokes = {}
    for edge, strokes in twice.items():
        by_strokes.setdefault(strokes, []).append(edge)
    out = []
    for strokes, edges in by_strokes.items():
        parent = {}

        def find(x):
            while parent.setdefault(x, x) != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x

        for u, v in edges:
            parent[find(u)] = find(v)
        runs = {}
        for u, v in edges:
            r = runs.setdefault(find(u), [0.0, []])
            r[0] += math.dist(vertices[u], vertices[v])
            r[1].append((u, v))
        out.extend((strokes, length, run) for length, run in runs.values())
    return out


def segment_fit(q, pa, pb):
    """(distance from q to the line through pa and pb, position along it: 0 at pa, 1 at pb)."""
    d = pb - pa
    dd = float(d @ d)
    t = float((q - pa) @ d / dd) if dd > 0 else 0.0
    return float(np.hypot(*(pa + t * d - q))), t


def not_neighbours(places):
    """Whether a stroke's places (position, path length, cyclic) at one vertex include two that are
    not next to each other along the path (a loop closed, a crossing of the stroke with itself)."""
    if len(places) < 2:
        return False
    positions = sorted(p for p, _, _ in places)
    n, cyc = places[0][1], places[0][2]
    for a in positions:
        for b in positions:
            if b <= a:
                continue
            gap = b - a
            if cyc:
                gap = min(gap, n - gap)
            if gap > 1:
                return True
            # an open path whose first and last vertex are one: closed by the cleaning
            if not cyc and a == 0 and b == n - 1:
                return True
    return False


def path_order_problems(i, points, cyclic, pv, path, path_cyclic, vertices, size, named_at=None, merge=0.0,
                        bends=None):
    """The path passes through its points' vertices in order; what lies between two of them lies
    on the segment between them, as drawn or as cleaned, in order along it. Except: a junction
    within the merge distance of the segment, at a vertex where a change names this stroke (a
    crossing put on another stroke's point that was that close: the stroke bends through it);
    those go to `bends` as (stroke, vertex, distance)."""
    # runs of points on one vertex: (vertex, first input point, last input point)
    runs = [[pv[0], 0, 0]]
    for j, v in enumerate(pv[1:], 1):
        if v != runs[-1][0]:
            runs.append([v, j, j])
        else:
            runs[-1][2] = j
    if cyclic and len(runs) > 1 and runs[-1][0] == runs[0][0]:
        runs.pop()
    seq = [r[0] for r in runs]
    drawn = {}  # (vertex a, vertex b) of consecutive runs: the drawn segment between them
    moves = {}  # and how far its two points moved
    closing = runs + ([runs[0]] if cyclic or path_cyclic else [])
    for r0, r1 in zip(closing, closing[1:]):
        pa, pb = points[r0[2]], points[r1[1]]
        drawn.setdefault((r0[0], r1[0]), (pa, pb))
        moves.setdefault((r0[0], r1[0]), max(math.dist(pa, vertices[r0[0]]), math.dist(pb, vertices[r1[0]])))
    walk = list(path)
    if path_cyclic and walk:
        if seq[0] in walk:
            k = walk.index(seq[0])
            walk = walk[k:] + walk[:k]
        walk = walk + [walk[0]]
    targets = seq + ([seq[0]] if cyclic or path_cyclic else [])
    problems = []
    pos = 0
    if not walk or walk[0] != targets[0]:
        return [f"stroke {i}'s path starts at vertex {walk[0] if walk else None}, its first point's vertex is {seq[0]}"]
    for a, b in zip(targets, targets[1:]):
        start = pos
        pos += 1
        while pos < len(walk) and walk[pos] != b:
            pos += 1
        if pos >= len(walk):
            return [f"stroke {i}'s path does not pass through its points' vertices in order (vertex {b} after {a})"]
        # A vertex put between the two points lies on their segment: as drawn, or between where
        # they went when one of them moved (a reported merge or snap)
        segments = [np.array(drawn.get((a, b), (vertices[a], vertices[b])), dtype=float),
                    np.array([vertices[a], vertices[b]], dtype=float)]
        last_t = [0.0, 0.0]
        run = walk[start:pos + 1]
        for n, v in enumerate(run[1:-1], 1):
            q = np.array(vertices[v])
            fits = [segment_fit(q, pa, pb) for pa, pb in segments]
            k = 0 if fits[0][0] <= fits[1][0] else 1
            off, t = fits[k]
            # When one of the two points moved (a reported snap), the stroke from its last junction
            # to the moved point is drawn straight anew, and later junctions land on that piece:
            # the vertex lies between an earlier and a later vertex of this run, no further from
            # the drawn segment than the point moved.
            if off > ON_SEGMENT * size and fits[0][0] <= moves.get((a, b), 0.0) * (1 + 1e-9) + ON_SEGMENT * size \
                    and any(segment_fit(q, np.array(vertices[x]), np.array(vertices[y]))[0] <= ON_SEGMENT * size
                            and 0 < segment_fit(q, np.array(vertices[x]), np.array(vertices[y]))[1] < 1
                            for x in run[:n] for y in run[n + 1:]):
                continue
            if off > ON_SEGMENT * size and off <= merge * (1 + 1e-9) and last_t[k] < t < 1.0 \
                    and i in (named_at or {}).get(v, set()):
                if bends is not None:
                    bends.append((i, v, off))
                last_t[k] = t
                continue
            if off > ON_SEGMENT * size or not last_t[k] < t < 1.0:
                problems.append(f"stroke {i}: vertex {v} at {list(vertices[v])} on its path between the vertices of "
                                f"two consecutive points ({a}, {b}) is off their segment by {off / size:.3g} of the "
                                f"size (t = {t:.6g})")
                break
            last_t[k] = t
    if pos != len(walk) - 1:
        problems.append(f"stroke {i}'s path goes on past its last point's vertex ({walk[pos + 1:][:5]})")
    return problems[:MAX_PROBLEMS]


def on_path(doc, k, v, self_stroke=False):
    """Whether vertex v is on stroke k's path (for a stroke and itself: at two places that are
    not neighbours, or its path closed)."""
    path = doc["cleaning"]["strokes"][k]
    verts = list(path["vertices"])
    if not self_stroke:
        return v in verts
    places = [(p, len(verts), bool(path.get("cyclic"))) for p, x in enumerate(verts) if x == v]
    return not_neighbours(places)


def found_defects(entry, drawing, doc, size):
    """The planted defects found (the module docstring's "found") and the changes the manifest
    does not explain."""
    vertices, _ = figure_of(doc)
    c = doc["cleaning"]
    pv = c["point_vertices"]
    planted = entry["planted"]
    out = {"missed": []}
    gaps = 0
    for g in planted["gaps"]:
        i, j, k = g["stroke"], g["point"], g["other_stroke"]
        if on_path(doc, k, pv[i][j], self_stroke=(i == k)):
            gaps += 1
        else:
            out["missed"].append(f"gap: the {g['end']} of stroke {i} (point {j}, {g['distance_tol']:.2f} tolerances "
                                 f"from stroke {k}) is not joined to it")
    touches = 0
    for t in planted["touches"]:
        i, j, k = t["stroke"], t["point"], t["other_stroke"]
        if on_path(doc, k, pv[i][j], self_stroke=(i == k)):
            touches += 1
        else:
            out["missed"].append(f"touch: point {j} of stroke {i} lies on stroke {k}, its vertex is not on its path")
    crossings = reported_crossings = 0
    vert = np.array(vertices, dtype=float).reshape(-1, 2)
    crossing_changes = [ch for ch in c["changes"] if ch["kind"] == "crossing"]
    matched_changes = set()
    for x in planted["crossings"]:
        i, k = x["stroke"], x["other_stroke"]
        near = np.nonzero(np.hypot(*(vert - np.array(x["at"])[None, :]).T) <= CROSSING_MATCH * size)[0]
        hit = [int(w) for w in near if (on_path(doc, i, int(w), i == k) and on_path(doc, k, int(w), i == k))]
        if hit:
            crossings += 1
            w = hit[0]
            for n, ch in enumerate(crossing_changes):
                if tuple(map(float, ch["at"])) == vertices[w] and {ch["stroke"], ch.get("other_stroke")} == {i, k}:
                    reported_crossings += 1
                    matched_changes.add(n)
                    break
        else:
            out["missed"].append(f"crossing of strokes {i} and {k} at {x['at']}: no vertex there on both")
    duplicates = 0
    for d in planted["duplicates"]:
        i, j = d["stroke"], d["point"]
        if pv[i][j] == pv[i][j - 1]:
            duplicates += 1
        else:
            out["missed"].append(f"duplicate: point {j} of stroke {i} is not the vertex of point {j - 1}")
    # snaps of ends the manifest has as free, crossings it does not have
    gap_ends = {(g["stroke"], g["point"]) for g in planted["gaps"]}
    gap_ends |= {(x["stroke"], x["point"]) for x in planted["touches"]}  # a touching end may be a snap by 0
    partners = set()
    for g in planted["gaps"]:
        # an end stopped short of another stroke's end: that end may be the one that snaps
        k = g["other_stroke"]
        for j in (0, len(drawing[k][0]) - 1):
            p = np.array(drawing[k][0][j])
            if math.hypot(*(p - np.array(drawing[g["stroke"]][0][g["point"]]))) <= 1.5 * entry["tolerance"]:
                partners.add((k, j))
    extra_snaps = [ch for ch in c["changes"] if ch["kind"] == "snap" and (ch["stroke"], ch["point"]) not in gap_ends
                   and not end_of_same_place(drawing, ch, gap_ends | partners)]
    extra_crossings = [ch for n, ch in enumerate(crossing_changes) if n not in matched_changes]
    out.update(gaps=gaps, touches=touches, crossings=crossings, crossings_reported=reported_crossings,
               duplicates=duplicates,
               extra_snaps=[f"stroke {ch['stroke']} point {ch['point']} onto stroke {ch.get('other_stroke')}, "
                            f"{ch['distance']:.4g} ({ch['distance'] / entry['tolerance']:.2f} tolerances)"
                            for ch in extra_snaps],
               extra_crossings=[f"strokes {ch['stroke']} and {ch.get('other_stroke')} at {ch['at']}"
                                for ch in extra_crossings])
    return out


def end_of_same_place(drawing, ch, ends):
    """A snap of a duplicate of a planted end (a pen pause at the end: the same place)."""
    p = drawing[ch["stroke"]][0][ch["point"]]
    return any(s == ch["stroke"] and drawing[s][0][j] == p for s, j in ends)


def short_stubs(doc, limit):
    """Free ends of the cleaned figure less than `limit` along it from a junction: [(end vertex,
    junction, length)]. The corpus draws no free end that close to another stroke (overshoots run 2-4
    tolerances past), so each is left by the cleaning (an end snapped onto a stroke next to that
    stroke's own end, which then sticks out) or planted by a touch next to an end."""
    vertices, edges = figure_of(doc)
    adj = {}
    for u, v in edges:
        adj.setdefault(u, []).append(v)
        adj.setdefault(v, []).append(u)
    out = []
    for start, nbrs in adj.items():
        if len(nbrs) != 1:
            continue
        prev, cur, length = start, nbrs[0], 0.0
        length += math.dist(vertices[start], vertices[cur])
        while len(adj[cur]) == 2 and length < limit:
            nxt = adj[cur][0] if adj[cur][1] == prev else adj[cur][1]
            length += math.dist(vertices[cur], vertices[nxt])
            prev, cur = cur, nxt
        if len(adj[cur]) >= 3 and length < limit:
            out.append((start, cur, length))
    return out


def change_counts(doc):
    return {k: sum(1 for ch in doc["cleaning"]["changes"] if ch["kind"] == k) for k in KINDS}


def idempotence_problems(first, second):
    """Cleaning the cleaned figure again: no change, the same vertices and edges bit for bit."""
    problems = []
    c = second["cleaning"]
    if c["changes"] or c["junctions_made"] or c["ends_snapped"] or c["points_merged"]:
        kinds = {k: v for k, v in change_counts(second).items() if v}
        problems.append(f"cleaning again made {len(c['changes'])} changes ({kinds}); the first: "
                        + "; ".join(f"{ch['kind']} stroke {ch['stroke']} point {ch.get('point')} other "
                                    f"{ch.get('other_stroke')} at {ch['at']} by {ch['distance']:.3g}"
                                    for ch in c["changes"][:3]))
    if first["vertices"] != second["vertices"] or first["edges"] != second["edges"]:
        a = {tuple(v) for v in first["vertices"]}
        b = {tuple(v) for v in second["vertices"]}
        same_sets = a == b and ({frozenset((tuple(first["vertices"][u]), tuple(first["vertices"][v])))
                                 for u, v in first["edges"]}
                                == {frozenset((tuple(second["vertices"][u]), tuple(second["vertices"][v])))
                                    for u, v in second["edges"]})
        problems.append(f"the figure changed: {len(first['vertices'])} -> {len(second['vertices'])} vertices, "
                        f"{len(first['edges'])} -> {len(second['edges'])} edges"
                        + (" (the same geometry, numbered otherwise)" if same_sets else ""))
    return problems


# ---------------------------------------------------------------------------
# running the CLI

def run(cmd, timeout=TIMEOUT_SECONDS):
    start = time.monotonic()
    try:
        r = subprocess.run([str(x) for x in cmd], capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "", f"timed out after {timeout} s", time.monotonic() - start
    return r.returncode, r.stdout, r.stderr, time.monotonic() - start


def first_line(text):
    lines = text.strip().splitlines()
    return lines[0] if lines else ""


def clean(cli, src, out, tolerance=None):
    cmd = [cli, "clean", src, "-o", out]
    if tolerance is not None:
        cmd += ["--tolerance", repr(float(tolerance))]
    code, stdout, stderr, seconds = run(cmd)
    doc = None
    if code == 0:
        try:
            doc = json.loads(pathlib.Path(out).read_text())
        except (OSError, ValueError) as error:
            return code, f"unreadable output: {error}", seconds, None
    return code, (first_line(stderr) if code != 0 else stdout.strip()), seconds, doc


def check_drawing(cli, corpus, entry, work):
    """Everything for one drawing: a row for the table and the JSON."""
    src = corpus / entry["file"]
    drawing = read_drawing(src)
    size = drawing_size(drawing)
    out = work / f"{entry['name']}.clean.json"
    row = {"name": entry["name"], "kind": entry["kind"], "pair": entry.get("pair"), "strokes": len(drawing),
           "points": sum(len(p) for p, _ in drawing), "planted": entry["counts"], "problems": {}}
    code, message, seconds, doc = clean(cli, src, out)
    row["seconds"] = round(seconds, 4)
    if code != 0 or doc is None:
        row["error"] = f"exit {code}: {message}"
        return row, None
    c = doc["cleaning"]
    row.update(vertices=len(doc["vertices"]), edges=len(doc["edges"]), tolerance=c.get("tolerance"),
               summary=message)
    problems = structure_problems(drawing, doc)
    if problems:
        row["problems"]["structure"] = problems
        return row, doc
    row["changes"] = change_counts(doc)
    row["tolerance_expected"] = entry["tolerance"]
    if not close(float(c["tolerance"]), float(entry["tolerance"])) and \
            abs(float(c["tolerance"]) - float(entry["tolerance"])) > 1e-9 * entry["tolerance"]:
        row["problems"]["tolerance"] = [f"tolerance {c['tolerance']!r}, 1% of the box diagonal is "
                                        f"{entry['tolerance']!r}"]
    # (a) valid
    check_code, _, check_err, _ = run([cli, "check", out, out])
    exact = validity_problems(doc)
    row["valid_cli"] = check_code == 0
    row["valid_exact"] = not exact
    if check_code != 0:
        row["problems"].setdefault("valid", []).append(f"stickmorph check OUT OUT: exit {check_code}: "
                                                       f"{first_line(check_err)}")
    if exact:
        row["problems"].setdefault("valid", []).extend(exact)
    # (b) every change reported
    limits = limit_problems(drawing, doc)
    row["within_limits"] = not limits
    if limits:
        row["problems"]["limits"] = limits
    bends, shared = [], []
    accounting = accounting_problems(drawing, doc, size, bends, shared)
    row["shared_edges"] = len(shared)
    row["accounted"] = not accounting
    row["bends"] = [{"stroke": i, "vertex": v, "distance": d, "of_merge": d / (float(c["tolerance"]) * MERGE_FRACTION)}
                    for i, v, d in bends]
    if accounting:
        row["problems"]["accounted"] = accounting
    found = found_defects(entry, drawing, doc, size)
    row["found"] = {k: found[k] for k in ("gaps", "touches", "crossings", "crossings_reported", "duplicates")}
    row["stubs"] = [{"end": e, "junction": j, "length_tol": length / float(c["tolerance"])}
                    for e, j, length in short_stubs(doc, float(c["tolerance"]))]
    row["extra_snaps"], row["extra_crossings"] = found["extra_snaps"], found["extra_crossings"]
    if found["missed"]:
        row["problems"]["missed"] = found["missed"][:MAX_PROBLEMS]
    # (c) idempotent
    again = work / f"{entry['name']}.again.json"
    code2, message2, _, doc2 = clean(cli, out, again, tolerance=c["tolerance"])
    if doc2 is None:
        row["idempotent"] = False
        row["problems"]["idempotent"] = [f"cleaning the output again: exit {code2}: {message2}"]
    else:
        idem = idempotence_problems(doc, doc2)
        row["idempotent"] = not idem
        if idem:
            row["problems"]["idempotent"] = idem
    code3, message3, _, doc3 = clean(cli, out, work / f"{entry['name']}.again_default.json")
    if doc3 is None:
        row["idempotent_default"] = False
        row["problems"]["idempotent_default"] = [f"cleaning the output again (default tolerance): exit {code3}: "
                                                 f"{message3}"]
    else:
        idem = idempotence_problems(doc, doc3)
        row["idempotent_default"] = not idem
        if idem:
            row["problems"]["idempotent_default"] = idem
    return row, doc


def check_pair(cli, pair, cleaned, work, frames):
    """Morphs the two cleaned poses with --correspond auto; the ends on the cleaned drawings."""
    a, b = pair["a"].rsplit(".", 1)[0], pair["b"].rsplit(".", 1)[0]
    out = {"name": pair["name"], "kind": pair["kind"], "a": a, "b": b}
    if cleaned.get(a) is None or cleaned.get(b) is None:
        out["error"] = "a pose was not cleaned"
        return out
    m = work / f"{pair['name']}.morph.json"
    code, _, stderr, seconds = run([cli, "morph", work / f"{a}.clean.json", work / f"{b}.clean.json", "-o", m,
                                    "--correspond", "auto", "--frames", frames])
    out["seconds"] = round(seconds, 3)
    if code != 0:
        out["error"] = f"exit {code}: {first_line(stderr)}"
        return out
    doc = json.loads(m.read_text())
    va, ea = figure_of(cleaned[a])
    vb, eb = figure_of(cleaned[b])
    corr = doc.get("correspondence", {})
    medges = [tuple(e) for e in doc["edges"]]
    frames_out = doc["frames"]
    problems = cc.subdivision_problems(frames_out[0], medges, list(corr.get("source", [])), va, ea, "source")
    problems += cc.subdivision_problems(frames_out[-1], medges, list(corr.get("target", [])), vb, eb, "target")
    out.update(frames=len(frames_out), matched_vertices=len(frames_out[0]), ends_on_drawings=not problems,
               verified=(doc.get("stats") or {}).get("verified", True))
    if problems:
        out["problems"] = problems[:MAX_PROBLEMS]
    return out


# ---------------------------------------------------------------------------
# refusals

def bad_drawings(drawing):
    """Drawings `clean` must refuse, from a good one: (label, strokes, the stroke to name)."""
    strokes = [{"points": [list(p) for p in pts], "cyclic": cyc} for pts, cyc in drawing]
    first = next(n for n, (pts, cyc) in enumerate(drawing) if not cyc and len(pts) >= 12)
    pts = [list(p) for p in drawing[first][0]]
    out = [("no strokes", [], None)]
    one = strokes + [{"points": [pts[len(pts) // 2]], "cyclic": False}]
    out.append(("a stroke of one point", one, len(strokes)))
    # a new stroke along a length of another: a copy of some of its points (they overlap)
    m = len(pts) // 2
    along = strokes + [{"points": pts[m:m + 4], "cyclic": False}]
    out.append(("a stroke along another", along, len(strokes)))
    # a stroke that turns back on itself: its last segment drawn back (exactly collinear)
    retrace = [dict(s) for s in strokes]
    retrace[first] = {"points": pts + [pts[-2]], "cyclic": False}
    out.append(("a stroke that retraces itself", retrace, first))
    return out


def names_stroke(line, n):
    """Whether an error line names stroke n ("stroke 7", "strokes 0 and 7", "point 3 of stroke 7")."""
    named = set()
    for first, second in re.findall(r"\bstrokes? (\d+)(?: and (\d+))?", line):
        named.update(int(x) for x in (first, second) if x)
    return n in named


def check_refusals(cli, corpus, entry, work):
    drawing = read_drawing(corpus / entry["file"])
    rows = []
    for label, strokes, stroke in bad_drawings(drawing):
        path = work / f"bad_{len(rows)}.json"
        path.write_text(json.dumps({"name": label, "strokes": strokes}) + "\n")
        code, stdout, stderr, _ = run([cli, "clean", path, "-o", work / "bad_out.json"])
        lines = stderr.strip().splitlines()
        ok = code == 2 and len(lines) == 1 and lines[0].startswith("error: ") and "internal" not in lines[0].lower()
        if stroke is not None:
            ok = ok and names_stroke(lines[0] if lines else "", stroke)
        rows.append({"case": label, "from": entry["name"], "exit": code, "stderr": stderr.strip()[:300],
                     "stdout": stdout.strip()[:300], "stroke": stroke, "ok": ok})
    return rows


# ---------------------------------------------------------------------------
# summary and printing

def pick_showcase(rows, docs, entries):
    """The drawing the report draws before and after: a stick figure with the most kinds of
    change, then the fewest points (else any drawing)."""
    best = None
    for row in rows:
        if row["name"] not in docs or docs[row["name"]] is None or "changes" not in row:
            continue
        kinds = sum(1 for v in row["changes"].values() if v)
        key = (row["kind"] == "stickman", kinds, -row["points"])
        if best is None or key > best[0]:
            best = (key, row["name"])
    if best is None:
        return None
    name = best[1]
    doc = docs[name]
    return {"name": name, "kind": entries[name]["kind"], "subject": entries[name].get("subject"),
            "strokes": entries[name]["_strokes"], "vertices": doc["vertices"], "edges": doc["edges"],
            "changes": doc["cleaning"]["changes"], "tolerance": doc["cleaning"]["tolerance"]}


def summarize(rows, pairs, refusals):
    def block(rs):
        done = [r for r in rs if "error" not in r and "changes" in r]
        s = {"drawings": len(rs), "cleaned": len(done), "failed": len(rs) - len(done),
             "points": sum(r["points"] for r in rs), "strokes": sum(r["strokes"] for r in rs),
             "planted": {k: sum(r["planted"][k] for r in rs) for k in ("gaps", "touches", "crossings", "overshoots",
                                                                        "duplicates")},
             "found": {k: sum(r["found"][k] for r in done) for k in ("gaps", "touches", "crossings",
                                                                    "crossings_reported", "duplicates")},
             "changes": {k: sum(r["changes"][k] for r in done) for k in KINDS},
             "extra_snaps": sum(len(r["extra_snaps"]) for r in done),
             "extra_crossings": sum(len(r["extra_crossings"]) for r in done),
             "stubs": sum(len(r.get("stubs", [])) for r in done),
             "stub_drawings": sum(1 for r in done if r.get("stubs")),
             "shared_edges": sum(r.get("shared_edges", 0) for r in done),
             "bends": sum(len(r.get("bends", [])) for r in done),
             "bent_drawings": sum(1 for r in done if r.get("bends")),
             "bend_max_of_merge": max((b["of_merge"] for r in done for b in r.get("bends", [])), default=None),
             "valid": sum(1 for r in done if r.get("valid_cli") and r.get("valid_exact")),
             "valid_cli": sum(1 for r in done if r.get("valid_cli")),
             "valid_exact": sum(1 for r in done if r.get("valid_exact")),
             "accounted": sum(1 for r in done if r.get("accounted")),
             "within_limits": sum(1 for r in done if r.get("within_limits", True)),
             "idempotent": sum(1 for r in done if r.get("idempotent")),
             "idempotent_default": sum(1 for r in done if r.get("idempotent_default")),
             "seconds": round(sum(r["seconds"] for r in rs), 3),
             "seconds_max": max((r["seconds"] for r in rs), default=0.0)}
        s["changes"]["total"] = sum(s["changes"][k] for k in KINDS)
        return s

    kinds = sorted({r["kind"] for r in rows})
    out = {"all": block(rows), "by_kind": {k: block([r for r in rows if r["kind"] == k]) for k in kinds}}
    out["pairs"] = {"pairs": len(pairs), "morphed": sum(1 for p in pairs if "error" not in p),
                    "ends_on_drawings": sum(1 for p in pairs if p.get("ends_on_drawings"))}
    out["refusals"] = {"cases": len(refusals), "ok": sum(1 for r in refusals if r["ok"])}
    failures = []
    for r in rows:
        if "error" in r:
            failures.append({"name": r["name"], "what": "clean", "detail": r["error"]})
        for what, problems in r["problems"].items():
            failures.append({"name": r["name"], "what": what, "detail": problems[0], "count": len(problems)})
    for p in pairs:
        if "error" in p:
            failures.append({"name": p["name"], "what": "morph", "detail": p["error"]})
        elif p.get("problems"):
            failures.append({"name": p["name"], "what": "morph ends", "detail": p["problems"][0]})
    for r in refusals:
        if not r["ok"]:
            said = (f"exit 0, not refused ({r.get('stdout', '')[:200]})" if r["exit"] == 0
                    else f"exit {r['exit']}: {r['stderr'][:200]}")
            failures.append({"name": r["from"], "what": f"refusal: {r['case']}", "detail": said})
    out["failures"] = failures
    return out


def fmt(value, spec="{:.3f}"):
    return "-" if value is None else spec.format(value)


def fraction(a, b):
    return f"{a}/{b}"


def table_rows(summary):
    rows = []
    for label, s in list(summary["by_kind"].items()) + [("all", summary["all"])]:
        p, f, c = s["planted"], s["found"], s["changes"]
        rows.append([label, str(s["drawings"]), str(s["points"]), str(s["strokes"]),
                     f"{p['gaps']}/{p['crossings']}/{p['duplicates']}",
                     f"{f['gaps']}/{f['crossings']}/{f['duplicates']}",
                     f"{c['merge']}/{c['snap']}/{c['crossing']}/{c['touch']}",
                     fraction(s["valid"], s["drawings"]), fraction(s["accounted"], s["drawings"]),
                     fraction(s["idempotent"], s["drawings"]), f"{s['seconds']:.2f}"])
    return rows


HEADER = ["kind", "drawings", "points", "strokes", "planted gaps/crossings/duplicates",
          "found gaps/crossings/duplicates", "reported merge/snap/crossing/touch", "valid", "accounted",
          "idempotent", "seconds"]


def print_report(summary, pairs, refusals, stream=sys.stdout):
    rows = table_rows(summary)
    widths = [max(len(HEADER[k]), *(len(r[k]) for r in rows)) for k in range(len(HEADER))]
    print(" | ".join(h.ljust(w) for h, w in zip(HEADER, widths)), file=stream)
    print("-+-".join("-" * w for w in widths), file=stream)
    for r in rows:
        print(" | ".join(c.ljust(w) for c, w in zip(r, widths)), file=stream)
    s = summary["all"]
    print(f"\ntouches planted {s['planted']['touches']}, found {s['found']['touches']}; crossings found "
          f"{s['found']['crossings']}, reported as crossings at their vertex {s['found']['crossings_reported']}; "
          f"snaps of ends the manifest has as free {s['extra_snaps']}, crossings it does not have "
          f"{s['extra_crossings']}; free ends less than the tolerance from a junction {s['stubs']} (in "
          f"{s['stub_drawings']} drawings); edges within the tolerance on two strokes' paths {s['shared_edges']}; "
          f"strokes bent through a junction within the merge distance {s['bends']} (in "
          f"{s['bent_drawings']} drawings, at most {fmt(s['bend_max_of_merge'], '{:.2f}')} of the merge distance); "
          f"merges and snaps within their limits {s['within_limits']}/{s['drawings']}; "
          f"valid by `check` {s['valid_cli']}, exactly {s['valid_exact']}; idempotent with the "
          f"default tolerance {s['idempotent_default']}/{s['drawings']}; slowest clean {s['seconds_max']:.3f} s",
          file=stream)
    ps = summary["pairs"]
    print(f"pairs: {ps['morphed']}/{ps['pairs']} morphed with --correspond auto, ends on the cleaned drawings "
          f"{ps['ends_on_drawings']}/{ps['pairs']}", file=stream)
    rs = summary["refusals"]
    if rs["cases"]:
        print(f"refusals: {rs['ok']}/{rs['cases']} bad drawings refused with one error line naming the stroke",
              file=stream)
    if summary["failures"]:
        print("\nfailures:", file=stream)
        for f in summary["failures"]:
            more = f" (+{f['count'] - 1} more)" if f.get("count", 1) > 1 else ""
            print(f"  {f['name']}: {f['what']}: {f['detail']}{more}", file=stream)


def build_source(build_dir):
    """The commit the build's source folder is at and whether its engine (native/) had uncommitted
    changes; None where unknown."""
    try:
        cache = (pathlib.Path(build_dir) / "CMakeCache.txt").read_text()
        source = next(line.split("=", 1)[1] for line in cache.splitlines()
                      if line.startswith("CMAKE_HOME_DIRECTORY:"))
        commit = subprocess.run(["git", "-C", source, "rev-parse", "--short=12", "HEAD"], capture_output=True,
                                text=True, check=True).stdout.strip()
        status = subprocess.run(["git", "-C", source, "status", "--porcelain", "--", "native"],
                                capture_output=True, text=True, check=True).stdout
    except (OSError, StopIteration, subprocess.CalledProcessError):
        return None
    return {"commit": commit, "uncommitted_native": bool(status.strip())}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("corpus", type=pathlib.Path, help="folder with manifest.json (bench/drawing_corpus.py)")
    ap.add_argument("--build-dir", type=pathlib.Path, default=REPO / "build")
    ap.add_argument("--json", type=pathlib.Path, help="write the results here")
    ap.add_argument("--only", action="append", help="check only this drawing (repeatable; its pair is skipped "
                    "unless both poses are named)")
    ap.add_argument("--keep", type=pathlib.Path, help="keep the cleaned files and morphs in this folder")
    ap.add_argument("--frames", type=int, default=DEFAULT_FRAMES, help=f"frames per pair morph (default "
                    f"{DEFAULT_FRAMES})")
    ap.add_argument("--no-refusals", action="store_true", help="skip the bad drawings")
    args = ap.parse_args(argv)
    cli = args.build_dir / "stickmorph"
    manifest_path = args.corpus / "manifest.json"
    for path in (cli, manifest_path):
        if not path.exists():
            print(f"error: {path} does not exist", file=sys.stderr)
            return 2
    if args.frames < 2:
        print("error: --frames must be at least 2", file=sys.stderr)
        return 2
    manifest = json.loads(manifest_path.read_text())
    entries = [e for e in manifest["drawings"] if not args.only or e["name"] in args.only]
    if not entries:
        print("error: no drawing to check", file=sys.stderr)
        return 2
    help_text = run([cli, "clean", "--help"])[1]
    if not help_text:
        print(f"error: {cli} has no clean command (`stickmorph clean --help` failed)", file=sys.stderr)
        return 2
    by_name = {e["name"]: e for e in entries}
    started = time.monotonic()
    work = args.keep if args.keep else pathlib.Path(tempfile.mkdtemp(prefix="cleaning_"))
    work.mkdir(parents=True, exist_ok=True)
    try:
        rows, docs = [], {}
        for entry in entries:
            row, doc = check_drawing(cli, args.corpus, entry, work)
            rows.append(row)
            docs[entry["name"]] = doc if not row.get("error") else None
            entry["_strokes"] = [{"points": [list(p) for p in pts], "cyclic": cyc}
                                 for pts, cyc in read_drawing(args.corpus / entry["file"])]
            bad = "; ".join(f"{k}: {v[0]}" for k, v in row["problems"].items())
            print(f"{entry['name']}: " + (row.get("error") or row.get("summary", "")) + (f"  PROBLEMS {bad}" if bad
                                                                                        else ""), file=sys.stderr)
        pairs = []
        for pair in manifest.get("pairs", []):
            a, b = pair["a"].rsplit(".", 1)[0], pair["b"].rsplit(".", 1)[0]
            if a in by_name and b in by_name:
                pairs.append(check_pair(cli, pair, docs, work, args.frames))
                p = pairs[-1]
                print(f"pair {pair['name']}: " + (p.get("error") or ("ends on the drawings" if p.get("ends_on_drawings")
                                                                     else "; ".join(p.get("problems", [])))),
                      file=sys.stderr)
        refusals = [] if args.no_refusals else check_refusals(cli, args.corpus, entries[0], work)
        summary = summarize(rows, pairs, refusals)
        print_report(summary, pairs, refusals)
        if args.json:
            doc = {"command": "/usr/bin/python3 bench/cleaning.py " + " ".join(argv if argv is not None
                                                                               else sys.argv[1:]),
                   "build": build_source(args.build_dir), "corpus": str(args.corpus), "seed": manifest.get("seed"),
                   "tolerance_fraction": manifest.get("tolerance_fraction"), "frames": args.frames,
                   "seconds": round(time.monotonic() - started, 1), "summary": summary, "drawings": rows,
                   "pairs": pairs, "refusals": refusals,
                   "showcase": pick_showcase(rows, docs, by_name)}
            args.json.parent.mkdir(parents=True, exist_ok=True)
            args.json.write_text(json.dumps(doc, indent=1) + "\n")
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
