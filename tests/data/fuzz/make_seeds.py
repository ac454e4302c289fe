#!/usr/bin/env python3
"""Regenerates the seed corpora of the libFuzzer targets (native/fuzz).

figure_reader/  copies of the small stick figure files of tests/data (valid
                pairs, the paper's S and U, regressions, malformed inputs).
morph_pair/     pair documents {"source": ..., "target": ...} made from the
                pairs of tests/data (compatible and incompatible), one per
                Steiner method for the smallest ones, plus inputs in the
                target's binary encoding (see fuzz_morph_pair.cpp) for a few
                small grid figures with moved targets.
correspond_pair/
                pair documents {"source": ..., "target": ..., "pins"?: ...}
                for fuzz_correspond_pair.cpp: the pairs of tests/data as
                they are, with the target redrawn (subdivided, renumbered,
                its edges reordered, turned and moved), pinned (well, in
                contradiction, or with ill-formed pins), mirrored or against
                a figure of another topology (unmatchable), plus inputs in
                the target's binary encoding for a few small grid figures.

Only files up to MAX_SEED_BYTES are used: the fuzz scripts run with
-max_len=MAX_SEED_BYTES, and longer seeds would be cut. Running the script
again rewrites the same files. Regression inputs found by fuzzing live in
regressions/ and are kept by hand, not generated.

Usage: /usr/bin/python3 tests/data/fuzz/make_seeds.py
"""

import glob
import json
import os
import shutil
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.dirname(HERE)
MAX_SEED_BYTES = 4096


def pair_files():
    """(name, source path, target path) for every pair under tests/data."""
    pairs = []
    for folder in ("pairs/compatible", "pairs/incompatible", "paper", "regressions", "polygon_pairs"):
        for source in sorted(glob.glob(os.path.join(DATA, folder, "*.source.json"))):
            target = source[: -len(".source.json")] + ".target.json"
            name = folder.replace("/", "_") + "_" + os.path.basename(source)[: -len(".source.json")]
            pairs.append((name, source, target))
    return pairs


def reset(folder):
    path = os.path.join(HERE, folder)
    if os.path.isdir(path):
        shutil.rmtree(path)
    os.makedirs(path)
    return path


def write_figure_reader_seeds():
    out = reset("figure_reader")
    inputs = [p for _, s, t in pair_files() for p in (s, t)]
    inputs += sorted(glob.glob(os.path.join(DATA, "malformed", "*")))
    for path in inputs:
        if os.path.getsize(path) > MAX_SEED_BYTES:
            continue
        name = os.path.relpath(path, DATA).replace("/", "_")
        shutil.copyfile(path, os.path.join(out, name))


def compact(document):
    return json.dumps(document, separators=(",", ":")).encode()


def binary_pair(flags, exponent, sides, source, tree_parents, extra_edges, moves):
    """The binary encoding of fuzz_morph_pair.cpp; values are taken modulo
    as the decoder does, so the bytes decode to exactly these figures."""
    n = len(source)
    data = bytes([flags, n - 1, exponent + 128, sides - 3])
    data += b"".join(struct.pack("bb", x, y) for x, y in source)
    assert len(tree_parents) == n - 1 and all(p < i for i, p in enumerate(tree_parents, 1))
    data += bytes(tree_parents)
    data += bytes([len(extra_edges)]) + b"".join(bytes(e) for e in extra_edges)
    data += b"".join(struct.pack("bb", dx, dy) for dx, dy in moves)
    return data


