#!/usr/bin/env python3
"""Measure motions through key poses (issue 28): validity, keys hit, smoothness at the keys.

    /usr/bin/python3 bench/sequence_motion.py CORPUS --build-dir build [--mode chained ...]
                     [--extra "--method rigid"] [--json FILE]

CORPUS is a folder bench/key_pose_corpus.py wrote. Each sequence of K keys gets N = 49 S + 1
frames (S = K - 1 segments) with key k at F_k = round(k (N-1) / (K-1)), as docs/FORMAT.md's
"Key poses" defaults, made one of two ways:

  chained    today's pair morphs, one per segment (`stickmorph morph KEY_k KEY_k+1 --frames
             F_k+1 - F_k + 1`), joined at the keys: the baseline
  sequence   one `stickmorph morph KEY1 ... KEYK --frames N` (issue 28's sequence morph; a
             CLI without it is reported, not measured)
  linear     each vertex on straight lines from key to key at constant speed per segment:
             what Blender's shape-key animation does between pose-to-pose keys
  matched    the sequence morph of the keys drawn on their own (the corpus's "drawn" files,
             key_pose_corpus.py --redrawn) with `--correspond auto`: measured on the common
             figure, the key error over every key vertex (the file's "keys" places)
  loop       (only when asked for) `stickmorph morph KEY1 ... KEYK --loop`, N = 49 K + 1: key 1
             again at the last frame; also measured: the jump across the seam at key 1,
             |(X[1] - X[0]) - (X[N-1] - X[N-2])| / mean step, and whether the last frame is key 1
             bit for bit

and measured, X[f] being frame f's vertex positions as one vector:
  valid      every frame is a drawing of the figure with key 1's rotation system, parts,
             outer faces and nesting, decided in exact arithmetic here (the independent
             checker of bench/multipart_check.py), not by the engine
  key error  max over keys of max |X[F_k] - key k| / the figure's size (1e-9 is the bound)
  jump       at each interior key, |v+ - v-| / (mean |X[f+1] - X[f]| over the sequence),
             v- = X[F_k] - X[F_k - 1], v+ = X[F_k + 1] - X[F_k]; the median over interior
             keys is the issue's smoothness number (<= 0.25 wanted; chained pairs 1.3-1.9)
  pass speed at keys the motion passes through (the key-to-key displacements before and
             after point the same way: cosine > 0.5), min(|v-|, |v+|) / mean step; the
             smallest such value (>= 0.3 wanted: no stop)
  edge dev   per segment, motion_quality.py's edge-length deviation (the pair morph's
             rigidity target, median <= 0.02), the median over segments

It prints one row per sequence and mode, then the medians per mode and kind.
"""
import argparse
import json
import pathlib
import shlex
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import motion_quality as mq  # noqa: E402  (edge-length deviation, as the pair morph is measured)
import multipart_check as topo  # noqa: E402  (the exact validity of a frame, independent of the engine)

TIMEOUT_SECONDS = 600
FRAMES_PER_SEGMENT = 49
PASS_COSINE = 0.5
MODES = ("chained", "sequence", "linear", "matched", "loop")
DEFAULT_MODES = ("chained", "sequence", "linear", "matched")


def key_frames(keys, frames):
    """docs/FORMAT.md's default key frames: F_k = round(k (N-1) / (K-1))."""
    return [round(k * (frames - 1) / (keys - 1)) for k in range(keys)]


def chained(cli, paths, keys_at, extra, tmp):
    """The pair morphs of consecutive keys, joined at the keys (each key once)."""
    joined = []
    for s in range(len(paths) - 1):
        out = pathlib.Path(tmp) / f"segment{s}.json"
        frames, _, _ = mq.run_morph(cli, paths[s], paths[s + 1], out, keys_at[s + 1] - keys_at[s] + 1, extra)
        joined.extend(frames if s == 0 else frames[1:])
    return np.asarray(joined)


def sequence(cli, paths, frames, extra, tmp):
    """The sequence morph, or None if the CLI refuses more than two figures as a usage error."""
    out = pathlib.Path(tmp) / "sequence.json"
    cmd = [str(cli), "morph", *map(str, paths), "-o", str(out), "--frames", str(frames), *extra]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    if r.returncode != 0:
        if len(paths) > 2 and "unexpected extra argument" in r.stderr:
            return None  # a stickmorph from before issue 28
        raise RuntimeError(r.stderr.strip() or f"exit {r.returncode}")
    return np.asarray(json.loads(out.read_text())["frames"], dtype=float)


def linear(keys, keys_at):
    """Straight lines from key to key, each segment at constant speed (shape-key blending)."""
    frames = [keys[0]]
    for s in range(len(keys) - 1):
        span = keys_at[s + 1] - keys_at[s]
        frames += [keys[s] + (f / span) * (keys[s + 1] - keys[s]) for f in range(1, span + 1)]
    return np.asarray(frames)


