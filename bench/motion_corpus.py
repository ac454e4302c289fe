#!/usr/bin/env python3
"""Generate the motion-quality corpus: compatible figure pairs that look like real use.

Issue 12 ("Natural motion with the guarantee kept") asks to measure first: before a
`rigid` motion mode is built, there must be a fixed set of pairs it will be judged on.
This script writes that set as FORMAT.md figure files, NAME.source.json / NAME.target.json,
plus manifest.json (kind, size and special tags of every pair) into a folder:

    /usr/bin/python3 bench/motion_corpus.py [OUT_DIR] [--seed N] [--build-dir build]

Kinds (see docs/MOTION.md):
  glyph       hand-written stroke letters (trees and graphs with junctions) into a deformed
              pose: bent strokes, moved junctions, thinner/bolder, italic, rotated, scaled;
              and one letter into another (S into Z, C into U, T into Y, ...), resampled strokes
  skeleton    humanoid / quadruped / spider stick figures in two poses (forward kinematics:
              only joint angles and the root placement change, bone lengths are kept)
  polygon     stars, blobs and letter outlines in two shapes
  triangulation  a Delaunay triangulation of scattered points and a smooth
              orientation-keeping deformation of it
  sample      the pairs shipped in blend_samples/figures/ and tests/data/paper/
  special     a figure into itself turned by 180, 90 and 170 degrees, pure similarities

The output is deterministic for a given seed. Every pair is checked with
`stickmorph check SRC TGT`; a random pair that is not compatible is redrawn with gentler
deformation (up to MAX_ATTEMPTS times) and dropped if it never is. Counts are printed.
"""
import argparse
import json
import math
import os
import pathlib
import random
import shutil
import subprocess
import sys
import tempfile

import numpy as np

REPO = pathlib.Path(__file__).resolve().parents[1]
MAX_ATTEMPTS = 12


# ---------------------------------------------------------------------------
# figures as (points: float array n x 2, edges: list of (i, j))

class Builder:
    """Accumulates vertices and edges; named nodes are shared between strokes, which is
    how a glyph gets its junctions."""

    def __init__(self):
        self.points = []
        self.edges = []
        self.names = {}

    def node(self, name, xy):
        if name not in self.names:
            self.names[name] = len(self.points)
            self.points.append(tuple(xy))
        return self.names[name]

    def vertex(self, xy):
        self.points.append(tuple(xy))
        return len(self.points) - 1

    def edge(self, i, j):
        self.edges.append((i, j))


def write_figure(path, name, points, edges):
    doc = {"name": name,
           "vertices": [[float(x), float(y)] for x, y in points],
           "edges": [[int(i), int(j)] for i, j in edges]}
    path.write_text(json.dumps(doc) + "\n")


def similarity(points, angle_deg=0.0, scale=1.0, shift=(0.0, 0.0), about=None):
    p = np.asarray(points, dtype=float)
    c = p.mean(axis=0) if about is None else np.asarray(about, dtype=float)
    a = math.radians(angle_deg)
    rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    return (p - c) @ rot.T * scale + c + np.asarray(shift, dtype=float)


# ---------------------------------------------------------------------------
# glyphs: letters as strokes through named key points in a unit box (y up)

