#!/usr/bin/env python3
"""Write a corpus of figure pairs for `stickmorph morph --correspond auto`.

    /usr/bin/python3 bench/correspondence_corpus.py OUT_DIR [--seed N] [--count-per-family K]

With `--correspond auto` the engine is given two figure files that do not correspond by
index: they may have different numbers of vertices, other numbering, another edge order and
direction, and strokes subdivided differently. It has to find the match itself (adding dummy
vertices where one figure has a vertex the other has not) or refuse the pair with exit 2 and
one `error: ` line when no match exists. The pairs here are drawn the way such files arise in
practice, so neither the engine nor bench/correspondence_check.py can lean on an accident of
construction. Families (K pairs each, default 12, so 60 pairs):

  font      the outline of one single-contour glyph (C E F ... z 1 2 3 5 7) in two different
            fonts bundled with matplotlib, its quadratic/cubic Beziers flattened here at two
            different tolerances: two polygons with different vertex counts. Every fourth pair
            pins three extreme points (rightmost, topmost, leftmost, bottommost) to each other.
  stroke    hand-authored centre-line letters with junctions (A B E F H K P R T X Y 4 6 9 e 8),
            the same letter in two styles: other proportions, slant, bend of the strokes and
            sampling density, so the junctions agree and the chains between them do not.
            Every third pair pins a junction and one more named point of the letter.
  skeleton  stick people, trees, quadrupeds and hands in two styles/poses (same junctions).
  cross     two different letters or figures with the same junction structure, which must
            match: B->8, A->R, E->F, T->Y, K->H, 6->9, P->9, e->6, and mirror images whose
            mirror is the same plane graph (F reflected, a stick person reflected).
  refuse    pairs with no match: a loop against a tree (A vs H, a glyph outline vs the same
            letter's centre line), other junction degrees (T vs X, Y vs K, 4 vs A), a chiral
            figure against its mirror image (a person with a two- and a three-fingered hand; a
            tree with a forked and a three-pronged bough), other loop counts (8 vs 6, B vs P), a
            tail inside the loop against one outside (clock vs balloon), and contradictory
            pins (three outline points pinned in reversed cyclic order; a T's junction pinned
            to an end of the other T).

Then every pair is disguised: both figures get a random vertex numbering, edge order and edge
direction, and the target a random rotation (up to 60 degrees either way), scale (0.5 to 2) and
translation. Every figure written is checked to be a connected plane straight-line graph with
the exact test of correspondence_check.py and to keep every vertex at least 0.2% of its size
away from edges that do not end there (rounding-safe); a draw that fails is redrawn, a
glyph whose outline fails is skipped.

OUT_DIR gets NAME.source.json / NAME.target.json and manifest.json: a list of {name, family,
source, target, expect ("match" or "refuse"), why, pins ([[s, t], ...], only when pinned),
landmarks ([[s, t], ...]: the intended partners of the named junctions and ends, stroke and
skeleton families only; the contract does not fix which of several valid matches the engine
takes, so the checker reports them without failing), n_source, n_target}. The output is a function of --seed and --count-per-family alone.
"""
import argparse
import json
import math
import os
import pathlib
import random
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import correspondence_check as cc  # noqa: E402  (the exact plane-graph test, shared on purpose)

# A vertex nearer than this (relative to the figure's diagonal) to an edge that does not end at
# it makes a valid but fragile figure: the engine's rounding could make it touch.
MIN_CLEARANCE = 2e-3
MAX_REDRAWS = 40

FONTS = ["DejaVuSans.ttf", "DejaVuSans-Bold.ttf", "DejaVuSans-Oblique.ttf", "DejaVuSans-BoldOblique.ttf",
         "DejaVuSerif.ttf", "DejaVuSerif-Bold.ttf", "DejaVuSerif-Italic.ttf", "DejaVuSerif-BoldItalic.ttf",
         "DejaVuSansMono.ttf", "DejaVuSansMono-Bold.ttf", "DejaVuSansMono-Oblique.ttf",
         "DejaVuSansMono-BoldOblique.ttf", "STIXGeneral.ttf", "STIXGeneralBol.ttf", "STIXGeneralItalic.ttf",
         "STIXGeneralBolIta.ttf", "cmr10.ttf", "cmss10.ttf", "cmtt10.ttf"]
GLYPHS = "CEFGHIJKLMNSTUVWXYZcfhklmnrstuvwxyz12357"


# ---------------------------------------------------------------------------
# figures: points (n x 2 floats), edges [(i, j)], keys {name: vertex} for pins

class Figure:
    def __init__(self, points, edges, keys=None):
        self.points = np.asarray(points, dtype=float).reshape(-1, 2)
        self.edges = [(int(i), int(j)) for i, j in edges]
        self.keys = dict(keys or {})

    def problems(self):
        """Why this figure may not go into the corpus (empty: it may)."""
        out = cc.plane_problems(self.points, self.edges)
        if out:
            return out
        n = len(self.points)
        if len({frozenset(e) for e in self.edges}) != len(self.edges) or any(i == j for i, j in self.edges):
            return ["a repeated edge or a loop edge"]
        if cc.components(n, self.edges) != 1:
            return ["not connected"]
        if len(self.edges) > 1:
            gap = cc.clearance(self.points, self.edges)
            if gap < MIN_CLEARANCE:
                return [f"a vertex is {gap:.2g} of the size from an edge (fragile)"]
        return []


def similarity(points, angle_deg, scale, shift):
    p = np.asarray(points, dtype=float)
    c = p.mean(axis=0)
    a = math.radians(angle_deg)
    rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    return (p - c) @ rot.T * scale + c + np.asarray(shift, dtype=float)


