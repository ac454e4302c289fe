#!/usr/bin/env python3
"""Check `stickmorph` on figures of several parts, with exact geometry of its own.

    /usr/bin/python3 bench/multipart_check.py CORPUS_DIR --stickmorph build/stickmorph \
        [--frames N] [--method M] [--timeout S] [--json REPORT] [--keep DIR] [--only NAME ...]

CORPUS_DIR holds manifest.json and the figure files that bench/multipart_corpus.py writes.
A *part* of a figure is one of its connected components (an isolated vertex is a part of its
own); parts are numbered 0, 1, 2, ... in the order of their smallest vertex index. The contract
(docs/FORMAT.md, "Components"): a pair of such figures is compatible when every part is
compatible as a connected figure is (the same cyclic order of neighbours at every vertex, the
same outer face walk) and every part lies in the same face of every other part in both figures.
The morph of a compatible pair keeps all of this in every frame. This script never imports the
engine or its module: it runs the CLI as a subprocess and checks the files it writes.

For each pair of the manifest, by its `kind`:

  deformed         the target is a deformed copy of the source (same numbering). Required:
                   `stickmorph check SRC TGT` exits 0 printing `compatible`;
                   `stickmorph morph SRC TGT -o OUT --frames N` exits 0, and OUT has N frames of n
                   points each, `edges` is the input's edge set, frames[0] is the source and the
                   last frame the target bit for bit, and EVERY frame (a) is a plane straight-line
                   graph (no two vertices at one point, no vertex on an edge that does not end
                   there, no crossing), (b) has the source's counter-clockwise order of neighbours
                   at every vertex and the source's outer face walk for every part, and (c) has
                   every part in the same face of every other part as the source.
  redrawn          the target was drawn separately (resampled, renumbered, moved): the same with
                   `morph --correspond auto`, the frames being the matched figure's: frames[0] is
                   a subdivision of the source drawing (every matched vertex a source vertex, bit
                   for bit, or a dummy on a source edge, each source edge one chain of matched
                   edges; the test of bench/correspondence_check.py), the last frame one of the
                   target drawing, every matched part made of exactly one source part and one
                   target part, and every frame valid as above against frames[0].
  nesting_changes  a part lies in another face in the target: `check` exits 1 with one stdout
                   line `incompatible: ...` that says "nest" and names a part ("part <i>") that
                   is one of the parts whose nesting differs (computed here); `morph` exits 2,
                   nothing on stdout, exactly one stderr line starting with `error: `, no output.

Exactness: every coordinate is a double; Fraction(x) is exactly its value, with a power-of-two
denominator, so all coordinates of a frame are scaled by the largest denominator to integers,
exactly. Orientation tests, the angular order of neighbours, face areas and the winding number
that decides which face of part C holds a vertex of part D are then integer arithmetic: no
tolerance anywhere in (a)-(c). Candidate pairs for the crossing tests come from a bounding-box
filter on the doubles themselves (comparing doubles is exact, touching segments have meeting
boxes), so nothing is missed.

Faces: the rotation system (neighbours counter-clockwise) gives every part's face walks (after
the dart u->v comes v->w, w the neighbour before u counter-clockwise around v, so each face is
on the left). For a connected part the bounded faces are the walks of positive area, the outer
face the one of negative area (a tree has one walk, of area 0: it is the outer face). A point
off the part lies in the bounded face whose walk winds around it (winding number 1; an edge
walked twice cancels), or in the outer face when none does. A face is named by its smallest
dart, so "the same face" is compared combinatorially between frames.

It prints one row per pair and a summary, writes the rows to --json, and exits 1 if any pair
failed (2 for a bad command line or corpus).
"""
import argparse
import json
import math
import pathlib
import re
import subprocess
import sys
import time
from fractions import Fraction

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
# The subdivision test of a `--correspond auto` output against a drawing, and the shape of a
# refusal: shared with the checker of connected pairs on purpose (neither is the engine).
import correspondence_check as cc  # noqa: E402