# Each letter: key points, and strokes as sequences of key-point names. A key point shared by
# two strokes is a junction. Curved parts (B, R, S) are written as many key points.
LETTERS = {
    "A": ({"bl": (0, 0), "cl": (0.2, 0.4), "ap": (0.5, 1), "cr": (0.8, 0.4), "br": (1, 0)},
          [["bl", "cl", "ap", "cr", "br"], ["cl", "cr"]]),
    "B": ({"s0": (0, 0), "s1": (0, 0.5), "s2": (0, 1),
           "u1": (0.45, 1), "u2": (0.63, 0.93), "u3": (0.68, 0.77), "u4": (0.6, 0.62), "u5": (0.35, 0.56),
           "l1": (0.4, 0.44), "l2": (0.65, 0.4), "l3": (0.76, 0.25), "l4": (0.7, 0.09), "l5": (0.48, 0)},
          [["s0", "s1", "s2"], ["s2", "u1", "u2", "u3", "u4", "u5", "s1"],
           ["s1", "l1", "l2", "l3", "l4", "l5", "s0"]]),
    "E": ({"b": (0, 0), "m": (0, 0.5), "t": (0, 1), "tr": (0.8, 1), "mr": (0.6, 0.5), "br": (0.8, 0)},
          [["b", "m", "t"], ["t", "tr"], ["m", "mr"], ["b", "br"]]),
    "F": ({"b": (0, 0), "m": (0, 0.55), "t": (0, 1), "tr": (0.8, 1), "mr": (0.6, 0.55)},
          [["b", "m", "t", "tr"], ["m", "mr"]]),
    "H": ({"lb": (0, 0), "lm": (0, 0.5), "lt": (0, 1), "rb": (1, 0), "rm": (1, 0.5), "rt": (1, 1)},
          [["lb", "lm", "lt"], ["rb", "rm", "rt"], ["lm", "rm"]]),
    "K": ({"b": (0, 0), "m": (0, 0.4), "t": (0, 1), "j": (0.24, 0.58), "ur": (0.8, 1), "lr": (0.85, 0)},
          [["b", "m", "t"], ["m", "j", "ur"], ["j", "lr"]]),
    "R": ({"b": (0, 0), "m": (0, 0.5), "t": (0, 1), "u1": (0.45, 1), "u2": (0.65, 0.9),
           "u3": (0.7, 0.75), "u4": (0.62, 0.58), "j": (0.35, 0.5), "leg": (0.75, 0)},
          [["b", "m", "t", "u1", "u2", "u3", "u4", "j", "m"], ["j", "leg"]]),
    "S": ({"p0": (0.85, 0.85), "p1": (0.6, 1), "p2": (0.25, 0.98), "p3": (0.05, 0.8), "p4": (0.15, 0.6),
           "p5": (0.5, 0.5), "p6": (0.85, 0.38), "p7": (0.92, 0.18), "p8": (0.7, 0), "p9": (0.3, 0),
           "p10": (0.05, 0.15)},
          [["p0", "p1", "p2", "p3", "p4", "p5", "p6", "p7", "p8", "p9", "p10"]]),
    "T": ({"l": (0, 1), "c": (0.5, 1), "r": (1, 1), "b": (0.5, 0)}, [["l", "c", "r"], ["c", "b"]]),
    "X": ({"bl": (0, 0), "c": (0.5, 0.5), "tr": (1, 1), "br": (1, 0), "tl": (0, 1)},
          [["bl", "c", "tr"], ["br", "c", "tl"]]),
    "Y": ({"tl": (0, 1), "tr": (1, 1), "c": (0.5, 0.5), "b": (0.5, 0)}, [["tl", "c", "b"], ["tr", "c"]]),
    "Z": ({"tl": (0, 1), "tr": (1, 1), "bl": (0, 0), "br": (1, 0)}, [["tl", "tr", "bl", "br"]]),
}


def glyph(letter, rng, spacing, jitter, bend, move, width=1.0, slant=0.0, angle=0.0, scale=1.0,
          shift=(0.0, 0.0)):
    """One drawing of a letter. The key points are moved by up to `move`, every stroke
    segment is subdivided at `spacing` and bent sideways by a half sine of up to `bend` times
    its length, then the whole letter is made thinner/bolder (`width`), slanted, rotated,
    scaled and moved. Subdivision counts depend only on the letter and `spacing`, so two
    drawings with the same spacing have the same vertices and edges (they correspond)."""
    keys, strokes = LETTERS[letter]
    # The random draws happen in a fixed order so the pair's two drawings stay aligned.
    moved = {k: np.array(v, float) + np.array([rng.uniform(-move, move), rng.uniform(-move, move)])
             + np.array([rng.uniform(-jitter, jitter), rng.uniform(-jitter, jitter)])
             for k, v in sorted(keys.items())}
    b = Builder()
    done = set()
    for stroke in strokes:
        for a, c in zip(stroke, stroke[1:]):
            ia = b.node(a, moved[a])
            ic = b.node(c, moved[c])
            # subdivision from the *base* shape, so it is the same for both drawings
            base_len = float(np.hypot(*np.subtract(keys[c], keys[a])))
            pieces = max(1, int(round(base_len / spacing)))
            pa, pc = moved[a], moved[c]
            d = pc - pa
            normal = np.array([-d[1], d[0]])
            amount = rng.uniform(-bend, bend)
            prev = ia
            for k in range(1, pieces):
                s = k / pieces
                q = pa + s * d + amount * math.sin(math.pi * s) * normal
                cur = b.vertex(q)
                b.edge(prev, cur)
                prev = cur
            assert (a, c) not in done
            done.add((a, c))
            b.edge(prev, ic)
    p = np.array(b.points, float)
    p[:, 0] = 0.5 + (p[:, 0] - 0.5) * width
    p[:, 0] += slant * (p[:, 1] - 0.5)
    p = similarity(p, angle, scale, shift, about=(0.5, 0.5))
    return p, b.edges