def reflect(fig):
    """The mirror image (x -> -x)."""
    p = fig.points.copy()
    p[:, 0] = -p[:, 0]
    return Figure(p, fig.edges, fig.keys)


# ---------------------------------------------------------------------------
# font outlines

_OUTLINES = {}


def glyph_contours(font, char):
    """The glyph's contours as lists of Bezier control-point arrays (degree 1, 2 or 3), in a
    box of height 1. None when the font has no outline for it."""
    key = (font, char)
    if key not in _OUTLINES:
        import matplotlib
        from matplotlib.font_manager import FontProperties
        from matplotlib.textpath import TextPath
        path = TextPath((0, 0), char, size=1,
                        prop=FontProperties(fname=os.path.join(matplotlib.get_data_path(), "fonts", "ttf", font)))
        contours, current, closed = [], None, []
        for seg, code in path.iter_bezier():
            cp = np.asarray(seg.control_points, dtype=float)
            if code == 1:  # MOVETO starts a contour
                current = []
                contours.append(current)
                closed.append(False)
            elif code == 79:  # CLOSEPOLY: the closing line back to the start
                closed[-1] = True
                current.append(cp)
            else:
                current.append(cp)
        if not contours:
            _OUTLINES[key] = None
        else:
            allpts = np.concatenate([np.concatenate(c) for c in contours if c])
            lo, hi = allpts.min(axis=0), allpts.max(axis=0)
            h = max(hi[1] - lo[1], 1e-9)
            _OUTLINES[key] = ([[(cp - lo) / h for cp in c] for c in contours], closed)
    return _OUTLINES[key]


def flatten(beziers, tolerance):
    """A closed Bezier contour as polygon points: each curve is cut into n equal parameter
    steps, n from the usual bound (deviation <= d(d-1)/8 * max second difference / n^2), so a
    smaller tolerance gives more points. Consecutive duplicates and back-tracking spikes (a
    point where the outline turns back on itself) are dropped, as is the closing repeat."""
    pts = []
    for cp in beziers:
        deg = len(cp) - 1
        if deg <= 1:
            pts.append(cp[-1])
            continue
        second = np.max(np.linalg.norm(cp[2:] - 2 * cp[1:-1] + cp[:-2], axis=1))
        n = max(1, int(math.ceil(math.sqrt(deg * (deg - 1) * second / (8 * tolerance)))))
        for k in range(1, n + 1):
            t = k / n
            # de Casteljau
            q = cp.copy()
            for _ in range(deg):
                q = (1 - t) * q[:-1] + t * q[1:]
            pts.append(q[0])
    return clean_cycle(np.array(pts))


def clean_cycle(pts):
    """Drop repeated and near-repeated points and spikes from a closed point list."""
    size = max(np.ptp(pts[:, 0]), np.ptp(pts[:, 1]), 1e-12)
    changed = True
    pts = [tuple(p) for p in pts]
    while changed and len(pts) > 3:
        changed = False
        out = []
        for p in pts:
            if out and math.dist(out[-1], p) <= 1e-9 * size:
                changed = True
                continue
            out.append(p)
        if len(out) > 1 and math.dist(out[0], out[-1]) <= 1e-9 * size:
            out.pop()
            changed = True
        n = len(out)
        keep = []
        for i in range(n):
            a, b, c = np.array(out[i - 1]), np.array(out[i]), np.array(out[(i + 1) % n])
            u, v = b - a, c - b
            cross = u[0] * v[1] - u[1] * v[0]
            if abs(cross) <= 1e-12 * (np.dot(u, u) + np.dot(v, v)) and np.dot(u, v) < 0:
                changed = True  # the outline goes back along itself: an overlap
                continue
            keep.append(out[i])
        pts = keep
    return np.array(pts)


def cycle_figure(points):
    n = len(points)
    return Figure(points, [(i, (i + 1) % n) for i in range(n)])


def outline_figure(font, char, tolerance):
    """The glyph as one polygon, or None when it is not exactly one closed contour or the
    polygon is not a valid (and clear) figure."""
    data = glyph_contours(font, char)
    if data is None:
        return None
    contours, closed = data
    contours = [c for c in contours if c]
    if len(contours) != 1 or not closed[0]:
        return None
    pts = flatten(contours[0], tolerance)
    if len(pts) < 3:
        return None
    fig = cycle_figure(pts)
    return None if fig.problems() else fig


def extreme_pins(a, b):
    """Three (vertex of a, vertex of b) pairs: the first three of the rightmost, topmost,
    leftmost and bottommost points (each figure in its own frame) that are three distinct
    vertices in both. Extreme points in counter-clockwise directions are hull vertices in
    counter-clockwise order, and a simple polygon passes its hull vertices in hull order, so
    these pins keep the cyclic order and some match honours them."""
    def ext(fig):
        p = fig.points
        return [int(np.argmax(p[:, 0])), int(np.argmax(p[:, 1])), int(np.argmin(p[:, 0])), int(np.argmin(p[:, 1]))]
    ea, eb = ext(a), ext(b)
    for skip in (3, 2, 1, 0):
        keep = [k for k in range(4) if k != skip]
        pa, pb = [ea[k] for k in keep], [eb[k] for k in keep]
        if len(set(pa)) == 3 and len(set(pb)) == 3:
            return list(zip(pa, pb))
    return None


def font_pair(rng):
    """A glyph in two fonts, flattened at two tolerances, or None when no font pair works."""
    for _ in range(MAX_REDRAWS):
        char = rng.choice(GLYPHS)
        fa, fb = rng.sample(FONTS, 2)
        ta = 10 ** rng.uniform(-2.6, -1.8)
        tb = 10 ** rng.uniform(-3.3, -2.4)
        if rng.random() < 0.5:
            ta, tb = tb, ta
        a, b = outline_figure(fa, char, ta), outline_figure(fb, char, tb)
        if a is not None and b is not None and len(a.points) != len(b.points):
            return char, fa, fb, a, b
    return None