MAX_PROBLEMS = 8
KINDS = ("deformed", "redrawn", "nesting_changes")


# ---------------------------------------------------------------------------
# exact coordinates and predicates

def exact_frame(points):
    """The points as integer pairs: every double times one common power of two, exactly."""
    fr = [(Fraction(float(x)), Fraction(float(y))) for x, y in points]
    den = 1
    for x, y in fr:
        den = max(den, x.denominator, y.denominator)  # all powers of two: the largest is the lcm
    return [(int(x * den), int(y * den)) for x, y in fr]


# Shared with the checker of connected pairs: exact on the integer frames above.
orient = cc.orient
plane_problems = cc.plane_problems
adjacency = cc.adjacency
load_figure = cc.load_figure
parts_of = cc.parts_of


# ---------------------------------------------------------------------------
# parts, rotation system, faces, nesting

def _angle_key(d):
    """Sort key of a nonzero integer direction by its angle in [0, 2 pi): first the half plane
    (y > 0 or y = 0 < x: [0, pi); else [pi, 2 pi)), then, within it, -x/y as an exact fraction,
    which grows with the angle (the cotangent falls); the ray along the axis comes first."""
    x, y = d
    half = 0 if (y > 0 or (y == 0 and x > 0)) else 1
    return (half, -math.inf if y == 0 else Fraction(-x, y))


def rotation_system(exact, adj):
    """For every vertex its neighbours counter-clockwise, started at the smallest, so that equal
    cyclic orders are equal tuples (sorted exactly by `_angle_key`)."""
    rot = []
    for v, nbrs in enumerate(adj):
        if len(nbrs) <= 2:
            rot.append(tuple(sorted(nbrs)))  # one cyclic order only
            continue
        pv = exact[v]
        keys = {w: _angle_key((exact[w][0] - pv[0], exact[w][1] - pv[1])) for w in nbrs}
        order = sorted(nbrs, key=lambda w: keys[w])
        k = order.index(min(order))
        rot.append(tuple(order[k:] + order[:k]))
    return rot


def face_walks(rot, vertices):
    """The face walks (lists of darts (u, v), face on the left) of the graph on `vertices`."""
    pos = {}
    for v in vertices:
        for k, w in enumerate(rot[v]):
            pos[(v, w)] = k
    seen, out = set(), []
    for v in vertices:
        for w in rot[v]:
            if (v, w) in seen:
                continue
            walk, dart = [], (v, w)
            while dart not in seen:
                seen.add(dart)
                walk.append(dart)
                a, b = dart
                order = rot[b]
                dart = (b, order[(pos[(b, a)] - 1) % len(order)])
            out.append(walk)
    return out


def walk_area2(walk, exact):
    """Twice the signed area enclosed by the walk (exact)."""
    return sum(exact[u][0] * exact[v][1] - exact[v][0] * exact[u][1] for u, v in walk)


def winding(p, walk, exact):
    """Winding number of the closed walk around point p (p not on the walk), exactly."""
    w = 0
    py = p[1]
    for u, v in walk:
        a, b = exact[u], exact[v]
        if a[1] <= py:
            if b[1] > py and orient(a, b, p) > 0:
                w += 1
        elif b[1] <= py and orient(a, b, p) < 0:
            w -= 1
    return w


