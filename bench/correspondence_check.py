#!/usr/bin/env python3
"""Check `stickmorph morph --correspond auto` on a corpus, with geometry of its own.

    /usr/bin/python3 bench/correspondence_check.py CORPUS_DIR --stickmorph build/stickmorph \
        [--frames N] [--timeout S] [--json REPORT] [--keep DIR] [--max-full-edges E]

CORPUS_DIR holds manifest.json and the figure files that bench/correspondence_corpus.py
writes. For every pair the CLI is run as

    stickmorph morph SOURCE TARGET -o OUT --correspond auto --frames N [--pin S:T ...]

What is being checked (the contract, in this checker's words). Without `--correspond auto`
vertex i of the source becomes vertex i of the target. With it the two files need not agree
on anything but their shape: vertex counts, numbering, edge order and direction, and how finely
each stroke is subdivided may all differ. The engine matches the figures itself and morphs
the *matched figure*: every vertex of the source and every vertex of the target is one of its
m vertices; a vertex that has no partner in the other figure is put there as a dummy vertex
on one of that figure's edges. The output's `correspondence.source[i]` is the source vertex
that matched vertex i is in the first frame, or -1 when it is a dummy on a source edge there;
`correspondence.target[i]` the same for the target and the last frame. `--pin S:T` forces
source vertex S and target vertex T to be one matched vertex. A pair that cannot be matched
(a loop against a tree, other junction degrees, a chiral figure against its mirror image,
contradictory pins) is refused: exit 2, nothing on stdout, one line `error: ...` on stderr.

So for a pair the manifest expects to match, this script requires:
  * exit 0 within the timeout, and an output file with edges, times, frames, correspondence;
  * every source vertex exactly once in correspondence.source, every target vertex exactly
    once in correspondence.target, no matched vertex that is a dummy on both sides, pins kept;
  * frames[0] is a subdivision of the source drawing: an original vertex sits exactly
    (bit for bit) on its source vertex; a dummy lies on a source edge (within 1e-9 of the
    source's size) strictly between its ends; every source edge is exactly one chain of
    matched edges through dummies on that edge, in order along it, and there is no other
    matched edge. The last frame is the same against the target;
  * every checked frame is a plane straight-line graph (exact orientation tests in
    fractions.Fraction on the doubles: no crossing, no vertex on an edge that does not end
    there, no two vertices at one point) with the cyclic order of edges around every vertex
    of frames[0] and the same outer face: the matched figure keeps its topology.
    The exact test visits every pair whose bounding boxes meet (float comparisons of the
    coordinates themselves are exact, so the box filter drops no real contact). All frames
    are checked when the matched figure has at most --max-full-edges edges, otherwise the
    first, the last and 8 evenly spaced ones; the table says which.
If the optional `source_edge`/`source_fraction` (or target_...) fields are present they
must agree with where the dummy was found.

Informational, never a failure: when the manifest lists `landmarks` (the intended partners
of the named junctions and ends of same-figure pairs), the table says how many the engine's
match kept. A symmetric figure (an X, an H) has several valid matches, and the contract does
not say which one the engine takes.

For a pair the manifest expects to be refused: exit 2, empty stdout, exactly one stderr line,
starting with `error: `, not mentioning an internal error, within the timeout. If the CLI
matches such a pair anyway, its output is checked as above and the verdict says whether that
match was valid (then the expectation, not the engine, may be what is wrong).

It prints one row per pair and a summary, writes the rows to --json, and exits 1 if any pair
failed (2 for a bad command line or corpus).
"""
import argparse
import functools
import json
import math
import pathlib
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

import numpy as np

# Relative distance (to the figure's bounding-box diagonal) within which a dummy vertex counts
# as lying on an edge: the engine places dummies by interpolating doubles, so they are only
# within rounding of the exact segment.
ON_EDGE_TOLERANCE = 1e-9
# Relative tolerance on the optional *_fraction fields (position along the edge).
FRACTION_TOLERANCE = 1e-6
# Frames checked when the figure is too big to check them all: first, last and this many between.
SPREAD_FRAMES = 8
DEFAULT_MAX_FULL_EDGES = 300
MAX_PROBLEMS = 8  # per check, so one broken frame does not bury the report


# ---------------------------------------------------------------------------
# exact predicates

def exact_points(points):
    """The coordinates as Fractions: exactly the doubles given."""
    return [(Fraction(float(x)), Fraction(float(y))) for x, y in points]


