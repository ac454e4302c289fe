#!/usr/bin/env python3
"""Write a corpus of multi-part figure pairs for `stickmorph check` / `morph`.

    /usr/bin/python3 bench/multipart_corpus.py OUT_DIR [--seed S] [--per-kind K] [--max-vertices N]

A *part* is a connected component of a figure (an isolated vertex is one). Every figure here
has several, some nested: the counter of an O inside the O, ring in ring, a dot in a face.
The pairs are of three kinds (manifest field `kind`):

  deformed         the target is a deformed copy of the source, same numbering: a smooth
                   orientation-preserving warp (bend, wave, twist about a point, bulge,
                   shear, stretch) then a rotation of up to 120 degrees, a scale and a shift.
                   The warp is a diffeomorphism of the plane, but the edges stay straight, so
                   every target is checked exactly (bench/multipart_check.py): a valid plane
                   figure, every vertex with the source's order of neighbours, every part with
                   its outer face, every part in the same face of every other part, and every
                   vertex at least 0.2% of the size away from edges not ending there. A warp
                   that fails is halved in strength and tried again.
  redrawn          the same shape drawn separately: the glyph outlined at another tolerance
                   (or in another font with the same contours), the drawing sampled at another
                   density, warped a little, renumbered, its edges shuffled and reversed, then
                   turned (up to 60 degrees), scaled and moved. For `--correspond auto`.
  nesting_changes  a part moves to another face in the target (then a mild warp): an eye out
                   of the head, a dot into the counter of an o, the counter of an O out of it,
                   the middle ring's contents into the annulus, a fly from one window pane to
                   another (another face of the same part), the centre of a bullseye out of
                   its ring. `check` must say incompatible naming the part, `morph` refuse.

The shapes: outlines of glyphs with several contours (i j ! ? = % ; : " e-acute o-umlaut
a-umlaut A-umlaut O o 0 8 B D P Q R A a e g 6 9 @ &) from the DejaVu and STIX fonts that
matplotlib bundles (read and flattened by bench/correspondence_corpus.py), and centre-line
drawings: a dotted i and j (the dot an isolated vertex or a tiny polygon), a face (head, two eye
rings with pupils, a mouth polyline, a nose vertex), a target of three concentric rings, rings
three deep with a spiral polyline inside, a bullseye with an isolated centre, a house with a
window loop (a cross in it: four panes, one with a fly), a door and smoke, glasses (two lenses
joined by a bridge, a pupil in each), a snowman, a key ring.

OUT_DIR gets NAME.source.json / NAME.target.json (docs/FORMAT.md figure files) and
manifest.json: a list of {name, kind, source, target, why, n_source, n_target, parts}, plus for
nesting_changes `moved` (what moves) and `moved_part` (its part number in the source: parts are
numbered in the order of their smallest vertex). The output is a function of the options alone.
"""
import argparse
import json
import math
import pathlib
import random
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import correspondence_check as cc  # noqa: E402  (clearance: the distance test of the other corpus)
import correspondence_corpus as outlines  # noqa: E402  (glyph_contours, flatten: font outlines)
import multipart_check as mc  # noqa: E402  (the exact plane test, parts, faces, nesting)

MIN_CLEARANCE = 2e-3
MAX_TRIES = 8
FONTS = ["DejaVuSans.ttf", "DejaVuSans-Bold.ttf", "DejaVuSans-Oblique.ttf", "DejaVuSerif.ttf",
         "DejaVuSerif-Bold.ttf", "DejaVuSerif-Italic.ttf", "DejaVuSansMono.ttf", "DejaVuSansMono-Bold.ttf",
         "STIXGeneral.ttf", "STIXGeneralBol.ttf", "STIXGeneralItalic.ttf"]
GLYPHS = "ij!?=%;:\"éöäÄOo08BDPQRAaeg69@&"
GLYPH_LABELS = {"!": "exclam", "?": "question", "=": "equal", "%": "percent", ";": "semicolon", ":": "colon",
                '"': "quotedbl", "é": "eacute", "ö": "odieresis", "ä": "adieresis", "Ä": "Adieresis",
                "@": "at", "&": "ampersand"}


def glyph_label(ch):
    if ch in GLYPH_LABELS:
        return GLYPH_LABELS[ch]
    return ch if ch.isupper() or ch.isdigit() else f"{ch}_lower"


# ---------------------------------------------------------------------------
# figures with named groups of vertices