class Topology:
    """What a morph must keep: rotation system, parts, every part's outer face and the face of
    every other part that holds each part, for one drawing."""

    def __init__(self, points, edges):
        pts = np.asarray(points, dtype=float).reshape(-1, 2)
        self.n = len(pts)
        self.edges = [(int(u), int(v)) for u, v in edges]
        self.adj = adjacency(self.n, self.edges)
        self.part = parts_of(self.n, self.edges)
        self.count = max(self.part) + 1 if self.part else 0
        self.members = [[] for _ in range(self.count)]
        for v, c in enumerate(self.part):
            self.members[c].append(v)
        exact = exact_frame(pts)
        self.rotation = rotation_system(exact, self.adj)
        self.outer, self.nesting = self.faces_and_nesting(exact, self.rotation)

    def faces_and_nesting(self, exact, rot):
        """outer[c]: the smallest dart of part c's outer face walk (None for an isolated vertex);
        nesting[(c, d)]: the smallest dart of the face of part c that holds part d, for every
        part c with a bounded face. Problems (two outer walks...) raise ValueError."""
        outer, nesting = {}, {}
        for c, verts in enumerate(self.members):
            walks = face_walks(rot, verts)
            if not walks:
                outer[c] = None
                continue
            areas = [walk_area2(w, exact) for w in walks]
            outside = [w for w, a in zip(walks, areas) if a <= 0]
            if len(outside) != 1:
                raise ValueError(f"part {c} has {len(outside)} face walks of area <= 0, not 1 "
                                 "(it is not drawn as a plane graph)")
            outer[c] = min(outside[0])
            bounded = [(min(w), w, _walk_box(w, exact)) for w, a in zip(walks, areas) if a > 0]
            if not bounded:
                continue
            for d in range(self.count):
                if d == c:
                    continue
                p = exact[self.members[d][0]]
                inside = [key for key, w, box in bounded
                          if box[0] <= p[0] <= box[2] and box[1] <= p[1] <= box[3] and winding(p, w, exact) != 0]
                if len(inside) > 1:
                    raise ValueError(f"vertex {self.members[d][0]} of part {d} is inside {len(inside)} faces of "
                                     f"part {c}")
                nesting[(c, d)] = inside[0] if inside else outer[c]
        return outer, nesting

    def describe_face(self, c, key):
        if key == self.outer.get(c):
            return f"the outside of part {c}"
        return f"the face of part {c} along the edge {key[0]}-{key[1]}"

    def frame_problems(self, points, limit=MAX_PROBLEMS):
        """Why this drawing of the same graph (a frame) is not valid against this topology."""
        pts = np.asarray(points, dtype=float)
        if pts.shape != (self.n, 2):
            return [f"the frame has shape {list(pts.shape)}, not [{self.n}, 2]"]
        exact = exact_frame(pts)
        bad = plane_problems(pts, self.edges, limit=limit, exact=exact)
        if bad:
            return ["not a plane graph: " + "; ".join(bad)]
        rot = rotation_system(exact, self.adj)
        changed = [v for v in range(self.n) if rot[v] != self.rotation[v]]
        if changed:
            v = changed[0]
            return [f"the order of neighbours changes at {len(changed)} vertices, e.g. vertex {v}: "
                    f"{list(rot[v])} counter-clockwise, {list(self.rotation[v])} in the source"]
        try:
            outer, nesting = self.faces_and_nesting(exact, rot)
        except ValueError as exc:
            return [str(exc)]
        out = []
        for c in range(self.count):
            if outer[c] != self.outer[c]:
                out.append(f"part {c} has another outer face walk (through {outer[c]}, was {self.outer[c]})")
        for (c, d), key in sorted(nesting.items()):
            if key != self.nesting[(c, d)]:
                out.append(f"part {d} is in {self.describe_face(c, key)}, in the source in "
                           f"{self.describe_face(c, self.nesting[(c, d)])}")
                if len(out) >= limit:
                    break
        return out


def _walk_box(walk, exact):
    xs = [exact[u][0] for u, _ in walk]
    ys = [exact[u][1] for u, _ in walk]
    return (min(xs), min(ys), max(xs), max(ys))


def nesting_differences(source_points, target_points, edges):
    """The (container part, contained part) pairs whose face differs between two drawings of
    one graph (the same rotation system assumed); also parts whose outer face differs."""
    s, t = Topology(source_points, edges), Topology(target_points, edges)
    diff = [(c, d) for (c, d), key in s.nesting.items() if t.nesting.get((c, d)) != key]
    return diff