def glyph_pair(letter, rng, gentle, big_turn=False):
    spacing = rng.uniform(0.05, 0.1)
    seed = rng.getrandbits(32)
    # the source: a neat hand drawing; the target: the same letter in another hand
    src, edges = glyph(letter, random.Random(seed), spacing, jitter=0.01 * gentle, bend=0.02 * gentle,
                       move=0.0)
    r2 = random.Random(seed)  # same draw order as the source, other amplitudes
    turn = rng.choice([-1, 1]) * rng.uniform(100, 150) if big_turn else rng.uniform(-35, 35)
    tgt, edges2 = glyph(letter, r2, spacing, jitter=0.01 * gentle, bend=0.12 * gentle, move=0.08 * gentle,
                        width=rng.uniform(0.65, 1.35), slant=rng.uniform(-0.3, 0.35) * gentle,
                        angle=turn * (1 if big_turn else gentle), scale=rng.uniform(0.6, 1.6),
                        shift=(rng.uniform(-1, 1), rng.uniform(-1, 1)))
    assert edges == edges2
    return src, tgt, edges, {"turn_deg": round(turn, 1)}


# One letter into another, as font stroke data gives them: single-stroke letters are paths
# (any two paths with as many vertices are compatible) and star-shaped letters are trees
# with one junction; each arm is resampled at equal arc length to one vertex count, so the
# vertex at a fraction of the stroke in one letter meets the same fraction in the other.
# This is the paper's S-into-U kind of pair, where the motion is hardest to make natural.
ARC = [(0.5 + 0.45 * math.cos(math.radians(a)), 0.5 + 0.45 * math.sin(math.radians(a)))
       for a in range(40, 321, 20)]
STROKES = {
    "S": [LETTERS["S"][0][f"p{k}"] for k in range(11)],
    "C": ARC,
    "U": [(0, 1), (0, 0.3), (0.1, 0.1), (0.3, 0), (0.7, 0), (0.9, 0.1), (1, 0.3), (1, 1)],
    "L": [(0, 1), (0, 0), (0.7, 0)],
    "V": [(0, 1), (0.5, 0), (1, 1)],
    "N": [(0, 0), (0, 1), (1, 0), (1, 1)],
    "M": [(0, 0), (0, 1), (0.5, 0.4), (1, 1), (1, 0)],
    "W": [(0, 1), (0.25, 0), (0.5, 0.6), (0.75, 0), (1, 1)],
    "Z": [(0, 1), (1, 1), (0, 0), (1, 0)],
    "2": [(0.05, 0.75), (0.2, 0.95), (0.5, 1), (0.8, 0.92), (0.9, 0.72), (0.75, 0.5), (0, 0), (1, 0)],
    "J": [(0.9, 1), (0.9, 0.25), (0.75, 0.05), (0.5, 0), (0.25, 0.05), (0.1, 0.25)],
    "7": [(0, 1), (1, 1), (0.4, 0)],
}
# star letters: the junction, then the arms counter-clockwise (matching arms in order)
STARS = {
    "T": ((0.5, 1), [[(1, 1)], [(0, 1)], [(0.5, 0)]]),
    "Y": ((0.5, 0.5), [[(1, 1)], [(0, 1)], [(0.5, 0)]]),
    "X": ((0.5, 0.5), [[(1, 1)], [(0, 1)], [(0, 0)], [(1, 0)]]),
    "+": ((0.5, 0.5), [[(1, 0.5)], [(0.5, 1)], [(0, 0.5)], [(0.5, 0)]]),
}
CROSS_PAIRS = [("S", "Z"), ("C", "U"), ("L", "V"), ("N", "M"), ("W", "M"), ("Z", "2"), ("J", "U"),
               ("7", "L"), ("T", "Y"), ("X", "+")]


def resample(polyline, count):
    """`count` points at equal arc length along the polyline, both ends included."""
    p = np.asarray(polyline, dtype=float)
    seg = np.linalg.norm(np.diff(p, axis=0), axis=1)
    s = np.concatenate([[0], np.cumsum(seg)])
    u = np.linspace(0, s[-1], count)
    return np.stack([np.interp(u, s, p[:, 0]), np.interp(u, s, p[:, 1])], axis=1)