def orient(a, b, c):
    """Sign of the turn a -> b -> c (1 left, -1 right, 0 collinear), exact on Fraction points."""
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def _box_pairs(lo, hi, lo2, hi2, same):
    """Index pairs (i, j) whose closed boxes [lo, hi] and [lo2, hi2] meet (i < j when same).
    Comparing the doubles is exact, and two segments (or a point and a segment) that touch
    have boxes that meet, so nothing is missed. Done in row blocks to bound the memory."""
    out = []
    block = 256
    for start in range(0, len(lo), block):
        l1, h1 = lo[start:start + block, None, :], hi[start:start + block, None, :]
        meet = np.all((l1 <= hi2[None, :, :]) & (lo2[None, :, :] <= h1), axis=2)
        rows, cols = np.nonzero(meet)
        rows = rows + start
        if same:
            keep = rows < cols
            rows, cols = rows[keep], cols[keep]
        out.extend(zip(rows.tolist(), cols.tolist()))
    return out


def plane_problems(points, edges, limit=MAX_PROBLEMS, exact=None):
    """Why the drawing is not a straight-line plane graph (empty list: it is one).

    Complete for segments: two edges without a common end either cross properly (all four
    orientations nonzero, opposite in pairs) or one has an end on the other (caught by the
    vertex-on-edge test) or they are apart; two edges with a common end can only overlap,
    and then the nearer far end lies on the other edge. Coincident vertices are compared as
    exact doubles. `exact`: the points already made exact (Fractions, or integers after one
    common power of two), when the caller has them."""
    pts = np.asarray(points, dtype=float).reshape(-1, 2)
    problems = []
    if not np.all(np.isfinite(pts)):
        bad = int(np.nonzero(~np.all(np.isfinite(pts), axis=1))[0][0])
        return [f"vertex {bad} is not finite: {pts[bad].tolist()}"]
    seen = {}
    for i, (x, y) in enumerate(pts.tolist()):
        j = seen.setdefault((x, y), i)
        if j != i:
            problems.append(f"vertices {j} and {i} coincide at ({x!r}, {y!r})")
            if len(problems) >= limit:
                return problems
    if not edges:
        return problems
    e = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    a, b = pts[e[:, 0]], pts[e[:, 1]]
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    if exact is None:
        exact = exact_points(pts)

    for i, k in _box_pairs(pts, pts, lo, hi, same=False):
        u, v = int(e[k, 0]), int(e[k, 1])
        if i == u or i == v:
            continue
        if orient(exact[u], exact[v], exact[i]) == 0:
            problems.append(f"vertex {i} lies on edge {k} ({u}, {v})")
            if len(problems) >= limit:
                return problems

    for k, l in _box_pairs(lo, hi, lo, hi, same=True):
        p, q = int(e[k, 0]), int(e[k, 1])
        r, s = int(e[l, 0]), int(e[l, 1])
        if len({p, q, r, s}) < 4:
            continue  # adjacent: only an overlap is possible, and the vertex test finds it
        o1 = orient(exact[p], exact[q], exact[r])
        o2 = orient(exact[p], exact[q], exact[s])
        o3 = orient(exact[r], exact[s], exact[p])
        o4 = orient(exact[r], exact[s], exact[q])
        if o1 * o2 < 0 and o3 * o4 < 0:
            problems.append(f"edges {k} ({p}, {q}) and {l} ({r}, {s}) cross")
            if len(problems) >= limit:
                return problems
    return problems


def parts_of(n, edges):
    """part[v] for every vertex, parts numbered in the order of their smallest vertex."""
    parent = list(range(n))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for u, v in edges:
        ru, rv = find(u), find(v)
        if ru != rv:
            parent[max(ru, rv)] = min(ru, rv)
    number, part = {}, []
    for v in range(n):
        part.append(number.setdefault(find(v), len(number)))
    return part


def components(n, edges):
    """Number of connected components of the graph on vertices 0..n-1."""
    return len(set(parts_of(n, edges)))