# ---------------------------------------------------------------------------
# stroke drawings: key points in a unit box, strokes through them

# A stroke is (kind, key names): "line" straight segments (optionally bent by the style),
# "curve" an open centripetal Catmull-Rom spline through the keys (a corner at each end),
# "ring" a closed smooth spline. A key named in two strokes, or twice in one, is a junction.
def _ellipse(cx, cy, rx, ry, start_deg, count, prefix):
    return {f"{prefix}{k}": (cx + rx * math.cos(math.radians(start_deg + 360 * k / count)),
                             cy + ry * math.sin(math.radians(start_deg + 360 * k / count)))
            for k in range(count)}


SIX_LOOP = {"j": (0.12, 0.42), "a1": (0.35, 0.58), "a2": (0.72, 0.52), "a3": (0.82, 0.25), "a4": (0.5, 0.0),
            "a5": (0.16, 0.14)}
SIX_TAIL = {"t1": (0.2, 0.75), "t2": (0.42, 0.96), "t3": (0.75, 1.0)}
SIX = ({**SIX_LOOP, **SIX_TAIL},
       [("curve", ["j", "a1", "a2", "a3", "a4", "a5", "j"]), ("curve", ["j", "t1", "t2", "t3"])])
NINE = ({k: (1 - x, 1 - y) for k, (x, y) in SIX[0].items()}, SIX[1])

LETTERS = {
    "A": ({"bl": (0, 0), "cl": (0.2, 0.42), "ap": (0.5, 1), "cr": (0.8, 0.42), "br": (1, 0)},
          [("line", ["bl", "cl", "ap", "cr", "br"]), ("line", ["cl", "cr"])]),
    "B": ({"s0": (0, 0), "s1": (0, 0.52), "s2": (0, 1), "u1": (0.45, 1), "u2": (0.68, 0.9), "u3": (0.66, 0.68),
           "u4": (0.4, 0.58), "l1": (0.42, 0.46), "l2": (0.76, 0.36), "l3": (0.76, 0.12), "l4": (0.45, 0)},
          [("line", ["s0", "s1", "s2"]), ("curve", ["s2", "u1", "u2", "u3", "u4", "s1"]),
           ("curve", ["s1", "l1", "l2", "l3", "l4", "s0"])]),
    "C": ({"c0": (0.88, 0.82), "c1": (0.6, 1), "c2": (0.2, 0.9), "c3": (0, 0.5), "c4": (0.2, 0.1),
           "c5": (0.6, 0), "c6": (0.88, 0.18)},
          [("curve", ["c0", "c1", "c2", "c3", "c4", "c5", "c6"])]),
    "E": ({"b": (0, 0), "m": (0, 0.5), "t": (0, 1), "tr": (0.8, 1), "mr": (0.6, 0.5), "br": (0.8, 0)},
          [("line", ["br", "b", "m", "t", "tr"]), ("line", ["m", "mr"])]),
    "F": ({"b": (0, 0), "m": (0, 0.55), "t": (0, 1), "tr": (0.8, 1), "mr": (0.6, 0.55)},
          [("line", ["b", "m", "t", "tr"]), ("line", ["m", "mr"])]),
    "H": ({"lb": (0, 0), "lm": (0, 0.5), "lt": (0, 1), "rb": (1, 0), "rm": (1, 0.5), "rt": (1, 1)},
          [("line", ["lb", "lm", "lt"]), ("line", ["rb", "rm", "rt"]), ("line", ["lm", "rm"])]),
    "K": ({"b": (0, 0), "m": (0, 0.4), "t": (0, 1), "j": (0.24, 0.58), "ur": (0.8, 1), "lr": (0.85, 0)},
          [("line", ["b", "m", "t"]), ("line", ["m", "j", "ur"]), ("line", ["j", "lr"])]),
    "P": ({"b": (0, 0), "m": (0, 0.45), "t": (0, 1), "p1": (0.45, 1), "p2": (0.72, 0.88), "p3": (0.7, 0.6),
           "p4": (0.42, 0.46)},
          [("line", ["b", "m", "t"]), ("curve", ["t", "p1", "p2", "p3", "p4", "m"])]),
    "R": ({"b": (0, 0), "m": (0, 0.5), "t": (0, 1), "u1": (0.45, 1), "u2": (0.7, 0.88), "u3": (0.68, 0.62),
           "j": (0.38, 0.5), "leg": (0.8, 0)},
          [("line", ["b", "m", "t"]), ("curve", ["t", "u1", "u2", "u3", "j"]), ("line", ["j", "m"]),
           ("line", ["j", "leg"])]),
    "T": ({"l": (0, 1), "c": (0.5, 1), "r": (1, 1), "b": (0.5, 0)}, [("line", ["l", "c", "r"]), ("line", ["c", "b"])]),
    "X": ({"bl": (0, 0), "c": (0.5, 0.5), "tr": (1, 1), "br": (1, 0), "tl": (0, 1)},
          [("line", ["bl", "c", "tr"]), ("line", ["br", "c", "tl"])]),
    "Y": ({"tl": (0, 1), "tr": (1, 1), "c": (0.5, 0.5), "b": (0.5, 0)},
          [("line", ["tl", "c", "b"]), ("line", ["tr", "c"])]),
    "4": ({"t": (0.62, 1), "l": (0, 0.32), "j": (0.62, 0.32), "r": (0.9, 0.32), "b": (0.62, 0)},
          [("line", ["t", "l", "j", "r"]), ("line", ["t", "j", "b"])]),
    "6": SIX,
    "9": NINE,
    "e": ({"l": (0.02, 0.5), "r": (1, 0.5), "u1": (0.88, 0.82), "u2": (0.52, 1), "u3": (0.16, 0.84),
           "d1": (0.12, 0.16), "d2": (0.5, 0), "d3": (0.86, 0.12)},
          [("line", ["l", "r"]), ("curve", ["r", "u1", "u2", "u3", "l"]), ("curve", ["l", "d1", "d2", "d3"])]),
    "8": ({"c": (0.5, 0.5), "u1": (0.76, 0.62), "u2": (0.8, 0.84), "u3": (0.6, 0.99), "u4": (0.36, 0.96),
           "u5": (0.22, 0.78), "u6": (0.28, 0.6), "l1": (0.78, 0.36), "l2": (0.86, 0.12), "l3": (0.55, 0.0),
           "l4": (0.2, 0.04), "l5": (0.12, 0.26), "l6": (0.25, 0.4)},
          [("curve", ["c", "u1", "u2", "u3", "u4", "u5", "u6", "c"]),
           ("curve", ["c", "l6", "l5", "l4", "l3", "l2", "l1", "c"])]),
    # a ring with a hand from the rim to the middle (inside), and one with a string (outside)
    "clock": ({**_ellipse(0.5, 0.5, 0.5, 0.5, -90, 8, "r"), "h": (0.55, 0.45)},
              [("ring", [f"r{k}" for k in range(8)]), ("line", ["r0", "h"])]),
    "balloon": ({**_ellipse(0.5, 0.62, 0.38, 0.38, -90, 8, "r"), "s1": (0.45, 0.12), "s2": (0.52, -0.2)},
                [("ring", [f"r{k}" for k in range(8)]), ("curve", ["r0", "s1", "s2"])]),
}
STROKE_LETTERS = ["A", "B", "E", "F", "H", "K", "P", "R", "T", "X", "Y", "4", "6", "9", "e", "8"]
# the keys a pinned stroke pair pins: a junction and a stroke end of each letter
PIN_KEYS = {"A": ["cl", "br"], "B": ["s1", "s2"], "E": ["m", "tr"], "F": ["m", "tr"], "H": ["lm", "rt"],
            "K": ["j", "b"], "P": ["m", "b"], "R": ["j", "leg"], "T": ["c", "b"], "X": ["c", "tl"],
            "Y": ["c", "b"], "4": ["j", "r"], "6": ["j", "t3"], "9": ["j", "t3"], "e": ["l", "d3"],
            "8": ["c", "u3"]}