def write_morph_pair_seeds():
    out = reset("morph_pair")
    for name, source_path, target_path in pair_files():
        with open(source_path) as f:
            source = json.load(f)
        with open(target_path) as f:
            target = json.load(f)
        document = compact({"source": source, "target": target})
        if len(document) > MAX_SEED_BYTES:
            continue
        with open(os.path.join(out, name + ".json"), "wb") as f:
            f.write(document)
        if len(source["vertices"]) <= 12:
            for method in ("aronov", "sg2001"):
                for weights in ("uniform", "floater"):
                    with open(os.path.join(out, f"{name}.{method}.{weights}.json"), "wb") as f:
                        f.write(compact({"source": source, "target": target,
                                         "steiner": method, "weights": weights}))

    # Binary seeds: flags bits 0-1 method (0 improved, 1 sg2001, 2 aronov),
    # bits 2-3 weights (0 mvc, 1 uniform, 2 floater), bits 4-5 frames - 2.
    square = [(0, 0), (16, 0), (16, 16), (0, 16)]
    square_moves = [(0, 0), (40, 8), (-8, 40), (0, 0)]
    zigzag = [(0, 0), (10, 20), (20, 0), (30, 20), (40, 0), (50, 20)]
    zigzag_moves = [(0, 0), (60, -100), (0, 0), (60, -100), (0, 0), (60, -100)]
    star = [(0, 0), (20, 0), (0, 20), (-20, 0), (0, -20), (14, 14)]
    star_moves = [(0, 0), (0, 60), (-60, 0), (0, -60), (60, 0), (-30, 30)]
    seeds = {
        "square_diagonal": (square, [0, 1, 2], [(3, 0), (0, 2)], square_moves),
        "zigzag_polyline": (zigzag, [0, 1, 2, 3, 4], [], zigzag_moves),
        "star_tree": (star, [0, 0, 0, 0, 0], [], star_moves),
        "single_edge": ([(0, 0), (5, 3)], [0], [], [(0, 0), (-90, 90)]),
        "single_vertex": ([(7, -3)], [], [], [(10, 10)]),
    }
    for name, (source, parents, extra, moves) in seeds.items():
        for method in range(3):
            for weights in range(3):
                flags = method | (weights << 2) | (1 << 4) | ((method & 1) << 6)
                data = binary_pair(flags, 0, 6 if method == 0 else 3 + 2 * method, source,
                                   parents, extra, moves)
                with open(os.path.join(out, f"grid_{name}.m{method}w{weights}.bin"), "wb") as f:
                    f.write(data)
    # Far from the unit scale both ways.
    for exponent in (-100, 90):
        data = binary_pair(0, exponent, 6, square, [0, 1, 2], [(3, 0), (0, 2)], square_moves)
        with open(os.path.join(out, f"grid_square_diagonal.scale{exponent}.bin"), "wb") as f:
            f.write(data)


def degrees(figure):
    degree = [0] * len(figure["vertices"])
    for a, b in figure["edges"]:
        degree[a] += 1
        degree[b] += 1
    return degree