def cross_letter(letter, counts):
    """A path letter with counts[0] vertices, or a star letter with counts[k] vertices on arm k
    (the junction not counted)."""
    if letter in STROKES:
        p = resample(STROKES[letter], counts[0])
        return p, [(i, i + 1) for i in range(len(p) - 1)]
    centre, arms = STARS[letter]
    pts, edges = [centre], []
    for arm, k in zip(arms, counts):
        q = resample([centre] + arm, k + 1)[1:]
        first = len(pts)
        pts += [tuple(x) for x in q]
        edges.append((0, first))
        edges += [(first + i, first + i + 1) for i in range(k - 1)]
    return np.array(pts, float), edges


def cross_glyph_pair(a, b, rng, gentle):
    arms = 1 if a in STROKES else len(STARS[a][1])
    counts = [rng.randrange(24, 61)] if arms == 1 else [rng.randrange(6, 16)] * arms
    src, edges = cross_letter(a, counts)
    tgt, edges2 = cross_letter(b, counts)
    assert edges == edges2
    jitter = 0.008 * gentle
    src = src + np.array([[rng.uniform(-jitter, jitter) for _ in range(2)] for _ in src])
    tgt = tgt + np.array([[rng.uniform(-jitter, jitter) for _ in range(2)] for _ in tgt])
    turn = rng.uniform(-30, 30) * gentle
    tgt = similarity(tgt, turn, rng.uniform(0.7, 1.4), (rng.uniform(-1, 1), rng.uniform(-1, 1)))
    return src, tgt, edges, {"letters": f"{a}->{b}", "turn_deg": round(turn, 1)}


# ---------------------------------------------------------------------------
# skeletons: forward kinematics of a bone tree

# bone: (name, parent or None, length, rest angle relative to the parent in degrees,
#        pieces, pose range in degrees). Children start at the parent's tip.
HUMANOID = [
    ("spine1", None, 0.25, 90, 2, 15), ("spine2", "spine1", 0.25, 0, 2, 15),
    ("neck", "spine2", 0.1, 0, 1, 20),
    ("uarm_l", "spine2", 0.28, 150, 2, 50), ("farm_l", "uarm_l", 0.25, 10, 2, 60),
    ("hand_l", "farm_l", 0.07, 0, 1, 30),
    ("uarm_r", "spine2", 0.28, -150, 2, 50), ("farm_r", "uarm_r", 0.25, -10, 2, 60),
    ("hand_r", "farm_r", 0.07, 0, 1, 30),
    ("hip_l", None, 0.1, 200, 1, 5), ("thigh_l", "hip_l", 0.4, 60, 2, 40), ("shin_l", "thigh_l", 0.38, 5, 2, 50),
    ("foot_l", "shin_l", 0.1, 90, 1, 20),
    ("hip_r", None, 0.1, -20, 1, 5), ("thigh_r", "hip_r", 0.4, -60, 2, 40), ("shin_r", "thigh_r", 0.38, -5, 2, 50),
    ("foot_r", "shin_r", 0.1, 90, 1, 20),
]
QUADRUPED = [
    ("back1", None, 0.3, 0, 2, 10), ("back2", "back1", 0.3, 0, 2, 10), ("back3", "back2", 0.3, 0, 2, 10),
    ("neck", "back3", 0.3, 45, 2, 30), ("head", "neck", 0.2, -60, 2, 30),
    ("tail1", None, 0.2, 200, 1, 30), ("tail2", "tail1", 0.2, 10, 1, 40), ("tail3", "tail2", 0.2, 10, 1, 40),
    ("fthigh_1", "back3", 0.3, -110, 2, 25), ("fshin_1", "fthigh_1", 0.3, 10, 2, 30),
    ("fthigh_2", "back3", 0.3, -75, 2, 25), ("fshin_2", "fthigh_2", 0.3, 10, 2, 30),
    ("hthigh_1", None, 0.3, -120, 2, 25), ("hshin_1", "hthigh_1", 0.3, 30, 2, 30),
    ("hthigh_2", None, 0.3, -70, 2, 25), ("hshin_2", "hthigh_2", 0.3, 10, 2, 30),
]
# eight legs curling the same way (a pinwheel), so neighbouring legs stay apart
SPIDER = [(f"leg{k}_{s}", None if s == 1 else f"leg{k}_{s - 1}", (0.3, 0.25, 0.2)[s - 1],
           (k * 45 + 22.5 if s == 1 else 20), 2, (12, 20, 20)[s - 1])
          for k in range(8) for s in (1, 2, 3)]
SKELETONS = {"humanoid": (HUMANOID, "head"), "quadruped": (QUADRUPED, None), "spider": (SPIDER, "body")}


