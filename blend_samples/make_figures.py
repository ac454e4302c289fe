#!/usr/bin/python3
"""Write the sample stick-figure pairs of blend_samples/ as JSON (docs/CLI.md format).

The coordinates below are the only copy of the sample data in the repository; the
JSON files in blend_samples/figures/ and the .blend files made from them by
make_samples.py are generated.  Before writing, every figure is checked to be a plane
straight-line graph (distinct vertices, no vertex inside an edge, no two edges that
cross) in exact rational arithmetic on the given doubles, and to be connected.

    /usr/bin/python3 blend_samples/make_figures.py [--output-dir DIR]

Vertex i of a source corresponds to vertex i of its target and both share one edge
list; the pairs were drawn so that every vertex keeps the counter-clockwise order of
its neighbours and the exterior face stays the same, so `stickmorph check` reports
them compatible.
"""

import argparse
import json
import os
import sys
from fractions import Fraction


def path_edges(vertices):
    """Edges of the polyline through the given vertex indices."""
    return [[a, b] for a, b in zip(vertices, vertices[1:])]


def cycle_edges(vertices):
    """Edges of the closed loop through the given vertex indices."""
    return path_edges(list(vertices) + [vertices[0]])


# --------------------------------------------------------------------------------------
# 1. Monkey -> basketball player (Figure 8a of the paper: 18 vertices).
#    Both face the viewer's right / the viewer.  Vertex roles (monkey / player):
#     0 pelvis / pelvis             1 tail root / right shoulder   2 shoulder / neck
#     3,4,5 head loop with 2: snout, crown, back of head / right, top, left of the head
#     6,7 arm: elbow, hand (long monkey arm / the player's free arm)
#     8,9 front leg: knee, foot     10,11 back leg: knee, foot
#     12,13,14 tail / the shooting arm: elbow, wrist, hand
#     14,15,16,17 the curl at the tail's tip / the ball held overhead
# --------------------------------------------------------------------------------------
MONKEY_EDGES = (
    path_edges([0, 1, 2])
    + cycle_edges([2, 3, 4, 5])
    + path_edges([2, 6, 7])
    + path_edges([0, 8, 9])
    + path_edges([0, 10, 11])
    + path_edges([1, 12, 13, 14])
    + cycle_edges([14, 15, 16, 17])
)

MONKEY = [
    [3.6, 4.4],    # 0 pelvis
    [3.2, 4.8],    # 1 tail root
    [5.6, 6.2],    # 2 shoulders, the back bent forward
    [7.3, 6.7],    # 3 snout
    [6.5, 7.8],    # 4 crown
    [5.5, 7.4],    # 5 back of the head
    [6.7, 4.6],    # 6 elbow
    [7.3, 1.0],    # 7 knuckles on the ground
    [5.0, 3.1],    # 8 front knee, bent forward
    [4.8, 1.0],    # 9 front foot
    [3.5, 2.8],    # 10 back knee
    [3.1, 1.0],    # 11 back foot
    [2.2, 4.3],    # 12 tail
    [1.3, 4.9],    # 13 tail
    [1.0, 6.0],    # 14 tail, start of the curl
    [1.3, 7.0],    # 15 curl
    [2.1, 7.1],    # 16 curl
    [1.75, 6.45],  # 17 curl
]

PLAYER = [
    [5.0, 4.2],    # 0 pelvis
    [4.45, 7.1],   # 1 right shoulder (the viewer's left)
    [5.1, 7.3],    # 2 neck
    [5.5, 8.0],    # 3 head, viewer's right
    [5.1, 9.0],    # 4 top of the head
    [4.7, 8.0],    # 5 head, viewer's left
    [5.9, 6.2],    # 6 elbow of the free arm
    [6.5, 5.1],    # 7 hand of the free arm
    [5.6, 2.3],    # 8 knee
    [6.0, 0.3],    # 9 foot
    [4.4, 2.3],    # 10 knee
    [4.1, 0.3],    # 11 foot
    [3.6, 8.2],    # 12 elbow of the shooting arm
    [3.8, 9.3],    # 13 wrist
    [4.0, 9.8],    # 14 hand under the ball
    [3.15, 10.65], # 15 ball, left
    [4.0, 11.5],   # 16 ball, top
    [4.85, 10.65], # 17 ball, right
]