def redraw(figure, mirror=False):
    """A second drawing of `figure`, as a user who drew it again would make
    it: every other edge subdivided (at a third of its length), the vertices
    renumbered (reversed and rotated), the edges in reverse order and
    direction, and the whole turned a quarter, doubled and moved; `mirror`
    reflects it too. The quarter turn and the doubling are exact in binary
    floating point, so the redrawn figure is as valid as the original
    unless the move's rounding closes a near touch. Returns the figure and
    each original vertex's index in it."""
    vertices = [list(p) for p in figure["vertices"]]
    edges = [list(e) for e in figure["edges"]]
    for i in range(0, len(figure["edges"]), 2):
        a, b = edges[i]
        pa, pb = vertices[a], vertices[b]
        vertices.append([pa[0] + (pb[0] - pa[0]) / 3, pa[1] + (pb[1] - pa[1]) / 3])
        edges[i] = [a, len(vertices) - 1]
        edges.append([len(vertices) - 1, b])
    m = len(vertices)
    image = [(m - 1 - v + m // 3) % m for v in range(m)]
    moved = [None] * m
    for v, (x, y) in enumerate(vertices):
        if mirror:
            x = -x
        moved[image[v]] = [-2 * y + 10, 2 * x - 5]
    redrawn = {"name": figure.get("name", "") + " redrawn",
               "vertices": moved,
               "edges": [[image[b], image[a]] for a, b in reversed(edges)]}
    return redrawn, image[: len(figure["vertices"])]


def write_pair(out, name, source, target, pins=None):
    document = {"source": source, "target": target}
    if pins is not None:
        document["pins"] = pins
    data = compact(document)
    if len(data) <= MAX_SEED_BYTES:
        with open(os.path.join(out, name + ".json"), "wb") as f:
            f.write(data)


def binary_correspond(flags, exponent, source, target, pins=()):
    """The binary encoding of fuzz_correspond_pair.cpp. `source` is a grid
    figure (points, tree parents, extra edges); `target` is another grid
    figure (then flags bit 0 must be set) or a dict of the redrawing's
    bytes: subdivisions [(edge, fraction)], perm (m - 1 renumbering bytes), shift,
    moves [(dx, dy)], similarity (angle, scale, tx, ty). Bytes the dict
    leaves out are written as zeros, which the decoder would read anyway;
    perm and moves are cut or padded to the subdivided vertex count, so
    that one dict serves figures of every size."""
    def grid(points, parents, extra):
        assert len(parents) == len(points) - 1 and all(p < i for i, p in enumerate(parents, 1))
        data = bytes([len(points) - 1]) + b"".join(struct.pack("bb", x, y) for x, y in points)
        return data + bytes(parents) + bytes([len(extra)]) + b"".join(bytes(e) for e in extra)

    assert len(pins) <= 2
    flags |= len(pins) << 4
    data = bytes([flags, exponent + 128]) + grid(*source)
    if flags & 1:
        data += grid(*target)
    else:
        subdivisions = target.get("subdivisions", [])
        m = len(source[0]) + (len(subdivisions) if source[1] else 0)
        data += bytes([len(subdivisions)]) + b"".join(bytes(s) for s in subdivisions)
        perm = target.get("perm", [])
        data += bytes((perm + [0] * m)[: m - 1])
        data += bytes([target.get("shift", 0)])
        moves = target.get("moves", [])
        moves = (moves + [(0, 0)] * m)[:m]
        data += b"".join(struct.pack("bb", dx, dy) for dx, dy in moves)
        angle, scale, tx, ty = target.get("similarity", (0, 32, 0, 0))
        data += struct.pack("BBbb", angle, scale, tx, ty)
    return data + b"".join(bytes(p) for p in pins)


def write_correspond_pair_seeds():
    out = reset("correspond_pair")
    for name, source_path, target_path in pair_files():
        with open(source_path) as f:
            source = json.load(f)
        with open(target_path) as f:
            target = json.load(f)
        write_pair(out, name, source, target)
        redrawn, image = redraw(target)
        write_pair(out, name + ".redrawn", source, redrawn)
        if not name.startswith(("pairs_compatible", "paper")):
            continue
        # The compatible pairs: pinned well (a node and a vertex inside a
        # stroke to their own images), pinned against the geometry (a node
        # to the image of another node of its degree, which only a symmetry
        # satisfies), and mirrored (refused unless the figure is symmetric).
        degree = degrees(source)
        node = next((v for v, d in enumerate(degree) if d != 2), None)
        inner = next((v for v, d in enumerate(degree) if d == 2), None)
        good = [[v, image[v]] for v in (node, inner) if v is not None]
        write_pair(out, name + ".redrawn.pinned", source, redrawn, good)
        if node is not None:
            other = next((v for v, d in enumerate(degree) if v != node and d == degree[node]), None)
            if other is not None:
                write_pair(out, name + ".redrawn.crossed_pin", source, redrawn, [[node, image[other]]])
        mirrored, _ = redraw(target, mirror=True)
        write_pair(out, name + ".mirrored", source, mirrored)

    # Ill-formed pins (InvalidArgumentError): out of range on either side,
    # one vertex pinned twice, a junction pinned to an end, a junction to a
    # vertex inside a stroke; and pins that are not whole numbers in int
    # range (refused by the target's reader).
    with open(os.path.join(DATA, "pairs", "compatible", "letter_a.source.json")) as f:
        letter_a = json.load(f)
    redrawn_a, image_a = redraw(letter_a)
    n_a = len(letter_a["vertices"])
    for pin_name, pins in {
        "source_out_of_range": [[n_a, 0]],
        "negative": [[-1, 0]],
        "target_out_of_range": [[0, len(redrawn_a["vertices"])]],
        "twice": [[1, image_a[1]], [1, image_a[2]]],
        "junction_to_end": [[1, image_a[3]]],
        "junction_to_inner": [[1, len(redrawn_a["vertices"]) - 1]],
        "fractional": [[0.5, 0]],
        "huge": [[1e10, 0]],
    }.items():
        write_pair(out, "letter_a.bad_pin_" + pin_name, letter_a, redrawn_a, pins)
    # Unmatchable by topology: a loop against a tree, a wheel against a
    # square, the letter A against its outline.
    def load(folder, name, side):
        with open(os.path.join(DATA, folder, f"{name}.{side}.json")) as f:
            return json.load(f)
    polygon = load("pairs/compatible", "polygon", "source")
    polyline = load("pairs/compatible", "polyline", "source")
    wheel = load("pairs/compatible", "wheel", "source")
    spikes = load("pairs/compatible", "square_with_spikes", "source")
    tree = load("pairs/compatible", "tree_junction", "source")
    write_pair(out, "unmatchable.loop_vs_polyline", polygon, redraw(polyline)[0])
    write_pair(out, "unmatchable.wheel_vs_polygon", wheel, redraw(polygon)[0])
    write_pair(out, "unmatchable.spikes_vs_tree", spikes, redraw(tree)[0])
    write_pair(out, "unmatchable.letter_a_vs_polygon", letter_a, polygon)

    # Binary seeds. Flags: bit 0 independent target, bit 1 edges reversed in
    # order, bit 2 in direction, bit 3 mirrored; pins come from the list.
    square = ([(0, 0), (16, 0), (16, 16), (0, 16)], [0, 1, 2], [(3, 0), (0, 2)])
    spiked_square = ([(0, 0), (16, 0), (16, 16), (0, 16), (24, 24), (-6, 2)], [0, 1, 2, 2, 3], [(3, 0)])
    zigzag = ([(0, 0), (10, 20), (20, 0), (30, 20), (40, 0), (50, 20)], [0, 1, 2, 3, 4], [])
    star = ([(0, 0), (20, 0), (0, 20), (-20, 0), (0, -20), (14, 14)], [0, 0, 0, 0, 0], [])
    triangle = ([(0, 0), (30, 0), (0, 20)], [0, 1], [(2, 0)])
    pentagon = ([(0, 20), (19, 6), (12, -16), (-12, -16), (-19, 6)], [0, 1, 2, 3], [(4, 0)])
    single_edge = ([(0, 0), (5, 3)], [0], [])
    single_vertex = ([(7, -3)], [], [])
    redrawn = {"subdivisions": [(0, 127), (3, 63), (5, 200)], "perm": [0, 3, 1, 4, 1, 5, 2, 6, 3],
               "shift": 2, "moves": [(3, -2), (-4, 1), (0, 5), (2, 2), (-3, 0), (1, -1)],
               "similarity": (32, 40, 5, -3)}
    plain = {"similarity": (0, 32, 0, 0)}
    # Subdivided, renumbered, turned and moved as a whole, no vertex moved:
    # the target's oracle then requires a match with these pins.
    faithful = {**redrawn, "moves": []}
    seeds = {
        "square_diagonal.redrawn.pinned": (0b110, square, redrawn, [(0, 0x80), (1, 0x80)]),
        "square_diagonal.renumbered": (0, square, {"perm": [1, 2, 3], "similarity": (64, 48, -7, 9)}, []),
        "square_diagonal.mirrored": (0b1000, square, redrawn, []),
        "square_diagonal.faithful.pinned": (0b010, square, faithful, [(0, 0x80), (1, 0x80)]),
        "spiked_square.faithful.pinned": (0b100, spiked_square, faithful, [(4, 0x80), (5, 0x80)]),
        "star.faithful.pinned": (0, star, faithful, [(0, 0x80), (3, 0x80)]),
        "zigzag.faithful.pinned": (0b110, zigzag, faithful, [(2, 0x80), (5, 0x80)]),
        "spiked_square.redrawn": (0b010, spiked_square, redrawn, []),
        "spiked_square.mirrored": (0b1100, spiked_square, redrawn, []),
        "zigzag.redrawn": (0b100, zigzag, redrawn, [(2, 0x80)]),
        "zigzag.reversed_pin": (0, zigzag, plain, [(0, 5)]),
        "star.redrawn": (0b110, star, redrawn, []),
        "star.bad_pins": (0, star, redrawn, [(6, 0), (0, 1)]),
        "triangle.redrawn": (0, triangle, {**redrawn, "similarity": (128, 20, 0, 0)}, [(1, 0x80)]),
        "triangle_vs_pentagon": (1, triangle, pentagon, []),
        "triangle_vs_pentagon.pinned": (1, triangle, pentagon, [(0, 0), (1, 2)]),
        "square_vs_pentagon": (1, square, pentagon, []),
        "star_vs_zigzag": (1, star, zigzag, []),
        "single_edge.redrawn": (0, single_edge, redrawn, [(0, 0x80)]),
        "single_vertex": (0, single_vertex, redrawn, [(0, 0x80)]),
    }
    for name, (flags, source, target, pins) in seeds.items():
        with open(os.path.join(out, f"grid_{name}.bin"), "wb") as f:
            f.write(binary_correspond(flags, 0, source, target, pins))
    # Far from the unit scale both ways.
    for exponent in (-100, 90):
        with open(os.path.join(out, f"grid_square_diagonal.scale{exponent}.bin"), "wb") as f:
            f.write(binary_correspond(0, exponent, square, redrawn, [(0, 0x80)]))


if __name__ == "__main__":
    write_figure_reader_seeds()
    write_morph_pair_seeds()
    write_correspond_pair_seeds()
