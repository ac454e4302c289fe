#!/usr/bin/env python3
"""Generate hand-drawn-like drawings for issue 32's cleaning (`stickmorph clean`), every planted
defect listed in a manifest.

    /usr/bin/python3 bench/drawing_corpus.py OUT_DIR --seed S [--count N]

Issue 32 turns a *drawing* (strokes that cross and touch, ends that stop short, points repeated)
into a valid stick figure. bench/cleaning.py measures that on drawings like these. A drawing
file is `{"name": ..., "strokes": [{"points": [[x, y], ...], "cyclic": bool}, ...]}`.

Subjects (each drawn in a unit frame, then scaled by 8 to 8000 and moved by up to 3 sizes, one
drawing in four by up to 1000 sizes):
  stickman  a head (a closed stroke, or an open one that stops short of its start or ends
            exactly on it), a body whose top meets the head, arms (one stroke across the body,
            two arms from the body, an arm starting just past the body, a hand on the hip that
            stops short of it), legs that start exactly at the body's end or one inverted V
            that the body ends on
  glyph     a word of one to three letters drawn as strokes: A, H, X, T, E, K, #, +
  house     walls (a closed stroke, an open one closed by its end, or four strokes whose corners
            meet or overshoot), a roof, a door on the floor, a window with a cross, a chimney
  tree      a ground line, a trunk on it (or through it), branches from the trunk, one drawn
            across it, a crown outline that the trunk and some branches cross
  star      a pentagram drawn as one self-crossing stroke (closed, nearly closed or ending on
            its start), sometimes with a circle through it
  fish      one stroke that crosses itself at the tail, an eye, a fin on the body
  sun       a circle with rays that start on it, short of it or inside it

How a tablet draws: every stroke resampled along its arc length every 0.3-1% of the drawing's
size (its bounding-box diagonal), each stroke bent by its own smooth displacement field (up to
0.2% of the size; a diffeomorphism of the plane, so it adds no crossing of its own) and jittered
by 0.02%, coordinates on a grid: a power of two near size/8192 (a tablet's device units, three in
four drawings) or a decimal step near size/5000 (an exported SVG). Where a stroke ends on
another one the plan says how ("join"), and each drawing picks the defect:
  gap       the end stops short, 0.15-0.85 of the tolerance away (the default tolerance,
            1% of the size; the manifest keeps the distance measured on the final points)
  touch     the end lies exactly on the other stroke: on one of its points, or (on the power-
            of-two grid, where it can be exact) strictly inside one of its segments
  shared    the end is exactly another stroke's end (legs at the hip, an A's apex)
A join within 3 tolerances of the other stroke's end is a corner (an A's apex, a house's corner,
a head closing on its start): its end stops short of, or touches, that end itself, so that the
cleaned corner is a corner whatever the defect (a touch one segment from the end would leave the
end sticking out past the junction: another figure, and the two poses of a pair would differ).
and "overshoot" ends run 2-4 tolerances past the stroke they cross (a crossing and a tail).
Pen pauses: 0-3 exact duplicate consecutive points per stroke, some at the ends.

Every drawing is then analysed exactly (fractions.Fraction on the doubles): its proper
crossings (per pair of strokes, as planned), its exact contacts (only the planned touches and
shared ends), no overlap and no stroke retracing itself (the drawings `clean` must refuse), every
free end at least 1.5 tolerances from every other stroke, every planned gap within 0.1-0.9 of the
final tolerance, and no two strokes within 2 tolerances of each other away from a planned
feature (a sharp corner of one stroke counts as one), so that what cleaning should do is never
ambiguous. A drawing that fails is drawn again (the manifest counts the attempts).

Pairs: one item in three is a pair, the same subject (the same plan: the same strokes, joins and
overshoots) in two poses with independent jitter and defects, `NAME_a` and `NAME_b`, for
`stickmorph morph A.clean.json B.clean.json --correspond auto`.

Files: NAME.json per drawing and manifest.json: {"seed", "count", "tolerance_fraction",
"drawings": [{"name", "file", "kind", "subject", "pair", "pose", "strokes", "cyclic_strokes",
"points", "size", "tolerance", "grid", "scale", "offset", "attempts", "planted": {"gaps": [{"stroke",
"point", "end", "other_stroke", "distance", "near"}], "touches": [{"stroke", "point", "end",
"other_stroke", "on": "point"|"segment"|"end", "at"}], "crossings": [{"stroke", "other_stroke",
"segment", "other_segment", "at", "overshoot"}], "duplicates": [{"stroke", "point"}]},
"counts": {"gaps", "touches", "crossings", "overshoots", "duplicates"}}], "pairs": [{"name",
"kind", "a", "b"}], "totals"}. Point indices are into the stroke's points as written; a
duplicate's point is the copy (equal to the point before it). Deterministic for a seed.
"""
import argparse
import json
import math
import pathlib
import random
import sys
from fractions import Fraction

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import correspondence_check as cc  # noqa: E402  (the box filter of the exact plane-graph test)

TOLERANCE_FRACTION = 0.01  # issue 32's default tolerance: 1% of the bounding-box diagonal
SPACING = (0.003, 0.01)  # tablet point spacing, of the size
WOBBLE = 0.002  # a stroke's smooth displacement, of the size
JITTER = 0.0002  # per point, of the size; well under the spacing, so no stroke folds back
GAP_RANGE = (0.15, 0.85)  # planted gaps, of the tolerance
GAP_ACCEPT = (0.1, 0.9)  # measured on the final points (the tolerance moves with the box)
OVERSHOOT_RANGE = (2.0, 4.0)  # tails past a crossed stroke, in tolerances
OVERSHOOT_CLEAR = 1.3  # an overshooting end at least this far from the stroke it crossed
FREE_CLEAR = 1.5  # free ends at least this far from any other stroke, in tolerances
NEAR = 2.0  # strokes closer than this (in tolerances) must be near a planned feature
FEATURE_RADIUS = 8.0  # "near a planned feature", in tolerances
SELF_WINDOW = 6.0  # parts of one stroke closer along it than this (in tolerances) are neighbours
CORNER = 3.0  # a join this close (in tolerances) to the other stroke's end is made at that end
MAX_ATTEMPTS = 60
KINDS = ("stickman", "glyph", "house", "tree", "star", "fish", "sun")
PAIR_EVERY = 3  # one item in three is a pair of poses
LETTERS = "AHXTEK#+"


# ---------------------------------------------------------------------------
# ideal paths in the unit frame

def rot(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s], [s, c]])


def unit(v):
    n = float(np.hypot(*v))
    return np.asarray(v, dtype=float) / n if n > 0 else np.array([1.0, 0.0])


def densify(points, step=0.002, closed=False):
    """A polyline through the points, every piece cut into pieces of at most `step`."""
    pts = [np.asarray(p, dtype=float) for p in points]
    if closed:
        pts = pts + [pts[0]]
    out = [pts[0]]
    for a, b in zip(pts, pts[1:]):
        n = max(1, int(math.ceil(np.hypot(*(b - a)) / step)))
        for k in range(1, n + 1):
            out.append(a + (b - a) * k / n)
    if closed:
        out.pop()
    return np.array(out)