def matched(cli, paths, frames, extra, tmp):
    """The sequence morph of separately drawn keys (`--correspond auto`): its frames, edges, key
    frames and the key error over every vertex of every key (the "keys" entries' places)."""
    out = pathlib.Path(tmp) / "matched.json"
    cmd = [str(cli), "morph", *map(str, paths), "-o", str(out), "--frames", str(frames), "--correspond", "auto",
           *extra]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    if r.returncode != 0:
        raise RuntimeError(r.stderr.strip() or f"exit {r.returncode}")
    doc = json.loads(out.read_text())
    motion = np.asarray(doc["frames"], dtype=float)
    keys_at = [k["frame"] for k in doc["keys"]]
    error = 0.0
    for path, key in zip(paths, doc["keys"]):
        points, _ = mq.read_figure(path)
        size = max(float(np.ptp(points, axis=0).max()), 1e-300)
        vertex = np.asarray(key["vertex"])
        own = vertex >= 0
        error = max(error, float(np.abs(motion[key["frame"]][own] - points[vertex[own]]).max()) / size)
    return motion, [tuple(e) for e in doc["edges"]], keys_at, error


def measure_loop(cli, paths, keys, edges, extra, tmp):
    """The looped sequence morph's numbers: measure()'s over keys 1..K and key 1 again at the
    last frame (its jumps at keys 2..K), plus the jump across the seam and the last frame."""
    count = len(keys)
    frames = FRAMES_PER_SEGMENT * count + 1
    motion = sequence(cli, paths, frames, ["--loop", *extra], tmp)
    keys_at = [round(k * (frames - 1) / count) for k in range(count)] + [frames - 1]
    row = measure(motion, keys + [keys[0]], edges, keys_at)
    flat = motion.reshape(len(motion), -1)
    mean_step = float(np.linalg.norm(np.diff(flat, axis=0), axis=1).mean()) or 1e-300
    row["seam_jump"] = float(np.linalg.norm((flat[1] - flat[0]) - (flat[-1] - flat[-2]))) / mean_step
    row["last_is_key_1"] = bool(np.array_equal(motion[-1], keys[0]))
    row["keys_at"] = keys_at
    return row


def measure(frames, keys, edges, keys_at):
    """The numbers of the module docstring for one motion (frames: N x V x 2)."""
    size = max(float(np.ptp(np.concatenate(keys), axis=0).max()), 1e-300)
    key_error = max(float(np.abs(frames[f] - key).max()) for f, key in zip(keys_at, keys)) / size
    flat = frames.reshape(len(frames), -1)
    steps = np.linalg.norm(np.diff(flat, axis=0), axis=1)
    mean_step = float(steps.mean()) or 1e-300
    jumps, pass_speeds = [], []
    for k in range(1, len(keys) - 1):
        f = keys_at[k]
        v_minus, v_plus = flat[f] - flat[f - 1], flat[f + 1] - flat[f]
        jumps.append(float(np.linalg.norm(v_plus - v_minus)) / mean_step)
        before, after = (keys[k] - keys[k - 1]).ravel(), (keys[k + 1] - keys[k]).ravel()
        denominator = np.linalg.norm(before) * np.linalg.norm(after)
        if denominator > 0 and float(before @ after) / denominator > PASS_COSINE:
            pass_speeds.append(min(float(np.linalg.norm(v_minus)), float(np.linalg.norm(v_plus))) / mean_step)
    edge_devs = []
    for s in range(len(keys) - 1):
        part = frames[keys_at[s]:keys_at[s + 1] + 1]
        edge_devs.append(mq.edge_length_deviation(part, edges, np.linspace(0, 1, len(part))))
    checker = topo.Topology(keys[0], edges)
    invalid = [f for f in range(len(frames)) if checker.frame_problems(frames[f], limit=1)]
    return {"frames": len(frames), "invalid_frames": invalid, "key_error": key_error,
            "jump_median": float(np.median(jumps)) if jumps else None, "jumps": jumps,
            "pass_speed_min": min(pass_speeds) if pass_speeds else None, "pass_keys": len(pass_speeds),
            "edge_dev_median": float(np.median(edge_devs))}


def profiles(frames):
    """Per frame, over the mean step: the speed |X[f+1] - X[f]| and the change of velocity
    |X[f+1] - 2 X[f] + X[f-1]| (the jump of the module docstring at every frame), which the
    report plots."""
    flat = frames.reshape(len(frames), -1)
    steps = np.linalg.norm(np.diff(flat, axis=0), axis=1)
    mean_step = steps.mean() or 1e-300
    changes = np.linalg.norm(np.diff(flat, 2, axis=0), axis=1)
    return {"speeds": (steps / mean_step).round(5).tolist(),
            "velocity_changes": (changes / mean_step).round(5).tolist()}


