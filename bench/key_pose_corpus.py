#!/usr/bin/env python3
"""Generate a corpus of key-pose sequences: K >= 3 poses of one stick figure (issue 28).

Issue 28 asks for one continuous, valid motion through a sequence of key poses, judged by
how smooth the motion is at the interior keys. This writes the sequences it is measured on
(bench/sequence_motion.py), as an animator would pose them: the same figure, vertex for
vertex, in K poses.

    /usr/bin/python3 bench/key_pose_corpus.py OUT_DIR [--seed N] [--build-dir build]
                     [--per-kind N] [--redrawn]

Kinds:
  cycle      a skeleton (a humanoid figure, a quadruped, a spider) whose joint angles follow one smooth
             periodic motion (a walk or a wave: every joint a sine of its own phase, swinging
             up to twice motion_corpus's pose range) sampled at K keys, the root turning up to
             120 degrees and moving along an arc: the motion passes through most interior
             keys, so a smooth morph must not stop there
  poses      a skeleton in K independent random poses, as a pose-to-pose animator sets them:
             the motion turns back at some keys
  glyph      a hand-written letter (bench/motion_corpus.py's glyphs) bent K times, moving
             along an arc and turning

Files: NAME.key1.json ... NAME.keyK.json (the docs/FORMAT.md figure format, the same
vertices and edges in every key), and manifest.json: [{"name", "kind", "keys": [file...],
"vertices", "edges"}]. Every key is checked against key 1 with `stickmorph check` (the keys
of a sequence must be compatible with each other); a sequence that is not is drawn again
with gentler poses, and dropped (and counted) if it never is. Deterministic for a seed.
"""
import argparse
import json
import math
import pathlib
import random
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import motion_corpus as mc  # noqa: E402  (the figures: skeletons and glyphs)

MAX_ATTEMPTS = 8

# motion_corpus's humanoid hangs its arms beside the hips, where a swinging arm soon crosses
# a leg; an animator's figure in a walk or a wave holds them away from the body: the same
# bones with the upper arms raised to 110 degrees from the spine (and the forearms bent
# outwards), which leaves them room to swing.
RAISED_ARMS = {"uarm_l": 110, "farm_l": 20, "uarm_r": -110, "farm_r": -20}
mc.SKELETONS["figure"] = ([(name, parent, length, RAISED_ARMS.get(name, rest), pieces, swing)
                           for name, parent, length, rest, pieces, swing in mc.HUMANOID], "head")


class PhaseAngles:
    """Stands in for the random generator motion_corpus.skeleton draws joint offsets from:
    the i-th joint gets the offset at phase `phase` of a sine with its own phase shift, so
    that every joint moves smoothly and periodically as the phase advances."""

    def __init__(self, phase, shifts):
        self.phase, self.shifts, self.joint = phase, shifts, 0

    def uniform(self, low, high):
        shift = self.shifts[self.joint % len(self.shifts)]
        self.joint += 1
        return (low + high) / 2 + (high - low) / 2 * math.sin(self.phase + shift)


def cycle_sequence(kind, rng, keys, gentle):
    """A periodic motion of the skeleton sampled at `keys` phases (not a whole period, so the
    keys differ), every joint swinging up to twice its pose range of motion_corpus, the root
    turning by up to 120 degrees in all and moving along an arc."""
    shifts = [rng.uniform(0, 2 * math.pi) for _ in range(64)]
    span = rng.uniform(0.6, 0.9) * 2 * math.pi  # of the period the keys cover
    turn = rng.uniform(-120, 120) * gentle
    figures = []
    for k in range(keys):
        s = k / (keys - 1)
        points, edges = mc.skeleton(kind, PhaseAngles(s * span, shifts), 2.0 * gentle, turn * s,
                                    1.0 + 0.1 * gentle * math.sin(math.pi * s),
                                    (0.8 * s, 0.25 * gentle * math.sin(math.pi * s)))
        figures.append((points, edges))
    return figures, {"turn_deg": round(turn, 1)}


def pose_sequence(kind, rng, keys, gentle):
    """K independent random poses (joints up to 1.5 times motion_corpus's pose range), the
    root turned up to 90 degrees, scaled and moved each time."""
    figures = []
    for k in range(keys):
        figures.append(mc.skeleton(kind, random.Random(rng.getrandbits(32)), 1.5 * gentle,
                                   rng.uniform(-90, 90) * gentle * (k > 0), rng.uniform(0.85, 1.15) if k else 1.0,
                                   (rng.uniform(-0.5, 0.5) * (k > 0), rng.uniform(-0.3, 0.3) * (k > 0))))
    return figures, {}


def glyph_sequence(letter, rng, keys, gentle):
    """The same letter bent differently at each key (motion_corpus.glyph with its own seed and
    the same sampling), moving along an arc and turning up to 60 degrees in all."""
    spacing = rng.uniform(0.05, 0.09)
    seeds = [rng.getrandbits(32) for _ in range(keys)]
    turn = rng.uniform(-60, 60) * gentle
    figures = []
    for k, seed in enumerate(seeds):
        s = k / (keys - 1)
        points, edges = mc.glyph(letter, random.Random(seed), spacing, jitter=0.004 * gentle,
                                 bend=0.08 * gentle, move=0.06 * gentle, angle=turn * s,
                                 scale=1.0 + 0.2 * gentle * math.sin(math.pi * s))
        points = points + np.array([1.2 * s, 0.4 * math.sin(math.pi * s)])
        figures.append((points, edges))
    return figures, {"letter": letter, "turn_deg": round(turn, 1)}