class Fig:
    def __init__(self):
        self.points, self.edges, self.groups, self.regions = [], [], {}, {}

    def _add(self, pts, label):
        base = len(self.points)
        self.points.extend([tuple(map(float, p)) for p in pts])
        ids = list(range(base, base + len(pts)))
        if label:
            self.groups.setdefault(label, []).extend(ids)
        return ids

    def ring(self, pts, label=None):
        ids = self._add(pts, label)
        self.edges += [(ids[k], ids[(k + 1) % len(ids)]) for k in range(len(ids))]
        return ids

    def path(self, pts, label=None):
        ids = self._add(pts, label)
        self.edges += list(zip(ids, ids[1:]))
        return ids

    def vertex(self, p, label=None):
        return self._add([p], label)[0]

    def array(self):
        return np.array(self.points, dtype=float).reshape(-1, 2)

    def copy_with(self, points):
        f = Fig()
        f.points = [tuple(map(float, p)) for p in points]
        f.edges, f.groups, f.regions = list(self.edges), dict(self.groups), dict(self.regions)
        return f


def circle(c, r, count, phase=0.0, ry=None):
    ry = r if ry is None else ry
    return [(c[0] + r * math.cos(phase + 2 * math.pi * k / count), c[1] + ry * math.sin(phase + 2 * math.pi * k / count))
            for k in range(count)]


def sample(curve, length, spacing, lo=0.0, hi=1.0, ends=True):
    """Points of curve(t) for t in [lo, hi], about `spacing` apart (length: the curve's)."""
    count = max(2, int(round(length / spacing)) + 1)
    ts = np.linspace(lo, hi, count)
    if not ends:
        ts = ts[1:-1]
    return [curve(t) for t in ts]


def count_for(r, spacing, minimum=5):
    return max(minimum, int(round(2 * math.pi * r / spacing)))


# ---------------------------------------------------------------------------
# validity (exact) and fragility

def problems(points, edges):
    """Why (points, edges) may not go into the corpus (empty: it may)."""
    pts = np.asarray(points, dtype=float)
    if len({frozenset(e) for e in edges}) != len(edges) or any(u == v for u, v in edges):
        return ["a repeated edge or a loop edge"]
    bad = mc.plane_problems(pts, edges, limit=1)
    if bad:
        return bad
    if len(edges) > 1 and cc.clearance(pts, edges) < MIN_CLEARANCE:
        return ["a vertex almost touches an edge"]
    deg = np.zeros(len(pts), dtype=int)
    for u, v in edges:
        deg[u] += 1
        deg[v] += 1
    lone = pts[deg == 0]
    if len(lone):
        size = cc.figure_size(pts)
        d = np.linalg.norm(lone[:, None, :] - pts[None, :, :], axis=2)
        d[d == 0] = np.inf
        if d.min() < MIN_CLEARANCE * size:
            return ["an isolated vertex almost touches another vertex"]
    return []


def same_topology(a, b):
    """True when the two Topology objects agree on everything a morph must keep."""
    return a.rotation == b.rotation and a.outer == b.outer and a.nesting == b.nesting


# ---------------------------------------------------------------------------
# warps: smooth orientation-preserving maps of the plane

def random_warp(rng, big_turn=True):
    return {"bend": rng.uniform(-0.6, 0.6), "wave": rng.uniform(0, 0.08), "wave_len": rng.uniform(0.7, 1.5),
            "wave_phase": rng.uniform(0, 2 * math.pi), "twist": rng.uniform(-1.3, 1.3),
            "twist_c": (rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2)), "twist_s": rng.uniform(0.3, 0.6),
            "bulge": rng.uniform(-0.35, 0.6), "bulge_c": (rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)),
            "bulge_s": rng.uniform(0.2, 0.45), "shear": rng.uniform(-0.4, 0.4),
            "stretch": (math.exp(rng.uniform(-0.25, 0.25)), math.exp(rng.uniform(-0.25, 0.25))),
            "turn": rng.uniform(-120, 120) if big_turn else rng.uniform(-60, 60),
            "scale": math.exp(rng.uniform(-0.5, 0.5)), "shift": (rng.uniform(-1, 1), rng.uniform(-1, 1))}


def apply_warp(points, w, strength):
    """The warped points. Coordinates are first made relative (centroid 0, diagonal 1); each
    non-rigid term is scaled by `strength`; the rotation, scale and shift are not."""
    p = np.asarray(points, dtype=float)
    c = p.mean(axis=0)
    size = cc.figure_size(p)
    q = (p - c) / size
    s = strength
    x, y = q[:, 0].copy(), q[:, 1].copy()
    y = y + s * w["bend"] * x * x                                          # bend: (x, y + b x^2)
    x = x + s * w["wave"] * np.sin(2 * math.pi * y / w["wave_len"] + w["wave_phase"])  # wave
    tc = np.array(w["twist_c"])
    d = np.stack([x, y], axis=1) - tc
    r2 = np.einsum("ij,ij->i", d, d)
    ang = s * w["twist"] * np.exp(-r2 / w["twist_s"] ** 2)                  # twist: turn by angle(r)
    x = tc[0] + np.cos(ang) * d[:, 0] - np.sin(ang) * d[:, 1]
    y = tc[1] + np.sin(ang) * d[:, 0] + np.cos(ang) * d[:, 1]
    bc = np.array(w["bulge_c"])
    d = np.stack([x, y], axis=1) - bc
    r2 = np.einsum("ij,ij->i", d, d)
    g = 1 + s * w["bulge"] * np.exp(-r2 / w["bulge_s"] ** 2)               # bulge: r -> r g(r), monotone
    x, y = bc[0] + d[:, 0] * g, bc[1] + d[:, 1] * g
    x = x + s * w["shear"] * y                                             # shear
    sx, sy = w["stretch"]
    x, y = x * (1 + s * (sx - 1)), y * (1 + s * (sy - 1))                  # stretch
    a = math.radians(w["turn"])
    xr, yr = math.cos(a) * x - math.sin(a) * y, math.sin(a) * x + math.cos(a) * y
    out = np.stack([xr, yr], axis=1) * size * w["scale"] + c + np.array(w["shift"]) * size
    return out


