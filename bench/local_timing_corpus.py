#!/usr/bin/env python3
"""Generate the local-timing corpus (issue 31): skeleton pairs where the body bends while ONE limb
turns about its junction, with the timing files that delay that limb.

Issue 31 adds `stickmorph morph SRC TGT -o OUT --timing FILE.json`, FILE.json being
`{"delay": [w_0, ..., w_n-1], "overlap": d}`: every part of the figure moves at its local time
clamp((t - d w) / (1 - d), 0, 1), so parts of weight 1 lag those of weight 0 by d (overlapping
action). Its must-show is measured (bench/local_timing.py) on pairs like these:

    /usr/bin/python3 bench/local_timing_corpus.py OUT_DIR --seed S [--count N] [--build-dir build]
                     [--overlaps 0,0.3,0.5]

Figures (forward kinematics of a bone tree, bone lengths kept, every bone split into the same
number of straight pieces so that a figure has 10 to about 400 vertices):
  humanoid      pelvis, a spine of three bones, neck and a ring head, arms of three bones
                (upper arm, forearm, hand), legs of three (thigh, shin, foot)
  stickman      a smaller stick man: a spine of two bones, a stick head, arms of two or three
                bones, legs of two
  quadruped     a back of three bones, neck and head, a tail of four bones, four legs
  lizard        a body chain, a head, a tail of six bones, four short legs
  tree          a trunk with branches alternating left and right, some with a twig, and roots
                (drawn afresh for every pair)

In each pair the body bends: every joint outside the limb changes by up to B degrees (B drawn
per pair from 5 to 40; the torso's joints all bend one way, so it curves), the legs shift, the
whole figure turns by up to 8 degrees and moves a little. ONE limb (an arm, a leg, the neck and
head, the tail, a branch) turns about its junction by 45 to 150 degrees, either way (within the
angle its neighbours at the junction leave it; which limb is drawn once per pair), its own joints changing by up to 10 degrees.
Half the figures are drawn mirrored. A pair is kept when, at the level of bones, source and
target keep non-adjacent bones apart by 3% of the figure's size and adjacent bones 12 degrees
apart, every limb bone turns by 30 degrees or more, at least three other bones by 8 or more,
the morph's own path (joint angles at constant speed) stays clear, and `stickmorph check` says
the subdivided pair is compatible. The path delayed as issue 31 asks is simulated too for every
overlap d, on the subdivided figure: every edge turning at constant speed at the local time of
its ends (their mean where they differ), clamp((t - d w) / (1 - d), 0, 1), each of its 25
frames checked exactly (bench/multipart_check.py's Topology: a plane graph with the source's
rotation system). The plain path (d = 0) must be valid; on four pairs of five the delayed ones
must be too, the fifth is drawn without that condition (its manifest entry says whether they
are), so the corpus may also hold pairs where the delayed motion runs into the body and the morph
must give way.

Files: NAME.source.json, NAME.target.json (docs/FORMAT.md figures), NAME.timing_D.json for every
overlap D (`{"delay": [...], "overlap": D}`: weight 1 on the limb's vertices, 0 elsewhere, the
junction vertex itself 0) and manifest.json: {"seed", "overlaps", "pairs": [{"name", "kind",
"source", "target", "timing": {D: file}, "vertices", "edges", "pieces", "limb", "junction",
"limb_vertices", "limb_edges" (indices into the figure's edge list: every edge with an end on the
limb, the one at the junction included), "turn_deg", "bend_deg", "root_turn_deg", "mirrored",
"delayed_clear": {D: bool}, "delayed_required", "attempts"}], "counts"}. Deterministic for a seed.
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

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import correspondence_check as cc  # noqa: E402  (the exact plane-graph test)
import multipart_check as topo  # noqa: E402  (the exact test of a frame against the source)

REPO = pathlib.Path(__file__).resolve().parents[1]
MAX_ATTEMPTS = 400  # drawings per pair; a drawing is cheap until the CLI check
DEFAULT_OVERLAPS = (0.0, 0.3, 0.5)
KINDS = ("humanoid", "stickman", "quadruped", "lizard", "tree")
TURN_RANGE = (45.0, 150.0)
BEND_RANGE = (5.0, 40.0)
LIMB_OWN_BEND = 10.0
ROOT_TURN = 8.0
# bone-level acceptance (fractions of the figure's bounding-box diagonal, degrees)
GAP_POSE, ANGLE_POSE = 0.03, 12.0
GAP_PATH, ANGLE_PATH = 0.006, 3.0
PATH_SAMPLES = 25
LIMB_MIN_TURN, OTHER_MIN_TURN, OTHER_MIN_COUNT = 30.0, 8.0, 3
DELAYED_FREE_EVERY = 5  # every fifth pair is drawn without asking the delayed path to be clear


# ---------------------------------------------------------------------------
# bone trees: (name, parent or None (the root), length, rest angle relative to the parent's
# direction (the root's for None), pose range, torso?). A "ring" (name, parent, radius, sides)
# is a closed head on the parent's tip, rigid with it.

def _humanoid(rng):
    bones = [("spine1", None, 0.20, 0, 6, True), ("spine2", "spine1", 0.20, 0, 8, True),
             ("spine3", "spine2", 0.16, 0, 8, True), ("neck", "spine3", 0.07, 0, 12, False)]
    for side, s in (("l", 1), ("r", -1)):
        bones += [(f"uarm_{side}", "spine3", 0.26, s * 140, 25, False),
                  (f"farm_{side}", f"uarm_{side}", 0.24, s * 15, 35, False),
                  (f"hand_{side}", f"farm_{side}", 0.07, 0, 20, False),
                  (f"thigh_{side}", None, 0.40, s * 165, 8, False),
                  (f"shin_{side}", f"thigh_{side}", 0.38, -s * 5, 20, False),
                  (f"foot_{side}", f"shin_{side}", 0.10, -s * 80, 12, False)]
    limbs = {"arm_l": ("uarm_l", (25, 172)), "arm_r": ("uarm_r", (-172, -25)),
             "leg_l": ("thigh_l", (75, 188)), "leg_r": ("thigh_r", (-188, -75)),
             "head": ("neck", (-85, 85))}
    return bones, [("head", "neck", 0.09, 6)], 90.0, limbs


def _stickman(rng):
    arm = rng.choice((2, 3))
    bones = [("spine1", None, 0.25, 0, 8, True), ("spine2", "spine1", 0.25, 0, 8, True),
             ("head", "spine2", 0.16, 0, 12, False)]
    for side, s in (("l", 1), ("r", -1)):
        bones += [(f"uarm_{side}", "spine2", 0.26, s * 135, 25, False),
                  (f"farm_{side}", f"uarm_{side}", 0.24, s * 15, 35, False)]
        if arm == 3:
            bones.append((f"hand_{side}", f"farm_{side}", 0.08, 0, 20, False))
        bones += [(f"thigh_{side}", None, 0.42, s * 160, 10, False),
                  (f"shin_{side}", f"thigh_{side}", 0.40, -s * 5, 20, False)]
    limbs = {"arm_l": ("uarm_l", (25, 172)), "arm_r": ("uarm_r", (-172, -25)),
             "leg_l": ("thigh_l", (75, 190)), "leg_r": ("thigh_r", (-190, -75))}
    return bones, [], 90.0, limbs


def _quadruped(rng):
    bones = [("back1", None, 0.30, 0, 5, True), ("back2", "back1", 0.30, 0, 5, True),
             ("back3", "back2", 0.25, 0, 5, True),
             ("neck1", "back3", 0.20, 55, 12, False), ("neck2", "neck1", 0.15, 0, 12, False),
             ("head", "neck2", 0.20, -75, 12, False),
             ("tail1", None, 0.15, 195, 12, False), ("tail2", "tail1", 0.15, -10, 12, False),
             ("tail3", "tail2", 0.15, -10, 12, False), ("tail4", "tail3", 0.12, -10, 12, False),
             ("hthigh_1", None, 0.28, -105, 8, False), ("hshin_1", "hthigh_1", 0.28, 20, 15, False),
             ("hthigh_2", None, 0.28, -75, 8, False), ("hshin_2", "hthigh_2", 0.28, 20, 15, False),
             ("fthigh_1", "back3", 0.28, -105, 8, False), ("fshin_1", "fthigh_1", 0.28, -10, 15, False),
             ("fthigh_2", "back3", 0.28, -75, 8, False), ("fshin_2", "fthigh_2", 0.28, -10, 15, False)]
    limbs = {"tail": ("tail1", (70, 240)), "neck": ("neck1", (-60, 165)),
             "front_leg": ("fthigh_1", (-178, -85)), "hind_leg": ("hthigh_2", (-100, -5))}
    return bones, [], 0.0, limbs


def _lizard(rng):
    bones = [("body1", None, 0.15, 0, 6, True), ("body2", "body1", 0.15, 0, 6, True),
             ("body3", "body2", 0.15, 0, 6, True), ("body4", "body3", 0.15, 0, 6, True),
             ("head1", "body4", 0.12, 0, 12, False), ("head2", "head1", 0.08, 0, 10, False)]
    bones += [(f"tail{k}", None if k == 1 else f"tail{k - 1}", 0.13 - 0.01 * k, 180 if k == 1 else 0, 10, False)
              for k in range(1, 7)]
    for side, s in (("l", 1), ("r", -1)):
        bones += [(f"hleg_{side}", None, 0.13, s * 70, 12, False),
                  (f"hfoot_{side}", f"hleg_{side}", 0.08, -s * 40, 15, False),
                  (f"fleg_{side}", "body4", 0.13, s * 70, 12, False),
                  (f"ffoot_{side}", f"fleg_{side}", 0.08, s * 40, 15, False)]
    limbs = {"tail": ("tail1", (80, 280)), "head": ("head1", (-62, 62)),
             "front_leg": ("fleg_l", (15, 172))}
    return bones, [], 0.0, limbs


def _tree(rng):
    trunk = rng.randint(4, 6)
    bones = []
    lengths = [0.22, 0.20, 0.18, 0.16, 0.14, 0.12]
    for k in range(trunk):
        bones.append((f"trunk{k + 1}", None if k == 0 else f"trunk{k}", lengths[k], 0, 5, True))
    limbs = {}
    side = rng.choice((1, -1))
    for k in range(1, trunk):
        name = f"branch{k}"
        count = rng.randint(2, 3)
        for j in range(count):
            parent = f"trunk{k}" if j == 0 else f"{name}_{j}"
            rest = side * rng.uniform(40, 70) if j == 0 else rng.uniform(-15, 15)
            bones.append((f"{name}_{j + 1}", parent, (0.2, 0.15, 0.1)[j] * rng.uniform(0.85, 1.15), rest, 10, False))
        if rng.random() < 0.6:
            bones.append((f"{name}_twig", f"{name}_1", 0.09, -side * rng.uniform(30, 50), 10, False))
        limbs[name] = (f"{name}_1", (15, 165) if side > 0 else (-165, -15))
        side = -side
    for s in (1, -1):
        bones.append((f"root_{s}", None, 0.12, s * rng.uniform(140, 160), 6, False))
    return bones, [], 90.0, limbs


FIGURES = {"humanoid": _humanoid, "stickman": _stickman, "quadruped": _quadruped, "lizard": _lizard, "tree": _tree}


# ---------------------------------------------------------------------------
# posing

class Skeleton:
    """A bone tree with its rings, the limb that turns and its weights."""

    def __init__(self, bones, rings, root_dir, limb_bone):
        self.bones, self.rings, self.root_dir = bones, rings, root_dir
        self.index = {b[0]: i for i, b in enumerate(bones)}
        self.children = {}
        for b in bones:
            self.children.setdefault(b[1], []).append(b[0])
        self.limb_bone = limb_bone
        limb = set()
        stack = [limb_bone]
        while stack:
            name = stack.pop()
            limb.add(name)
            stack += self.children.get(name, [])
        self.limb = limb  # the limb's bones (its rings follow their parent bone)

    def absolute(self, rel, root_turn):
        """Absolute bone directions in degrees, accumulated without wrapping, so that a
        difference of two poses is the turn the morph makes."""
        out = {}
        for name, parent, _, _, _, _ in self.bones:  # parents come first
            base = self.root_dir + root_turn if parent is None else out[parent]
            out[name] = base + rel[name]
        return out

    def draw(self, angles, root, ring_angles=None):
        """Bone-level drawing: (points, segments (u, v, bone, on a ring?), owner bone per vertex)
        with vertex 0 the root; every bone adds its tip, every ring its other corners. angles: absolute directions per bone (degrees);
        ring_angles: per ring, the direction of its axis (default its parent bone's)."""
        pts = [np.asarray(root, float)]
        tip, segs, owner = {}, [], [None]
        for name, parent, length, _, _, _ in self.bones:
            start = 0 if parent is None else tip[parent]
            a = math.radians(angles[name])
            pts.append(pts[start] + length * np.array([math.cos(a), math.sin(a)]))
            tip[name] = len(pts) - 1
            owner.append(name)
            segs.append((start, tip[name], name, False))
        for name, parent, radius, sides in self.rings:
            a = math.radians((ring_angles or {}).get(name, angles[parent]))
            c = pts[tip[parent]] + radius * np.array([math.cos(a), math.sin(a)])
            ring = [tip[parent]]
            for k in range(1, sides):
                b = a + math.pi + 2 * math.pi * k / sides
                pts.append(c + radius * np.array([math.cos(b), math.sin(b)]))
                owner.append(parent)
                ring.append(len(pts) - 1)
            for u, v in zip(ring, ring[1:] + ring[:1]):
                segs.append((u, v, parent, True))
        return np.array(pts), segs, owner


def seg_distance(p, q):
    """Distances between segments p[i] = (a, b) and q[i] = (c, d) (arrays k x 2 x 2): 0 where
    they cross, else the least of the four end-to-segment distances."""
    def point_seg(x, a, b):
        d = b - a
        t = np.clip(np.einsum("ij,ij->i", x - a, d) / np.maximum(np.einsum("ij,ij->i", d, d), 1e-300), 0, 1)
        return np.linalg.norm(x - (a + t[:, None] * d), axis=1)

    a, b, c, d = p[:, 0], p[:, 1], q[:, 0], q[:, 1]

    def cross(o, u, v):
        return (u[:, 0] - o[:, 0]) * (v[:, 1] - o[:, 1]) - (u[:, 1] - o[:, 1]) * (v[:, 0] - o[:, 0])

    crossing = (cross(a, b, c) * cross(a, b, d) < 0) & (cross(c, d, a) * cross(c, d, b) < 0)
    dist = np.minimum.reduce([point_seg(a, c, d), point_seg(b, c, d), point_seg(c, a, b), point_seg(d, a, b)])
    return np.where(crossing, 0.0, dist)


class Clearance:
    """The bone-level test: non-adjacent segments apart, adjacent ones at an angle."""

    def __init__(self, segs):
        self.segs = [(u, v) for u, v, _, _ in segs]
        far, near = [], []
        for i, (u, v) in enumerate(self.segs):
            for j in range(i + 1, len(self.segs)):
                x, y = self.segs[j]
                shared = {u, v} & {x, y}
                if not shared:
                    far.append((i, j))
                elif len(shared) == 1:
                    w = shared.pop()
                    near.append((w, v if u == w else u, y if x == w else x))
        self.far = np.array(far, dtype=int).reshape(-1, 2)
        self.near = np.array(near, dtype=int).reshape(-1, 3)

    def worst(self, pts, size):
        """(smallest gap / size between non-adjacent segments, smallest angle in degrees between
        adjacent ones)."""
        s = np.array([[pts[u], pts[v]] for u, v in self.segs])
        gap = float(seg_distance(s[self.far[:, 0]], s[self.far[:, 1]]).min()) / size if len(self.far) else math.inf
        if len(self.near):
            d1 = pts[self.near[:, 1]] - pts[self.near[:, 0]]
            d2 = pts[self.near[:, 2]] - pts[self.near[:, 0]]
            cos = np.einsum("ij,ij->i", d1, d2) / (np.linalg.norm(d1, axis=1) * np.linalg.norm(d2, axis=1))
            angle = float(np.degrees(np.arccos(np.clip(cos, -1, 1))).min())
        else:
            angle = 180.0
        return gap, angle


def delayed_path(skel, abs_s, abs_t, root_s, root_t, overlap, samples=PATH_SAMPLES):
    """Bone-level frames of issue 31's delayed motion as a joint-angle morph would make it: every
    bone turns at constant speed at the local time of its ends (mean where they differ: the limb's
    first bone), the root moves on a straight line, rings stay rigid with their bone."""
    def local(t, w):
        return min(1.0, max(0.0, (t - overlap * w) / (1.0 - overlap)))

    frames = []
    for t in np.linspace(0.0, 1.0, samples):
        angles = {}
        for name, *_ in skel.bones:
            if name == skel.limb_bone:
                tau = (local(t, 0.0) + local(t, 1.0)) / 2
            else:
                tau = local(t, 1.0 if name in skel.limb else 0.0)
            angles[name] = abs_s[name] + (abs_t[name] - abs_s[name]) * tau
        rings = {}
        for name, parent, _, _ in skel.rings:
            tau = local(t, 1.0 if parent in skel.limb else 0.0)
            rings[name] = abs_s[parent] + (abs_t[parent] - abs_s[parent]) * tau
        tau0 = local(t, 0.0)
        root = (1 - tau0) * np.asarray(root_s) + tau0 * np.asarray(root_t)
        frames.append(skel.draw(angles, root, rings)[0])
    return frames


def mirror_points(points):
    return np.asarray(points) * np.array([-1.0, 1.0])


def draw_pair(kind, rng, require_delayed, overlaps, limb_index):
    """One attempt: a pair of bone-level poses, or None when a test fails. The limb that turns
    is the figure's limb_index-th (modulo their number, in name order)."""
    bones, rings, root_dir, limbs = FIGURES[kind](rng)
    limb_name = sorted(limbs)[limb_index % len(limbs)]
    limb_bone, (lo, hi) = limbs[limb_name]
    skel = Skeleton(bones, rings, root_dir, limb_bone)
    width = hi - lo
    top = min(TURN_RANGE[1], width - 4.0)
    if top < TURN_RANGE[0]:
        return None
    turn = rng.uniform(TURN_RANGE[0], top) * rng.choice((1, -1))
    start = rng.uniform(lo + max(0.0, -turn) + 2, hi - max(0.0, turn) - 2)
    bend = rng.uniform(*BEND_RANGE)
    torso_sign = rng.choice((1, -1))
    rel_s, rel_t = {}, {}
    for name, parent, _, rest, swing, torso in bones:
        if name == limb_bone:
            rel_s[name], rel_t[name] = start, start + turn
            continue
        rel_s[name] = rest + rng.uniform(-0.5, 0.5) * swing
        if name in skel.limb:
            change = rng.uniform(-LIMB_OWN_BEND, LIMB_OWN_BEND)
        elif torso:
            change = torso_sign * rng.uniform(0.3, 1.0) * bend / 2
        else:
            change = rng.uniform(-bend, bend)
        rel_t[name] = rel_s[name] + change
    root_turn = rng.uniform(-ROOT_TURN, ROOT_TURN)
    abs_s, abs_t = skel.absolute(rel_s, 0.0), skel.absolute(rel_t, root_turn)
    if any(abs(abs_t[b] - abs_s[b]) < LIMB_MIN_TURN for b in skel.limb):
        return None
    if sum(1 for b, *_ in bones if b not in skel.limb and abs(abs_t[b] - abs_s[b]) >= OTHER_MIN_TURN) < OTHER_MIN_COUNT:
        return None
    root_t = (rng.uniform(-0.2, 0.2), rng.uniform(-0.1, 0.1))
    src, segs, owner = skel.draw(abs_s, (0.0, 0.0))
    tgt, _, _ = skel.draw(abs_t, root_t)
    size = cc.figure_size(np.concatenate([src, tgt]))
    clear = Clearance(segs)
    for pts in (src, tgt):
        gap, angle = clear.worst(pts, size)
        if gap < GAP_POSE or angle < ANGLE_POSE:
            return None
    delayed_clear = {}
    for d in sorted(set([0.0] + list(overlaps))):
        ok = True
        for pts in delayed_path(skel, abs_s, abs_t, (0.0, 0.0), root_t, d):
            gap, angle = clear.worst(pts, size)
            if gap < GAP_PATH or angle < ANGLE_PATH:
                ok = False
                break
        if d == 0.0 and not ok:
            return None  # the plain morph's own path must be clear
        delayed_clear[d] = ok
    if require_delayed and not all(delayed_clear.values()):
        return None  # the quick test at the level of bones; the figure's own path is checked later
    return {"skel": skel, "limb_name": limb_name, "src": src, "tgt": tgt, "segs": segs, "owner": owner,
            "turn": turn, "bend": bend, "root_turn": root_turn, "bones_clear": delayed_clear,
            "turns": {b: abs_t[b] - abs_s[b] for b in abs_s}}


def subdivide(drawn, pieces, ring_pieces):
    """The figure file's vertices and edges: every bone split into `pieces` straight pieces
    (ring sides into `ring_pieces`); per vertex its weight (1 on the limb, the junction 0), the
    limb's edges and per edge its bone."""
    skel, src, tgt, segs, owner = drawn["skel"], drawn["src"], drawn["tgt"], drawn["segs"], drawn["owner"]
    n0 = len(src)
    weight = [1 if owner[v] in skel.limb else 0 for v in range(n0)]
    p_src, p_tgt = [tuple(p) for p in src], [tuple(p) for p in tgt]
    edges, limb_edges, edge_bone = [], [], []
    for u, v, name, is_ring in segs:
        k = ring_pieces if is_ring else pieces
        chain = [u]
        for j in range(1, k):
            f = j / k
            p_src.append(tuple(src[u] + f * (src[v] - src[u])))
            p_tgt.append(tuple(tgt[u] + f * (tgt[v] - tgt[u])))
            weight.append(1 if name in skel.limb else 0)
            chain.append(len(p_src) - 1)
        chain.append(v)
        for a, b in zip(chain, chain[1:]):
            if name in skel.limb:
                limb_edges.append(len(edges))
            edges.append((a, b))
            edge_bone.append(name)
    return np.array(p_src), np.array(p_tgt), edges, weight, limb_edges, edge_bone


def figure_path(src, tgt, edges, turns, weights, overlap, samples=PATH_SAMPLES):
    """Frames of the figure itself moving as issue 31 asks with a joint-angle morph: every edge
    turns at constant speed by `turns` (radians) at the local time of its ends (their mean where
    they differ), its length linear in that time, the vertices fitted to the edge vectors (exact
    for a tree; rings stay rigid), the centroid on a straight line."""
    e = np.asarray(edges, dtype=int)
    v0, v1 = src[e[:, 1]] - src[e[:, 0]], tgt[e[:, 1]] - tgt[e[:, 0]]
    a0 = np.arctan2(v0[:, 1], v0[:, 0])
    l0, l1 = np.linalg.norm(v0, axis=1), np.linalg.norm(v1, axis=1)
    n, count = len(src), len(e)
    incidence = np.zeros((count + 1, n))
    incidence[np.arange(count), e[:, 1]] = 1.0
    incidence[np.arange(count), e[:, 0]] = -1.0
    incidence[count, :] = 1.0 / n
    solve = np.linalg.pinv(incidence)
    w = np.asarray(weights, dtype=float)
    frames = []
    for t in np.linspace(0.0, 1.0, samples):
        tau = np.clip((t - overlap * w) / (1.0 - overlap), 0.0, 1.0)
        tau_e = (tau[e[:, 0]] + tau[e[:, 1]]) / 2
        a, r = a0 + turns * tau_e, l0 + (l1 - l0) * tau_e
        centroid = (1 - t) * src.mean(axis=0) + t * tgt.mean(axis=0)
        frames.append(solve @ np.vstack([np.stack([r * np.cos(a), r * np.sin(a)], axis=1), centroid]))
    return frames


def path_valid(topology, frames):
    """Whether every frame is a drawing of the figure with the source's rotation system, checked
    exactly (bench/multipart_check.py's Topology)."""
    return all(not topology.frame_problems(f, limit=1) for f in frames)


def write_figure(path, name, points, edges):
    doc = {"name": name, "vertices": [[float(x), float(y)] for x, y in points],
           "edges": [[int(i), int(j)] for i, j in edges]}
    path.write_text(json.dumps(doc) + "\n")


def timing_doc(weights, overlap):
    return {"delay": [float(w) for w in weights], "overlap": float(overlap)}


def overlap_label(d):
    """0.3 -> "0.3", 0 -> "0": the key of an overlap in file names and JSON."""
    return f"{float(d):g}"


def check(cli, src_path, tgt_path):
    r = subprocess.run([str(cli), "check", str(src_path), str(tgt_path)], capture_output=True, text=True,
                       timeout=120)
    return r.returncode, (r.stdout + r.stderr).strip()


def make_pair(kind, rng, require_delayed, overlaps, target_vertices, limb_index):
    """Draws until the bone-level tests pass (the given limb first; after half the attempts any
    limb); then subdivides to about target_vertices."""
    for attempt in range(MAX_ATTEMPTS):
        drawn = draw_pair(kind, rng, require_delayed, overlaps,
                          limb_index if attempt < MAX_ATTEMPTS // 2 else rng.randrange(64))
        if drawn is None:
            continue
        mirrored = rng.random() < 0.5
        if mirrored:
            drawn["src"], drawn["tgt"] = mirror_points(drawn["src"]), mirror_points(drawn["tgt"])
            drawn["turn"], drawn["root_turn"] = -drawn["turn"], -drawn["root_turn"]
        skel = drawn["skel"]
        bone_count = len(skel.bones)
        ring_sides = sum(r[3] for r in skel.rings)
        pieces = max(1, round((target_vertices - 1 - ring_sides) / (bone_count + ring_sides / 2)))
        limb_bones = len(skel.limb)
        if pieces * limb_bones < 3:
            pieces = 2  # the limb needs 3 edges or more: its junction edge lags by d/2 only
        ring_pieces = max(1, pieces // 2)
        src, tgt, edges, weight, limb_edges, edge_bone = subdivide(drawn, pieces, ring_pieces)
        if cc.plane_problems(src, edges, limit=1) or cc.plane_problems(tgt, edges, limit=1):
            continue
        # The figure's own path, exactly: the plain one must be valid; the delayed ones on the pairs
        # that ask for it (and recorded on all).
        turns = np.radians([drawn["turns"][b] for b in edge_bone]) * (-1.0 if mirrored else 1.0)
        topology = topo.Topology(src, edges)
        clear = {d: path_valid(topology, figure_path(src, tgt, edges, turns, weight, d))
                 for d in sorted(set([0.0] + list(overlaps)))}
        if not clear[0.0] or (require_delayed and not all(clear.values())):
            continue
        drawn["delayed_clear"] = clear
        return drawn, mirrored, pieces, src, tgt, edges, weight, limb_edges, attempt + 1
    return None


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", type=pathlib.Path, help="output folder")
    ap.add_argument("--seed", type=int, default=31, help="random seed (default 31)")
    ap.add_argument("--count", type=int, default=36, help="pairs to write (default 36)")
    ap.add_argument("--overlaps", default=",".join(overlap_label(d) for d in DEFAULT_OVERLAPS),
                    help="overlaps to write timing files for (default 0,0.3,0.5)")
    ap.add_argument("--build-dir", default=os.environ.get("STICKMORPH_BUILD_DIR", str(REPO / "build")),
                    help="folder with the stickmorph CLI (default $STICKMORPH_BUILD_DIR or build)")
    args = ap.parse_args(argv)
    cli = pathlib.Path(args.build_dir) / "stickmorph"
    if not cli.exists():
        print(f"error: {cli} is missing (cmake --build build --target stickmorph)", file=sys.stderr)
        return 2
    try:
        overlaps = sorted({float(x) for x in args.overlaps.split(",") if x.strip()})
    except ValueError:
        print(f"error: --overlaps {args.overlaps!r}: expected numbers like 0,0.3,0.5", file=sys.stderr)
        return 2
    if not overlaps or any(not 0.0 <= d < 1.0 for d in overlaps):
        print("error: --overlaps: every overlap must be in [0, 1)", file=sys.stderr)
        return 2
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    for old in out.glob("*.json"):
        old.unlink()
    manifest = {"seed": args.seed, "overlaps": overlaps, "pairs": []}
    counts = {}
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="local_timing_corpus_"))
    try:
        for i in range(args.count):
            kind = KINDS[i % len(KINDS)]
            name = f"{kind}_{i // len(KINDS) + 1}"
            c = counts.setdefault(kind, {"written": 0, "dropped": 0})
            rng = random.Random(f"{args.seed}:{name}")
            # 10 to 400 vertices, log-uniformly
            target_vertices = int(round(math.exp(rng.uniform(math.log(10), math.log(400)))))
            require_delayed = (i % DELAYED_FREE_EVERY) != DELAYED_FREE_EVERY - 1
            limb_index = rng.randrange(64)  # which limb turns: drawn once per pair
            for _ in range(4):  # a drawing the CLI refuses is drawn again
                made = make_pair(kind, rng, require_delayed, overlaps, target_vertices, limb_index)
                if made is None:
                    break
                drawn, mirrored, pieces, src, tgt, edges, weight, limb_edges, attempts = made
                s_path, t_path = tmp / "s.json", tmp / "t.json"
                write_figure(s_path, f"{name} source", src, edges)
                write_figure(t_path, f"{name} target", tgt, edges)
                code, msg = check(cli, s_path, t_path)
                if code == 0:
                    break
                print(f"{name}: stickmorph check: {msg}; drawn again", file=sys.stderr)
                made = None
            if made is None:
                c["dropped"] += 1
                print(f"dropped {name}: no drawing passed in {MAX_ATTEMPTS} attempts", file=sys.stderr)
                continue
            shutil.move(str(s_path), out / f"{name}.source.json")
            shutil.move(str(t_path), out / f"{name}.target.json")
            timing = {}
            for d in overlaps:
                file = f"{name}.timing_{overlap_label(d)}.json"
                (out / file).write_text(json.dumps(timing_doc(weight, d)) + "\n")
                timing[overlap_label(d)] = file
            skel = drawn["skel"]
            junction = int(edges[limb_edges[0]][0])
            manifest["pairs"].append({
                "name": name, "kind": kind, "source": f"{name}.source.json", "target": f"{name}.target.json",
                "timing": timing, "vertices": len(src), "edges": len(edges), "pieces": pieces,
                "limb": drawn["limb_name"], "junction": junction,
                "limb_vertices": [v for v, w in enumerate(weight) if w == 1], "limb_edges": limb_edges,
                "turn_deg": round(drawn["turn"], 2), "bend_deg": round(drawn["bend"], 2),
                "root_turn_deg": round(drawn["root_turn"], 2), "mirrored": mirrored,
                "delayed_clear": {overlap_label(d): ok for d, ok in drawn["delayed_clear"].items()},
                "delayed_required": require_delayed, "attempts": attempts})
            c["written"] += 1
            print(f"{name:14s} {len(src):4d} vertices, limb {drawn['limb_name']:9s} ({len(limb_edges)} edges) turns "
                  f"{drawn['turn']:+7.1f} deg, body bends up to {drawn['bend']:4.1f} deg, delayed path clear "
                  + ", ".join(f"d={overlap_label(d)}: {'yes' if ok else 'no'}"
                              for d, ok in drawn["delayed_clear"].items() if d > 0))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    manifest["counts"] = counts
    (out / "manifest.json").write_text(json.dumps(manifest, indent=1) + "\n")
    sizes = [p["vertices"] for p in manifest["pairs"]]
    total = len(manifest["pairs"])
    print(f"{total} compatible pairs in {out}"
          + (f", {min(sizes)}-{max(sizes)} vertices" if sizes else "")
          + ", dropped " + str(sum(c["dropped"] for c in counts.values())))
    return 0 if total else 1


if __name__ == "__main__":
    sys.exit(main())