def skeleton(kind, pose_rng, amplitude, root_angle, root_scale, root_shift):
    """Pose a bone tree: every joint angle is its rest angle plus a random offset within its
    range times `amplitude`; the root is rotated, scaled and moved. The humanoid gets a
    hexagonal head on the neck, the spider an octagonal body; both move rigidly with their
    bone."""
    bones, extra = SKELETONS[kind]
    b = Builder()
    root = b.node("root", (0.0, 0.0))
    tip = {}
    direction = {}
    rot0 = math.radians(root_angle)
    for name, parent, length, rest, pieces, rng_deg in bones:
        offset = pose_rng.uniform(-rng_deg, rng_deg) * amplitude
        if parent is None:
            start, base = root, rot0
            if kind == "spider":
                # legs start on the body octagon's corners
                k = int(name[3])
                a = rot0 + math.radians(k * 45 + 22.5)
                start = b.node(f"corner{k}", (0.15 * math.cos(a), 0.15 * math.sin(a)))
                base = a - math.radians(k * 45 + 22.5)
        else:
            start, base = tip[parent], direction[parent]
        ang = base + math.radians(rest + offset)
        p0 = np.array(b.points[start])
        step = np.array([math.cos(ang), math.sin(ang)]) * length / pieces
        prev = start
        for k in range(1, pieces + 1):
            cur = b.vertex(p0 + k * step)
            b.edge(prev, cur)
            prev = cur
        tip[name] = prev
        direction[name] = ang
    if extra == "head":
        # a hexagon whose bottom corner is the neck's tip, aligned with the neck
        a = direction["neck"]
        c = np.array(b.points[tip["neck"]]) + 0.09 * np.array([math.cos(a), math.sin(a)])
        ring = [tip["neck"]] + [b.vertex(c + 0.09 * np.array([math.cos(a + math.pi + k * math.pi / 3),
                                                              math.sin(a + math.pi + k * math.pi / 3)]))
                                for k in range(1, 6)]
        for u, v in zip(ring, ring[1:] + ring[:1]):
            b.edge(u, v)
    if extra == "body":
        corners = [b.names[f"corner{k}"] for k in range(8)]
        for u, v in zip(corners, corners[1:] + corners[:1]):
            b.edge(u, v)
        for u in corners:
            b.edge(root, u)
    p = similarity(np.array(b.points), 0.0, root_scale, root_shift, about=(0.0, 0.0))
    return p, b.edges


def skeleton_pair(kind, rng, gentle):
    seed_a, seed_b = rng.getrandbits(32), rng.getrandbits(32)
    src, edges = skeleton(kind, random.Random(seed_a), 0.8 * gentle, 0.0, 1.0, (0, 0))
    turn = rng.uniform(-40, 40) * gentle
    tgt, edges2 = skeleton(kind, random.Random(seed_b), 1.0 * gentle, turn, rng.uniform(0.8, 1.25),
                           (rng.uniform(-0.5, 0.5), rng.uniform(-0.3, 0.3)))
    assert edges == edges2
    return src, tgt, edges, {"turn_deg": round(turn, 1), "rigid_bones": True}


# ---------------------------------------------------------------------------
# polygons

def closed(points):
    n = len(points)
    return np.asarray(points, float), [(i, (i + 1) % n) for i in range(n)]


def subdivide_polygon(points, per_edge):
    out = []
    n = len(points)
    for i in range(n):
        a, c = np.asarray(points[i]), np.asarray(points[(i + 1) % n])
        for k in range(per_edge):
            out.append(a + (c - a) * k / per_edge)
    return out


