#!/usr/bin/env python3
"""Regenerates the polygon-pair corpus of the compatible-triangulation benchmark.

Each pair is <name>.source.json and <name>.target.json, two stick figure files
(../../../../shared/FORMAT.md, "Stick figure file") holding one closed cycle:
vertex i is joined to i+1 and the last to vertex 0, and vertex i of the source
corresponds to vertex i of the target. Every polygon is written
counter-clockwise, so source and target have the same orientation; a polygon
and its mirror image would be incompatible (paper, section 2.1).

Hand-made outlines are literal below; the generated ones come from seeded
random.Random instances and closed-form curves, so running the script again
rewrites byte-identical files. Before writing, every polygon is checked to be
simple and counter-clockwise with exact rational arithmetic on the very doubles
that go into the file (fractions.Fraction converts a float exactly), which is
the same decision the engine's exact predicates make when reading it.

Usage: python3 make_corpus.py [OUTPUT_DIR]   (default: this script's folder)
"""

import math
import os
import random
import sys
from fractions import Fraction

# ---------------------------------------------------------------------------
# Hand-made outlines.

# A left hand, palm towards the viewer: thumb on the right, four fingers.
# 38 corners, like the polygons of the paper's Figure 7.
HAND = [
    (3.0, 0.0), (4.5, -0.2), (6.0, 0.0), (6.4, 1.0), (6.3, 2.0),
    # thumb
    (7.2, 3.0), (8.8, 3.4), (10.0, 4.2), (10.2, 5.0), (9.6, 5.4), (8.3, 5.0), (7.3, 4.9),
    # index finger
    (7.4, 6.6), (7.55, 7.9), (7.6, 9.2), (7.4, 10.4), (6.8, 10.6), (6.3, 9.4), (6.1, 7.2),
    # middle finger
    (5.9, 9.8), (5.7, 11.6), (5.0, 11.8), (4.6, 10.0), (4.5, 7.2),
    # ring finger
    (4.3, 9.6), (4.0, 11.0), (3.3, 11.0), (3.0, 9.4), (2.9, 7.0),
    # little finger
    (2.7, 8.6), (2.4, 9.6), (1.8, 9.5), (1.5, 8.2), (1.5, 6.5),
    # outer edge of the palm
    (1.4, 5.0), (1.6, 3.5), (2.2, 2.2), (2.8, 1.2),
]

# A bird facing right with a raised wing, two legs and a forked tail.
# 38 corners, so it corresponds to HAND corner by corner.
BIRD = [
    (0.0, 3.0), (3.0, 2.6), (4.5, 2.0),
    # legs
    (5.0, 1.9), (4.9, 0.4), (4.4, 0.0), (5.6, 0.0), (5.3, 0.4), (5.4, 1.8),
    (6.2, 1.8), (6.3, 0.4), (5.9, 0.0), (7.1, 0.0), (6.7, 0.4), (6.6, 1.9),
    # breast, head and beak
    (7.8, 2.4), (8.6, 3.4), (8.9, 4.6), (9.4, 5.2), (11.0, 5.4), (9.5, 5.8),
    (9.2, 6.4), (8.4, 6.6), (7.8, 6.2), (7.6, 5.4),
    # raised wing
    (7.0, 5.2), (7.4, 8.0), (6.8, 8.6), (5.6, 8.2), (5.3, 7.2), (4.6, 7.6),
    (4.5, 6.6), (3.8, 6.8), (3.9, 5.4),
    # back and forked tail
    (2.8, 4.6), (1.4, 4.4), (0.2, 4.8), (0.8, 3.9),
]

# Block letters, 12 corners each: S and U.
GLYPH_S = [
    (0, 0), (4, 0), (4, 3), (1, 3), (1, 4), (4, 4),
    (4, 5), (0, 5), (0, 2), (3, 2), (3, 1), (0, 1),
]
GLYPH_U = [
    (1, 0), (3, 0), (4, 1), (4, 5), (3, 5), (3, 1.5),
    (2.5, 1), (1.5, 1), (1, 1.5), (1, 5), (0, 5), (0, 1),
]

# Block letters, 8 corners each: L (with a chamfered top) and T.
GLYPH_L = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 4.5), (0.7, 5), (0.3, 5), (0, 4.5)]
GLYPH_T = [(1.5, 0), (2.5, 0), (2.5, 4), (4, 4), (4, 5), (0, 5), (0, 4), (1.5, 4)]

# ---------------------------------------------------------------------------
# Generated outlines.