def _centripetal(p0, p1, p2, p3, ts):
    """Points of the centripetal Catmull-Rom segment from p1 to p2 at parameters ts in [0, 1]."""
    def knot(t, a, b):
        return t + max(np.linalg.norm(b - a), 1e-12) ** 0.5
    t0 = 0.0
    t1 = knot(t0, p0, p1)
    t2 = knot(t1, p1, p2)
    t3 = knot(t2, p2, p3)
    out = []
    for s in ts:
        t = t1 + (t2 - t1) * s
        a1 = (t1 - t) / (t1 - t0) * p0 + (t - t0) / (t1 - t0) * p1
        a2 = (t2 - t) / (t2 - t1) * p1 + (t - t1) / (t2 - t1) * p2
        a3 = (t3 - t) / (t3 - t2) * p2 + (t - t2) / (t3 - t2) * p3
        b1 = (t2 - t) / (t2 - t0) * a1 + (t - t0) / (t2 - t0) * a2
        b2 = (t3 - t) / (t3 - t1) * a2 + (t - t1) / (t3 - t1) * a3
        out.append((t2 - t) / (t2 - t1) * b1 + (t - t1) / (t2 - t1) * b2)
    return out


class Drawing:
    """Builds a figure from strokes; a named key is one vertex however many strokes use it."""

    def __init__(self):
        self.points, self.edges, self.keys = [], [], {}

    def key(self, name, xy):
        if name not in self.keys:
            self.keys[name] = len(self.points)
            self.points.append(np.asarray(xy, dtype=float))
        return self.keys[name]

    def chain(self, start, inner, end):
        """Edges start -> inner points -> end (start, end: vertex indices)."""
        prev = start
        for q in inner:
            self.points.append(np.asarray(q, dtype=float))
            cur = len(self.points) - 1
            self.edges.append((prev, cur))
            prev = cur
        self.edges.append((prev, end))

    def stroke(self, kind, names, pos, spacing, bend_rng=None, bend=0.0):
        """Sample a stroke through the keys `names` (positions in `pos`) about every `spacing`."""
        pts = [np.asarray(pos[k], dtype=float) for k in names]
        idx = [self.key(k, pos[k]) for k in names]
        if kind == "ring":
            pts = pts + pts[:1]
            idx = idx + idx[:1]
        n = len(pts)
        for s in range(n - 1):
            a, b = pts[s], pts[s + 1]
            pieces = max(1, int(round(np.linalg.norm(b - a) / spacing)))
            ts = [k / pieces for k in range(1, pieces)]
            if kind == "line":
                d = b - a
                normal = np.array([-d[1], d[0]])
                amount = bend_rng.uniform(-bend, bend) if bend_rng is not None else 0.0
                inner = [a + t * d + amount * math.sin(math.pi * t) * normal for t in ts]
            else:
                if kind == "ring":
                    prev, nxt = pts[(s - 1) % (n - 1)], pts[(s + 2) % (n - 1)]
                else:
                    prev = pts[s - 1] if s > 0 else 2 * a - b
                    nxt = pts[s + 2] if s + 2 < n else 2 * b - a
                inner = _centripetal(prev, a, b, nxt, ts)
            self.chain(idx[s], inner, idx[s + 1])

    def figure(self):
        return Figure(np.array(self.points), self.edges, self.keys)