def clearance(points, edges):
    """Smallest distance from a vertex to an edge that does not end at it, relative to the
    bounding-box diagonal (inf for a single edge). Two non-crossing segments are nearest at an
    end of one of them, so this is also the smallest gap between non-adjacent edges. The corpus
    uses it to refuse figures that are valid but touch almost (rounding-fragile)."""
    pts = np.asarray(points, dtype=float)
    e = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    size = figure_size(pts)
    best = math.inf
    a, b = pts[e[:, 0]], pts[e[:, 1]]
    d = b - a
    dd = np.maximum(np.einsum("ij,ij->i", d, d), 1e-300)
    for start in range(0, len(pts), 256):
        p = pts[start:start + 256]
        t = np.clip(np.einsum("pij,ij->pi", p[:, None, :] - a[None], d) / dd, 0.0, 1.0)
        near = a[None] + t[..., None] * d[None]
        dist = np.linalg.norm(p[:, None, :] - near, axis=2)
        idx = np.arange(start, start + len(p))[:, None]
        dist[(e[None, :, 0] == idx) | (e[None, :, 1] == idx)] = math.inf
        best = min(best, float(dist.min()) if dist.size else math.inf)
    return best / size


def figure_size(points):
    pts = np.asarray(points, dtype=float)
    span = pts.max(axis=0) - pts.min(axis=0)
    return max(float(np.hypot(*span)), 1e-300)


# ---------------------------------------------------------------------------
# rotation system and faces

def _half(d):
    """0 for directions in [0, pi), 1 for [pi, 2 pi): the first key of the angular order."""
    return 0 if (d[1] > 0 or (d[1] == 0 and d[0] > 0)) else 1


def _by_angle(a, b):
    ha, hb = _half(a), _half(b)
    if ha != hb:
        return ha - hb
    c = a[0] * b[1] - a[1] * b[0]
    return -1 if c > 0 else (1 if c < 0 else 0)


def adjacency(n, edges):
    adj = [[] for _ in range(n)]
    for u, v in edges:
        adj[u].append(v)
        adj[v].append(u)
    return adj


def rotation_system(points, edges, exact=None, adj=None):
    """For every vertex, its neighbours in counter-clockwise order, started at the smallest
    index so that equal cyclic orders compare equal. Sorted exactly (Fraction directions)."""
    exact = exact_points(points) if exact is None else exact
    adj = adjacency(len(exact), edges) if adj is None else adj
    rot = []
    for v, nbrs in enumerate(adj):
        if len(nbrs) <= 2:
            rot.append(tuple(sorted(nbrs)))  # one or two edges have only one cyclic order
            continue
        pv = exact[v]
        dirs = {w: (exact[w][0] - pv[0], exact[w][1] - pv[1]) for w in nbrs}
        order = sorted(nbrs, key=functools.cmp_to_key(lambda p, q: _by_angle(dirs[p], dirs[q])))
        k = order.index(min(order))
        rot.append(tuple(order[k:] + order[:k]))
    return rot


def faces(rotation, n):
    """The faces of the embedding as lists of darts (u, v), each with the face on its left:
    after u -> v comes v -> w with w the neighbour before u counter-clockwise around v."""
    position = {}
    for v, order in enumerate(rotation):
        for k, w in enumerate(order):
            position[(v, w)] = k
    seen = set()
    out = []
    for v in range(n):
        for w in rotation[v]:
            if (v, w) in seen:
                continue
            face = []
            dart = (v, w)
            while dart not in seen:
                seen.add(dart)
                face.append(dart)
                a, b = dart
                order = rotation[b]
                nxt = order[(position[(b, a)] - 1) % len(order)]
                dart = (b, nxt)
            out.append(face)
    return out


def outer_face(face_list, points):
    """Index of the unbounded face: the one of negative signed area (its darts run clockwise
    around the figure). A figure without a cycle has one face, so the answer is 0 there."""
    pts = np.asarray(points, dtype=float)
    areas = []
    for face in face_list:
        u = np.array([d[0] for d in face])
        v = np.array([d[1] for d in face])
        areas.append(float(np.sum(pts[u, 0] * pts[v, 1] - pts[v, 0] * pts[u, 1])))
    return int(np.argmin(areas)) if areas else 0


def rotation_differences(reference, rotation, limit=MAX_PROBLEMS):
    out = []
    for v, (a, b) in enumerate(zip(reference, rotation)):
        if a != b:
            out.append(f"vertex {v}: neighbours {list(b)} counter-clockwise, {list(a)} in frame 0")
            if len(out) >= limit:
                break
    return out


# ---------------------------------------------------------------------------
# the matched figure against one of the original figures