def star(tips, r_out, r_in, phase, per_edge):
    pts = []
    for k in range(2 * tips):
        r = r_out[k // 2] if k % 2 == 0 else r_in
        a = phase + math.pi * k / tips
        pts.append((r * math.cos(a), r * math.sin(a)))
    return subdivide_polygon(pts, per_edge)


def blob(n, coeffs):
    pts = []
    for k in range(n):
        a = 2 * math.pi * k / n
        r = 1.0 + sum(amp * math.cos(f * a + ph) for f, amp, ph in coeffs)
        pts.append((r * math.cos(a), r * math.sin(a)))
    return pts


OUTLINES = {
    # counter-clockwise outlines of bold letters in a unit box
    "T": [(0, 0.8), (0, 1), (1, 1), (1, 0.8), (0.6, 0.8), (0.6, 0), (0.4, 0), (0.4, 0.8)],
    "E": [(0, 0), (0.8, 0), (0.8, 0.18), (0.22, 0.18), (0.22, 0.42), (0.6, 0.42), (0.6, 0.58),
          (0.22, 0.58), (0.22, 0.82), (0.8, 0.82), (0.8, 1), (0, 1)],
    "L": [(0, 0), (0.8, 0), (0.8, 0.2), (0.25, 0.2), (0.25, 1), (0, 1)],
}


def outline_shape(letter, per_edge, width, slant, bolden, angle, scale, shift):
    p = np.array(subdivide_polygon(OUTLINES[letter], per_edge), float)
    c = np.array([0.45, 0.5])
    # "bolder": push points away from the letter's centre line a little, a smooth map
    p = c + (p - c) * (1 + bolden * np.exp(-np.sum((p - c) ** 2, axis=1)))[:, None]
    p[:, 0] = 0.5 + (p[:, 0] - 0.5) * width + slant * (p[:, 1] - 0.5)
    return similarity(p, angle, scale, shift, about=(0.5, 0.5))


def polygon_pair(which, rng, gentle):
    if which.startswith("star"):
        tips = int(which[4:])
        per = rng.choice([2, 3])
        src = star(tips, [1.0] * tips, 0.45, 0.0, per)
        tgt = star(tips, [1.0 + rng.uniform(-0.3, 0.4) * gentle for _ in range(tips)],
                   0.45 + 0.25 * gentle, rng.uniform(-0.6, 0.6) * gentle, per)
        tgt = similarity(tgt, rng.uniform(-30, 30), rng.uniform(0.7, 1.4), (rng.uniform(-1, 1), 0))
        p, edges = closed(src)
        return p, tgt, edges, {}
    if which.startswith("blob"):
        n = rng.randrange(60, 181)

        def coeffs(g):
            return [(f, rng.uniform(0, 0.3 / f * 2) * g, rng.uniform(0, 2 * math.pi)) for f in range(2, 6)]
        src = blob(n, coeffs(1.0))
        tgt = similarity(blob(n, coeffs(gentle)), rng.uniform(-60, 60) * gentle, rng.uniform(0.7, 1.4),
                         (rng.uniform(-1, 1), rng.uniform(-1, 1)))
        p, edges = closed(src)
        return p, tgt, edges, {}
    letter = which[len("outline"):]
    per = rng.choice([2, 3, 4])
    src = outline_shape(letter, per, 1.0, 0.0, 0.0, 0.0, 1.0, (0, 0))
    tgt = outline_shape(letter, per, rng.uniform(0.7, 1.3), rng.uniform(-0.3, 0.3) * gentle,
                        rng.uniform(0, 0.5) * gentle, rng.uniform(-40, 40) * gentle, rng.uniform(0.7, 1.4),
                        (rng.uniform(-1, 1), rng.uniform(-1, 1)))
    p, edges = closed(src)
    return p, tgt, edges, {}


# ---------------------------------------------------------------------------
# triangulations

def delaunay(points):
    """Bowyer-Watson on a few dozen points (quadratic, plenty for the corpus). Returns
    counter-clockwise triangles as index triples."""
    pts = [tuple(p) for p in points]
    n = len(pts)
    big = 1e3 * (1 + max(max(abs(x), abs(y)) for x, y in pts))
    pts_all = pts + [(-big, -big), (big, -big), (0.0, big)]
    tris = [(n, n + 1, n + 2)]

    def circum_contains(t, p):
        (ax, ay), (bx, by), (cx, cy) = (pts_all[i] for i in t)
        ax, ay, bx, by, cx, cy = ax - p[0], ay - p[1], bx - p[0], by - p[1], cx - p[0], cy - p[1]
        det = ((ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay)
               + (cx * cx + cy * cy) * (ax * by - bx * ay))
        return det > 0  # t is counter-clockwise

    for i, p in enumerate(pts):
        bad = [t for t in tris if circum_contains(t, p)]
        count = {}
        for t in bad:
            for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
                key = tuple(sorted(e))
                count[key] = count.get(key, 0) + 1
        boundary = [e for t in bad for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))
                    if count[tuple(sorted(e))] == 1]
        tris = [t for t in tris if t not in bad] + [(a, c, i) for a, c in boundary]
    return [t for t in tris if max(t) < n]


def orientations_kept(p, q, tris):
    def area(x, t):
        a, b, c = x[list(t)]
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return all(area(p, t) > 0 and area(q, t) > 0 for t in tris)