def style(rng, strength=1.0):
    """A random way of drawing: proportions, slant, wobble of the key points, bend of straight
    strokes and sampling density. strength 0 is the neat base drawing (only density varies)."""
    return {"width": 1 + strength * rng.uniform(-0.3, 0.3), "slant": strength * rng.uniform(-0.25, 0.25),
            "jitter": 0.03 * strength, "bend": 0.12 * strength, "spacing": rng.uniform(0.025, 0.11),
            "seed": rng.getrandbits(32)}


def draw_letter(letter, st):
    keys, strokes = LETTERS[letter]
    r = random.Random(st["seed"])
    pos = {}
    for name in sorted(keys):
        x, y = keys[name]
        x += r.uniform(-st["jitter"], st["jitter"])
        y += r.uniform(-st["jitter"], st["jitter"])
        pos[name] = (0.5 + (x - 0.5) * st["width"] + st["slant"] * (y - 0.5), y)
    d = Drawing()
    for kind, names in strokes:
        d.stroke(kind, names, pos, st["spacing"], r, st["bend"])
    return d.figure()


def drawn_pair(draw_a, draw_b, rng, strength=1.0):
    """Draw both figures in independent random styles until both are valid figures."""
    for attempt in range(MAX_REDRAWS):
        gentle = strength * (1 - attempt / MAX_REDRAWS)
        a, b = draw_a(style(rng, gentle)), draw_b(style(rng, gentle))
        if not a.problems() and not b.problems():
            return a, b
    raise RuntimeError("no valid drawing found")


# ---------------------------------------------------------------------------
# skeletons: joints by forward kinematics, limbs as curves

def limb(d, start, angles, lengths, spacing, curl, names=None):
    """A limb from vertex `start`: joints at the given absolute angles and lengths, each bone a
    slightly curved stroke (curl: sideways bow relative to the bone length). Returns the end."""
    cur = start
    for k, (ang, ln) in enumerate(zip(angles, lengths)):
        p = d.points[cur]
        q = p + ln * np.array([math.cos(ang), math.sin(ang)])
        normal = np.array([-math.sin(ang), math.cos(ang)])
        pieces = max(1, int(round(ln / spacing)))
        inner = [p + (q - p) * (i / pieces) + curl * ln * math.sin(math.pi * i / pieces) * normal
                 for i in range(1, pieces)]
        name = names[k] if names else f"_j{len(d.points)}"
        end = d.key(name, q)
        d.chain(cur, inner, end)
        cur = end
    return cur


def ring(d, at, centre, count, prefix):
    """A closed loop of `count` vertices through vertex `at`, on the circle about `centre`
    (a head, a palm). Returns its vertices counter-clockwise from `at`. Their names start with
    "~": the count depends on the style, so equal names are not the same point of two drawings."""
    c = np.asarray(centre, dtype=float)
    p0 = d.points[at]
    a0 = math.atan2(p0[1] - c[1], p0[0] - c[0])
    r0 = np.linalg.norm(p0 - c)
    idx = [at]
    for k in range(1, count):
        a = a0 + 2 * math.pi * k / count
        idx.append(d.key(f"{prefix}{k}", c + r0 * np.array([math.cos(a), math.sin(a)])))
    for u, v in zip(idx, idx[1:] + idx[:1]):
        d.edges.append((u, v))
    return idx


def person(st, fingers=(1, 1), mirror=False):
    """A stick person: a ring head on the neck, arms from the shoulders, legs from the hip.
    fingers: how many fingers each hand has (1: the arm just ends)."""
    r = random.Random(st["seed"])
    sp, cu = st["spacing"] * 0.8, 0.08 * st["bend"] / 0.12
    d = Drawing()
    hip = d.key("hip", (0.0, 0.0))
    lean = math.radians(90 + r.uniform(-12, 12) * st["bend"] / 0.12)
    body = 0.55 * (1 + r.uniform(-0.15, 0.15))
    chest = limb(d, hip, [lean], [body], sp, r.uniform(-cu, cu), ["chest"])
    neck = limb(d, chest, [lean + r.uniform(-0.2, 0.2)], [0.12], sp, 0.0, ["neck"])
    head_r = 0.12 * (1 + r.uniform(-0.2, 0.2))
    na = math.atan2(*(d.points[neck] - d.points[chest])[::-1])
    centre = d.points[neck] + head_r * np.array([math.cos(na), math.sin(na)])
    ring(d, neck, centre, max(6, int(2 * math.pi * head_r / sp)), "~head")
    # side "l" is to the left (sign 1): arms at 145..200 degrees, the leg at 240..262
    for side, sign, nf in (("l", 1, fingers[0]), ("r", -1, fingers[1])):
        up = math.radians(90 + sign * r.uniform(55, 110))
        fore = up + math.radians(sign * r.uniform(-10, 40))
        wrist = limb(d, chest, [up, fore], [0.3 * (1 + r.uniform(-0.15, 0.15)), 0.27], sp, r.uniform(-cu, cu),
                     [f"elbow_{side}", f"hand_{side}"])
        for f in range(nf if nf > 1 else 0):
            limb(d, wrist, [fore + math.radians((f - (nf - 1) / 2) * 28)], [0.08], sp, 0.0, [f"finger_{side}{f}"])
        thigh = math.radians(270 - sign * r.uniform(8, 30))
        shin = thigh + math.radians(sign * r.uniform(-5, 25))
        ankle = limb(d, hip, [thigh, shin], [0.42, 0.4 * (1 + r.uniform(-0.1, 0.1))], sp, r.uniform(-cu, cu),
                     [f"knee_{side}", f"ankle_{side}"])
        limb(d, ankle, [math.pi if sign > 0 else 0.0], [0.09], sp, 0.0, [f"toe_{side}"])
    fig = d.figure()
    return reflect(fig) if mirror else fig