def bowed(p, q, bow, step=0.002):
    """The segment p-q bent sideways by bow times its length at its middle (a hand's line)."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    length = float(np.hypot(*(q - p)))
    n = max(2, int(math.ceil(length / step)))
    t = np.linspace(0.0, 1.0, n + 1)[:, None]
    normal = np.array([-(q - p)[1], (q - p)[0]]) / max(length, 1e-12)
    return p + t * (q - p) + normal * bow * length * np.sin(np.pi * t)


def path(*parts):
    """Pieces joined end to start (the first point of each later piece dropped)."""
    out = [np.asarray(parts[0], float)]
    for piece in parts[1:]:
        out.append(np.asarray(piece, float)[1:])
    return np.concatenate(out)


def arc(center, rx, ry, a0, a1, step=0.002):
    n = max(8, int(math.ceil(abs(a1 - a0) * max(rx, ry) / step)))
    t = np.linspace(a0, a1, n + 1)
    return np.stack([center[0] + rx * np.cos(t), center[1] + ry * np.sin(t)], axis=1)


def ellipse(center, rx, ry, a0=0.0, step=0.002, closed=True):
    """A closed ellipse starting at angle a0 (the last point before the first again)."""
    pts = arc(center, rx, ry, a0, a0 + 2 * math.pi, step)
    return pts[:-1] if closed else pts


def quad(p0, p1, p2, step=0.002):
    p0, p1, p2 = (np.asarray(p, float) for p in (p0, p1, p2))
    length = np.hypot(*(p1 - p0)) + np.hypot(*(p2 - p1))
    t = np.linspace(0.0, 1.0, max(8, int(math.ceil(length / step))) + 1)[:, None]
    return (1 - t) ** 2 * p0 + 2 * (1 - t) * t * p1 + t ** 2 * p2


class Stroke:
    """One stroke's ideal path in the unit frame and what happens at its ends.

    start/end: ("free",), ("join", k), ("overshoot", k), ("share", k, "start"|"end"),
    ("self",) (the end stops short of, or touches, this stroke's own start part) or ("closed",)
    (the end is exactly this stroke's start)."""

    def __init__(self, name, points, cyclic=False, start=("free",), end=("free",)):
        self.name, self.ideal, self.cyclic = name, np.asarray(points, float), cyclic
        self.start, self.end = start, end


class Subject:
    def __init__(self, label):
        self.label = label
        self.strokes, self.corners, self.crossings = [], [], {}

    def add(self, stroke):
        self.strokes.append(stroke)
        return len(self.strokes) - 1

    def cross(self, i, k, n=1):
        key = (min(i, k), max(i, k))
        self.crossings[key] = self.crossings.get(key, 0) + n


def choose(rng, options):
    return options[rng.randrange(len(options))]


def join_or_overshoot(plan, overshoot_share=0.3):
    return "overshoot" if plan.random() < overshoot_share else "join"


# ---------------------------------------------------------------------------
# subjects: plan (shared by the two poses of a pair) and pose (each drawing)

def stickman(plan, pose):
    s = Subject("stick figure")
    head_style = choose(plan, ["cyclic", "self", "closed"])
    arms = choose(plan, ["across", "two", "overshoot", "hip"])
    legs = choose(plan, ["shared", "vee"])
    tilt = math.radians(pose.uniform(-8, 8))
    up = rot(tilt) @ np.array([0.0, 1.0])
    side = rot(tilt) @ np.array([1.0, 0.0])
    hip = np.array([0.0, 0.42])
    neck = hip + 0.33 * up
    r = 0.11
    center = neck + (r + 0.005) * up
    bottom = center - r * up  # where the body meets the head
    a0 = tilt + math.radians(plan.uniform(-30, 210))  # a head's own ends away from the neck
    head_pts = ellipse(center, r, r, a0, closed=(head_style == "cyclic"))
    if head_style == "cyclic":
        head = s.add(Stroke("head", head_pts, cyclic=True))
    else:
        head = s.add(Stroke("head", head_pts, end=("self",) if head_style == "self" else ("closed",)))
    body = s.add(Stroke("body", bowed(bottom, hip, pose.uniform(-0.03, 0.03)), start=("join", head)))
    shoulder = hip + 0.26 * up

    def limb(base, a1, a2, l1=0.15, l2=0.14):
        elbow = base + l1 * (rot(tilt) @ np.array([math.cos(a1), math.sin(a1)]))
        hand = elbow + l2 * (rot(tilt) @ np.array([math.cos(a2), math.sin(a2)]))
        return elbow, hand

    la1, ra1 = math.radians(pose.uniform(160, 215)), math.radians(pose.uniform(-35, 20))
    la2, ra2 = la1 + math.radians(pose.uniform(-40, 40)), ra1 + math.radians(pose.uniform(-40, 40))
    if arms == "across":
        le, lh = limb(shoulder, la1, la2)
        re, rh = limb(shoulder, ra1, ra2)
        arm = s.add(Stroke("arms", densify([lh, le, shoulder, re, rh])))
        s.cross(arm, body)
    elif arms in ("two", "overshoot"):
        le, lh = limb(shoulder, la1, la2)
        right = shoulder - 0.045 * up  # the two joins apart by 3 tolerances or more
        re, rh = limb(right, ra1, ra2)
        kind = "overshoot" if arms == "overshoot" else "join"
        s.add(Stroke("left arm", densify([shoulder, le, lh]), start=(kind, body)))
        s.add(Stroke("right arm", densify([right, re, rh]), start=("join", body)))
    else:  # a hand on the hip: the arm goes out and comes back to the body
        elbow = shoulder + 0.15 * (rot(tilt) @ np.array([math.cos(math.radians(pose.uniform(195, 215))),
                                                            math.sin(math.radians(pose.uniform(195, 215)))]))
        on_hip = hip + 0.09 * up
        s.add(Stroke("left arm", densify([shoulder, elbow, on_hip]), start=("join", body), end=("join", body)))
        s.corners.append(elbow)
        re, rh = limb(shoulder, ra1, ra2)
        s.add(Stroke("right arm", densify([shoulder, re, rh]), start=("join", body)))
    knee_l = hip + rot(tilt) @ np.array([-pose.uniform(0.06, 0.12), -0.2])
    knee_r = hip + rot(tilt) @ np.array([pose.uniform(0.06, 0.12), -0.2])
    foot_l = knee_l + rot(tilt) @ np.array([-pose.uniform(0.0, 0.08), -0.2])
    foot_r = knee_r + rot(tilt) @ np.array([pose.uniform(0.0, 0.08), -0.2])
    if legs == "shared":
        s.add(Stroke("left leg", densify([hip, knee_l, foot_l]), start=("share", body, "end")))
        s.add(Stroke("right leg", densify([hip, knee_r, foot_r]), start=("share", body, "end")))
    else:
        vee = s.add(Stroke("legs", densify([foot_l, knee_l, hip, knee_r, foot_r])))
        s.strokes[body].end = ("join", vee)
    s.corners.append(hip)
    return s


def letter(plan, pose, ch, origin, s):
    """Strokes of one letter into s, its box [0, 0.8] x [0, 1] moved to origin."""
    shear = pose.uniform(-0.2, 0.2)
    stretch = pose.uniform(0.9, 1.1)

    def P(x, y):
        return np.array([origin[0] + stretch * (x + shear * y), origin[1] + y])

    def line(p, q):
        return bowed(p, q, pose.uniform(-0.02, 0.02))

    if ch == "A":
        apex, bl, br = P(0.4, 1.0), P(0.0, 0.0), P(0.8, 0.0)
        style = choose(plan, ["one", "shared", "join"])
        if style == "one":
            leg = s.add(Stroke("A", path(line(bl, apex), line(apex, br))))
            left = right = leg
        else:
            left = s.add(Stroke("A left", line(bl, apex)))
            rel = ("share", left, "end") if style == "shared" else ("join", left)
            right = s.add(Stroke("A right", line(apex, br), start=rel))
        s.corners.append(apex)
        a, b = bl + 0.4 * (apex - bl), br + 0.4 * (apex - br)
        ends = (join_or_overshoot(plan), join_or_overshoot(plan))
        s.add(Stroke("A bar", line(a, b), start=(ends[0], left), end=(ends[1], right)))
    elif ch == "H":
        left = s.add(Stroke("H left", line(P(0.0, 1.0), P(0.0, 0.0))))
        right = s.add(Stroke("H right", line(P(0.7, 1.0), P(0.7, 0.0))))
        s.add(Stroke("H bar", line(P(0.0, 0.5), P(0.7, 0.5)), start=(join_or_overshoot(plan), left),
                     end=(join_or_overshoot(plan), right)))
    elif ch in "X+":
        if ch == "X":
            a = s.add(Stroke("X 1", line(P(0.0, 1.0), P(0.8, 0.0))))
            b = s.add(Stroke("X 2", line(P(0.8, 1.0), P(0.0, 0.0))))
        else:
            a = s.add(Stroke("+ 1", line(P(0.0, 0.5), P(0.8, 0.5))))
            b = s.add(Stroke("+ 2", line(P(0.4, 0.95), P(0.4, 0.05))))
        s.cross(a, b)
    elif ch == "T":
        top = s.add(Stroke("T top", line(P(0.0, 1.0), P(0.8, 1.0))))
        s.add(Stroke("T stem", line(P(0.4, 1.0), P(0.4, 0.0)), start=(join_or_overshoot(plan), top)))
    elif ch == "E":
        style = choose(plan, ["bracket", "bars"])
        if style == "bracket":
            spine = s.add(Stroke("E", path(line(P(0.65, 1.0), P(0.0, 1.0)), line(P(0.0, 1.0), P(0.0, 0.0)),
                                           line(P(0.0, 0.0), P(0.65, 0.0)))))
            s.corners += [P(0.0, 1.0), P(0.0, 0.0)]
            s.add(Stroke("E middle", line(P(0.0, 0.5), P(0.5, 0.5)), start=(join_or_overshoot(plan), spine)))
        else:
            spine = s.add(Stroke("E spine", line(P(0.0, 1.0), P(0.0, 0.0))))
            for y, w in ((1.0, 0.65), (0.5, 0.5), (0.0, 0.65)):
                s.add(Stroke(f"E bar {y}", line(P(0.0, y), P(w, y)), start=("join", spine)))
    elif ch == "K":
        spine = s.add(Stroke("K spine", line(P(0.0, 1.0), P(0.0, 0.0))))
        upper = s.add(Stroke("K upper", line(P(0.0, 0.42), P(0.65, 1.0)), start=(join_or_overshoot(plan), spine)))
        s.add(Stroke("K lower", line(P(0.22, 0.615), P(0.7, 0.0)), start=("join", upper)))
    elif ch == "#":
        hs = [s.add(Stroke(f"# h{k}", line(P(0.0, y), P(0.8, y)))) for k, y in enumerate((0.33, 0.67))]
        vs = [s.add(Stroke(f"# v{k}", line(P(x, 1.0), P(x - 0.05, 0.0)))) for k, x in enumerate((0.3, 0.6))]
        for h in hs:
            for v in vs:
                s.cross(h, v)


def glyph(plan, pose):
    word = "".join(choose(plan, LETTERS) for _ in range(plan.choice((1, 2, 2, 3))))
    s = Subject(f"glyphs {word}")
    for k, ch in enumerate(word):
        letter(plan, pose, ch, (1.15 * k, 0.0), s)
    return s


def house(plan, pose):
    s = Subject("house")
    w, h = 1.0, pose.uniform(0.6, 0.75)
    lean = pose.uniform(-0.05, 0.05)

    def P(x, y):
        return np.array([x + lean * y, y])

    def line(p, q):
        return bowed(p, q, pose.uniform(-0.015, 0.015))

    corners = [P(0, 0), P(w, 0), P(w, h), P(0, h)]
    s.corners += corners
    walls_style = choose(plan, ["cyclic", "self", "four"])
    if walls_style == "cyclic":
        walls = s.add(Stroke("walls", densify(corners, closed=True), cyclic=True))
        floor = top = walls
    elif walls_style == "self":
        walls = s.add(Stroke("walls", densify(corners + [corners[0]]), end=("self",)))
        floor = top = walls
    else:
        names = ("floor", "right wall", "top", "left wall")
        corner_kind = [join_or_overshoot(plan, 0.5) for _ in range(4)]
        ids = [s.add(Stroke(names[k], line(corners[k], corners[(k + 1) % 4]))) for k in range(4)]
        for k in range(4):
            nxt = ids[(k + 1) % 4]
            if corner_kind[k] == "overshoot":  # both run past the corner: they cross there
                s.strokes[ids[k]].end = ("overshoot", nxt)
                s.strokes[nxt].start = ("overshoot", ids[k])
                s.cross(ids[k], nxt, -1)  # counted once per overshoot below, but it is one crossing
            else:
                s.strokes[ids[k]].end = ("join", nxt)
        floor, top = ids[0], ids[2]
    apex = P(w / 2, h + pose.uniform(0.3, 0.45))
    roof_kind = (join_or_overshoot(plan), join_or_overshoot(plan))
    left_eave, right_eave = P(0.12, h), P(w - 0.12, h)
    s.add(Stroke("roof", path(line(left_eave, apex), line(apex, right_eave)),
                 start=(roof_kind[0], top), end=(roof_kind[1], top)))
    roof = len(s.strokes) - 1
    s.corners.append(apex)
    dx = pose.uniform(0.12, 0.25)
    door = [P(dx, 0), P(dx, 0.55 * h), P(dx + 0.18, 0.55 * h), P(dx + 0.18, 0)]
    s.corners += door[1:3]
    door_kind = join_or_overshoot(plan)
    s.add(Stroke("door", densify(door), start=(door_kind, floor), end=(door_kind, floor)))
    if plan.random() < 0.7:
        cx, cy, half = pose.uniform(0.68, 0.78), 0.6 * h, 0.09
        frame = [P(cx - half, cy - half), P(cx + half, cy - half), P(cx + half, cy + half), P(cx - half, cy + half)]
        s.corners += frame
        window = s.add(Stroke("window", densify(frame, closed=True), cyclic=True))
        kind = join_or_overshoot(plan)
        a = s.add(Stroke("window bar 1", line(P(cx - half, cy), P(cx + half, cy)), start=(kind, window),
                         end=(kind, window)))
        b = s.add(Stroke("window bar 2", line(P(cx, cy + half), P(cx, cy - half)), start=(kind, window),
                         end=(kind, window)))
        s.cross(a, b)
    if plan.random() < 0.5:
        # a chimney on the right slope of the roof
        t0, t1 = pose.uniform(0.25, 0.35), pose.uniform(0.55, 0.62)
        base0 = apex + t0 * (right_eave - apex)
        base1 = apex + t1 * (right_eave - apex)
        top_y = apex[1] - 0.02
        c = [base0, np.array([base0[0], top_y]), np.array([base1[0], top_y]), base1]
        s.corners += c[1:3]
        s.add(Stroke("chimney", densify(c), start=("join", roof), end=("join", roof)))
    return s


def tree(plan, pose):
    s = Subject("tree")
    sway = pose.uniform(-0.08, 0.08)

    def P(x, y):
        return np.array([x + sway * y * y, y])

    ground = s.add(Stroke("ground", bowed(P(-0.55, 0), P(0.55, 0), pose.uniform(-0.01, 0.01))))
    trunk_kind = join_or_overshoot(plan, 0.4)
    trunk_pts = np.array([P(0.0, y) for y in np.linspace(0.0, 0.8, 200)])
    trunk = s.add(Stroke("trunk", trunk_pts, start=(trunk_kind, ground)))
    crown_c, crown_rx, crown_ry = P(0.0, 0.8), pose.uniform(0.4, 0.46), pose.uniform(0.3, 0.34)
    crown_pts = ellipse(crown_c, crown_rx, crown_ry, math.radians(plan.uniform(0, 360)))
    crown = s.add(Stroke("crown", crown_pts, cyclic=True))
    s.cross(crown, trunk)  # the trunk enters the crown from below
    count = plan.choice((2, 3, 4))
    across = plan.random() < 0.5
    for k in range(count):
        y = 0.58 + 0.12 * k / max(1, count - 1) + pose.uniform(-0.015, 0.015)
        sign = 1 if k % 2 == 0 else -1
        base = P(0.0, y)
        angle = math.radians(90 - sign * pose.uniform(35, 55))
        d = np.array([math.cos(angle), math.sin(angle)])
        # where the branch would leave the crown (the ellipse), from inside
        t_exit = ray_ellipse(base, d, crown_c, crown_rx, crown_ry)
        tip_kind = choose(plan, ["inside", "inside", "overshoot", "join"])
        if tip_kind == "inside":
            tip = base + d * t_exit * pose.uniform(0.55, 0.75)
            end = ("free",)
        else:
            tip = base + d * t_exit
            end = ("overshoot" if tip_kind == "overshoot" else "join", crown)
        if across and k == 0:
            start = base - d * 0.07  # drawn across the trunk
            b = s.add(Stroke(f"branch {k}", bowed(start, tip, pose.uniform(-0.02, 0.02)), end=end))
            s.cross(b, trunk)
        else:
            s.add(Stroke(f"branch {k}", bowed(base, tip, pose.uniform(-0.02, 0.02)), start=("join", trunk),
                         end=end))
    return s


def ray_ellipse(p, d, c, rx, ry):
    """The t > 0 where p + t d meets the ellipse (p inside)."""
    q = (p - c) / np.array([rx, ry])
    e = d / np.array([rx, ry])
    a, b, cc_ = e @ e, 2 * q @ e, q @ q - 1
    return (-b + math.sqrt(b * b - 4 * a * cc_)) / (2 * a)


def star(plan, pose):
    s = Subject("star")
    style = choose(plan, ["cyclic", "self", "closed"])
    turn = math.radians(pose.uniform(-12, 12))
    sx = pose.uniform(0.88, 1.12)
    tips = []
    for k in range(5):
        a = math.pi / 2 + turn + 2 * math.pi * k / 5
        radius = 0.5 * pose.uniform(0.93, 1.05)
        tips.append(np.array([sx * radius * math.cos(a), radius * math.sin(a)]))
    order = [tips[(2 * k) % 5] for k in range(5)]
    s.corners += tips
    if style == "cyclic":
        st = s.add(Stroke("star", densify(order, closed=True), cyclic=True))
    else:
        st = s.add(Stroke("star", densify(order + [order[0]]), end=("self",) if style == "self" else ("closed",)))
    s.cross(st, st, 5)
    if plan.random() < 0.4:
        circle = s.add(Stroke("circle", ellipse((0.0, 0.0), 0.3 * sx, 0.3, math.radians(plan.uniform(0, 360))),
                              cyclic=True))
        s.cross(circle, st, 10)
    return s


def fish(plan, pose):
    s = Subject("fish")
    spread = pose.uniform(0.16, 0.24)
    nose = np.array([0.5, pose.uniform(-0.05, 0.05)])
    t1, t2 = np.array([-0.6, spread]), np.array([-0.6, -spread])
    bulge = pose.uniform(0.38, 0.48)
    lower = quad(t1, (0.0, -bulge), nose)
    upper = quad(nose, (0.0, bulge), t2)
    body = s.add(Stroke("body", path(lower, upper)))
    s.cross(body, body, 1)
    s.corners.append(nose)
    s.add(Stroke("eye", ellipse((0.25, 0.05 + nose[1] / 2), 0.035, 0.035, math.radians(plan.uniform(0, 360))),
                 cyclic=True))
    if plan.random() < 0.6:
        # a fin on the lower side: a small V whose ends meet the body
        b0 = quad_point(upper, 0.45)
        b1 = quad_point(upper, 0.62)
        mid = (b0 + b1) / 2 + np.array([0.0, 0.12])
        s.corners.append(mid)
        s.add(Stroke("fin", densify([b0, mid, b1]), start=("join", body), end=("join", body)))
    return s


def quad_point(points, f):
    return np.asarray(points[int(round(f * (len(points) - 1)))], float)


def sun(plan, pose):
    s = Subject("sun")
    r = 0.3
    style = choose(plan, ["cyclic", "self"])
    a0 = math.radians(plan.uniform(0, 360))
    circle_pts = ellipse((0.0, 0.0), r, r, a0, closed=(style == "cyclic"))
    circle = s.add(Stroke("sun", circle_pts, cyclic=style == "cyclic", end=("self",) if style == "self" else ("free",)))
    rays = plan.choice((6, 7, 8, 9))
    turn = pose.uniform(0, 2 * math.pi / rays)
    kinds = [join_or_overshoot(plan, 0.35) for _ in range(rays)]
    for k in range(rays):
        a = turn + 2 * math.pi * k / rays
        if style == "self" and abs(math.remainder(a - a0, 2 * math.pi)) < 0.25:
            a += 0.3  # keep rays off the circle's own start and end
        d = np.array([math.cos(a), math.sin(a)])
        length = pose.uniform(0.18, 0.28)
        s.add(Stroke(f"ray {k}", bowed(r * d, (r + length) * d, pose.uniform(-0.02, 0.02)),
                     start=(kinds[k], circle)))
    return s


SUBJECTS = {"stickman": stickman, "glyph": glyph, "house": house, "tree": tree, "star": star, "fish": fish,
            "sun": sun}


# ---------------------------------------------------------------------------
# the tablet

def arclength(points, cyclic=False):
    pts = np.vstack([points, points[:1]]) if cyclic else points
    seg = np.hypot(*np.diff(pts, axis=0).T)
    return pts, np.concatenate([[0.0], np.cumsum(seg)])


def resample(points, cyclic, spacing, rng):
    """Points every `spacing` (times 0.75-1.25) along the path; an open path keeps both ends."""
    pts, s = arclength(points, cyclic)
    total = s[-1]
    at = [0.0]
    while True:
        nxt = at[-1] + spacing * rng.uniform(0.75, 1.25)
        if nxt >= total - (0.5 * spacing if cyclic else 0.4 * spacing):
            break
        at.append(nxt)
    if not cyclic:
        at.append(total)
    x = np.interp(at, s, pts[:, 0])
    y = np.interp(at, s, pts[:, 1])
    return np.stack([x, y], axis=1)


def wobble_field(rng, size):
    """A stroke's smooth displacement: three waves, wavelengths 0.3-0.8 of the size, WOBBLE in
    all (its derivative stays well under 1, so it moves the plane without folding it)."""
    waves = []
    for _ in range(3):
        lam = rng.uniform(0.3, 0.8) * size
        theta = rng.uniform(0, 2 * math.pi)
        k = 2 * math.pi / lam * np.array([math.cos(theta), math.sin(theta)])
        amp = WOBBLE * size / 3 * rng.uniform(0.5, 1.0)
        waves.append((k, amp, rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi)))

    def move(p):
        out = np.array(p, dtype=float)
        for k, amp, px, py in waves:
            phase = p @ k
            out[:, 0] += amp * np.sin(phase + px)
            out[:, 1] += amp * np.sin(phase + py)
        return out
    return move


def extend(points, at_start, length):
    """The path with its start (or end) carried on straight for `length`."""
    if at_start:
        d = unit(points[0] - points[min(5, len(points) - 1)])
        return np.vstack([[points[0] + d * length], points])
    d = unit(points[-1] - points[max(-6, -len(points))])
    return np.vstack([points, [points[-1] + d * length]])


def bbox_diagonal(points):
    pts = np.asarray(points, float).reshape(-1, 2)
    return float(np.hypot(*(pts.max(axis=0) - pts.min(axis=0))))


class Grid:
    """Where coordinates may lie: multiples of a power of two, or of a decimal step."""

    def __init__(self, kind, size):
        self.kind = kind
        if kind == "dyadic":
            self.step = 2.0 ** math.floor(math.log2(size / 8192))
            self.decimals = None
        else:
            self.decimals = max(0, math.ceil(-math.log10(size / 5000)))
            self.step = 10.0 ** -self.decimals

    def snap(self, p):
        p = np.asarray(p, float)
        if self.kind == "dyadic":
            return np.round(p / self.step) * self.step
        return np.round(p, self.decimals)

    def describe(self):
        return {"kind": self.kind, "step": self.step}


# ---------------------------------------------------------------------------
# geometry on the final points

def point_segment_distance(p, a, b):
    """Distances from point p to the segments a[i]-b[i] and the nearest points."""
    d = b - a
    dd = np.einsum("ij,ij->i", d, d)
    t = np.where(dd > 0, np.einsum("ij,ij->i", p[None, :] - a, d) / np.where(dd > 0, dd, 1.0), 0.0)
    t = np.clip(t, 0.0, 1.0)
    near = a + t[:, None] * d
    return np.hypot(*(near - p[None, :]).T), near, t


def stroke_segments(points, cyclic):
    pts = np.asarray(points, float)
    if cyclic:
        return pts, np.roll(pts, -1, axis=0)
    return pts[:-1], pts[1:]


def cumulative(points, cyclic):
    a, b = stroke_segments(points, cyclic)
    return np.concatenate([[0.0], np.cumsum(np.hypot(*(b - a).T))])


def distance_to_stroke(p, points, cyclic, skip_arc=None, from_end=True):
    """Distance from p to the stroke and the nearest point; skip_arc: leave out the part of the
    stroke within that arc length of its end (from_end) or start (its own neighbourhood)."""
    a, b = stroke_segments(points, cyclic)
    if len(a) == 0:
        return math.inf, None
    dist, near, _ = point_segment_distance(np.asarray(p, float), a, b)
    if skip_arc is not None:
        s = cumulative(points, cyclic)
        total = s[-1]
        mid = (s[:-1] + s[1:]) / 2
        keep = (mid < total - skip_arc) if from_end else (mid > skip_arc)
        if not keep.any():
            return math.inf, None
        dist = np.where(keep, dist, np.inf)
    k = int(np.argmin(dist))
    return float(dist[k]), near[k]


def compress(points, cyclic):
    """The stroke's points without consecutive exact duplicates: (points, original index of each)."""
    keep = [0]
    for j in range(1, len(points)):
        if tuple(points[j]) != tuple(points[keep[-1]]):
            keep.append(j)
    if cyclic and len(keep) > 1 and tuple(points[keep[-1]]) == tuple(points[keep[0]]):
        keep.pop()
    return [tuple(points[j]) for j in keep], keep


def analyse(strokes, limit=50):
    """The drawing's exact features, fractions.Fraction on the doubles.

    strokes: [(points, cyclic)]. Returns {"crossings": [(i, seg_i, k, seg_k, (x, y))] (proper
    crossings, i <= k, seg the original index of the segment's first point), "contacts":
    [(i, j, k, on, (x, y))] (point j of stroke i exactly on stroke k, not where the two are the
    same point of one stroke or neighbours along it; on "point" or "segment"), "problems":
    [text] (overlaps, retraces, strokes of one point)}."""
    segs = []  # (stroke, first original index, second original index, a, b, position in stroke)
    exact = {}
    problems = []
    for i, (points, cyclic) in enumerate(strokes):
        pts, idx = compress(points, cyclic)
        if len(pts) < 2:
            problems.append(f"stroke {i} has a single point")
            continue
        n = len(pts)
        count = n if cyclic and n > 2 else n - 1
        for m in range(count):
            segs.append((i, idx[m], idx[(m + 1) % n], pts[m], pts[(m + 1) % n], m, count, cyclic and n > 2))
        for p in pts:
            if p not in exact:
                exact[p] = (Fraction(p[0]), Fraction(p[1]))
    if not segs:
        return {"crossings": [], "contacts": [], "problems": problems}
    a = np.array([s[3] for s in segs])
    b = np.array([s[4] for s in segs])
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    crossings, contacts = [], {}

    def orient(p, q, r):
        P, Q, R = exact[p], exact[q], exact[r]
        d = (Q[0] - P[0]) * (R[1] - P[1]) - (Q[1] - P[1]) * (R[0] - P[0])
        return (d > 0) - (d < 0)

    def on_closed(p, q, r):
        """r on the closed segment p-q (collinear assumed)."""
        return min(p[0], q[0]) <= r[0] <= max(p[0], q[0]) and min(p[1], q[1]) <= r[1] <= max(p[1], q[1])

    def adjacent(s, t):
        if s[0] != t[0]:
            return False
        d = abs(s[5] - t[5])
        return d == 1 or (s[7] and d == s[6] - 1)

    for x, y in cc._box_pairs(lo, hi, lo, hi, same=True):
        s, t = segs[x], segs[y]
        p, q, r, u = s[3], s[4], t[3], t[4]
        if adjacent(s, t):
            shared = ({p, q} & {r, u})
            if len({p, q, r, u}) == 2:  # the same segment drawn back (a, b, a)
                problems.append(f"stroke {s[0]} retraces itself at point {s[2] if s[2] == t[1] else t[2]}")
            elif shared and len({p, q, r, u}) == 3:
                c = shared.pop()
                far_s = q if p == c else p
                far_t = u if r == c else r
                if orient(c, far_s, far_t) == 0:
                    ds = (exact[far_s][0] - exact[c][0], exact[far_s][1] - exact[c][1])
                    dt = (exact[far_t][0] - exact[c][0], exact[far_t][1] - exact[c][1])
                    if ds[0] * dt[0] + ds[1] * dt[1] > 0:
                        problems.append(f"stroke {s[0]} retraces itself at point {s[2] if s[2] == t[1] else t[2]}")
            continue
        o1, o2, o3, o4 = orient(p, q, r), orient(p, q, u), orient(r, u, p), orient(r, u, q)
        if o1 * o2 < 0 and o3 * o4 < 0:
            i, k = s[0], t[0]
            at = intersection(p, q, r, u)
            if i <= k:
                crossings.append((i, s[1], k, t[1], at))
            else:
                crossings.append((k, t[1], i, s[1], at))
            continue
        if o1 == 0 and o2 == 0:
            # collinear: an overlap unless they meet in one end at most
            common = [z for z in (p, q) if on_closed(r, u, z)] + [z for z in (r, u) if on_closed(p, q, z)]
            if len(set(common)) >= 2:
                problems.append(f"strokes {s[0]} and {t[0]} overlap along a length near {p}")
                continue
        for (z, j, owner), (e0, e1, j0, j1, other) in (
                ((p, s[1], s[0]), (r, u, t[1], t[2], t[0])), ((q, s[2], s[0]), (r, u, t[1], t[2], t[0])),
                ((r, t[1], t[0]), (p, q, s[1], s[2], s[0])), ((u, t[2], t[0]), (p, q, s[1], s[2], s[0]))):
            if orient(e0, e1, z) == 0 and on_closed(e0, e1, z):
                if owner == other and ((z == e0 and j == j0) or (z == e1 and j == j1)):
                    continue  # the same point of one stroke (between two of its segments)
                on = "point" if z in (e0, e1) else "segment"
                key = (owner, j, other)
                if key not in contacts or on == "point":
                    contacts[key] = (owner, j, other, on, (float(z[0]), float(z[1])))
        if len(problems) >= limit:
            break
    return {"crossings": crossings, "contacts": sorted(contacts.values()), "problems": problems}


def intersection(p, q, r, u):
    """Where segments p-q and r-u cross (floats; the manifest's location)."""
    p, q, r, u = (np.asarray(z, float) for z in (p, q, r, u))
    d1, d2 = q - p, u - r
    den = d1[0] * d2[1] - d1[1] * d2[0]
    t = ((r[0] - p[0]) * d2[1] - (r[1] - p[1]) * d2[0]) / den
    x = p + t * d1
    return (float(x[0]), float(x[1]))


def near_misses(strokes, tol, features, corners):
    """Places where two strokes (or two parts of one stroke further apart along it than
    SELF_WINDOW tolerances) come within NEAR tolerances of each other more than FEATURE_RADIUS
    tolerances from every planned feature and corner: [(i, k, (x, y), distance / tol)]."""
    segs = []
    for i, (points, cyclic) in enumerate(strokes):
        pts = np.asarray(compress(points, cyclic)[0], float)
        if len(pts) < 2:
            continue
        a, b = stroke_segments(pts, cyclic and len(pts) > 2)
        s = cumulative(pts, cyclic and len(pts) > 2)
        for m in range(len(a)):
            segs.append((i, a[m], b[m], (s[m] + s[m + 1]) / 2, s[-1], cyclic))
    if not segs:
        return []
    a = np.array([x[1] for x in segs])
    b = np.array([x[2] for x in segs])
    lo, hi = np.minimum(a, b) - NEAR * tol, np.maximum(a, b) + NEAR * tol
    marks = np.array(list(features) + list(corners), float).reshape(-1, 2)
    out = []
    for x, y in cc._box_pairs(lo, hi, lo, hi, same=True):
        s, t = segs[x], segs[y]
        if s[0] == t[0]:
            along = abs(s[3] - t[3])
            if s[5]:
                along = min(along, s[4] - along)
            if along < SELF_WINDOW * tol:
                continue
        d = segment_distance(s[1], s[2], t[1], t[2])
        if d >= NEAR * tol:
            continue
        mid = (s[1] + s[2]) / 2
        if len(marks) and np.min(np.hypot(*(marks - mid[None, :]).T)) <= FEATURE_RADIUS * tol:
            continue
        out.append((s[0], t[0], (float(mid[0]), float(mid[1])), d / tol))
    return out


def segment_distance(p, q, r, u):
    """Distance between segments p-q and r-u (0 when they cross)."""
    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    if (cross(p, q, r) * cross(p, q, u) < 0) and (cross(r, u, p) * cross(r, u, q) < 0):
        return 0.0
    best = math.inf
    for z, e0, e1 in ((p, r, u), (q, r, u), (r, p, q), (u, p, q)):
        d, _, _ = point_segment_distance(np.asarray(z, float), np.array([e0]), np.array([e1]))
        best = min(best, float(d[0]))
    return best


# ---------------------------------------------------------------------------
# drawing one subject

class Rejected(Exception):
    """A drawing that does not have exactly the planned features: drawn again."""


def end_index(points, which):
    return 0 if which == "start" else len(points) - 1


def oriented(points, which):
    """The stroke as a list with the end in question last (reversed for the start)."""
    return list(points[::-1]) if which == "start" else list(points)


def restore(points, which):
    return points[::-1] if which == "start" else points


def trim_towards(points, which, target, keep_distance):
    """The stroke's points, the end `which` last, without its last points within keep_distance
    of target (at least two stay)."""
    pts = oriented(points, which)
    while len(pts) > 2 and float(np.hypot(*(np.asarray(pts[-1]) - target))) < keep_distance:
        pts.pop()
    return pts


def draw(subject, rng, size, offset, grid_kind):
    """The drawing of a subject: (strokes [(points list, cyclic)], planted, grid, scale)."""
    ideal_all = np.vstack([s.ideal for s in subject.strokes])
    unit_size = bbox_diagonal(ideal_all)
    tol_unit = TOLERANCE_FRACTION * unit_size
    scale = size / unit_size
    planted = {"gaps": [], "touches": [], "crossings": [], "duplicates": []}
    # 1. ideal paths, overshoots carried on past the stroke they cross
    ideal = []
    for s in subject.strokes:
        pts = s.ideal
        for which in ("start", "end"):
            rel = getattr(s, which)
            if rel[0] == "overshoot":
                pts = extend(pts, which == "start", rng.uniform(*OVERSHOOT_RANGE) * tol_unit)
        ideal.append(pts)
    # 2. the tablet: resampled, bent, jittered, moved to the page, on the grid
    grid = Grid(grid_kind, size)
    strokes = []
    for s, pts in zip(subject.strokes, ideal):
        spacing = rng.uniform(*SPACING) * unit_size
        samples = resample(pts, s.cyclic, spacing, rng)
        samples = wobble_field(rng, unit_size)(samples)
        samples = samples + rng_normal(rng, samples.shape) * JITTER * unit_size
        world = grid.snap(offset + samples * scale)
        strokes.append([tuple(map(float, p)) for p in world])
    corners = [offset + np.asarray(c) * scale for c in subject.corners]
    tol = TOLERANCE_FRACTION * bbox_diagonal(np.vstack([np.array(p) for p in strokes]))
    step = lambda pts: float(np.median(np.hypot(*np.diff(np.asarray(pts), axis=0).T)))  # noqa: E731
    features = []  # world points where strokes may come close (crossings, joins)
    # 3. the ends: touches on segments first (they move a point of the other stroke), then the
    # rest; shared ends after the end they copy
    choice = {}
    for i, s in enumerate(subject.strokes):
        for which in ("start", "end"):
            rel = getattr(s, which)
            if rel[0] in ("join", "self"):
                r = rng.random()
                if r < 0.6:
                    choice[(i, which)] = "gap"
                elif r < 0.8 or grid_kind != "dyadic":
                    choice[(i, which)] = "touch_point"
                else:
                    choice[(i, which)] = "touch_segment"
    order = [(i, w) for i in range(len(subject.strokes)) for w in ("start", "end")]
    order.sort(key=lambda iw: (getattr(subject.strokes[iw[0]], iw[1])[0] == "share",
                               choice.get(iw) != "touch_segment"))
    moved_targets = set()
    for i, which in order:
        s = subject.strokes[i]
        rel = getattr(s, which)
        if rel[0] in ("free", "overshoot"):
            continue
        pts = strokes[i]
        end = np.asarray(pts[end_index(pts, which)])
        h = step(pts)
        if rel[0] == "share":
            k, kw = rel[1], rel[2]
            target = np.asarray(strokes[k][end_index(strokes[k], kw)])
            kept = trim_towards(pts, which, target, 0.5 * h)
            kept.append(tuple(map(float, target)))
            strokes[i] = restore(kept, which)
            features.append(target)
            continue
        if rel[0] == "closed":
            target = np.asarray(pts[0])
            kept = trim_towards(pts, "end", target, max(0.6 * h, 1.0 * tol))
            kept.append(tuple(map(float, target)))
            strokes[i] = kept
            features.append(target)
            continue
        k = i if rel[0] == "self" else rel[1]
        how = choice[(i, which)]
        other = strokes[k]
        other_cyclic = subject.strokes[k].cyclic
        if k == i:
            # the stroke's own beginning: leave out its part near this end
            total = cumulative(np.asarray(pts), False)[-1]
            dist, near = distance_to_stroke(end, np.asarray(pts), False, skip_arc=0.25 * total,
                                            from_end=(which == "end"))
        else:
            dist, near = distance_to_stroke(end, np.asarray(other), other_cyclic)
        if near is None:
            raise Rejected(f"stroke {i}: no place to join")
        # A join next to the other stroke's end is a corner (an A's apex, a house's corner, a
        # head closed): it joins that end itself. A touch one segment from it would leave that
        # end sticking out past the junction, another figure than the corner the plan draws.
        corner = None
        if not other_cyclic:
            for e in ([0] if k == i else [0, len(other) - 1]):  # a stroke closing on itself: its start
                if float(np.hypot(*(np.asarray(other[e]) - near))) <= CORNER * tol:
                    corner = np.asarray(other[e], float)
        if corner is not None:
            near = corner
            if how != "gap":
                how = "touch_point"
        if corner is not None and how == "touch_point":
            d = 0.0
        elif how == "touch_point":
            cand = np.asarray(other)
            if k == i:
                cut = len(cand) // 4
                cand = cand[:-cut] if which == "end" else cand[cut:]
            near = cand[int(np.argmin(np.hypot(*(cand - near[None, :]).T)))]
            d = 0.0
        elif how == "touch_segment":
            near, d = touch_on_segment(strokes, k, near, grid, moved_targets, other_cyclic), 0.0
        else:
            d = rng.uniform(*GAP_RANGE) * tol
        # the end's last points go (a stroke that ran a little past the other one must not cross
        # it on the way back); the new last segment points straight at the place it joins
        kept = trim_towards(pts, which, near, d + max(0.6 * h, 1.5 * tol))
        last = np.asarray(kept[-1])
        if d > 0:
            new_end = grid.snap(near + d * unit(last - near))
        else:
            new_end = np.asarray(near)
        kept.append(tuple(map(float, new_end)))
        strokes[i] = restore(kept, which)
        features.append(np.asarray(near))
        choice[(i, which)] = (how, k)
    # 4. pen pauses
    for i, pts in enumerate(strokes):
        n = rng.choice((0, 0, 1, 1, 2, 3))
        for _ in range(n):
            r = rng.random()
            j = 0 if r < 0.15 else (len(pts) - 1 if r < 0.3 else rng.randrange(len(pts)))
            copies = 2 if rng.random() < 0.2 else 1
            for _ in range(copies):
                pts.insert(j, pts[j])
    # 5. what the drawing really has, exactly, against the plan
    drawing = [(pts, s.cyclic) for pts, s in zip(strokes, subject.strokes)]
    found = analyse(drawing)
    if found["problems"]:
        raise Rejected("; ".join(found["problems"][:3]))
    tol = TOLERANCE_FRACTION * bbox_diagonal(np.vstack([np.array(p) for p, _ in drawing]))
    expected = dict(subject.crossings)
    overshoots = 0
    for i, s in enumerate(subject.strokes):
        for which in ("start", "end"):
            rel = getattr(s, which)
            if rel[0] == "overshoot":
                key = (min(i, rel[1]), max(i, rel[1]))
                expected[key] = expected.get(key, 0) + 1
                overshoots += 1
    expected = {k: v for k, v in expected.items() if v}
    got = {}
    for c in found["crossings"]:
        got[(c[0], c[2])] = got.get((c[0], c[2]), 0) + 1
    if got != expected:
        raise Rejected(f"crossings {sorted(got.items())}, planned {sorted(expected.items())}")
    for c in found["crossings"]:
        features.append(np.asarray(c[4]))
    # the planned contacts, and no other
    planned_contacts = {}
    for i, s in enumerate(subject.strokes):
        for which in ("start", "end"):
            rel = getattr(s, which)
            j = end_index(strokes[i], which)
            if rel[0] == "share":
                planned_contacts[(i, j, rel[1])] = "end"
            elif rel[0] == "closed":
                planned_contacts[(i, j, i)] = "end"
            elif isinstance(choice.get((i, which)), tuple) and choice[(i, which)][0].startswith("touch"):
                planned_contacts[(i, j, choice[(i, which)][1])] = choice[(i, which)][0]
    # A contact is seen from both sides (an end on a point is also that point on the end's
    # segment) and several strokes may share one point (two legs and the body): a contact is
    # planned when a planned touch lies at its place and names both of its strokes.
    at_place = {}
    for (pi, pj, pk) in planned_contacts:
        at_place.setdefault(tuple(strokes[pi][pj]), set()).update((pi, pk))
    seen = set()
    for (i, j, k, on, at) in found["contacts"]:
        if not {i, k} <= at_place.get(tuple(at), set()):
            raise Rejected(f"unplanned contact: stroke {i} point {j} on stroke {k} ({on})")
        seen.add((tuple(at), frozenset((i, k))))
    missing = [key for key in planned_contacts
               if (tuple(strokes[key[0]][key[1]]), frozenset((key[0], key[2]))) not in seen]
    if missing:
        raise Rejected(f"planned touches missing: {missing}")
    for (i, j, k), how in sorted(planned_contacts.items()):
        p = strokes[i][j]
        on = "end" if how == "end" else ("segment" if how == "touch_segment" else "point")
        if on != "end" and any(tuple(q) == tuple(p) for q in (strokes[k][0], strokes[k][-1])) and \
                not subject.strokes[k].cyclic:
            on = "end"
        planted["touches"].append({"stroke": i, "point": j, "end": "start" if j == 0 else "end",
                                   "other_stroke": k, "on": on, "at": list(p)})
    # gaps: measured again on the final points, within range of the final tolerance
    for (i, which), value in sorted(choice.items()):
        if not isinstance(value, tuple) or value[0] != "gap":
            continue
        k = value[1]
        j = end_index(strokes[i], which)
        p = np.asarray(strokes[i][j])
        if k == i:
            total = cumulative(np.asarray(strokes[i]), False)[-1]
            dist, near = distance_to_stroke(p, np.asarray(strokes[i]), False, skip_arc=0.25 * total,
                                            from_end=(which == "end"))
        else:
            dist, near = distance_to_stroke(p, np.asarray(strokes[k]), subject.strokes[k].cyclic)
        if not GAP_ACCEPT[0] * tol <= dist <= GAP_ACCEPT[1] * tol:
            raise Rejected(f"gap of stroke {i} {which} is {dist / tol:.3f} tolerances")
        for m, (other, cyc) in enumerate(drawing):
            if m in (i, k):
                continue
            d2, _ = distance_to_stroke(p, np.asarray(other), cyc)
            if d2 <= FREE_CLEAR * tol:
                raise Rejected(f"gap of stroke {i} {which} is also {d2 / tol:.2f} tolerances from stroke {m}")
        planted["gaps"].append({"stroke": i, "point": j, "end": which, "other_stroke": k,
                                "distance": dist, "distance_tol": dist / tol, "near": [float(near[0]), float(near[1])]})
    # free and overshooting ends: clear of every other stroke
    involved = set()
    for f in features:
        for m, (pts, cyc) in enumerate(drawing):
            if cyc:
                continue
            for which in ("start", "end"):
                if float(np.hypot(*(np.asarray(pts[end_index(pts, which)]) - f))) <= 3 * tol:
                    involved.add((m, which))
    for i, s in enumerate(subject.strokes):
        if s.cyclic:
            continue
        for which in ("start", "end"):
            rel = getattr(s, which)
            if rel[0] not in ("free", "overshoot") or (i, which) in involved and rel[0] == "free":
                continue
            p = np.asarray(strokes[i][end_index(strokes[i], which)])
            need = OVERSHOOT_CLEAR if rel[0] == "overshoot" else FREE_CLEAR
            for m, (other, cyc) in enumerate(drawing):
                if m == i:
                    total = cumulative(np.asarray(other), False)[-1]
                    d2, _ = distance_to_stroke(p, np.asarray(other), False,
                                               skip_arc=min(0.5 * total, SELF_WINDOW * tol), from_end=(which == "end"))
                else:
                    d2, _ = distance_to_stroke(p, np.asarray(other), cyc)
                if d2 <= need * tol:
                    raise Rejected(f"the {which} of stroke {i} ({rel[0]}) is {d2 / tol:.2f} tolerances from stroke {m}")
    misses = near_misses(drawing, tol, features, corners)
    if misses:
        i, k, at, d = misses[0]
        raise Rejected(f"strokes {i} and {k} come within {d:.2f} tolerances at {at}, away from any feature")
    for (i, si, k, sk, at) in found["crossings"]:
        over = False
        for m, which in ((i, "start"), (i, "end"), (k, "start"), (k, "end")):
            rel = getattr(subject.strokes[m], which)
            other = k if m == i else i
            if rel[0] == "overshoot" and rel[1] == other:
                p = np.asarray(strokes[m][end_index(strokes[m], which)])
                if float(np.hypot(*(p - np.asarray(at)))) < (OVERSHOOT_RANGE[1] + 2) * tol:
                    over = True
        planted["crossings"].append({"stroke": i, "other_stroke": k, "segment": si, "other_segment": sk,
                                     "at": list(at), "overshoot": over})
    for i, (pts, cyc) in enumerate(drawing):
        for j in range(1, len(pts)):
            if tuple(pts[j]) == tuple(pts[j - 1]):
                planted["duplicates"].append({"stroke": i, "point": j})
    return drawing, planted, grid, scale, tol


def touch_on_segment(strokes, k, near, grid, moved, cyclic):
    """Makes a point of the grid that lies exactly inside a segment of stroke k near `near`:
    moves that segment's second point to 2P - A (exact on a power-of-two grid). Returns P."""
    pts = strokes[k]
    arr = np.asarray(pts, float)
    a_all, b_all = stroke_segments(arr, cyclic)
    dist, _, _ = point_segment_distance(np.asarray(near), a_all, b_all)
    order = np.argsort(dist)
    for m in order[:4]:
        m = int(m)
        nxt = (m + 1) % len(pts)
        if nxt == 0 and not cyclic:
            continue
        if not cyclic and (m == 0 or nxt == len(pts) - 1):
            continue  # keep the stroke's ends where they are
        if (k, nxt) in moved or (k, m) in moved:
            continue
        a = np.asarray(pts[m], float)
        b = np.asarray(pts[nxt], float)
        p = grid.snap((a + b) / 2)
        b2 = 2 * p - a
        if tuple(b2) == tuple(a) or tuple(p) == tuple(a):
            continue
        if float(np.hypot(*(b2 - b))) > 4 * grid.step * 1.5:
            continue
        pts[nxt] = (float(b2[0]), float(b2[1]))
        moved.add((k, nxt))
        moved.add((k, m))
        return p
    raise Rejected(f"no segment of stroke {k} to touch")


def rng_normal(rng, shape):
    return np.array([rng.gauss(0.0, 1.0) for _ in range(int(np.prod(shape)))]).reshape(shape)


def make_drawing(kind, plan_seed, pose_seed, rng, size, offset, grid_kind):
    """Draws until the drawing has exactly its planned features."""
    last = None
    for attempt in range(1, MAX_ATTEMPTS + 1):
        subject = SUBJECTS[kind](random.Random(plan_seed), random.Random(f"{pose_seed}:{attempt}"))
        try:
            drawing, planted, grid, scale, tol = draw(subject, rng, size, offset, grid_kind)
        except Rejected as why:
            last = str(why)
            continue
        return subject, drawing, planted, grid, scale, tol, attempt
    raise Rejected(f"{kind}: no drawing in {MAX_ATTEMPTS} attempts (last: {last})")


def drawing_doc(name, drawing):
    return {"name": name, "strokes": [{"points": [[x, y] for x, y in pts], "cyclic": bool(cyc)}
                                      for pts, cyc in drawing]}


def counts_of(planted):
    return {"gaps": len(planted["gaps"]), "touches": len(planted["touches"]),
            "crossings": len(planted["crossings"]),
            "overshoots": sum(1 for c in planted["crossings"] if c["overshoot"]),
            "duplicates": len(planted["duplicates"])}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", type=pathlib.Path, help="output folder")
    ap.add_argument("--seed", type=int, default=32, help="random seed (default 32)")
    ap.add_argument("--count", type=int, default=40, help="drawings to write (default 40; pairs count twice)")
    args = ap.parse_args(argv)
    if args.count < 1:
        print("error: --count must be at least 1", file=sys.stderr)
        return 2
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    for old in out.glob("*.json"):
        old.unlink()
    manifest = {"seed": args.seed, "count": args.count, "tolerance_fraction": TOLERANCE_FRACTION,
                "drawings": [], "pairs": []}
    item = 0
    written = 0
    while written < args.count:
        kind = KINDS[item % len(KINDS)]
        number = item // len(KINDS) + 1
        is_pair = item % PAIR_EVERY == PAIR_EVERY - 1 and args.count - written >= 2
        base = f"{kind}_{number}"
        plan_seed = f"{args.seed}:{base}:plan"
        poses = ("a", "b") if is_pair else (None,)
        rng = random.Random(f"{args.seed}:{base}")
        size = math.exp(rng.uniform(math.log(8), math.log(8000)))
        far = rng.random() < 0.25
        offset = np.array([rng.uniform(-1, 1), rng.uniform(-1, 1)]) * size * (1000 if far else 3)
        grid_kind = "dyadic" if rng.random() < 0.75 else "decimal"
        offset = Grid(grid_kind, size).snap(offset)
        names = []
        for pose in poses:
            name = f"{base}_{pose}" if pose else base
            subject, drawing, planted, grid, scale, tol, attempts = make_drawing(
                kind, plan_seed, f"{args.seed}:{name}:pose", random.Random(f"{args.seed}:{name}:tablet"), size,
                offset, grid_kind)
            (out / f"{name}.json").write_text(json.dumps(drawing_doc(f"{subject.label} ({name})", drawing)) + "\n")
            all_points = np.vstack([np.array(p) for p, _ in drawing])
            entry = {"name": name, "file": f"{name}.json", "kind": kind, "subject": subject.label,
                     "pair": base if pose else None, "pose": pose, "strokes": len(drawing),
                     "stroke_names": [s.name for s in subject.strokes],
                     "cyclic_strokes": sum(1 for _, c in drawing if c), "points": int(len(all_points)),
                     "size": bbox_diagonal(all_points), "tolerance": tol, "grid": grid.describe(),
                     "scale": scale, "offset": [float(offset[0]), float(offset[1])], "attempts": attempts,
                     "planted": planted, "counts": counts_of(planted)}
            manifest["drawings"].append(entry)
            names.append(name)
            written += 1
            c = entry["counts"]
            print(f"{name:14s} {entry['strokes']:3d} strokes {entry['points']:5d} points, gaps {c['gaps']}, touches "
                  f"{c['touches']}, crossings {c['crossings']} ({c['overshoots']} overshoots), duplicates "
                  f"{c['duplicates']}; size {entry['size']:.4g}, {grid.kind} grid, attempt {attempts}")
        if is_pair:
            manifest["pairs"].append({"name": base, "kind": kind, "a": f"{names[0]}.json", "b": f"{names[1]}.json"})
        item += 1
    totals = {key: sum(d["counts"][key] for d in manifest["drawings"])
              for key in ("gaps", "touches", "crossings", "overshoots", "duplicates")}
    totals.update(drawings=len(manifest["drawings"]), pairs=len(manifest["pairs"]),
                  points=sum(d["points"] for d in manifest["drawings"]),
                  strokes=sum(d["strokes"] for d in manifest["drawings"]))
    manifest["totals"] = totals
    (out / "manifest.json").write_text(json.dumps(manifest, indent=1) + "\n")
    print(f"{totals['drawings']} drawings ({totals['pairs']} pairs) in {out}: {totals['points']} points, "
          f"{totals['strokes']} strokes; planted {totals['gaps']} gaps, {totals['touches']} touches, "
          f"{totals['crossings']} crossings ({totals['overshoots']} overshoots), {totals['duplicates']} duplicates")
    return 0


if __name__ == "__main__":
    sys.exit(main())