def triangulation_pair(which, rng, gentle):
    n = rng.randrange(25, 61)
    # jittered grid in a disk: well spread, Delaunay-like triangles of fair shape
    side = int(math.ceil(math.sqrt(n * 4 / math.pi))) + 1
    pts = []
    for i in range(side):
        for j in range(side):
            x = -1 + 2 * (i + 0.5 + rng.uniform(-0.3, 0.3)) / side
            y = -1 + 2 * (j + 0.5 + rng.uniform(-0.3, 0.3)) / side
            if x * x + y * y <= 1:
                pts.append((x, y))
    p = np.array(pts, float)
    tris = delaunay(p)
    edges = sorted({tuple(sorted((t[a], t[b]))) for t in tris for a, b in ((0, 1), (1, 2), (2, 0))})
    r2 = np.sum(p ** 2, axis=1)
    if which == "swirl":
        ang = 1.2 * gentle * np.exp(-r2 / 0.5)
        q = np.stack([p[:, 0] * np.cos(ang) - p[:, 1] * np.sin(ang),
                      p[:, 0] * np.sin(ang) + p[:, 1] * np.cos(ang)], axis=1)
    elif which == "bend":
        q = np.stack([p[:, 0], p[:, 1] + 0.5 * gentle * p[:, 0] ** 2], axis=1)
    else:  # bulge: radial pull towards the centre plus a stretch
        f = 1 - 0.35 * gentle * np.exp(-r2 / 0.3)
        q = p * f[:, None] * np.array([1.3, 0.8])
    q = similarity(q, rng.uniform(-50, 50) * gentle, rng.uniform(0.7, 1.4), (rng.uniform(-1, 1), 0))
    if not orientations_kept(p, q, tris):
        return None
    return p, q, edges, {"triangles": len(tris)}


# ---------------------------------------------------------------------------

def read_figure(path):
    doc = json.loads(path.read_text())
    return np.array(doc["vertices"], float), [tuple(e) for e in doc["edges"]]


