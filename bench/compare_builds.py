"""Compares two builds of stickmorph output for output, with timings masked:
for a refactoring that must not change any result (issue 27).

Every figure pair of the given folders (NAME.source.json with
NAME.target.json) goes through the same CLI commands in both builds
(check, triangulate, correspond, and morph with every method and the main
options, each with an SVG filmstrip), and through the same calls of both
builds' Python modules (each in its own child process). The exit code,
standard output, standard error, output file and SVG of every run are
compared byte for byte after the timings (keys ending in _ms, "milliseconds"
objects, "seconds") are set to 0; the module's results are compared as
canonical JSON (arrays by their bytes, shape and dtype).

    /usr/bin/python3 bench/compare_builds.py --base OLD_BUILD --build build \\
        tests/data/pairs/compatible tests/data/correspond tests/data/paper

OLD_BUILD is a build directory of the other revision (its `stickmorph` and
`python/`), for example made with `git worktree add /tmp/old REV` and
`cmake -S /tmp/old -B /tmp/old/build ... && cmake --build /tmp/old/build`.
Prints one line per differing run and a summary; exits 1 if any differ.
"""

import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile

CLI_RUNS = [
    ["check"], ["triangulate"], ["correspond"],
    ["morph", "--frames", "7"],
    ["morph", "--frames", "5", "--method", "barycentric"],
    ["morph", "--frames", "5", "--method", "linear"],
    ["morph", "--frames", "6", "--correspond", "auto"],
    ["morph", "--frames", "5", "--frame-check", "full", "--steiner", "sg2001", "--weights", "floater"],
    ["morph", "--frames", "5", "--easing", "in-out", "--turns", "1"],
]

# Run in a child process with one build's module on sys.path: prints one
# JSON object, "PAIR:call" -> canonical result or ["error", type, message].
MODULE_CHILD = r"""
import hashlib, json, sys
import numpy as np
import stickmorph as sm
CALLS = {
    'check': lambda a, b: sm.check_compatibility(a['vertices'], b['vertices'], a['edges'], b['edges']),
    'triangulate': lambda a, b: sm.triangulate_figures(a['vertices'], b['vertices'], a['edges'], b['edges']),
    'correspond': lambda a, b: sm.correspond(a['vertices'], b['vertices'], a['edges'], target_edges=b['edges']),
    'rigid': lambda a, b: sm.morph(a['vertices'], b['vertices'], a['edges'], frames=6, target_edges=b['edges']),
    'barycentric': lambda a, b: sm.morph(a['vertices'], b['vertices'], a['edges'], frames=5, method='barycentric',
                                         target_edges=b['edges']),
    'linear': lambda a, b: sm.morph(a['vertices'], b['vertices'], a['edges'], frames=5, method='linear',
                                    target_edges=b['edges']),
    'auto': lambda a, b: sm.morph(a['vertices'], b['vertices'], a['edges'], frames=5, correspond='auto',
                                  target_edges=b['edges']),
    'full': lambda a, b: sm.morph(a['vertices'], b['vertices'], a['edges'], frames=5, frame_check='full',
                                  easing='in-out', target_edges=b['edges']),
}
def canonical(x, key=''):
    if key.endswith('_ms') or key in ('milliseconds', 'seconds'):
        return 0
    if isinstance(x, np.ndarray):
        return [hashlib.sha1(np.ascontiguousarray(x).tobytes()).hexdigest(), list(x.shape), str(x.dtype)]
    if isinstance(x, dict):
        return {k: canonical(v, k) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [canonical(v) for v in x]
    if x is None or isinstance(x, (bool, int, float, str)):
        return x
    return {'type': type(x).__name__, **{a: canonical(getattr(x, a), a) for a in dir(x)
            if not a.startswith('_') and not callable(getattr(x, a))}}
out = {}
for source, target in json.loads(sys.argv[1]):
    a, b = sm.load_figure(source), sm.load_figure(target)
    for name, call in CALLS.items():
        try:
            out[source + ':' + name] = canonical(call(a, b))
        except Exception as e:
            out[source + ':' + name] = ['error', type(e).__name__, str(e)]
print(json.dumps(out, sort_keys=True))
"""


def without_timings(value, key=""):
    """A result with every timing set to 0: keys ending in _ms, "seconds",
    and the whole of a "milliseconds" object (one time per stage)."""
    if key.endswith("_ms") or key in ("milliseconds", "seconds"):
        return {k: 0 for k in value} if isinstance(value, dict) else 0
    if isinstance(value, dict):
        return {k: without_timings(v, k) for k, v in value.items()}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def masked(text):
    """A JSON text without its timings (canonical), or the text itself."""
    try:
        return json.dumps(without_timings(json.loads(text)), sort_keys=True)
    except ValueError:
        return text


def pairs_in(folders):
    pairs = []
    for folder in folders:
        for source in sorted(pathlib.Path(folder).glob("*.source.json")):
            target = source.with_name(source.name.replace(".source.", ".target."))
            if target.exists():
                pairs.append((source, target))
    return pairs


def cli_run(executable, arguments, source, target, work):
    output, svg = work / "out.json", work / "out.svg"
    for path in (output, svg):
        path.unlink(missing_ok=True)
    command = [executable, arguments[0], str(source), str(target)] + arguments[1:]
    if arguments[0] != "check":
        command += ["-o", str(output)]
    if arguments[0] == "morph":
        command += ["--svg", str(svg)]
    done = subprocess.run(command, capture_output=True, text=True, timeout=900)
    return (done.returncode, masked(done.stdout), done.stderr,
            masked(output.read_text()) if output.exists() else None, svg.read_bytes() if svg.exists() else None)


def module_results(python_dir, pairs):
    environment = dict(os.environ, PYTHONPATH=str(python_dir))
    done = subprocess.run([sys.executable, "-c", MODULE_CHILD, json.dumps([[str(s), str(t)] for s, t in pairs])],
                          capture_output=True, text=True, env=environment, timeout=3600, check=True)
    return json.loads(done.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--base", required=True, type=pathlib.Path, help="build directory of the other revision")
    parser.add_argument("--build", default=pathlib.Path("build"), type=pathlib.Path, help="this build (default build)")
    parser.add_argument("folders", nargs="+", help="folders of NAME.source.json / NAME.target.json pairs")
    args = parser.parse_args()
    pairs = pairs_in(args.folders)
    if not pairs:
        parser.error("no NAME.source.json with a NAME.target.json in " + ", ".join(args.folders))
    differ = runs = 0
    with tempfile.TemporaryDirectory() as folder:
        work = pathlib.Path(folder)
        for source, target in pairs:
            for arguments in CLI_RUNS:
                runs += 1
                old = cli_run(str(args.base / "stickmorph"), arguments, source, target, work)
                new = cli_run(str(args.build / "stickmorph"), arguments, source, target, work)
                if old != new:
                    differ += 1
                    print(f"differs: stickmorph {' '.join(arguments)} {source.name} (exit {old[0]} / {new[0]})")
    print(f"CLI: {runs} runs, {differ} differ")
    old, new = module_results(args.base / "python", pairs), module_results(args.build / "python", pairs)
    module_differ = sorted(key for key in set(old) | set(new) if old.get(key) != new.get(key))
    for key in module_differ:
        print(f"differs: module {key}")
    errors = sum(1 for value in new.values() if isinstance(value, list) and value[:1] == ["error"])
    print(f"module: {len(new)} calls ({errors} of them refused), {len(module_differ)} differ")
    return 1 if differ or module_differ else 0


if __name__ == "__main__":
    sys.exit(main())