# ---------------------------------------------------------------------------
# one morph output

def edge_set(edges):
    return {frozenset((int(u), int(v))) for u, v in edges}


def _as_list(frames):
    return [np.asarray(f, dtype=float).reshape(-1, 2) for f in frames]


def check_index_morph(source, target, doc, frames_expected=None):
    """Problems of a morph by index (`deformed`): source/target (points, edges); doc the output
    (the CLI's JSON or the module's dict). Empty list: every check passed."""
    problems = []
    spts, sedges = np.asarray(source[0], dtype=float).reshape(-1, 2), source[1]
    tpts = np.asarray(target[0], dtype=float).reshape(-1, 2)
    n = len(spts)
    for key in ("edges", "frames"):
        if key not in doc:
            return [f"the output has no {key!r}"]
    if edge_set(doc["edges"]) != edge_set(sedges) or len(doc["edges"]) != len(sedges):
        problems.append("the output's edges are not the input's edge set")
    frames = _as_list(doc["frames"])
    if frames_expected is not None and len(frames) != frames_expected:
        problems.append(f"{len(frames)} frames, {frames_expected} asked for")
    if any(f.shape != (n, 2) for f in frames):
        problems.append(f"a frame does not have {n} points")
    if problems or not frames:
        return problems or ["no frames"]
    if frames[0].tolist() != spts.tolist():
        problems.append("frames[0] is not the source bit for bit")
    if frames[-1].tolist() != tpts.tolist():
        problems.append("the last frame is not the target bit for bit")
    topo = Topology(spts, sedges)
    for k, f in enumerate(frames):
        bad = topo.frame_problems(f)
        if bad:
            problems.append(f"frame {k}: " + "; ".join(bad))
            if len(problems) >= MAX_PROBLEMS:
                break
    return problems


def check_auto_morph(source, target, doc, frames_expected=None):
    """Problems of a `--correspond auto` morph (`redrawn`)."""
    problems = []
    for key in ("edges", "frames", "correspondence"):
        if key not in doc:
            return [f"the output has no {key!r}"]
    corr = doc["correspondence"]
    cs, ct = list(corr.get("source", [])), list(corr.get("target", []))
    m = len(cs)
    medges = [(int(u), int(v)) for u, v in doc["edges"]]
    frames = _as_list(doc["frames"])
    if frames_expected is not None and len(frames) != frames_expected:
        problems.append(f"{len(frames)} frames, {frames_expected} asked for")
    if len(ct) != m or not frames or any(f.shape != (m, 2) for f in frames):
        return problems + [f"frames/correspondence are not all of {m} matched vertices"]
    if len(edge_set(medges)) != len(medges) or any(u == v or not (0 <= u < m and 0 <= v < m) for u, v in medges):
        return problems + ["the matched edges are not distinct pairs of distinct matched vertices"]
    spts, sedges = np.asarray(source[0], dtype=float).reshape(-1, 2), [tuple(e) for e in source[1]]
    tpts, tedges = np.asarray(target[0], dtype=float).reshape(-1, 2), [tuple(e) for e in target[1]]
    if not all(isinstance(x, int) for x in cs + ct):
        return problems + ["correspondence.source/target are not integers"]

    def ext(side):
        return (corr[f"{side}_edge"], corr.get(f"{side}_fraction")) if f"{side}_edge" in corr else None

    problems += cc.subdivision_problems(frames[0].tolist(), medges, cs, spts, sedges, "source", ext("source"))
    problems += cc.subdivision_problems(frames[-1].tolist(), medges, ct, tpts, tedges, "target", ext("target"))
    if problems:
        return problems
    # parts: every matched part is exactly one part of each drawing
    mpart = parts_of(m, medges)
    for side, corr_side, pts, edges in (("source", cs, spts, sedges), ("target", ct, tpts, tedges)):
        fpart = parts_of(len(pts), edges)
        fcount = max(fpart) + 1 if fpart else 0
        mcount = max(mpart) + 1 if mpart else 0
        if fcount != mcount:
            problems.append(f"the matched figure has {mcount} parts, the {side} {fcount}")
            continue
        image = {}
        for i, s in enumerate(corr_side):
            if s >= 0:
                image.setdefault(mpart[i], set()).add(fpart[s])
        split = {p: sorted(q) for p, q in image.items() if len(q) != 1}
        if split or len({min(q) for q in image.values()}) != fcount:
            problems.append(f"matched parts are not one {side} part each: {split or image}")
    if problems:
        return problems
    topo = Topology(frames[0], medges)
    for k, f in enumerate(frames):
        bad = topo.frame_problems(f)
        if bad:
            problems.append(f"frame {k}: " + "; ".join(bad))
            if len(problems) >= MAX_PROBLEMS:
                break
    return problems