# --------------------------------------------------------------------------------------
# 2. Scorpion -> dragonfly (Figure 8b of the paper: 33 vertices), both seen from above,
#    head up.  Spine 0..8: head, three thorax points, abdomen / tail ending in the sting.
#    Per side (right: 9..20, left: 21..32):
#      +0 pedipalp / forewing root, +1..+3 with +0 the claw / forewing loop,
#      +4,+5 first leg and +6,+7 second leg (from spine vertex 2),
#      +8,+9 third leg and +10,+11 fourth leg / hind wing (from spine vertex 3).
# --------------------------------------------------------------------------------------
def scorpion_dragonfly_edges():
    edges = path_edges(list(range(9)))
    for base in (9, 21):
        edges += [[1, base]] + cycle_edges([base, base + 1, base + 2, base + 3])
        edges += path_edges([2, base + 4, base + 5]) + path_edges([2, base + 6, base + 7])
        edges += path_edges([3, base + 8, base + 9]) + path_edges([3, base + 10, base + 11])
    return edges


SCORPION = [
    [0.0, 9.8],    # 0 head
    [0.0, 9.2],    # 1 pedipalp root
    [0.0, 8.4],    # 2 legs 1, 2
    [0.0, 7.4],    # 3 legs 3, 4
    [0.0, 6.1],    # 4 end of the body
    [0.0, 5.0],    # 5 tail
    [0.35, 3.9],   # 6 tail
    [1.1, 3.2],    # 7 tail
    [1.9, 3.45],   # 8 sting
    # right side
    [2.6, 10.0],   # 9 claw wrist
    [2.35, 11.0],  # 10 claw, inner finger
    [3.0, 12.2],   # 11 claw tip
    [3.45, 10.9],  # 12 claw, outer finger
    [1.6, 9.0],    # 13 leg 1 knee
    [2.5, 8.5],    # 14 leg 1 foot
    [1.8, 8.2],    # 15 leg 2 knee
    [2.8, 7.6],    # 16 leg 2 foot
    [1.8, 7.3],    # 17 leg 3 knee
    [2.8, 6.6],    # 18 leg 3 foot
    [1.6, 6.5],    # 19 leg 4 knee
    [2.4, 5.6],    # 20 leg 4 foot
    # left side (mirror image)
    [-2.6, 10.0],
    [-2.35, 11.0],
    [-3.0, 12.2],
    [-3.45, 10.9],
    [-1.6, 9.0],
    [-2.5, 8.5],
    [-1.8, 8.2],
    [-2.8, 7.6],
    [-1.8, 7.3],
    [-2.8, 6.6],
    [-1.6, 6.5],
    [-2.4, 5.6],
]

DRAGONFLY = [
    [0.0, 10.2],   # 0 head
    [0.0, 9.4],    # 1 forewing root
    [0.0, 8.8],    # 2 legs 1, 2
    [0.0, 8.0],    # 3 leg 3, hind wing
    [0.0, 6.8],    # 4 abdomen
    [0.0, 5.4],    # 5 abdomen
    [0.0, 4.0],    # 6 abdomen
    [0.0, 2.6],    # 7 abdomen
    [0.0, 1.2],    # 8 tip of the abdomen
    # right side
    [0.5, 9.4],    # 9 forewing root
    [3.0, 10.0],   # 10 forewing leading edge
    [6.5, 9.8],    # 11 forewing tip
    [3.0, 8.9],    # 12 forewing trailing edge
    [0.8, 8.95],   # 13 leg 1 knee
    [1.2, 9.15],   # 14 leg 1 foot
    [0.8, 8.6],    # 15 leg 2 knee
    [1.25, 8.45],  # 16 leg 2 foot
    [0.8, 8.2],    # 17 leg 3 knee
    [1.3, 8.3],    # 18 leg 3 foot
    [5.9, 7.5],    # 19 hind wing tip
    [1.0, 7.15],   # 20 hind wing trailing edge, near the abdomen
    # left side (mirror image)
    [-0.5, 9.4],
    [-3.0, 10.0],
    [-6.5, 9.8],
    [-3.0, 8.9],
    [-0.8, 8.95],
    [-1.2, 9.15],
    [-0.8, 8.6],
    [-1.25, 8.45],
    [-0.8, 8.2],
    [-1.3, 8.3],
    [-5.9, 7.5],
    [-1.0, 7.15],
]