def tree(st, shape, mirror=False):
    """A branching tree: `shape` lists, for the trunk's top and then depth by depth, how many
    branches each junction has; forks spread with the style's angles and curl."""
    r = random.Random(st["seed"])
    sp, cu = st["spacing"] * 0.8, 0.1 * st["bend"] / 0.12
    d = Drawing()
    root = d.key("root", (0.0, 0.0))
    top = limb(d, root, [math.radians(90 + r.uniform(-8, 8))], [0.45 * (1 + r.uniform(-0.2, 0.2))], sp,
               r.uniform(-cu, cu), ["fork0"])

    def grow(at, heading, length, level, path):
        if level >= len(shape):
            return
        k = shape[level][path] if isinstance(shape[level], dict) else shape[level]
        if k == 0:
            return
        # narrower forks higher up, so that neighbouring boughs' twigs stay apart
        spread = math.radians(r.uniform(80, 110) * (1 + 0.15 * (k - 2)) * 0.7 ** level)
        for b in range(k):
            h = heading + (spread * (b / (k - 1) - 0.5) if k > 1 else 0) + math.radians(r.uniform(-6, 6))
            end = limb(d, at, [h], [length * (1 + r.uniform(-0.2, 0.2))], sp, r.uniform(-cu, cu),
                       [f"b{path}{b}"])
            grow(end, h, length * 0.58, level + 1, f"{path}{b}")

    grow(top, math.radians(90), 0.42, 0, "")
    fig = d.figure()
    return reflect(fig) if mirror else fig


def quadruped(st):
    """A dog-like figure: a back, a neck with a ring head, a tail, four legs."""
    r = random.Random(st["seed"])
    sp, cu = st["spacing"] * 0.8, 0.08 * st["bend"] / 0.12
    d = Drawing()
    hips = d.key("hips", (0.0, 0.6))
    back = limb(d, hips, [math.radians(r.uniform(-8, 8))], [0.8 * (1 + r.uniform(-0.15, 0.15))], sp,
                r.uniform(-cu, cu), ["shoulders"])
    neck_a = math.radians(r.uniform(45, 75))
    neck = limb(d, back, [neck_a], [0.28], sp, r.uniform(-cu, cu), ["neck"])
    hr = 0.1 * (1 + r.uniform(-0.2, 0.2))
    centre = d.points[neck] + hr * np.array([math.cos(neck_a), math.sin(neck_a)])
    ring(d, neck, centre, max(6, int(2 * math.pi * hr / sp)), "~head")
    limb(d, hips, [math.radians(r.uniform(150, 200)), math.radians(r.uniform(160, 230))], [0.18, 0.16], sp,
         r.uniform(-cu, cu), ["tail1", "tail2"])
    for at, tag in ((hips, "h"), (back, "f")):
        for k, base in enumerate((250, 290)):
            a1 = math.radians(base + r.uniform(-10, 10))
            limb(d, at, [a1, a1 + math.radians(r.uniform(-15, 15))], [0.3, 0.28], sp, r.uniform(-cu, cu),
                 [f"knee_{tag}{k}", f"paw_{tag}{k}"])
    return d.figure()


def hand(st):
    """A palm ring with four fingers at its top, a thumb at its right and a wrist of two
    strokes from its bottom."""
    r = random.Random(st["seed"])
    sp, cu = st["spacing"] * 0.6, 0.1 * st["bend"] / 0.12
    d = Drawing()
    count = max(12, int(2 * math.pi * 0.3 / sp))
    start = d.key("~palm0", (0.0, -0.3))
    idx = ring(d, start, (0.0, 0.0), count, "~palm")  # idx[k] at angle -90 + 360 k / count degrees

    def at(fraction):
        return idx[int(round(fraction * count)) % count]

    for f in range(4):
        v = at(0.5 + (f - 1.5) * 0.07 + r.uniform(-0.01, 0.01))
        a = math.atan2(*d.points[v][::-1])
        limb(d, v, [a + math.radians(r.uniform(-5, 5)), a + math.radians(r.uniform(-15, 15))],
             [0.28 * (1 + r.uniform(-0.2, 0.2)), 0.2], sp, r.uniform(-cu, cu), [f"k{f}", f"tip{f}"])
    thumb = at(0.25)
    a = math.atan2(*d.points[thumb][::-1])
    limb(d, thumb, [a + math.radians(20), a + math.radians(r.uniform(20, 50))], [0.25, 0.18], sp,
         r.uniform(-cu, cu), ["tk", "ttip"])
    for name, fraction, lean in (("wl", -0.05, -10), ("wr", 0.05, 10)):
        limb(d, at(fraction), [math.radians(270 + lean)], [0.35], sp, 0.0, [name])
    return d.figure()


SKELETONS = {
    "person": lambda st, shape: person(st),
    "tree": lambda st, shape: tree(st, shape),
    "quadruped": lambda st, shape: quadruped(st),
    "hand": lambda st, shape: hand(st),
}


def tree_shape(rng):
    """Branching counts per level, the same for both drawings of a pair."""
    return [rng.choice([2, 3]), rng.choice([2, 3]), rng.choice([0, 2])][: rng.choice([2, 3])]


# ---------------------------------------------------------------------------
# the pairs