def subdivision_problems(frame, matched_edges, corr, fig_points, fig_edges, side, extension=None,
                         limit=MAX_PROBLEMS):
    """Why `frame` (positions of the m matched vertices) is not a subdivision of the figure
    (fig_points, fig_edges) under `corr` (corr[i]: the figure's vertex, or -1 for a dummy).

    extension: optional (edge list, fraction list) from the output's side_edge/side_fraction
    fields, checked against what is found here."""
    problems = []

    def add(msg):
        problems.append(f"{side}: {msg}")
        return len(problems) >= limit

    frame = np.asarray(frame, dtype=float)
    fig = np.asarray(fig_points, dtype=float)
    m, n = len(frame), len(fig)
    if len(corr) != m:
        add(f"correspondence has {len(corr)} entries for {m} matched vertices")
        return problems
    # every figure vertex exactly once
    where = {}
    for i, s in enumerate(corr):
        if not isinstance(s, int) or s < -1 or s >= n:
            if add(f"matched vertex {i} names vertex {s!r}, not -1 or 0..{n - 1}"):
                return problems
            continue
        if s >= 0:
            if s in where:
                if add(f"vertex {s} is matched vertices {where[s]} and {i}"):
                    return problems
            where.setdefault(s, i)
    missing = [s for s in range(n) if s not in where]
    if missing:
        if add(f"vertices {missing[:10]}{' ...' if len(missing) > 10 else ''} "
               f"({len(missing)} of {n}) are not in the correspondence"):
            return problems
    if problems:
        return problems

    # originals exactly where they were
    for i, s in enumerate(corr):
        if s >= 0 and frame[i].tolist() != fig[s].tolist():
            if add(f"matched vertex {i} is at {frame[i].tolist()}, its vertex {s} at {fig[s].tolist()}"):
                return problems

    # every dummy on an edge, strictly inside it
    size = figure_size(fig)
    fe = np.asarray(fig_edges, dtype=np.int64).reshape(-1, 2)
    a, b = fig[fe[:, 0]], fig[fe[:, 1]]
    d = b - a
    dd = np.einsum("ij,ij->i", d, d)
    # on_edges[i]: {edge: position along it} for every edge dummy i lies on (near a junction
    # a dummy may be within the tolerance of two; the chain below decides which it is on)
    on_edges = {}
    for i, s in enumerate(corr):
        if s >= 0:
            continue
        p = frame[i]
        t = np.einsum("ij,ij->i", p[None, :] - a, d) / dd
        foot = a + t[:, None] * d
        dist = np.linalg.norm(foot - p[None, :], axis=1)
        ok = (dist <= ON_EDGE_TOLERANCE * size) & (t > 0) & (t < 1)
        ok &= ~np.all(p[None, :] == a, axis=1) & ~np.all(p[None, :] == b, axis=1)
        candidates = np.nonzero(ok)[0]
        if len(candidates) == 0:
            clipped = np.clip(t, 0, 1)
            gap = np.linalg.norm(a + clipped[:, None] * d - p[None, :], axis=1)
            k = int(np.argmin(gap))
            if add(f"dummy {i} at {p.tolist()} lies on no edge strictly inside it (nearest: edge {k} "
                   f"({int(fe[k, 0])}, {int(fe[k, 1])}) at distance {gap[k] / size:.3g} of the size, t={t[k]:.6g})"):
                return problems
            continue
        on_edges[i] = {int(k): float(t[k]) for k in candidates}

    # the optional extension fields
    if extension is not None:
        claimed, fractions = extension
        if len(claimed) != m or (fractions is not None and len(fractions) != m):
            add(f"{side}_edge/{side}_fraction have {len(claimed)}/{len(fractions or [])} entries, not {m}")
            return problems
        for i, s in enumerate(corr):
            if s >= 0 and claimed[i] != -1:
                if add(f"{side}_edge[{i}] is {claimed[i]} for an original vertex (expected -1)"):
                    return problems
            elif s < 0 and i in on_edges:
                if claimed[i] not in on_edges[i]:
                    if add(f"{side}_edge[{i}] is {claimed[i]}, but dummy {i} lies on edge(s) "
                           f"{sorted(on_edges[i])}"):
                        return problems
                elif fractions is not None and abs(fractions[i] - on_edges[i][claimed[i]]) > FRACTION_TOLERANCE:
                    if add(f"{side}_fraction[{i}] is {fractions[i]!r}, the dummy is at "
                           f"{on_edges[i][claimed[i]]!r} of edge {claimed[i]}"):
                        return problems
    if problems:
        return problems

    # chains: from each original vertex along each matched edge through dummies to an original
    adj = adjacency(m, matched_edges)
    for i, s in enumerate(corr):
        if s < 0 and len(adj[i]) != 2:
            if add(f"dummy {i} has {len(adj[i])} matched edges, not 2"):
                return problems
    if problems:
        return problems
    edge_index = {}
    for k, (u, v) in enumerate(fig_edges):
        edge_index[frozenset((u, v))] = k
    covered = {}
    used = set()
    visited_dummies = set()
    for start in range(m):
        if corr[start] < 0:
            continue
        for first in adj[start]:
            if (start, first) in used:
                continue
            chain = [start]
            prev, cur = start, first
            used.add((start, first))
            while corr[cur] < 0 and len(chain) <= m:
                chain.append(cur)
                visited_dummies.add(cur)
                nxt = adj[cur][0] if adj[cur][1] == prev else adj[cur][1]
                used.add((cur, nxt))
                prev, cur = cur, nxt
            chain.append(cur)
            used.add((cur, prev))
            # mark the way back too, so the chain is found once
            for x, y in zip(chain, chain[1:]):
                used.add((y, x))
            u, v = corr[chain[0]], corr[chain[-1]]
            key = frozenset((u, v))
            k = edge_index.get(key)
            if k is None:
                if add(f"matched path {chain} joins vertices {u} and {v}, which are not an edge"):
                    return problems
                continue
            if k in covered:
                if add(f"edge {k} ({u}, {v}) is covered twice: by {covered[k]} and by {chain}"):
                    return problems
                continue
            covered[k] = chain
            # the dummies must lie on this edge, in order from u to v
            first_is_u = fig_edges[k][0] == u
            ts = []
            for x in chain[1:-1]:
                if k not in on_edges[x]:
                    if add(f"dummy {x} on the path for edge {k} ({u}, {v}) lies on edge(s) {sorted(on_edges[x])}"):
                        return problems
                    break
                ts.append(on_edges[x][k] if first_is_u else 1.0 - on_edges[x][k])
            else:
                if any(t1 >= t2 for t1, t2 in zip(ts, ts[1:])):
                    if add(f"the dummies {chain[1:-1]} on edge {k} ({u}, {v}) are not in order along it "
                           f"(positions {[round(t, 6) for t in ts]})"):
                        return problems
    uncovered = [k for k in range(len(fig_edges)) if k not in covered]
    if uncovered:
        add(f"edges {uncovered[:10]} ({len(uncovered)} of {len(fig_edges)}) are not covered by matched edges")
    stray = [i for i, s in enumerate(corr) if s < 0 and i not in visited_dummies]
    if stray:
        add(f"dummies {stray[:10]} are on no path between original vertices (a cycle of dummies)")
    return problems