# --------------------------------------------------------------------------------------
# 3. S -> U (Figure 8c of the paper: 12 vertices), as in tests/data/paper/s_to_u.*.json.
# --------------------------------------------------------------------------------------
S_TO_U_EDGES = path_edges(list(range(12)))

LETTER_S = [[3, 5], [2, 6], [1, 6], [0, 5], [0, 4], [1, 3], [2, 3], [3, 2], [3, 1], [2, 0],
            [1, 0], [0, 1]]

LETTER_U = [[0, 6], [0, 4.5], [0, 3], [0, 1.5], [0.5, 0.5], [1.5, 0], [2.5, 0], [3.5, 0.5],
            [4, 1.5], [4, 3], [4, 4.5], [4, 6]]

# --------------------------------------------------------------------------------------
# 4. Polygon: an eight-pointed star (16 vertices, counter-clockwise, points at radius 5,
#    dents at radius 2) -> a fish facing right (nose = vertex 0, tail fin 7..9).
# --------------------------------------------------------------------------------------
POLYGON_EDGES = cycle_edges(list(range(16)))

STAR = [
    [5.0, 0.0], [1.847759065023, 0.76536686473],
    [3.535533905933, 3.535533905933], [0.76536686473, 1.847759065023],
    [0.0, 5.0], [-0.76536686473, 1.847759065023],
    [-3.535533905933, 3.535533905933], [-1.847759065023, 0.76536686473],
    [-5.0, 0.0], [-1.847759065023, -0.76536686473],
    [-3.535533905933, -3.535533905933], [-0.76536686473, -1.847759065023],
    [0.0, -5.0], [0.76536686473, -1.847759065023],
    [3.535533905933, -3.535533905933], [1.847759065023, -0.76536686473],
]

FISH = [
    [6.0, 0.0],    # 0 nose
    [5.0, 1.2],
    [3.0, 2.2],
    [0.8, 3.6],    # 3 dorsal fin
    [-1.0, 2.4],
    [-3.0, 1.5],
    [-4.5, 0.6],   # 6 tail root
    [-6.5, 2.6],   # 7 tail fin, upper lobe
    [-5.8, 0.0],   # 8 tail fin notch
    [-6.5, -2.6],  # 9 tail fin, lower lobe
    [-4.5, -0.6],  # 10 tail root
    [-3.0, -1.5],
    [-1.0, -2.2],
    [0.8, -2.9],   # 13 pelvic fin
    [3.0, -2.1],
    [5.0, -1.2],
]

# --------------------------------------------------------------------------------------
# 5. Triangulation: a regular octagon (0..7) around four interior vertices (8..11); the
#    boundary stays, the inner square turns and stretches.  14 triangles.
# --------------------------------------------------------------------------------------
TRIANGULATION_EDGES = (
    cycle_edges(list(range(8)))
    + cycle_edges([8, 9, 10, 11]) + [[8, 10]]
    + [[8, 0], [8, 1], [8, 2], [9, 2], [9, 3], [9, 4],
       [10, 4], [10, 5], [10, 6], [11, 6], [11, 7], [11, 0]]
)

OCTAGON = [
    [6.0, 0.0], [4.242640687119, 4.242640687119], [0.0, 6.0],
    [-4.242640687119, 4.242640687119], [-6.0, 0.0],
    [-4.242640687119, -4.242640687119], [0.0, -6.0],
    [4.242640687119, -4.242640687119],
]

TRIANGULATION_SOURCE = OCTAGON + [[1.5, 1.5], [-1.5, 1.5], [-1.5, -1.5], [1.5, -1.5]]

TRIANGULATION_TARGET = OCTAGON + [[0.8, 3.4], [-2.6, 0.9], [-1.2, -3.9], [3.1, -0.6]]

PAIRS = [
    ("monkey_to_player", "monkey", MONKEY, "basketball player", PLAYER, MONKEY_EDGES),
    ("scorpion_to_dragonfly", "scorpion", SCORPION, "dragonfly", DRAGONFLY,
     scorpion_dragonfly_edges()),
    ("s_to_u", "S (Figure 8c source)", LETTER_S, "U (Figure 8c target)", LETTER_U,
     S_TO_U_EDGES),
    ("polygon", "eight-pointed star", STAR, "fish", FISH, POLYGON_EDGES),
    ("triangulation", "triangulated octagon", TRIANGULATION_SOURCE,
     "triangulated octagon, interior moved", TRIANGULATION_TARGET, TRIANGULATION_EDGES),
]