def disguise(fig, rng, move):
    """Random numbering, edge order and direction; for the target also a random similarity.
    Returns the new figure and old -> new vertex numbers."""
    n = len(fig.points)
    perm = list(range(n))
    rng.shuffle(perm)  # perm[old] = new
    points = np.empty_like(fig.points)
    points[perm] = fig.points
    edges = [(perm[u], perm[v]) if rng.random() < 0.5 else (perm[v], perm[u]) for u, v in fig.edges]
    rng.shuffle(edges)
    if move:
        size = cc.figure_size(points)
        points = similarity(points, rng.uniform(-60, 60), 2 ** rng.uniform(-1, 1),
                            (rng.uniform(-1, 1) * size, rng.uniform(-1, 1) * size))
    return Figure(points, edges), perm


def write_figure(path, name, fig):
    doc = {"name": name, "vertices": [[float(x), float(y)] for x, y in fig.points],
           "edges": [[int(i), int(j)] for i, j in fig.edges]}
    path.write_text(json.dumps(doc) + "\n")


def landmark_pairs(a, b):
    """(vertex of a, vertex of b) for every key drawn in both with a degree other than 2: the
    junctions and ends the drawer meant to be the same (a person's hip, a letter's top-left
    end). Ring vertices are left out (their names depend on the vertex count)."""
    def degrees(fig):
        deg = [0] * len(fig.points)
        for u, v in fig.edges:
            deg[u] += 1
            deg[v] += 1
        return deg
    da, db = degrees(a), degrees(b)
    return [(a.keys[k], b.keys[k]) for k in sorted(a.keys) if not k.startswith("~") and k in b.keys
            and da[a.keys[k]] != 2 and db[b.keys[k]] != 2]


class Corpus:
    def __init__(self, out, rng):
        self.out, self.rng, self.entries = out, rng, []

    def add(self, name, family, src, tgt, expect, why, pins=None, landmarks=False):
        """Disguise and write one pair; pins are (source vertex, target vertex) before disguise.
        landmarks: record the intended partners of the named nodes (see `landmark_pairs`)."""
        for _ in range(MAX_REDRAWS):
            s, sp = disguise(src, self.rng, move=False)
            t, tp = disguise(tgt, self.rng, move=True)
            if not s.problems() and not t.problems():
                break
        else:
            raise RuntimeError(f"{name}: no valid disguise")
        write_figure(self.out / f"{name}.source.json", f"{name} source", s)
        write_figure(self.out / f"{name}.target.json", f"{name} target", t)
        entry = {"name": name, "family": family, "source": f"{name}.source.json", "target": f"{name}.target.json",
                 "expect": expect, "why": why}
        if pins:
            entry["pins"] = [[sp[a], tp[b]] for a, b in pins]
        if landmarks:
            entry["landmarks"] = [[sp[a], tp[b]] for a, b in landmark_pairs(src, tgt)]
        entry["n_source"], entry["n_target"] = len(s.points), len(t.points)
        self.entries.append(entry)


def font_family(corpus, count):
    rng = corpus.rng
    made = 0
    while made < count:
        found = font_pair(rng)
        if found is None:
            raise RuntimeError("no glyph found in two fonts")
        char, fa, fb, a, b = found
        label = char if char.isupper() or char.isdigit() else f"{char}_lower"
        name = f"font_{made:02d}_{label}_{fa.split('.')[0]}_to_{fb.split('.')[0]}"
        why = (f"'{char}' outlined in {fa} ({len(a.points)} points) and {fb} ({len(b.points)} points): "
               "two simple polygons, and one cycle matches another")
        pins = None
        if made % 4 == 3:
            pins = extreme_pins(a, b)
            if pins is None:
                continue  # a glyph without three distinct extreme points: draw another
            why += "; pinned: three of the extreme points to each other (same cyclic order)"
        corpus.add(name, "font", a, b, "match", why, pins)
        made += 1


def stroke_family(corpus, count):
    rng = corpus.rng
    letters = STROKE_LETTERS[:]
    rng.shuffle(letters)
    for k in range(count):
        letter = letters[k % len(letters)]
        a, b = drawn_pair(lambda st: draw_letter(letter, st), lambda st: draw_letter(letter, st), rng)
        pins = None
        why = f"centre-line {letter} in two styles: the same junctions, other chain lengths"
        if k % 3 == 2:
            pins = [(a.keys[key], b.keys[key]) for key in PIN_KEYS[letter]]
            why += f"; pinned: {' and '.join(PIN_KEYS[letter])} to themselves"
        name = f"stroke_{k:02d}_{letter if letter.isupper() or letter.isdigit() else letter + '_lower'}"
        corpus.add(name, "stroke", a, b, "match", why, pins, landmarks=True)


def skeleton_family(corpus, count):
    rng = corpus.rng
    kinds = list(SKELETONS)
    for k in range(count):
        kind = kinds[k % len(kinds)]
        shape = tree_shape(rng)
        make = SKELETONS[kind]
        a, b = drawn_pair(lambda st: make(st, shape), lambda st: make(st, shape), rng)
        why = f"{kind} in two poses and proportions, limbs sampled at other densities"
        if kind == "tree":
            why += f" (branching {shape})"
        corpus.add(f"skeleton_{k:02d}_{kind}", "skeleton", a, b, "match", why, landmarks=True)


def letter(name):
    return lambda st: draw_letter(name, st)


CROSS = [
    ("B_to_8", letter("B"), letter("8"), "both are two loops meeting at one vertex of degree 4, side by side"),
    ("A_to_R", letter("A"), letter("R"), "both are a loop with two outward tails at two junctions of degree 3"),
    ("E_to_F", letter("E"), letter("F"), "both are a tree with one junction of degree 3 (E's corners have degree 2)"),
    ("T_to_Y", letter("T"), letter("Y"), "both are a star of three arms"),
    ("K_to_H", letter("K"), letter("H"), "both are two junctions of degree 3 joined by a chain, two ends at each"),
    ("6_to_9", letter("6"), letter("9"), "both are a loop with one outward tail"),
    ("P_to_9", letter("P"), letter("9"), "both are a loop with one outward tail"),
    ("e_to_6", letter("e"), letter("6"), "both are a loop with one outward tail"),
    ("F_to_mirrored_F", letter("F"), lambda st: reflect(draw_letter("F", st)),
     "a reflected F is still a star of three arms (all ends), so its arms can be matched in the other order"),
    ("person_to_mirrored_person", lambda st: person(st), lambda st: person(st, mirror=True),
     "a reflected stick person with equal hands is the same plane graph: the arms and legs swap sides"),
]