# ---------------------------------------------------------------------------
# one morph output against its pair

def frames_to_check(count, edge_count, max_full_edges):
    """All frame indices, or the first, last and SPREAD_FRAMES evenly spaced ones."""
    if edge_count <= max_full_edges or count <= SPREAD_FRAMES + 2:
        return list(range(count))
    return sorted({int(round(x)) for x in np.linspace(0, count - 1, SPREAD_FRAMES + 2)})


def _int_list(value):
    return isinstance(value, list) and all(isinstance(x, int) and not isinstance(x, bool) for x in value)


def check_match(source, target, doc, pins=(), frames_expected=None, max_full_edges=DEFAULT_MAX_FULL_EDGES):
    """Check one `--correspond auto` output. source/target: (points, edges) of the two files;
    doc: the parsed output. Returns a dict: problems (empty when the output is right), m,
    dummies, frames_checked (indices), frame_count."""
    result = {"problems": [], "m": None, "dummies": None, "frames_checked": [], "frame_count": None}
    problems = result["problems"]
    for key in ("edges", "times", "frames", "correspondence"):
        if key not in doc:
            problems.append(f"the output has no {key!r}")
    if problems:
        return result
    corr = doc["correspondence"]
    cs, ct = corr.get("source") if isinstance(corr, dict) else None, corr.get("target") if isinstance(corr, dict) else None
    if not _int_list(cs) or not _int_list(ct):
        problems.append("correspondence.source/target are not lists of integers")
        return result
    m = len(cs)
    result["m"] = m
    result["dummies"] = sum(1 for s in cs if s < 0) + sum(1 for t in ct if t < 0)
    frames, times, medges = doc["frames"], doc["times"], doc["edges"]
    result["frame_count"] = len(frames)
    if len(ct) != m:
        problems.append(f"correspondence.source has {m} entries, correspondence.target {len(ct)}")
    if not frames or any(len(f) != m for f in frames):
        problems.append(f"frames are not all lists of {m} points")
    if len(times) != len(frames):
        problems.append(f"{len(times)} times for {len(frames)} frames")
    elif times and (times[0] != 0.0 or times[-1] != 1.0):
        problems.append(f"times run from {times[0]} to {times[-1]}, not 0 to 1")
    if frames_expected is not None and len(frames) != frames_expected:
        problems.append(f"{len(frames)} frames, {frames_expected} asked for")
    bad_edges = [e for e in medges if not (_int_list(e) and len(e) == 2 and 0 <= e[0] < m and 0 <= e[1] < m
                                           and e[0] != e[1])]
    if bad_edges:
        problems.append(f"edges {bad_edges[:5]} are not pairs of distinct matched vertices")
    if problems:
        return result
    medges = [tuple(e) for e in medges]
    if len({frozenset(e) for e in medges}) != len(medges):
        problems.append("an edge of the matched figure is listed twice")
    both = [i for i in range(m) if cs[i] < 0 and ct[i] < 0]
    if both:
        problems.append(f"matched vertices {both[:10]} are dummies in both figures (they come from neither)")
    for s, t in pins:
        if not any(cs[i] == s and ct[i] == t for i in range(m)):
            problems.append(f"pin {s}:{t} not kept: source {s} is matched vertex "
                            f"{cs.index(s) if s in cs else None}, target {t} is {ct.index(t) if t in ct else None}")
    if components(m, medges) != 1:
        problems.append("the matched figure is not connected")
    if problems:
        return result

    def extension(side):
        edge_key, frac_key = f"{side}_edge", f"{side}_fraction"
        if edge_key not in corr:
            return None
        return corr[edge_key], corr.get(frac_key)

    problems += subdivision_problems(frames[0], medges, cs, *source, "source", extension("source"))
    problems += subdivision_problems(frames[-1], medges, ct, *target, "target", extension("target"))
    if problems:
        return result

    check = frames_to_check(len(frames), len(medges), max_full_edges)
    result["frames_checked"] = check
    adj = adjacency(m, medges)
    reference = rotation_system(frames[0], medges, adj=adj)
    face_list = faces(reference, m)
    outer0 = outer_face(face_list, frames[0])
    for k in check:
        frame = frames[k]
        invalid = plane_problems(frame, medges)
        if invalid:
            problems.append(f"frame {k} is not a plane graph: " + "; ".join(invalid))
            continue
        rot = rotation_system(frame, medges, adj=adj)
        changed = rotation_differences(reference, rot)
        if changed:
            problems.append(f"frame {k} changes the order of edges: " + "; ".join(changed))
            continue
        if len(face_list) > 1 and outer_face(face_list, frame) != outer0:
            problems.append(f"frame {k} has another outer face than frame 0")
        if len(problems) >= MAX_PROBLEMS:
            break
    return result