PART_NAMED = re.compile(r"\bpart (\d+)\b")


def check_nesting_refusal(check_proc, morph_proc, involved, output_exists=False):
    """Problems of the refusal of a pair whose nesting differs. involved: the part indices
    whose nesting relation differs (container and contained), or None to not check the name."""
    problems = []
    out = check_proc.stdout
    if check_proc.returncode != 1:
        problems.append(f"check: exit {check_proc.returncode}, expected 1 ({(out + check_proc.stderr).strip()[:200]!r})")
    elif out.count("\n") != 1 or not out.startswith("incompatible: "):
        problems.append(f"check: stdout is not one 'incompatible: ' line: {out[:200]!r}")
    else:
        if "nest" not in out:
            problems.append(f"check: the reason does not say 'nest': {out.strip()!r}")
        named = [int(x) for x in PART_NAMED.findall(out)]
        if not named:
            problems.append(f"check: the reason names no part ('part <i>'): {out.strip()!r}")
        elif involved is not None and not set(named) & set(involved):
            problems.append(f"check: the reason names part(s) {named}, but the nesting differs for parts "
                            f"{sorted(involved)}: {out.strip()!r}")
    problems += ["morph: " + p for p in cc.check_refusal(morph_proc.returncode, morph_proc.stdout, morph_proc.stderr)]
    if output_exists:
        problems.append("morph: an output file was written")
    return problems


# ---------------------------------------------------------------------------
# the corpus run

def _run(cmd, timeout):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, stdin=subprocess.DEVNULL)


