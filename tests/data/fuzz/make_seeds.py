#!/usr/bin/env python3
"""Regenerates the seed corpora of the libFuzzer targets (native/fuzz).

figure_reader/  copies of the small stick figure files of tests/data (valid
                pairs, the paper's S and U, regressions, malformed inputs).
morph_pair/     pair documents {"source": ..., "target": ...} made from the
                pairs of tests/data (compatible and incompatible), one per
                Steiner method for the smallest ones, plus inputs in the
                target's binary encoding (see fuzz_morph_pair.cpp) for a few
                small grid figures with moved targets.

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


if __name__ == "__main__":
    write_figure_reader_seeds()
    write_morph_pair_seeds()