def redrawn(points, edges, rng):
    """The key as drawn on its own, for `--correspond auto`: about a third of its edges split
    into 2 to 4 pieces (points evenly along the edge, so the drawing is the same), the
    vertices numbered in a random order and the edges listed in another."""
    points = [tuple(p) for p in points]
    pieces = []
    for a, b in edges:
        cut = rng.randint(2, 4) if rng.random() < 0.35 else 1
        chain = [a]
        for j in range(1, cut):
            f = j / cut
            points.append((points[a][0] + f * (points[b][0] - points[a][0]),
                           points[a][1] + f * (points[b][1] - points[a][1])))
            chain.append(len(points) - 1)
        chain.append(b)
        pieces += list(zip(chain, chain[1:]))
    order = list(range(len(points)))
    rng.shuffle(order)  # order[new] = old
    new_of = {old: new for new, old in enumerate(order)}
    rng.shuffle(pieces)
    return [points[old] for old in order], [[new_of[a], new_of[b]] for a, b in pieces]


def compatible_with_first(cli, paths):
    """Index of the first key that `stickmorph check` finds incompatible with key 1, or None."""
    for k, path in enumerate(paths[1:], start=1):
        r = subprocess.run([str(cli), "check", str(paths[0]), str(path)], capture_output=True, text=True,
                           timeout=120)
        if r.returncode != 0:
            return k
    return None


def same_graph(figures):
    edges = figures[0][1]
    return all(len(p) == len(figures[0][0]) and e == edges for p, e in figures)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", type=pathlib.Path)
    ap.add_argument("--seed", type=int, default=28)
    ap.add_argument("--build-dir", type=pathlib.Path, default=mc.REPO / "build")
    ap.add_argument("--per-kind", type=int, default=4, help="sequences per kind and figure (default 4)")
    ap.add_argument("--redrawn", action="store_true",
                    help="also write every key drawn on its own (NAME.drawnK.json: edges split, vertices and "
                         "edges renumbered), listed as the entry's \"drawn\", for --correspond auto")
    args = ap.parse_args(argv)
    cli = args.build_dir / "stickmorph"
    if not cli.exists():
        print(f"error: {cli} does not exist (build stickmorph first)", file=sys.stderr)
        return 2
    rng = random.Random(args.seed)
    makers = [("cycle", kind, cycle_sequence) for kind in ("figure", "quadruped", "spider")]
    makers += [("poses", kind, pose_sequence) for kind in ("figure", "quadruped", "spider")]
    makers += [("glyph", letter, glyph_sequence) for letter in ("A", "K", "R", "S", "Y")]
    args.out.mkdir(parents=True, exist_ok=True)
    manifest, dropped = [], []
    with tempfile.TemporaryDirectory(prefix="key_pose_corpus_") as tmp:
        for kind, figure, make in makers:
            for i in range(args.per_kind):
                keys = 3 + (i % 4)  # 3 to 6 keys
                name = f"{kind}_{figure}_{i:02d}_{keys}keys"
                seed = rng.getrandbits(32)
                for attempt in range(MAX_ATTEMPTS):
                    gentle = 0.8 ** attempt
                    figures, tags = make(figure, random.Random(seed), keys, gentle)
                    if not same_graph(figures):
                        raise RuntimeError(f"{name}: the keys are not one graph")
                    paths = [pathlib.Path(tmp) / f"key{k + 1}.json" for k in range(keys)]
                    for k, (points, edges) in enumerate(figures):
                        mc.write_figure(paths[k], f"{name} key {k + 1}", points, edges)
                    if compatible_with_first(cli, paths) is None:
                        break
                else:
                    dropped.append(name)
                    continue
                files = []
                for k, (points, edges) in enumerate(figures):
                    files.append(f"{name}.key{k + 1}.json")
                    mc.write_figure(args.out / files[-1], f"{name} key {k + 1}", points, edges)
                drawn = []
                if args.redrawn:
                    redraw_rng = random.Random(seed ^ 0x5eed)
                    for k, (points, edges) in enumerate(figures):
                        drawn.append(f"{name}.drawn{k + 1}.json")
                        mc.write_figure(args.out / drawn[-1], f"{name} key {k + 1} drawn",
                                        *redrawn(points, edges, redraw_rng))
                manifest.append({"name": name, "kind": kind, "figure": figure, "keys": files,
                                 **({"drawn": drawn} if drawn else {}),
                                 "vertices": len(figures[0][0]), "edges": len(figures[0][1]),
                                 "gentle": round(gentle, 3), **tags})
    (args.out / "manifest.json").write_text(json.dumps(manifest, indent=1) + "\n")
    print(f"{len(manifest)} sequences in {args.out}" + (f"; dropped (never compatible): {dropped}" if dropped else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