def run_pair(entry, corpus, cli, frames, timeout, workdir, method=None):
    name, kind = entry["name"], entry["kind"]
    src_path, tgt_path = corpus / entry["source"], corpus / entry["target"]
    source, target = load_figure(src_path), load_figure(tgt_path)
    out = workdir / f"{name}.morph.json"
    if out.exists():
        out.unlink()
    auto = ["--correspond", "auto"] if kind == "redrawn" else []
    check_cmd = [str(cli), "check", str(src_path), str(tgt_path), *auto]
    morph_cmd = [str(cli), "morph", str(src_path), str(tgt_path), "-o", str(out), "--frames", str(frames), *auto,
                 *(["--method", method] if method else [])]
    row = {"pair": name, "kind": kind, "n_source": len(source[0]), "n_target": len(target[0]),
           "parts": Topology(*source).count, "m": None, "result": "", "seconds": None, "check_seconds": None,
           "problems": [], "command": " ".join(morph_cmd), "check_command": " ".join(check_cmd)}
    start = time.monotonic()
    try:
        checked = _run(check_cmd, timeout)
        morphed = _run(morph_cmd, timeout)
    except subprocess.TimeoutExpired as exc:
        row["seconds"] = round(time.monotonic() - start, 2)
        row["problems"], row["result"] = [f"timed out after {timeout} s: {' '.join(exc.cmd)}"], "FAIL"
        return row
    row["seconds"] = round(time.monotonic() - start, 2)
    start = time.monotonic()
    problems = row["problems"]
    if kind == "nesting_changes":
        involved = set()
        try:
            for c, d in nesting_differences(source[0], target[0], source[1]):
                involved |= {c, d}
        except ValueError as exc:
            problems.append(f"corpus: {exc}")
        if not involved:
            problems.append("corpus: the pair's nesting does not differ (checker's computation)")
        problems += check_nesting_refusal(checked, morphed, involved or None, out.exists())
        row["stdout"] = checked.stdout.strip()
        row["stderr"] = morphed.stderr.strip()
    else:
        if (checked.returncode, checked.stdout) != (0, "compatible\n"):
            problems.append(f"check: exit {checked.returncode}: {(checked.stdout + checked.stderr).strip()[:300]!r}")
        if morphed.returncode != 0:
            first = morphed.stderr.strip().splitlines()[:1]
            problems.append(f"morph: exit {morphed.returncode}: {first[0] if first else '(no stderr)'}")
        elif not out.exists():
            problems.append("morph: exit 0 but no output file")
        else:
            try:
                doc = json.loads(out.read_text())
            except ValueError as exc:
                problems.append(f"morph: the output is not JSON: {exc}")
            else:
                row["m"] = len(doc.get("frames", [[]])[0])
                if kind == "deformed":
                    problems += check_index_morph(source, target, doc, frames)
                else:
                    problems += check_auto_morph(source, target, doc, frames)
    row["check_seconds"] = round(time.monotonic() - start, 2)
    row["result"] = "ok" if not problems else "FAIL"
    return row


def print_table(rows, stream=sys.stdout):
    head = ["pair", "kind", "parts", "n_source", "n_target", "m", "result", "cli s", "check s"]
    body = [[r["pair"], r["kind"], str(r["parts"]), str(r["n_source"]), str(r["n_target"]),
             "-" if r["m"] is None else str(r["m"]), r["result"],
             "-" if r["seconds"] is None else f"{r['seconds']:.2f}",
             "-" if r["check_seconds"] is None else f"{r['check_seconds']:.2f}"] for r in rows]
    cc.print_columns(head, body, stream)
    failed = [r for r in rows if r["result"] != "ok"]
    for r in failed:
        print(f"\nFAIL {r['pair']} ({r['kind']}):", file=stream)
        for p in r["problems"]:
            print(f"  - {p}", file=stream)
        print(f"  check: {r['check_command']}\n  morph: {r['command']}", file=stream)
    print("\nsummary:", file=stream)
    for kind in KINDS:
        mine = [r for r in rows if r["kind"] == kind]
        if mine:
            print(f"  {kind}: {sum(r['result'] == 'ok' for r in mine)}/{len(mine)} ok", file=stream)
    print(f"  total: {len(rows) - len(failed)}/{len(rows)} ok, {len(failed)} failed; CLI time "
          f"{sum(r['seconds'] or 0 for r in rows):.1f} s, checking {sum(r['check_seconds'] or 0 for r in rows):.1f} s",
          file=stream)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    cc.add_corpus_arguments(ap)
    ap.add_argument("--method", help="passed to `morph --method` (default: the CLI's own default)")
    args = ap.parse_args(argv)
    manifest = cc.read_manifest(args)
    if manifest is None:
        return 2
    bad = [e.get("name") for e in manifest if e.get("kind") not in KINDS]
    if bad:
        print(f"error: manifest entries of unknown kind: {bad}", file=sys.stderr)
        return 2
    if args.only:
        manifest = [e for e in manifest if e["name"] in args.only]
    def check(entry, workdir):
        return run_pair(entry, args.corpus, args.stickmorph.resolve(), args.frames, args.timeout, workdir,
                        args.method)

    return cc.check_corpus(args, manifest, check, print_table, "multipart_check_")

if __name__ == "__main__":
    sys.exit(main())