def fmt(value, spec="{:.3f}"):
    return "-" if value is None else spec.format(value)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("corpus", type=pathlib.Path, help="folder with manifest.json (bench/key_pose_corpus.py)")
    ap.add_argument("--build-dir", type=pathlib.Path, default=mq.REPO / "build")
    ap.add_argument("--mode", action="append", choices=MODES,
                    help="which motions to measure (repeatable; default chained, sequence and linear, and "
                         "matched where the corpus has drawn keys; loop only when asked for)")
    ap.add_argument("--extra", default="", help="more `stickmorph morph` arguments, e.g. \"--method rigid\"")
    ap.add_argument("--json", type=pathlib.Path, help="write the rows here")
    args = ap.parse_args(argv)
    cli = args.build_dir / "stickmorph"
    manifest_path = args.corpus / "manifest.json"
    for path in (cli, manifest_path):
        if not path.exists():
            print(f"error: {path} does not exist", file=sys.stderr)
            return 2
    modes = args.mode or list(DEFAULT_MODES)
    extra = shlex.split(args.extra)
    rows, unsupported = [], False
    with tempfile.TemporaryDirectory(prefix="sequence_motion_") as tmp:
        for entry in json.loads(manifest_path.read_text()):
            paths = [args.corpus / f for f in entry["keys"]]
            figures = [mq.read_figure(p) for p in paths]
            keys, edges = [f[0] for f in figures], figures[0][1]
            frames = FRAMES_PER_SEGMENT * (len(keys) - 1) + 1
            keys_at = key_frames(len(keys), frames)
            for mode in modes:
                if mode == "matched" and "drawn" not in entry:
                    continue
                row = {"name": entry["name"], "kind": entry["kind"], "keys": len(keys), "vertices": len(keys[0]),
                       "mode": mode}
                try:
                    if mode == "matched":
                        drawn = [args.corpus / f for f in entry["drawn"]]
                        motion, common_edges, common_at, key_error = matched(cli, drawn, frames, extra, tmp)
                        row.update(measure(motion, [motion[f] for f in common_at], common_edges, common_at))
                        row.update(key_error=key_error, vertices=int(motion.shape[1]))
                        row.update(profiles(motion))
                        rows.append(row)
                        continue
                    if mode == "loop":
                        row.update(measure_loop(cli, paths, keys, edges, extra, tmp))
                        rows.append(row)
                        continue
                    motion = (chained(cli, paths, keys_at, extra, tmp) if mode == "chained"
                              else linear(keys, keys_at) if mode == "linear"
                              else sequence(cli, paths, frames, extra, tmp))
                except RuntimeError as error:
                    row["error"] = str(error)
                    rows.append(row)
                    continue
                if motion is None:
                    unsupported = True
                    continue
                row.update(measure(motion, keys, edges, keys_at))
                row["keys_at"] = keys_at
                row.update(profiles(motion))
                if mode == "sequence" and not any(r.get("filmstrip") for r in rows):
                    # One sequence's frames for the report's filmstrip (make_benchmarks.py).
                    row["filmstrip"] = {"frames": motion.tolist(), "edges": [list(e) for e in edges]}
                rows.append(row)
    print("| sequence | mode | keys | V | valid | key error | jump median | pass speed min | edge dev median |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in rows:
        if "error" in r:
            print(f"| {r['name']} | {r['mode']} | {r['keys']} | {r['vertices']} | error: {r['error'][:80]} | | | | |")
            continue
        valid = "yes" if not r["invalid_frames"] else f"no ({len(r['invalid_frames'])} frames)"
        print(f"| {r['name']} | {r['mode']} | {r['keys']} | {r['vertices']} | {valid} | {r['key_error']:.1e} | "
              f"{fmt(r['jump_median'])} | {fmt(r['pass_speed_min'])} | {fmt(r['edge_dev_median'], '{:.4f}')} |")
    print("\nmedians (over sequences):")
    for mode in modes:
        for kind in sorted({r["kind"] for r in rows}) + ["all"]:
            mine = [r for r in rows if r["mode"] == mode and (kind == "all" or r["kind"] == kind) and "error" not in r]
            if not mine:
                continue
            jumps = [r["jump_median"] for r in mine if r["jump_median"] is not None]
            passes = [r["pass_speed_min"] for r in mine if r["pass_speed_min"] is not None]
            print(f"  {mode:9s} {kind:6s} {len(mine):3d} sequences: jump {fmt(np.median(jumps) if jumps else None)}"
                  f", pass speed {fmt(np.median(passes) if passes else None)}"
                  f", edge dev {fmt(np.median([r['edge_dev_median'] for r in mine]), '{:.4f}')}"
                  f", invalid frames {sum(len(r['invalid_frames']) for r in mine)}"
                  f", worst key error {max(r['key_error'] for r in mine):.1e}"
                  + (f", seam jump {fmt(np.median([r['seam_jump'] for r in mine]))} (max "
                     f"{fmt(max(r['seam_jump'] for r in mine))}), last frame key 1 in "
                     f"{sum(r['last_is_key_1'] for r in mine)}" if mode == "loop" else ""))
    failed = [r for r in rows if "error" in r]
    if failed:
        print(f"  {len(failed)} motions refused: " + ", ".join(f"{r['name']} ({r['mode']})" for r in failed))
    if unsupported:
        print("  sequence: this stickmorph does not take more than two figures (issue 28 not built); not measured")
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