def deform(points, edges, rng, reference=None, strength=1.0, big_turn=True):
    """A warped copy of the points that keeps `reference` (default: the points' own topology),
    and the strength used; the strength is halved until it does (None if it never does)."""
    ref = reference or mc.Topology(points, edges)
    w = random_warp(rng, big_turn)
    for _ in range(MAX_TRIES):
        out = apply_warp(points, w, strength)
        if not problems(out, edges) and same_topology(ref, mc.Topology(out, edges)):
            return out, strength
        strength /= 2
    return None, None


# ---------------------------------------------------------------------------
# glyph outlines: every closed contour a ring

def glyph_figure(font, char, tolerance, max_vertices):
    """The glyph's contours as rings (contour k's vertices in group f'contour{k}'), coarsened
    until it has at most max_vertices vertices; None when it is not a valid figure of two or
    more closed contours."""
    data = outlines.glyph_contours(font, char)
    if data is None:
        return None
    contours, closed = data
    keep = [c for c, cl in zip(contours, closed) if c]
    if len(keep) < 2 or not all(cl for c, cl in zip(contours, closed) if c):
        return None
    for _ in range(10):
        f = Fig()
        for k, c in enumerate(keep):
            pts = outlines.flatten(c, tolerance)
            if len(pts) < 3:
                return None
            f.ring(pts, f"contour{k}")
        if len(f.points) <= max_vertices:
            break
        tolerance *= 1.6
    else:
        return None
    return None if problems(f.array(), f.edges) else f


def nesting_shape(fig):
    """A canonical description of how the figure's parts nest (for comparing two glyphs)."""
    t = mc.Topology(fig.array(), fig.edges)
    depth = [sum(1 for (c, d), key in t.nesting.items() if d == p and key != t.outer[c]) for p in range(t.count)]
    return sorted(depth)


# ---------------------------------------------------------------------------
# centre-line drawings; sp is the sampling distance (the figures are about 2 across)

def dotted_i(rng, sp, polygon_dot=None):
    f = Fig()
    lean = rng.uniform(-0.08, 0.08)
    f.path([(-0.12 + lean, 0.55)] + sample(lambda t: (lean * (1 - t), 0.62 * (1 - t)), 0.62, sp)
           + [(0.14, -0.02)], "stem")
    dot = (lean * 1.2 + rng.uniform(-0.02, 0.02), 0.86)
    if polygon_dot if polygon_dot is not None else rng.random() < 0.5:
        f.ring(circle(dot, 0.06, 6, rng.uniform(0, 1)), "dot")
    else:
        f.vertex(dot, "dot")
    return f


def dotted_j(rng, sp, polygon_dot=None):
    f = Fig()
    x0 = 0.15
    stem = sample(lambda t: (x0, 0.6 - 0.75 * t), 0.75, sp)
    hook = sample(lambda t: (x0 - 0.22 + 0.22 * math.cos(-math.pi * t), -0.15 + 0.22 * math.sin(-math.pi * t)),
                  0.7, sp, ends=True)[1:]
    f.path(stem + hook, "stroke")
    dot = (x0 + rng.uniform(-0.02, 0.02), 0.85)
    if polygon_dot if polygon_dot is not None else rng.random() < 0.5:
        f.ring(circle(dot, 0.07, 5, rng.uniform(0, 1)), "dot")
    else:
        f.vertex(dot, "dot")
    return f


def face(rng, sp):
    f = Fig()
    f.ring(circle((0, 0), 1.0, count_for(1.0, sp, 12), rng.uniform(0, 1)), "head")
    for side, x in (("left", -0.38), ("right", 0.38)):
        c = (x, 0.3 + rng.uniform(-0.03, 0.03))
        f.ring(circle(c, 0.17, count_for(0.17, sp, 6), rng.uniform(0, 1), ry=0.13), f"{side}_eye")
        f.vertex((c[0] + 0.03, c[1] - 0.02), f"{side}_pupil")
        f.regions[f"{side}_eye"] = circle(c, 0.17, 24, 0.0, ry=0.13)
    f.vertex((0.0, -0.02), "nose")
    smile = rng.uniform(0.1, 0.22)
    f.path(sample(lambda t: (-0.45 + 0.9 * t, -0.38 - smile * (1 - (2 * t - 1) ** 2)), 0.95, sp), "mouth")
    f.regions["head"] = circle((0, 0), 1.0, 48)
    return f