def check_refusal(returncode, stdout, stderr):
    """Why a refusal is not the contract's (exit 2, no stdout, one 'error: ' line)."""
    problems = []
    if returncode < 0:
        problems.append(f"killed by signal {-returncode}")
    elif returncode != 2:
        problems.append(f"exit {returncode}, expected 2")
    if stdout:
        problems.append(f"stdout is not empty: {stdout[:200]!r}")
    lines = stderr.splitlines()
    if len(lines) != 1:
        problems.append(f"stderr has {len(lines)} lines, expected 1: {stderr[:300]!r}")
    elif not lines[0].startswith("error: "):
        problems.append(f"stderr does not start with 'error: ': {lines[0][:200]!r}")
    if "internal error" in stderr.lower():
        problems.append(f"stderr reports an internal error: {stderr[:300]!r}")
    return problems


# ---------------------------------------------------------------------------
# the corpus run

def load_figure(path):
    doc = json.loads(pathlib.Path(path).read_text())
    pts = np.asarray(doc["vertices"], dtype=float).reshape(-1, 2)
    return pts, [tuple(int(x) for x in e) for e in doc["edges"]]


def run_pair(entry, corpus, cli, frames, timeout, workdir, max_full_edges):
    name = entry["name"]
    src_path, tgt_path = corpus / entry["source"], corpus / entry["target"]
    source, target = load_figure(src_path), load_figure(tgt_path)
    pins = [tuple(p) for p in entry.get("pins", [])]
    out = workdir / f"{name}.morph.json"
    if out.exists():
        out.unlink()
    cmd = [str(cli), "morph", str(src_path), str(tgt_path), "-o", str(out), "--correspond", "auto",
           "--frames", str(frames)]
    for s, t in pins:
        cmd += ["--pin", f"{s}:{t}"]
    row = {"pair": name, "family": entry["family"], "expect": entry["expect"], "n_source": len(source[0]),
           "n_target": len(target[0]), "m": None, "dummies": None, "frames_checked": "-", "landmarks": "-",
           "result": "",
           "seconds": None, "check_seconds": None, "problems": [], "command": " ".join(cmd)}
    start = time.monotonic()
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        row["seconds"] = round(time.monotonic() - start, 2)
        row["problems"] = [f"timed out after {timeout} s"]
        row["result"] = "FAIL"
        return row
    row["seconds"] = round(time.monotonic() - start, 2)
    start = time.monotonic()
    if entry["expect"] == "refuse":
        row["problems"] = check_refusal(proc.returncode, proc.stdout, proc.stderr)
        row["stderr"] = proc.stderr.strip()
        if proc.returncode == 0 and out.exists():
            verdict = _check_output(out, source, target, pins, frames, max_full_edges, row)
            row["problems"].append("the CLI matched a pair expected to be refused; its output "
                                   + ("passes the match checks (is the expectation wrong?)" if not verdict
                                      else "fails them too: " + "; ".join(verdict)))
    else:
        if proc.returncode != 0:
            first = proc.stderr.strip().splitlines()[:1]
            row["problems"] = [f"exit {proc.returncode}: {first[0] if first else '(no stderr)'}"]
        elif not out.exists():
            row["problems"] = ["exit 0 but no output file"]
        else:
            row["problems"] = _check_output(out, source, target, pins, frames, max_full_edges, row)
            if entry.get("landmarks"):
                try:
                    kept = landmarks_kept(json.loads(out.read_text()), [tuple(x) for x in entry["landmarks"]])
                    row["landmarks"] = f"{kept}/{len(entry['landmarks'])}"
                except (OSError, ValueError, AttributeError):
                    pass
    row["check_seconds"] = round(time.monotonic() - start, 2)
    row["result"] = "ok" if not row["problems"] else "FAIL"
    return row