def spiral_band(m, turns, width):
    """A thick Archimedean spiral: m samples of the centre line, offset
    outwards going in and inwards coming back, 2*m corners."""
    outer, inner = [], []
    for i in range(m):
        theta = turns * 2 * math.pi * i / (m - 1)
        r = 2.0 + 1.2 * theta
        c, s = math.cos(theta), math.sin(theta)
        outer.append((round((r + width / 2) * c, 4), round((r + width / 2) * s, 4)))
        inner.append((round((r - width / 2) * c, 4), round((r - width / 2) * s, 4)))
    return outer + inner[::-1]


def zigzag_band(m):
    """A zig-zag (meander) band of 2*m corners: m peaks and valleys of the
    centre line, shifted down for the lower chain and up for the upper one.
    Both chains are x-monotone and apart at every x, so the band is simple."""
    centre = [(10 * i, 30 * (i % 2)) for i in range(m)]
    lower = [(x, y - 8) for x, y in centre]
    upper = [(x, y + 8) for x, y in centre]
    return lower + upper[::-1]


def comb(teeth):
    """A comb: a spine along the bottom and `teeth` teeth upwards, 4*teeth
    corners."""
    width, gap, top, base = 2, 2, 10, 3
    right = teeth * width + (teeth - 1) * gap
    p = [(0, 0), (right, 0)]
    for j in range(teeth - 1, -1, -1):
        left = j * (width + gap)
        p += [(left + width, top), (left, top)]
        if j > 0:
            p += [(left, base), (left - gap, base)]
    return p


def star(spikes, outer, inner, start_degrees):
    """A star of 2*spikes corners alternating between two radii."""
    p = []
    for k in range(2 * spikes):
        a = math.radians(start_degrees) + math.pi * k / spikes
        r = outer if k % 2 == 0 else inner
        p.append((round(r * math.cos(a), 4), round(r * math.sin(a), 4)))
    return p


def regular_polygon(n, radius):
    return [(round(radius * math.cos(2 * math.pi * k / n), 4),
             round(radius * math.sin(2 * math.pi * k / n), 4)) for k in range(n)]


def two_opt_polygon(rng, n, size):
    """A random simple polygon: random integer points joined in random order,
    untangled by 2-opt moves (reversing the chain between two crossing edges)
    until no edges cross. Each move shortens the tour, so this terminates.
    Integer coordinates keep every test exact."""
    points = set()
    while len(points) < n:
        points.add((rng.randrange(size), rng.randrange(size)))
    p = sorted(points)
    rng.shuffle(p)
    crossed = True
    while crossed:
        crossed = False
        for i in range(n):
            for j in range(i + 2, n):
                if i == 0 and j == n - 1:
                    continue
                if segments_meet(p[i], p[i + 1], p[j], p[(j + 1) % n]):
                    p[i + 1:j + 1] = reversed(p[i + 1:j + 1])
                    crossed = True
    return counter_clockwise(p)


def fourier_blob(rng, n, harmonics):
    """A smooth star-shaped blob: radius 1 plus a few random harmonics with
    decaying amplitudes, scaled so that they sum to at most 0.7. The radius
    then stays positive and, sampled at increasing angles, the polygon is
    star-shaped about the origin and therefore simple."""
    terms = [(h, rng.uniform(0.05, 0.4) / (h - 1), rng.uniform(0, 2 * math.pi))
             for h in range(2, 2 + harmonics)]
    shrink = min(1.0, 0.7 / sum(a for _, a, _ in terms))
    p = []
    for k in range(n):
        t = 2 * math.pi * k / n
        r = 1.0 + shrink * sum(a * math.cos(h * t + phase) for h, a, phase in terms)
        p.append((round(100 * r * math.cos(t), 3), round(100 * r * math.sin(t), 3)))
    return p