def cross_family(corpus, count):
    for k in range(count):
        label, da, db, why = CROSS[k % len(CROSS)]
        a, b = drawn_pair(da, db, corpus.rng)
        corpus.add(f"cross_{k:02d}_{label}", "cross", a, b, "match", why)


def _refuse_outline_vs_centreline(rng):
    for _ in range(MAX_REDRAWS):
        font = rng.choice(FONTS)
        fig = outline_figure(font, "C", 10 ** rng.uniform(-3, -2))
        if fig is not None:
            return fig, drawn_pair(letter("C"), letter("C"), rng)[1], f"the outline of C in {font} (a cycle) " \
                "against a centre-line C (a path): a loop against a tree"
    raise RuntimeError("no C outline")


def _refuse_reversed_pins(rng):
    for _ in range(MAX_REDRAWS):
        found = font_pair(rng)
        if found is None:
            break
        char, fa, fb, a, b = found
        pins = extreme_pins(a, b)
        if pins is not None:
            pins = [(pins[0][0], pins[2][1]), pins[1], (pins[2][0], pins[0][1])]
            return a, b, pins, (f"'{char}' in {fa} and {fb}, three extreme points pinned to the other's in "
                                "reversed cyclic order, which no orientation-keeping match of two polygons has")
    raise RuntimeError("no glyph for the reversed pins")


def _refuse_t_junction_to_end(rng):
    a, b = drawn_pair(letter("T"), letter("T"), rng)
    pins = [(a.keys["c"], b.keys["b"])]
    return a, b, pins, "T to T, but the junction (degree 3) is pinned to the other T's end (degree 1)"


REFUSE = [
    ("A_vs_H", lambda rng: drawn_pair(letter("A"), letter("H"), rng), "A has a loop, H is a tree"),
    ("outline_C_vs_stroke_C", _refuse_outline_vs_centreline, None),
    ("T_vs_X", lambda rng: drawn_pair(letter("T"), letter("X"), rng), "a junction of degree 3 against one of 4"),
    ("Y_vs_K", lambda rng: drawn_pair(letter("Y"), letter("K"), rng),
     "one junction of degree 3 against two"),
    ("person_vs_mirror", lambda rng: drawn_pair(lambda st: person(st, fingers=(2, 3)),
                                               lambda st: person(st, fingers=(2, 3), mirror=True), rng),
     "a person with a two-fingered left and a three-fingered right hand against its mirror image: around the "
     "shoulders the head, the hands and the hip come in the other order, and no arm can stand in for another"),
    ("tree_vs_mirror", lambda rng: drawn_pair(lambda st: tree(st, [2, {"0": 2, "1": 3}]),
                                             lambda st: tree(st, [2, {"0": 2, "1": 3}], mirror=True), rng),
     "a tree whose left bough forks in two and right bough in three, against its mirror image"),
    ("8_vs_6", lambda rng: drawn_pair(letter("8"), letter("6"), rng), "two loops against one"),
    ("B_vs_P", lambda rng: drawn_pair(letter("B"), letter("P"), rng), "two loops against one"),
    ("clock_vs_balloon", lambda rng: drawn_pair(letter("clock"), letter("balloon"), rng),
     "a loop with a tail inside it against a loop with a tail outside: the outer faces differ"),
    ("reversed_pins", _refuse_reversed_pins, None),
    ("T_junction_pinned_to_end", _refuse_t_junction_to_end, None),
    ("4_vs_A", lambda rng: drawn_pair(letter("4"), letter("A"), rng),
     "a loop with two tails at one junction of degree 4 against two junctions of degree 3"),
]


def refuse_family(corpus, count):
    for k in range(count):
        label, make, why = REFUSE[k % len(REFUSE)]
        made = make(corpus.rng)
        pins = None
        if len(made) == 4:
            a, b, pins, why = made
        elif len(made) == 3:
            a, b, why = made
        else:
            a, b = made
        corpus.add(f"refuse_{k:02d}_{label}", "refuse", a, b, "refuse", why, pins)


FAMILIES = [("font", font_family), ("stroke", stroke_family), ("skeleton", skeleton_family),
            ("cross", cross_family), ("refuse", refuse_family)]


def generate(out, seed=1, count=12):
    """Write the corpus into `out`; returns the manifest entries."""
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    corpus = Corpus(out, random.Random(seed))
    for _, fill in FAMILIES:
        fill(corpus, count)
    (out / "manifest.json").write_text(json.dumps(corpus.entries, indent=1) + "\n")
    return corpus.entries


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", type=pathlib.Path)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count-per-family", type=int, default=12)
    args = ap.parse_args(argv)
    if args.count_per_family < 1:
        print("error: --count-per-family must be at least 1", file=sys.stderr)
        return 2
    entries = generate(args.out, args.seed, args.count_per_family)
    for fam, _ in FAMILIES:
        mine = [e for e in entries if e["family"] == fam]
        sizes = [e["n_source"] + e["n_target"] for e in mine]
        print(f"{fam}: {len(mine)} pairs, {min(sizes)}-{max(sizes)} vertices per pair")
    print(f"{len(entries)} pairs written to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