def landmarks_kept(doc, landmarks):
    """How many of the (source, target) landmark pairs are one matched vertex."""
    corr = doc.get("correspondence", {})
    pairs = set(zip(corr.get("source", []), corr.get("target", [])))
    return sum(1 for s, t in landmarks if (s, t) in pairs)


def _check_output(out, source, target, pins, frames, max_full_edges, row):
    try:
        doc = json.loads(out.read_text())
    except (OSError, ValueError) as exc:
        return [f"the output is not JSON: {exc}"]
    result = check_match(source, target, doc, pins, frames, max_full_edges)
    row["m"], row["dummies"] = result["m"], result["dummies"]
    count, checked = result["frame_count"], result["frames_checked"]
    if checked:
        row["frames_checked"] = f"all {count}" if len(checked) == count else f"{len(checked)} of {count}"
        row["frame_indices"] = checked
    return result["problems"]


def print_columns(head, body, stream):
    """A plain-text table: the header row, then the rows, each column as wide as its widest cell."""
    widths = [max([len(h)] + [len(b[k]) for b in body]) for k, h in enumerate(head)]
    print("  ".join(h.ljust(w) for h, w in zip(head, widths)), file=stream)
    for b in body:
        print("  ".join(c.ljust(w) for c, w in zip(b, widths)), file=stream)


