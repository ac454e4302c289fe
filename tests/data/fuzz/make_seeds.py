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


def parts_stream(exponent, offset, renumber, groups, target_turn=0, target_scale=32, target_shift=(0, 0)):
    """decode_parts_pair's bytes (native/fuzz/fuzz_common.h) and the vertex
    count they decode to. A group is a dict: rings (list of dicts: sides,
    gap, phase, pull, collinear, turn, wobble, items: (kind, angle, span,
    turn, wobble) tuples), core (None, ("dots", [(x, y, turn, wobble)]) or
    ("tree", points, parents, extra, turn, wobble)), scale, gap, shift."""
    def s8(v):
        return v & 0xFF
    data = bytes([exponent + 128, s8(offset[0]), s8(offset[1]), renumber, len(groups) - 1])
    count = 0
    for g in groups:
        data += bytes([len(g["rings"]), g.get("scale", 0), g.get("gap", 64), s8(g.get("shift", 0))])
        core = g.get("core")
        if core is None:
            data += bytes([0])
        elif core[0] == "dots":
            dots = core[1]
            data += bytes([1]) if len(dots) == 1 else bytes([2, len(dots) - 1])
            for x, y, turn, wobble in dots:
                data += bytes([s8(x), s8(y), s8(turn), wobble])
            count += len(dots)
        else:
            _, points, parents, extra, turn, wobble = core
            data += bytes([3, len(points) - 2]) + b"".join(bytes([s8(x), s8(y)]) for x, y in points)
            data += bytes(parents) + bytes([len(extra)]) + b"".join(bytes(e) for e in extra)
            data += bytes([s8(turn), wobble])
            count += len(points)
        for r in g["rings"]:
            data += bytes([r["sides"] - 3, r.get("gap", 64), r.get("phase", 0), r.get("pull", 0),
                           r.get("collinear", 0), s8(r.get("turn", 0)), r.get("wobble", 0), len(r.get("items", ()))])
            for kind, angle, span, turn, wobble in r.get("items", ()):
                data += bytes([kind, angle, span, s8(turn), wobble])
                count += 1 if kind % 4 in (0, 3) else 3 if kind % 4 == 2 else 2 + (kind // 4) % 5
            count += r["sides"] + sum((r.get("collinear", 0) >> (j % 8)) & 1 for j in range(r["sides"]))
        if not g["rings"] and core is None:
            count += 1
    data += bytes([target_turn, target_scale, s8(target_shift[0]), s8(target_shift[1])])
    return data, count


def parts_seed_figures():
    """(name, parts stream, vertex count): figures of several parts."""
    bullseye = [{"core": ("dots", [(0, 0, 90, 0)]), "rings": [
        {"sides": 8, "gap": 40, "turn": 127, "items": [(0, 10, 0, -60, 0)]},
        {"sides": 10, "gap": 60, "phase": 30, "turn": -100, "items": [(1 + 4 * 2, 50, 200, 40, 20)]},
        {"sides": 12, "gap": 80, "turn": 64, "items": [(2, 200, 128, -128, 10), (3, 90, 0, 50, 0)]}]}]
    deep = [{"core": ("tree", [(0, 0), (60, 0), (-40, 50), (-40, -50)], [0, 0, 0], [], 100, 30), "rings": [
        {"sides": 3, "gap": 10, "collinear": 0b101, "turn": 127},
        {"sides": 5, "gap": 5, "pull": 20, "turn": -127, "wobble": 40},
        {"sides": 4, "gap": 25, "collinear": 0b1111, "turn": 60},
        {"sides": 7, "gap": 2, "turn": -30, "items": [(0, 0, 0, 127, 0)]}]}]
    side_by_side = [
        {"scale": 0, "core": ("dots", [(0, 0, 0, 0)]), "rings": [{"sides": 6, "gap": 30, "turn": 100}]},
        {"scale": 13, "gap": 2, "shift": 40, "core": ("dots", [(40, 0, 10, 0), (-40, 0, -10, 0)]),
         "rings": [{"sides": 9, "gap": 50, "turn": -80, "items": [(1 + 4 * 4, 0, 255, 30, 0)]}]},
        {"scale": 2, "gap": 0, "shift": -100, "rings": [], "core": None},
        {"scale": 7, "gap": 1, "shift": 90, "rings": [{"sides": 3, "gap": 200, "turn": 127}, {"sides": 4, "gap": 3}]}]
    strokes = [{"rings": [
        {"sides": 11, "gap": 255, "items": [(1 + 4 * 3, 0, 90, 40, 0), (1 + 4 * 1, 128, 255, -90, 100), (2, 64, 10, 127, 0)]},
        {"sides": 6, "gap": 200, "pull": 31, "turn": 90,
         "items": [(1, 10, 30, 0, 0), (1 + 4 * 4, 100, 60, 127, 50), (0, 0, 0, 3, 0)]}]}]
    return [
        ("bullseye", *parts_stream(0, (0, 0), 0, bullseye, target_turn=32)),
        ("deep_rings_tree", *parts_stream(-20, (0, 0), 0, deep, target_scale=40)),
        ("groups_tiny_beside_huge_far", *parts_stream(10, (100, -77), 0, side_by_side, target_turn=200, target_shift=(5, 9))),
        ("strokes_in_annuli", *parts_stream(0, (0, 0), 0, strokes)),
        ("bullseye_renumbered", *parts_stream(3, (-128, 127), 77, bullseye, target_turn=128, target_scale=0)),
        ("groups_renumbered", *parts_stream(-50, (1, 1), 201, side_by_side)),
    ]


def write_parts_seeds():
    """Binary seeds of the parts encodings (bit 7 of byte 0) of both pair
    targets, added to morph_pair/ and correspond_pair/ as parts_*.bin."""
    morph = os.path.join(HERE, "morph_pair")
    correspond = os.path.join(HERE, "correspond_pair")
    for name, stream, n in parts_seed_figures():
        # fuzz_morph_pair: byte 0 options | 0x80, byte 1 enclosure sides - 3.
        for suffix, flags in (("", 0x80 | (1 << 4)), (".reversed_edges", 0x80 | (1 << 6)),
                              (".sg2001_uniform", 0x80 | 1 | (1 << 2))):
            if flags & 3 and n > 24:
                continue
            with open(os.path.join(morph, f"parts_{name}{suffix}.bin"), "wb") as f:
                f.write(bytes([flags, 3]) + stream)
        if n > 64:
            continue
        # fuzz_correspond_pair: byte 0 flags | 0x80, byte 1 exponent (of the
        # redrawing's moves and shift: the parts' unit), then the redrawing: no subdivision, the
        # numbering reversed, no moves, a turn; one pin to its own image.
        redraw_bytes = bytes([0]) + bytes([1] * (n - 1)) + bytes([3]) + bytes(2 * n) + bytes([40, 40, 3, 250])
        faithful = bytes([0x80 | (1 << 4), stream[0]]) + stream + redraw_bytes + bytes([0, 0x80])
        with open(os.path.join(correspond, f"parts_{name}.faithful.pinned.bin"), "wb") as f:
            f.write(faithful)
        subdivided = bytes([0x80 | (1 << 6) | 2, stream[0]]) + stream + bytes([3, 0, 100, 1, 50, 2, 200]) + bytes([5] * n)
        with open(os.path.join(correspond, f"parts_{name}.deformed_redrawn.bin"), "wb") as f:
            f.write(subdivided)
    _, a, _ = parts_seed_figures()[0]
    _, b, _ = parts_seed_figures()[3]
    with open(os.path.join(correspond, "parts_bullseye_vs_strokes.independent.bin"), "wb") as f:
        f.write(bytes([0x81, 128]) + a[:-4] + bytes(4) + b)


if __name__ == "__main__":
    write_figure_reader_seeds()
    write_morph_pair_seeds()
    write_correspond_pair_seeds()
    write_parts_seeds()