def target_rings(rng, sp):
    f = Fig()
    for k, r in enumerate((1.0, 0.66, 0.33)):
        c = (rng.uniform(-0.03, 0.03) * k, rng.uniform(-0.03, 0.03) * k)
        f.ring(circle(c, r, count_for(r, sp, 8), rng.uniform(0, 2 * math.pi)), f"ring{k}")
        f.regions[f"ring{k}"] = circle(c, r, 48)
    return f


def rings_with_spiral(rng, sp):
    f = Fig()
    for k, r in enumerate((1.0, 0.72, 0.46)):
        f.ring(circle((0, 0), r, count_for(r, sp, 8), rng.uniform(0, 2 * math.pi)), f"ring{k}")
        f.regions[f"ring{k}"] = circle((0, 0), r, 48)
    turns = rng.uniform(1.0, 1.4)
    f.path(sample(lambda t: ((0.04 + 0.26 * t) * math.cos(2 * math.pi * turns * t),
                             (0.04 + 0.26 * t) * math.sin(2 * math.pi * turns * t)), 1.4 * turns, sp * 0.6),
           "spiral")
    return f


def bullseye(rng, sp):
    f = Fig()
    for k, r in enumerate((1.0, 0.6, 0.25)):
        f.ring(circle((0, 0), r, count_for(r, sp, 8), rng.uniform(0, 2 * math.pi)), f"ring{k}")
        f.regions[f"ring{k}"] = circle((0, 0), r, 48)
    f.vertex((rng.uniform(-0.03, 0.03), rng.uniform(-0.03, 0.03)), "centre")
    return f


def house(rng, sp):
    f = Fig()
    corners = [(-1, 0), (1, 0), (1, 1), (0, 1.7 + rng.uniform(-0.1, 0.1)), (-1, 1)]
    outline = []
    for a, b in zip(corners, corners[1:] + corners[:1]):
        length = math.dist(a, b)
        outline += sample(lambda t: (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t), length, sp)[:-1]
    f.ring(outline, "walls")
    f.regions["house"] = corners
    # window: a 3 x 3 grid of vertices, its 12 edges make four panes
    x0, x1, y0, y1 = 0.2, 0.75, 0.3, 0.8
    ids = {}
    for i, x in enumerate((x0, (x0 + x1) / 2, x1)):
        for j, y in enumerate((y0, (y0 + y1) / 2, y1)):
            ids[i, j] = f.vertex((x, y), "window")
    for i in range(3):
        for j in range(3):
            if i < 2:
                f.edges.append((ids[i, j], ids[i + 1, j]))
            if j < 2:
                f.edges.append((ids[i, j], ids[i, j + 1]))
    xm, ym = (x0 + x1) / 2, (y0 + y1) / 2
    f.regions["pane_ll"] = [(x0, y0), (xm, y0), (xm, ym), (x0, ym)]
    f.regions["pane_ur"] = [(xm, ym), (x1, ym), (x1, y1), (xm, y1)]
    f.regions["window"] = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    f.vertex((x0 + 0.08 + rng.uniform(0, 0.1), y0 + 0.08 + rng.uniform(0, 0.1)), "fly")
    # a door standing on nothing (it does not touch the walls): a U upside down
    f.path(sample(lambda t: (-0.7, 0.06 + 0.6 * t), 0.6, sp) + sample(lambda t: (-0.7 + 0.4 * t, 0.66), 0.4, sp)[1:]
           + sample(lambda t: (-0.3, 0.66 - 0.6 * t), 0.6, sp)[1:], "door")
    f.path(sample(lambda t: (0.55 + 0.08 * math.sin(4 * math.pi * t), 1.85 + 0.5 * t), 0.6, sp), "smoke")
    return f