# --------------------------------------------------------------------------------------
# Validation, exact.
# --------------------------------------------------------------------------------------
def orient(a, b, c):
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def on_segment(p, a, b):
    """p lies on the closed segment ab (given that p, a, b are collinear)."""
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and \
        min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def check_plane_graph(label, vertices, edges):
    """Raise ValueError unless (vertices, edges) is a connected plane straight-line graph."""
    n = len(vertices)
    for i, v in enumerate(vertices):
        if len(v) != 2 or not all(isinstance(c, (int, float)) for c in v):
            raise ValueError(f"{label}: vertex {i} is not a pair of numbers")
    pts = [(Fraction(x), Fraction(y)) for x, y in vertices]
    seen_points = {}
    for i, p in enumerate(pts):
        if p in seen_points:
            raise ValueError(f"{label}: vertices {seen_points[p]} and {i} coincide")
        seen_points[p] = i
    seen_edges = set()
    for k, (a, b) in enumerate(edges):
        if not (0 <= a < n and 0 <= b < n) or a == b:
            raise ValueError(f"{label}: edge {k} [{a}, {b}] is not an edge of {n} vertices")
        key = (min(a, b), max(a, b))
        if key in seen_edges:
            raise ValueError(f"{label}: edge {k} [{a}, {b}] is listed twice")
        seen_edges.add(key)
    # no vertex in the interior of an edge
    for k, (a, b) in enumerate(edges):
        for i, p in enumerate(pts):
            if i in (a, b):
                continue
            if orient(pts[a], pts[b], p) == 0 and on_segment(p, pts[a], pts[b]):
                raise ValueError(f"{label}: vertex {i} lies on edge {k} [{a}, {b}]")
    # no two edges without a common end point meet; two with one do not overlap
    for k in range(len(edges)):
        a, b = edges[k]
        for m in range(k + 1, len(edges)):
            c, d = edges[m]
            if len({a, b, c, d}) < 4:
                continue  # sharing an end point: overlap is caught by the vertex test
            o1 = orient(pts[a], pts[b], pts[c])
            o2 = orient(pts[a], pts[b], pts[d])
            o3 = orient(pts[c], pts[d], pts[a])
            o4 = orient(pts[c], pts[d], pts[b])
            if o1 * o2 < 0 and o3 * o4 < 0:
                raise ValueError(f"{label}: edges {k} [{a}, {b}] and {m} [{c}, {d}] cross")
    # connected
    adjacency = [[] for _ in range(n)]
    for a, b in edges:
        adjacency[a].append(b)
        adjacency[b].append(a)
    reached, stack = {0}, [0]
    while stack:
        for w in adjacency[stack.pop()]:
            if w not in reached:
                reached.add(w)
                stack.append(w)
    if len(reached) != n:
        missing = sorted(set(range(n)) - reached)
        raise ValueError(f"{label}: not connected (vertex {missing[0]} is cut off)")


def figure_json(name, vertices, edges):
    return json.dumps({"name": name, "vertices": vertices, "edges": edges}) + "\n"


def main(argv=None):
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output-dir", default=os.path.join(here, "figures"),
                        help="where to write <pair>.source.json and <pair>.target.json "
                             "(default: blend_samples/figures next to this script)")
    args = parser.parse_args(argv)

    outputs = []
    for pair, src_name, src, dst_name, dst, edges in PAIRS:
        if len(src) != len(dst):
            raise ValueError(f"{pair}: {len(src)} source vertices but {len(dst)} target ones")
        check_plane_graph(f"{pair} source", src, edges)
        check_plane_graph(f"{pair} target", dst, edges)
        outputs.append((f"{pair}.source.json", figure_json(src_name, src, edges)))
        outputs.append((f"{pair}.target.json", figure_json(dst_name, dst, edges)))

    os.makedirs(args.output_dir, exist_ok=True)
    for filename, text in outputs:
        with open(os.path.join(args.output_dir, filename), "w", encoding="utf-8") as f:
            f.write(text)
    for pair, _, src, _, _, edges in PAIRS:
        print(f"{pair}: {len(src)} vertices, {len(edges)} edges")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except ValueError as error:
        print(f"error: {error}", file=sys.stderr)
        sys.exit(1)