def print_table(rows, stream=sys.stdout):
    head = ["pair", "family", "n_source", "n_target", "m", "dummies", "frames checked", "landmarks", "result",
            "seconds"]
    body = [[r["pair"], r["family"], str(r["n_source"]), str(r["n_target"]),
             "-" if r["m"] is None else str(r["m"]), "-" if r["dummies"] is None else str(r["dummies"]),
             r["frames_checked"], r.get("landmarks", "-"), r["result"] + ("" if r["expect"] == "match" else " (refuse)"),
             "-" if r["seconds"] is None else f"{r['seconds']:.2f}"] for r in rows]
    print_columns(head, body, stream)
    failed = [r for r in rows if r["result"] != "ok"]
    for r in failed:
        print(f"\nFAIL {r['pair']} ({r['family']}, expect {r['expect']}):", file=stream)
        for p in r["problems"]:
            print(f"  - {p}", file=stream)
        print(f"  command: {r['command']}", file=stream)
    families = sorted({r["family"] for r in rows})
    print("\nsummary:", file=stream)
    for fam in families:
        mine = [r for r in rows if r["family"] == fam]
        print(f"  {fam}: {sum(r['result'] == 'ok' for r in mine)}/{len(mine)} ok", file=stream)
    marked = [r for r in rows if r.get("landmarks", "-") != "-"]
    if marked:
        whole = [r for r in marked if r["landmarks"].split("/")[0] == r["landmarks"].split("/")[1]]
        print(f"  landmarks (information): all kept in {len(whole)} of {len(marked)} pairs"
              + ("" if len(whole) == len(marked) else
                 " (not kept: " + ", ".join(f"{r['pair']} {r['landmarks']}" for r in marked if r not in whole) + ")"),
              file=stream)
    print(f"  total: {len(rows) - len(failed)}/{len(rows)} ok, {len(failed)} failed; CLI time "
          f"{sum(r['seconds'] or 0 for r in rows):.1f} s", file=stream)


def add_corpus_arguments(ap):
    """The arguments of a corpus checker (this one and multipart_check.py)."""
    ap.add_argument("corpus", type=pathlib.Path, help="folder with manifest.json")
    ap.add_argument("--stickmorph", required=True, type=pathlib.Path, help="the stickmorph executable")
    ap.add_argument("--frames", type=int, default=20, help="frames per morph (default 20)")
    ap.add_argument("--timeout", type=float, default=120.0, help="seconds per CLI run (default 120)")
    ap.add_argument("--json", type=pathlib.Path, help="write the rows here")
    ap.add_argument("--keep", type=pathlib.Path, help="keep the morph outputs in this folder")
    ap.add_argument("--only", action="append", default=[], help="check only this pair (repeatable)")


def read_manifest(args):
    """The corpus's manifest entries, or None after one `error:` line on stderr when the
    corpus, the executable or the frame count will not do."""
    manifest_path = args.corpus / "manifest.json"
    if not manifest_path.exists():
        print(f"error: {manifest_path} does not exist", file=sys.stderr)
        return None
    if not args.stickmorph.exists():
        print(f"error: {args.stickmorph} does not exist", file=sys.stderr)
        return None
    if args.frames < 2:
        print("error: --frames must be at least 2", file=sys.stderr)
        return None
    return json.loads(manifest_path.read_text())


def check_corpus(args, manifest, check, print_table, prefix):
    """Runs check(entry, workdir) on every manifest entry, in --keep or a temporary folder,
    with a progress line per pair on stderr; prints the table, writes --json, and returns
    the exit code (1 if any pair failed)."""
    rows = []
    with tempfile.TemporaryDirectory(prefix=prefix) as tmp:
        workdir = args.keep if args.keep else pathlib.Path(tmp)
        workdir.mkdir(parents=True, exist_ok=True)
        for entry in manifest:
            r = check(entry, workdir)
            rows.append(r)
            checking = f" + {r['check_seconds']} s" if "check_seconds" in r else ""
            print(f"{r['pair']}: {r['result']} ({r['seconds']} s{checking})", file=sys.stderr, flush=True)
    print_table(rows)
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1) + "\n")
    return 1 if any(r["result"] != "ok" for r in rows) else 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_corpus_arguments(ap)
    ap.add_argument("--max-full-edges", type=int, default=DEFAULT_MAX_FULL_EDGES,
                    help=f"check every frame up to this many matched edges (default {DEFAULT_MAX_FULL_EDGES})")
    args = ap.parse_args(argv)
    manifest = read_manifest(args)
    if manifest is None:
        return 2
    if args.only:
        manifest = [e for e in manifest if e["name"] in args.only]
    def check(entry, workdir):
        return run_pair(entry, args.corpus, args.stickmorph.resolve(), args.frames, args.timeout, workdir,
                        args.max_full_edges)

    return check_corpus(args, manifest, check, print_table, "correspondence_check_")

if __name__ == "__main__":
    sys.exit(main())