def glasses(rng, sp):
    f = Fig()
    count = 2 * max(6, count_for(0.5, sp) // 2)
    left = f.ring(circle((-0.6, 0), 0.5, count, 0.0), "frame")  # left[0] at angle 0 (its right end)
    right = f.ring(circle((0.6, 0), 0.5, count, 0.0), "frame")  # right[count // 2] at angle pi
    f.edges.append((left[0], right[count // 2]))
    arm = sample(lambda t: (-1.1 - 0.5 * t, 0.25 * t * t), 0.55, sp)[1:]
    ids = f.path(arm, "frame")
    f.edges.append((left[count // 2], ids[0]))
    f.vertex((-0.6 + rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1)), "left_pupil")
    f.vertex((0.6 + rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1)), "right_pupil")
    f.regions["left_lens"] = circle((-0.6, 0), 0.5, 48)
    f.regions["right_lens"] = circle((0.6, 0), 0.5, 48)
    return f


def snowman(rng, sp):
    f = Fig()
    body = [((0, 0), 0.6, "bottom"), ((0, 1.12), 0.42, "middle"), ((0, 1.88), 0.28, "head")]
    for c, r, name in body:
        count = 2 * max(5, count_for(r, sp) // 2)
        ids = f.ring(circle(c, r, count, 0.0), name)
        f.regions[name] = circle(c, r, 48)
        if name == "middle":  # arms from the vertices at angles 0 and pi
            for at, sign in ((ids[0], 1), (ids[count // 2], -1)):
                p0 = f.points[at]
                arm = f.path(sample(lambda t: (p0[0] + sign * 0.55 * t, p0[1] + 0.3 * t), 0.63, sp)[1:], "arms")
                f.edges.append((at, arm[0]))
                tip = f.points[arm[-1]]
                f.edges.append((arm[-1], f.vertex((tip[0] + sign * 0.12, tip[1] + 0.14), "arms")))
                f.edges.append((arm[-1], f.vertex((tip[0] + sign * 0.16, tip[1] - 0.05), "arms")))
    for k in range(3):
        f.vertex((rng.uniform(-0.03, 0.03), 1.3 - 0.18 * k), f"button{k}")
    for x in (-0.1, 0.1):
        f.ring(circle((x, 1.95), 0.035, 3, rng.uniform(0, 1)), "eyes")
    f.vertex((0.0, 1.84), "nose")
    return f


def key_ring(rng, sp):
    f = Fig()
    f.ring(circle((0, 0), 1.0, count_for(1.0, sp, 12), rng.uniform(0, 1)), "ring")
    f.regions["ring"] = circle((0, 0), 1.0, 48)
    bow = f.ring(circle((-0.25, 0.2), 0.25, count_for(0.25, sp, 6), 0.0), "key")  # bow[0] at angle 0
    p0 = f.points[bow[0]]
    blade = f.path(sample(lambda t: (p0[0] + 0.6 * t, p0[1] - 0.35 * t), 0.7, sp)[1:], "key")
    f.edges.append((bow[0], blade[0]))
    tip = f.points[blade[-3]]
    f.edges.append((blade[-3], f.vertex((tip[0] - 0.06, tip[1] - 0.12), "key")))
    f.path(sample(lambda t: (1.2 + 0.5 * t, -0.2 + 0.3 * math.sin(3 * t)), 0.8, sp), "string")
    return f


DRAWINGS = {"dotted_i": dotted_i, "dotted_j": dotted_j, "face": face, "target": target_rings,
            "rings_spiral": rings_with_spiral, "bullseye": bullseye, "house": house, "glasses": glasses,
            "snowman": snowman, "key_ring": key_ring}


def drawing(kind, rng, sp, **options):
    for _ in range(MAX_TRIES):
        f = DRAWINGS[kind](rng, sp, **options)
        if not problems(f.array(), f.edges):
            return f
        sp *= 0.8
    raise RuntimeError(f"{kind}: no valid drawing")


# ---------------------------------------------------------------------------
# moving one group of vertices into another face

def _inside(poly, pts):
    from matplotlib.path import Path
    return Path(np.asarray(poly, dtype=float)).contains_points(pts)


def _distance_to_figure(points, edges, skip, probe):
    """Distance from each probe point to the figure without the vertices in `skip`."""
    pts = np.asarray(points, dtype=float)
    keep_e = [(u, v) for u, v in edges if u not in skip and v not in skip]
    keep_v = [i for i in range(len(pts)) if i not in skip]
    best = np.full(len(probe), np.inf)
    if keep_v:
        d = np.linalg.norm(probe[:, None, :] - pts[keep_v][None, :, :], axis=2)
        best = np.minimum(best, d.min(axis=1))
    if keep_e:
        e = np.asarray(keep_e)
        a, b = pts[e[:, 0]], pts[e[:, 1]]
        ab = b - a
        t = np.clip(np.einsum("pij,ij->pi", probe[:, None, :] - a[None], ab) / np.maximum(
            np.einsum("ij,ij->i", ab, ab), 1e-300), 0, 1)
        near = a[None] + t[..., None] * ab[None]
        best = np.minimum(best, np.linalg.norm(probe[:, None, :] - near, axis=2).min(axis=1))
    return best


def move_group(fig, group, into=None, outside_of=None, beside=False, fill=0.45):
    """A copy of fig with the vertices of `group` moved (and shrunk to fit): into the region
    inside every polygon of `into` and outside every polygon of `outside_of` (polygons: region
    names or group names), at the point farthest from the rest of the figure; or, with
    beside=True, just right of the whole figure."""
    pts = fig.array()
    ids = fig.groups[group]
    g = pts[ids]
    centre = g.mean(axis=0)
    radius = max(float(np.max(np.linalg.norm(g - centre, axis=1))), 1e-3)
    size = cc.figure_size(pts)
    if beside:
        rest = np.delete(pts, ids, axis=0)
        dest = np.array([rest[:, 0].max() + radius + 0.08 * size, centre[1]])
        scale = 1.0
    else:
        def poly(name):
            return fig.regions[name] if name in fig.regions else pts[fig.groups[name]]
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        xs, ys = np.meshgrid(np.linspace(lo[0], hi[0], 70), np.linspace(lo[1], hi[1], 70))
        probe = np.stack([xs.ravel(), ys.ravel()], axis=1)
        ok = np.ones(len(probe), dtype=bool)
        for name in into or []:
            ok &= _inside(poly(name), probe)
        for name in outside_of or []:
            ok &= ~_inside(poly(name), probe)
        probe = probe[ok]
        if not len(probe):
            return None
        dist = _distance_to_figure(pts, fig.edges, set(ids), probe)
        k = int(np.argmax(dist))
        dest, room = probe[k], float(dist[k])
        scale = min(1.0, fill * room / radius)
    new = pts.copy()
    new[ids] = (g - centre) * scale + dest
    return fig.copy_with(new)


# ---------------------------------------------------------------------------
# the corpus

def disguise(points, edges, rng, turn=60):
    """Random numbering, edge order and direction, and a similarity (up to `turn` degrees)."""
    n = len(points)
    perm = list(range(n))
    rng.shuffle(perm)  # perm[old] = new
    new = np.empty_like(points)
    new[perm] = points
    e = [(perm[u], perm[v]) if rng.random() < 0.5 else (perm[v], perm[u]) for u, v in edges]
    rng.shuffle(e)
    size = cc.figure_size(new)
    a = math.radians(rng.uniform(-turn, turn))
    rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    c = new.mean(axis=0)
    new = (new - c) @ rot.T * math.exp(rng.uniform(-0.6, 0.6)) + c + size * np.array(
        [rng.uniform(-1, 1), rng.uniform(-1, 1)])
    return new, e


def write_figure(path, name, points, edges):
    doc = {"name": name, "vertices": [[float(x), float(y)] for x, y in points],
           "edges": [[int(u), int(v)] for u, v in edges]}
    path.write_text(json.dumps(doc) + "\n")


class Corpus:
    def __init__(self, out, rng, max_vertices):
        self.out, self.rng, self.max_vertices, self.entries = out, rng, max_vertices, []

    def add(self, name, kind, src, tgt, why, **extra):
        (sp, se), (tp, te) = src, tgt
        for pts, edges in (src, tgt):
            bad = problems(pts, edges)
            if bad:
                raise RuntimeError(f"{name}: corpus figure invalid: {bad}")
        write_figure(self.out / f"{name}.source.json", f"{name} source", sp, se)
        write_figure(self.out / f"{name}.target.json", f"{name} target", tp, te)
        entry = {"name": name, "kind": kind, "source": f"{name}.source.json", "target": f"{name}.target.json",
                 "why": why, "n_source": len(sp), "n_target": len(tp), "parts": mc.Topology(sp, se).count}
        entry.update(extra)
        self.entries.append(entry)

    def glyph(self, char, font=None):
        """(font, tolerance, Fig) of a glyph in a random font where it is a valid figure."""
        fonts = [font] if font else self.rng.sample(FONTS, len(FONTS))
        for f in fonts:
            tol = 10 ** self.rng.uniform(-3.0, -2.3)
            fig = glyph_figure(f, char, tol, self.max_vertices)
            if fig is not None:
                return f, tol, fig
        return None


def deformed_family(corpus, glyph_count, rng):
    made = 0
    chars = list(GLYPHS)
    rng.shuffle(chars)
    for char in chars[:glyph_count]:
        found = corpus.glyph(char)
        if found is None:
            continue
        font, _, fig = found
        pts = fig.array()
        tgt, strength = deform(pts, fig.edges, rng)
        if tgt is None:
            continue
        corpus.add(f"deformed_{made:02d}_glyph_{glyph_label(char)}", "deformed", (pts, fig.edges), (tgt, fig.edges),
                   f"'{char}' outlined in {font}: {len(fig.groups)} contours; warp at strength {strength:g}")
        made += 1
    for kind in DRAWINGS:
        fig = drawing(kind, rng, rng.uniform(0.06, 0.12))
        pts = fig.array()
        tgt, strength = deform(pts, fig.edges, rng)
        if tgt is None:
            continue
        corpus.add(f"deformed_{made:02d}_{kind}", "deformed", (pts, fig.edges), (tgt, fig.edges),
                   f"centre-line {kind.replace('_', ' ')}; warp at strength {strength:g}")
        made += 1


REDRAWN_GLYPHS = "O8B%ö"
REDRAWN_DRAWINGS = ["face", "target", "bullseye", "dotted_i", "house"]


def redrawn_family(corpus, rng):
    made = 0
    for char in REDRAWN_GLYPHS:
        found = corpus.glyph(char)
        if found is None:
            continue
        font, tol, a = found
        b = None
        for other in rng.sample(FONTS, len(FONTS)):
            b = glyph_figure(other, char, tol * 10 ** rng.uniform(0.3, 0.7) * rng.choice([1, 0.15]),
                             corpus.max_vertices)
            if b is not None and nesting_shape(b) == nesting_shape(a) and len(b.points) != len(a.points):
                break
            b = None
        if b is None:
            continue
        _emit_redrawn(corpus, f"redrawn_{made:02d}_glyph_{glyph_label(char)}", a, b, rng,
                      f"'{char}' in {font} and {other}, outlined at other tolerances")
        made += 1
    for kind in REDRAWN_DRAWINGS:
        # both drawings of a dotted letter have the same kind of dot (a vertex or a polygon)
        options = {"polygon_dot": rng.random() < 0.5} if kind in ("dotted_i", "dotted_j") else {}
        a = drawing(kind, rng, rng.uniform(0.07, 0.1), **options)
        b = drawing(kind, rng, rng.uniform(0.11, 0.16), **options)
        _emit_redrawn(corpus, f"redrawn_{made:02d}_{kind}", a, b, rng,
                      f"centre-line {kind.replace('_', ' ')} drawn twice, at two sampling densities")
        made += 1


def _emit_redrawn(corpus, name, a, b, rng, why):
    bp, strength = deform(b.array(), b.edges, rng, strength=0.35, big_turn=False)
    if bp is None:
        bp = b.array()
    for _ in range(MAX_TRIES):
        tp, te = disguise(bp, b.edges, rng)
        if not problems(tp, te):
            break
    corpus.add(name, "redrawn", (a.array(), a.edges), (tp, te),
               why + f"; the target warped a little (strength {strength}), renumbered, turned, scaled, moved")


# (name, shape: drawing kind or "glyph:<char>", group moved, placement, why)
NESTING = [
    ("face_eye_out", "face", "left_eye", {"beside": True}, "the left eye (a ring) moves out of the head"),
    ("face_nose_into_eye", "face", "nose", {"into": ["right_eye"]}, "the nose (an isolated vertex) moves into the right eye"),
    ("target_inner_out", "target", "ring2", {"beside": True}, "the innermost ring moves out of all the others"),
    ("target_inner_to_annulus", "target", "ring2", {"into": ["ring0"], "outside_of": ["ring1"], "fill": 0.6},
     "the innermost ring moves into the annulus between the outer two"),
    ("spiral_out", "rings_spiral", "spiral", {"beside": True}, "the spiral moves out of the three rings around it"),
    ("bullseye_centre_out", "bullseye", "centre", {"into": ["ring1"], "outside_of": ["ring2"]},
     "the centre vertex moves out of the inner ring"),
    ("house_window_out", "house", "window", {"beside": True}, "the window (four panes) moves out of the house"),
    ("house_fly_other_pane", "house", "fly", {"into": ["pane_ur"]},
     "the fly moves from the lower-left pane to the upper-right one: another face of the same part"),
    ("glasses_pupil_other_lens", "glasses", "left_pupil", {"into": ["right_lens"]},
     "the left pupil moves into the right lens: another face of the same part"),
    ("snowman_button_to_head", "snowman", "button1", {"into": ["head"]}, "a button moves from the middle ball to the head"),
    ("glyph_odieresis_dot_into_counter", "glyph:ö", "dot", {"into": ["counter"]}, "a dot of the o-umlaut moves into the counter of the o"),
    ("glyph_O_counter_out", "glyph:O", "counter", {"beside": True}, "the counter of the O moves out of it"),
    ("glyph_B_counter_into_other", "glyph:B", "counter", {"into": ["counter2"]}, "one counter of the B moves into the other"),
    ("glyph_i_dot_into_o", "glyph:o+i", "dot", {"into": ["counter"]}, "the dot of an i beside an o moves into the o's counter"),
]


def label_glyph_contours(fig):
    """Name the glyph's contours by nesting: 'counter' (and 'counter2') for contours inside
    another with nothing inside them, 'dot' for a small free contour."""
    t = mc.Topology(fig.array(), fig.edges)
    inside = {d: [c for (c, dd), key in t.nesting.items() if dd == d and key != t.outer[c]] for d in range(t.count)}
    holds = {c: [d for (cc_, d), key in t.nesting.items() if cc_ == c and key != t.outer[c]] for c in range(t.count)}
    pts = fig.array()
    names = {}
    counters = [p for p in range(t.count) if inside[p] and not holds[p]]
    counters.sort(key=lambda p: -pts[t.members[p]][:, 1].mean())  # the upper one first
    for k, p in enumerate(counters[:2]):
        names["counter" if k == 0 else "counter2"] = t.members[p]
    free = [p for p in range(t.count) if not inside[p] and not holds[p]]
    if free:
        small = min(free, key=lambda p: cc.figure_size(pts[t.members[p]]))
        names["dot"] = t.members[small]
    fig.groups.update(names)
    return fig


def glyph_o_and_i(corpus, rng):
    """An o and an i side by side, as one figure."""
    font = rng.choice(["DejaVuSans.ttf", "DejaVuSerif.ttf", "DejaVuSans-Bold.ttf"])
    o = glyph_figure(font, "o", 10 ** rng.uniform(-2.8, -2.3), corpus.max_vertices // 2)
    i = glyph_figure(font, "i", 10 ** rng.uniform(-2.8, -2.3), corpus.max_vertices // 2)
    if o is None or i is None:
        return None
    f = Fig()
    op = o.array()
    for pts, g, shift in ((op, o, 0.0), (i.array(), i, op[:, 0].max() + 0.12)):
        base = len(f.points)
        f.points += [(x + shift, y) for x, y in pts]
        f.edges += [(u + base, v + base) for u, v in g.edges]
    return font, label_glyph_contours(f)


def nesting_family(corpus, rng):
    made = 0
    for name, shape, group, placement, why in NESTING:
        fig, font = None, None
        for _ in range(MAX_TRIES):
            if shape == "glyph:o+i":
                found = glyph_o_and_i(corpus, rng)
                if found:
                    font, fig = found
            elif shape.startswith("glyph:"):
                found = corpus.glyph(shape[6:])
                if found:
                    font, _, fig = found
                    fig = label_glyph_contours(fig)
            else:
                fig = drawing(shape, rng, rng.uniform(0.07, 0.12))
            if fig is None or group not in fig.groups:
                fig = None
                continue
            pts = fig.array()
            moved = move_group(fig, group, **placement)
            if moved is None:
                fig = None
                continue
            mp = moved.array()
            src_t, mov_t = mc.Topology(pts, fig.edges), mc.Topology(mp, fig.edges)
            diff = mc.nesting_differences(pts, mp, fig.edges)
            if problems(mp, fig.edges) or not diff or mov_t.rotation != src_t.rotation:
                fig = None
                continue
            tgt, strength = deform(mp, fig.edges, rng, reference=mov_t, strength=0.4, big_turn=False)
            if tgt is None:
                fig = None
                continue
            break
        if fig is None:
            raise RuntimeError(f"{name}: no valid nesting change")
        moved_part = src_t.part[fig.groups[group][0]]
        involved = sorted({p for pair in diff for p in pair})
        corpus.add(f"nesting_{made:02d}_{name}", "nesting_changes", (pts, fig.edges), (tgt, fig.edges),
                   why + (f" ({font})" if font else "") + f"; then a mild warp (strength {strength:g})",
                   moved=group, moved_part=moved_part, involved_parts=involved)
        made += 1


def generate(out, seed=1, per_kind=None, max_vertices=300, glyphs=20):
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    rng = random.Random(seed)
    corpus = Corpus(out, rng, max_vertices)
    deformed_family(corpus, glyphs, rng)
    redrawn_family(corpus, rng)
    nesting_family(corpus, rng)
    entries = corpus.entries
    if per_kind is not None:
        keep = []
        for kind in mc.KINDS:
            mine = [e for e in entries if e["kind"] == kind]
            step = max(1, len(mine) // per_kind)
            keep += mine[::step][:per_kind]
        for e in entries:
            if e not in keep:
                (out / e["source"]).unlink()
                (out / e["target"]).unlink()
        entries = keep
    (out / "manifest.json").write_text(json.dumps(entries, indent=1) + "\n")
    return entries


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", type=pathlib.Path)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--per-kind", type=int, help="keep at most K pairs of each kind (spread over the list)")
    ap.add_argument("--max-vertices", type=int, default=300, help="vertices per glyph figure at most (default 300)")
    ap.add_argument("--glyphs", type=int, default=20, help="glyphs among the deformed pairs (default 20)")
    args = ap.parse_args(argv)
    if args.per_kind is not None and args.per_kind < 1:
        print("error: --per-kind must be at least 1", file=sys.stderr)
        return 2
    entries = generate(args.out, args.seed, args.per_kind, args.max_vertices, args.glyphs)
    for kind in mc.KINDS:
        mine = [e for e in entries if e["kind"] == kind]
        if mine:
            sizes = [max(e["n_source"], e["n_target"]) for e in mine]
            parts = [e["parts"] for e in mine]
            print(f"{kind}: {len(mine)} pairs, {min(sizes)}-{max(sizes)} vertices, {min(parts)}-{max(parts)} parts")
    print(f"{len(entries)} pairs written to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