def subdivided(corners, cuts):
    """The polygon with the given corners, edge k divided into cuts[k] equal
    parts: the extra vertices lie on the edge and have straight (pi) angles.
    Integer corners and divisors of the edge vectors keep them exact."""
    p = []
    for k, (a, b) in enumerate(zip(corners, corners[1:] + corners[:1])):
        for i in range(cuts[k]):
            p.append((a[0] + (b[0] - a[0]) * i // cuts[k], a[1] + (b[1] - a[1]) * i // cuts[k]))
    return p


def rotated_180(p):
    """Rotation by a half turn about the origin: negation, exact in floating
    point, and orientation-preserving (unlike a reflection)."""
    return [(-x, -y) for x, y in p]


# ---------------------------------------------------------------------------
# Exact validation.


def orient(a, b, c):
    """Sign of the cross product (b-a) x (c-a), exact on the stored doubles."""
    ax, ay, bx, by, cx, cy = (Fraction(v) for v in (*a, *b, *c))
    d = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    return (d > 0) - (d < 0)


def on_segment(a, b, p):
    """p, known collinear with a-b, lies within the segment's bounding box."""
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def segments_meet(a, b, c, d):
    """True if closed segments a-b and c-d share a point."""
    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    if o1 != o2 and o3 != o4 and o1 * o2 <= 0 and o3 * o4 <= 0:
        return True
    return ((o1 == 0 and on_segment(a, b, c)) or (o2 == 0 and on_segment(a, b, d)) or
            (o3 == 0 and on_segment(c, d, a)) or (o4 == 0 and on_segment(c, d, b)))


def twice_area(p):
    return sum(Fraction(p[i][0]) * Fraction(p[(i + 1) % len(p)][1]) -
               Fraction(p[(i + 1) % len(p)][0]) * Fraction(p[i][1]) for i in range(len(p)))


def counter_clockwise(p):
    return p if twice_area(p) > 0 else p[::-1]


def check_simple_ccw(name, p):
    """Raises ValueError unless p is a simple counter-clockwise polygon:
    distinct vertices, non-adjacent edges disjoint, adjacent edges meeting
    only at their shared vertex, positive area."""
    n = len(p)
    if len(set(p)) != n:
        raise ValueError(f"{name}: repeated vertex")
    for i in range(n):
        a, b = p[i], p[(i + 1) % n]
        for j in range(i + 1, n):
            c, d = p[j], p[(j + 1) % n]
            if j == i + 1 or (i == 0 and j == n - 1):
                # Adjacent: they share one vertex; they must not fold back
                # onto each other (collinear and overlapping).
                shared, u, v = (b, a, d) if j == i + 1 else (a, b, c)
                if orient(u, shared, v) == 0 and not on_segment(u, v, shared):
                    raise ValueError(f"{name}: edges {i} and {j} overlap")
                continue
            if segments_meet(a, b, c, d):
                raise ValueError(f"{name}: edges {i} ({i}-{(i + 1) % n}) and "
                                 f"{j} ({j}-{(j + 1) % n}) meet")
    if twice_area(p) <= 0:
        raise ValueError(f"{name}: not counter-clockwise")


# ---------------------------------------------------------------------------
# Output.


def number(v):
    """Shortest text that reads back as the same double; integers without a
    fraction part."""
    if isinstance(v, int):
        return str(v)
    return str(int(v)) if v == int(v) and abs(v) < 1e15 else repr(v)


def figure_text(name, p):
    n = len(p)
    vertices = ",\n".join(f"    [{number(x)}, {number(y)}]" for x, y in p)
    edges = ", ".join(f"[{i}, {(i + 1) % n}]" for i in range(n))
    return f'{{\n  "name": "{name}",\n  "vertices": [\n{vertices}\n  ],\n  "edges": [{edges}]\n}}\n'


def corpus():
    """(name, source, target) for every pair of the corpus."""
    pairs = [
        ("fig7_hand_bird", HAND, BIRD),
        ("glyph_s_u", GLYPH_S, GLYPH_U),
        ("glyph_l_t", GLYPH_L, GLYPH_T),
        ("spiral_meander", spiral_band(20, 1.5, 2.5), zigzag_band(20)),
        ("comb_star", comb(6), star(12, 10, 4, -90)),
        ("rotated_bird", BIRD, rotated_180(BIRD)),
        # Straight angles at different corners of the pair: a square and a
        # triangle, both 16 corners, most of them in the middle of an edge.
        ("straight_square_triangle", subdivided([(0, 0), (120, 0), (120, 120), (0, 120)], [4, 4, 4, 4]),
         subdivided([(0, 0), (240, 0), (120, 180)], [5, 5, 6])),
        ("identical_hand", HAND, HAND),
        ("convex_random", regular_polygon(32, 100), two_opt_polygon(random.Random(32), 32, 200)),
        ("blobs_96", fourier_blob(random.Random(961), 96, 6), fourier_blob(random.Random(962), 96, 6)),
        ("random_64", two_opt_polygon(random.Random(641), 64, 1000),
         two_opt_polygon(random.Random(642), 64, 1000)),
    ]
    for name, source, target in pairs:
        if len(source) != len(target):
            raise ValueError(f"{name}: {len(source)} source corners, {len(target)} target corners")
    return pairs


def main(argv):
    out = argv[1] if len(argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    os.makedirs(out, exist_ok=True)
    for name, source, target in corpus():
        for role, polygon in (("source", source), ("target", target)):
            check_simple_ccw(f"{name}.{role}", polygon)
            path = os.path.join(out, f"{name}.{role}.json")
            with open(path, "w", encoding="utf-8", newline="\n") as f:
                f.write(figure_text(f"{name} {role}", polygon))
        print(f"{name}: {len(source)} corners")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