def check(cli, src_path, tgt_path):
    r = subprocess.run([str(cli), "check", str(src_path), str(tgt_path)], capture_output=True, text=True,
                       timeout=120)
    return r.returncode, (r.stdout + r.stderr).strip()


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", nargs="?", default="out/motion_corpus", help="output folder (default out/motion_corpus)")
    ap.add_argument("--seed", type=int, default=12, help="random seed (default 12)")
    ap.add_argument("--build-dir", default=os.environ.get("STICKMORPH_BUILD_DIR", str(REPO / "build")),
                    help="folder with the stickmorph CLI (default $STICKMORPH_BUILD_DIR or build)")
    args = ap.parse_args(argv)
    cli = pathlib.Path(args.build_dir) / "stickmorph"
    if not cli.exists():
        sys.exit(f"error: {cli} is missing (cmake --build build --target stickmorph)")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for old in list(out.glob("*.source.json")) + list(out.glob("*.target.json")):
        old.unlink()
    rng = random.Random(args.seed)

    # (kind, name, generator(rng, gentle) -> (src, tgt, edges, tags) or None)
    jobs = []
    for letter in "ABEFHKRSTXYZ":
        jobs.append(("glyph", f"glyph_{letter}", lambda r, g, L=letter: glyph_pair(L, r, g)))
    for letter in "AKRY":
        jobs.append(("glyph", f"glyph_{letter}_turned", lambda r, g, L=letter: glyph_pair(L, r, g, big_turn=True)))
    for a, b in CROSS_PAIRS:
        tag = {"+": "plus"}.get(b, b)
        jobs.append(("glyph", f"glyph_{a}_to_{tag}", lambda r, g, A=a, B=b: cross_glyph_pair(A, B, r, g)))
    for kind, k in (("humanoid", 3), ("quadruped", 2), ("spider", 1)):
        for i in range(k):
            jobs.append(("skeleton", f"skeleton_{kind}_{i + 1}", lambda r, g, K=kind: skeleton_pair(K, r, g)))
    for which in ("star5", "star8", "blob1", "blob2", "outlineT", "outlineE", "outlineL"):
        jobs.append(("polygon", f"polygon_{which}", lambda r, g, W=which: polygon_pair(W[:-1] if W.startswith("blob")
                                                                                      else W, r, g)))
    for which in ("swirl", "bend", "bulge"):
        jobs.append(("triangulation", f"triangulation_{which}", lambda r, g, W=which: triangulation_pair(W, r, g)))

    def self_turn(figure_fn, degrees):
        def make(r, g):
            p, edges = figure_fn()
            return p, similarity(p, degrees), edges, {"self_turn_deg": degrees}
        return make

    r_letter = lambda: glyph("R", random.Random(7), 0.07, 0.01, 0.02, 0.0)  # noqa: E731
    for deg in (180, 90, 170):
        jobs.append(("special", f"special_self_turn_{deg}", self_turn(r_letter, deg)))

    def sim(figure_fn, deg, scale, shift):
        def make(r, g):
            p, edges = figure_fn()
            return p, similarity(p, deg, scale, shift), edges, {"similarity": [deg, scale, list(shift)]}
        return make
    jobs.append(("special", "special_similarity_F", sim(lambda: glyph("F", random.Random(3), 0.06, 0.01, 0.02, 0.0),
                                                         65, 1.5, (2.0, -1.0))))
    jobs.append(("special", "special_similarity_spider",
                 sim(lambda: skeleton("spider", random.Random(5), 0.8, 0, 1, (0, 0)), -120, 0.6, (-1.0, 0.5))))

    manifest = {"seed": args.seed, "pairs": []}
    counts = {}
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="motion_corpus_"))
    try:
        for kind, name, make in jobs:
            c = counts.setdefault(kind, {"written": 0, "redrawn": 0, "dropped": 0})
            job_rng = random.Random(f"{args.seed}:{name}")  # one stream per pair: stable when jobs change
            gentle = 1.0
            for attempt in range(MAX_ATTEMPTS):
                made = make(job_rng, gentle)
                if made is not None:
                    src, tgt, edges, tags = made
                    s_path, t_path = tmp / "s.json", tmp / "t.json"
                    write_figure(s_path, f"{name} source", src, edges)
                    write_figure(t_path, f"{name} target", tgt, edges)
                    code, msg = check(cli, s_path, t_path)
                    if code == 0:
                        shutil.move(str(s_path), out / f"{name}.source.json")
                        shutil.move(str(t_path), out / f"{name}.target.json")
                        manifest["pairs"].append({"name": name, "kind": kind, "vertices": len(src),
                                                  "edges": len(edges), "attempts": attempt + 1, **tags})
                        c["written"] += 1
                        break
                c["redrawn"] += 1
                gentle *= 0.8  # a gentler deformation is likelier to keep the cyclic orders
            else:
                c["dropped"] += 1
                print(f"dropped {name}: never compatible in {MAX_ATTEMPTS} draws", file=sys.stderr)
        # the shipped samples, as they are (a non-compatible one is reported and left out)
        c = counts.setdefault("sample", {"written": 0, "redrawn": 0, "dropped": 0})
        samples = sorted((REPO / "blend_samples" / "figures").glob("*.source.json")) + \
            sorted((REPO / "tests" / "data" / "paper").glob("*.source.json"))
        seen = {}
        for s_path in samples:
            t_path = s_path.with_name(s_path.name.replace(".source.json", ".target.json"))
            prefix = "sample_blend_" if "blend_samples" in str(s_path) else "sample_paper_"
            name = prefix + s_path.name[:-len(".source.json")]
            p, edges = read_figure(s_path)
            q, _ = read_figure(t_path)
            # the same pair shipped twice (the paper's S to U is also a Blender sample) would
            # count twice in every median
            key = (p.tobytes(), q.tobytes(), tuple(sorted(tuple(sorted(e)) for e in edges)))
            if key in seen:
                c["duplicates"] = c.get("duplicates", 0) + 1
                print(f"skipped {name}: the same pair as {seen[key]}", file=sys.stderr)
                continue
            seen[key] = name
            code, msg = check(cli, s_path, t_path)
            if code != 0:
                c["dropped"] += 1
                print(f"dropped {name}: {msg}", file=sys.stderr)
                continue
            shutil.copyfile(s_path, out / f"{name}.source.json")
            shutil.copyfile(t_path, out / f"{name}.target.json")
            manifest["pairs"].append({"name": name, "kind": "sample", "vertices": len(p), "edges": len(edges),
                                      "attempts": 1, "from": str(s_path.relative_to(REPO))})
            c["written"] += 1
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    manifest["counts"] = counts
    (out / "manifest.json").write_text(json.dumps(manifest, indent=1) + "\n")
    total = sum(c["written"] for c in counts.values())
    sizes = [p["vertices"] for p in manifest["pairs"]]
    for kind, c in counts.items():
        print(f"{kind:14s} written {c['written']:3d}  redrawn {c['redrawn']:3d}  dropped {c['dropped']:3d}"
              + (f"  duplicates skipped {c['duplicates']}" if c.get("duplicates") else ""))
    print(f"{total} compatible pairs in {out}, {min(sizes)}-{max(sizes)} vertices")
    return 0


if __name__ == "__main__":
    sys.exit(main())
