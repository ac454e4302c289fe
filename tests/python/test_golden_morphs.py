"""Golden morph outputs: `stickmorph morph` on a few pairs, pinned.

The other CLI tests check that a morph is valid (every frame a plane graph with
the source's cyclic sequences). A valid morph can still change: other Steiner
vertices, other weights, a different path through the same topology. This test
runs the CLI on fixed inputs and compares the whole output document with the
golden file in tests/data/golden/morphs/:

- integers (edge and triangle indices, counts) exactly;
- strings and booleans (stats.method, stats.weights, ...) exactly;
- floating-point numbers (times, frame and triangulation positions) to a
  relative tolerance of 1e-9 of the document's scale, the largest coordinate
  magnitude in the golden frames. Relative to each number alone would make a
  coordinate that happens to be near 0 fail on roundoff; the interior frames
  come from an iterative solve to a 1e-10 relative residual, so bitwise
  equality would only pin the solver's rounding.

Left out: stats.milliseconds (wall-clock times) and stats.factorizations
(how often the solver refactorized, bookkeeping that changes with its
heuristics while the frames stay within tolerance).

Each golden file also records the SHA-256 of its input files, so a changed
input is reported as such rather than as drift of the engine.

Regenerate deliberately with `bash scripts/update_golden.sh`, or
`STICKMORPH_UPDATE_GOLDEN=1 /usr/bin/python3 -m pytest tests/python/test_golden_morphs.py`,
then review and commit the diff.
"""
import hashlib
import json
import os
import pathlib
import re
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
GOLDEN_DIR = REPO / "tests" / "data" / "golden" / "morphs"
RELATIVE_TOLERANCE = 1e-9
TIMEOUT_SECONDS = 300
# Output fields that are not results (see the module docstring).
IGNORED_STATS = {"milliseconds", "factorizations"}
# Mismatches listed in a failure message; the rest are counted.
MAX_REPORTED = 12

# name -> (source, target, options), paths relative to the repository.
CASES = {
    # The paper's Figure 8c, the paper's morph with the CLI's defaults
    # otherwise (improved, mvc, hexagon).
    "s_to_u": ("tests/data/paper/s_to_u.source.json", "tests/data/paper/s_to_u.target.json",
               ["--frames", "5", "--method", "barycentric"]),
    # The paper's Figure 8a, the demo's sample, likewise.
    "monkey_to_player": ("blend_samples/figures/monkey_to_player.source.json",
                         "blend_samples/figures/monkey_to_player.target.json",
                         ["--frames", "5", "--method", "barycentric"]),
    # The non-default paths: the reduced spiderweb, the uniform weights and
    # another enclosure.
    "letter_b_sg2001_uniform_octagon": (
        "tests/data/pairs/compatible/letter_b.source.json",
        "tests/data/pairs/compatible/letter_b.target.json",
        ["--frames", "5", "--method", "barycentric", "--steiner", "sg2001", "--weights", "uniform",
         "--enclosure-sides", "8"]),
    # The rigid method, the default (issue 12): the paper's S into U, whose guide it follows only
    # where valid, and the demo's sample.
    "s_to_u_rigid": ("tests/data/paper/s_to_u.source.json", "tests/data/paper/s_to_u.target.json",
                     ["--frames", "7"]),
    "monkey_to_player_rigid": ("blend_samples/figures/monkey_to_player.source.json",
                               "blend_samples/figures/monkey_to_player.target.json", ["--frames", "5"]),
    # Its options: the other way round with a whole extra turn, eased.
    "letter_a_rigid_ccw_turn_eased": (
        "tests/data/pairs/compatible/letter_a.source.json", "tests/data/pairs/compatible/letter_a.target.json",
        ["--frames", "6", "--rotation", "ccw", "--turns", "1", "--easing", "in-out"]),
    # Figures drawn separately (issue 13): a W outlined in two fonts (13 and 50 vertices,
    # renumbered and moved), and a centre-line R drawn in two styles with one junction pinned.
    "w_two_fonts_correspond": ("tests/data/correspond/w_two_fonts.source.json",
                               "tests/data/correspond/w_two_fonts.target.json",
                               ["--frames", "5", "--correspond", "auto"]),
    "r_two_styles_correspond_pinned": ("tests/data/correspond/r_two_styles.source.json",
                                       "tests/data/correspond/r_two_styles.target.json",
                                       ["--frames", "4", "--correspond", "auto", "--pin", "68:41"]),
}


def golden_text(record):
    """The golden file's text: indented, but one innermost array of numbers
    (a point, an edge, a triangle) per line, so that a diff shows which
    points moved. repr of a float is the shortest round-trip text, so the
    file holds the CLI's doubles bit for bit."""
    text = json.dumps(record, indent=1)
    return re.sub(r"\[\s*(-?[0-9][-+0-9.eE,\s]*?)\s*\]",
                  lambda match: "[" + ", ".join(part.strip() for part in match.group(1).split(",")) + "]",
                  text) + "\n"


def updating():
    return os.environ.get("STICKMORPH_UPDATE_GOLDEN") == "1"


def sha256(relative_path):
    return hashlib.sha256((REPO / relative_path).read_bytes()).hexdigest()


def strip_unpinned(document):
    stats = document["stats"]
    for key in IGNORED_STATS:
        stats.pop(key, None)
    return document


def run_morph(cli, tmp_path, source, target, options):
    out = tmp_path / "morph.json"
    command = [str(cli), "morph", str(REPO / source), str(REPO / target), "-o", str(out), *options]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            stdin=subprocess.DEVNULL, timeout=TIMEOUT_SECONDS)
    assert result.returncode == 0, result.stderr.decode("utf-8", "replace")
    return json.loads(out.read_text(encoding="utf-8"))


def largest_coordinate(document):
    return max(abs(c) for frame in document["frames"] for point in frame for c in point)


def differences(actual, golden, tolerance, path="output"):
    """Yields 'path: what' for every place where actual departs from golden."""
    # bool is an int in Python; compare it, and strings and null, exactly.
    if isinstance(golden, (bool, str)) or golden is None:
        if type(actual) is not type(golden) or actual != golden:
            yield f"{path}: {actual!r}, golden {golden!r}"
    elif isinstance(golden, int):
        # The writer marks every double with a fraction ("1.0"), so an int
        # here is an index or a count.
        if type(actual) is not int or actual != golden:
            yield f"{path}: {actual!r}, golden {golden!r}"
    elif isinstance(golden, float):
        if type(actual) is not float or not abs(actual - golden) <= tolerance:
            yield f"{path}: {actual!r}, golden {golden!r} (tolerance {tolerance:.3g})"
    elif isinstance(golden, list):
        if not isinstance(actual, list) or len(actual) != len(golden):
            length = len(actual) if isinstance(actual, list) else type(actual).__name__
            yield f"{path}: length {length}, golden {len(golden)}"
            return
        for index, (a, g) in enumerate(zip(actual, golden)):
            yield from differences(a, g, tolerance, f"{path}[{index}]")
    elif isinstance(golden, dict):
        if not isinstance(actual, dict):
            yield f"{path}: {type(actual).__name__}, golden an object"
            return
        for key in sorted(golden.keys() - actual.keys()):
            yield f"{path}.{key}: missing, golden has it"
        for key in sorted(actual.keys() - golden.keys()):
            yield f"{path}.{key}: new, not in the golden file"
        for key in sorted(golden.keys() & actual.keys()):
            yield from differences(actual[key], golden[key], tolerance, f"{path}.{key}")
    else:
        raise TypeError(f"{path}: unexpected golden value {golden!r}")


@pytest.mark.parametrize("name", sorted(CASES))
def test_morph_matches_golden(cli, tmp_path, name):
    source, target, options = CASES[name]
    golden_path = GOLDEN_DIR / f"{name}.json"
    inputs = {source: sha256(source), target: sha256(target)}
    output = strip_unpinned(run_morph(cli, tmp_path, source, target, options))

    if updating():
        GOLDEN_DIR.mkdir(parents=True, exist_ok=True)
        record = {
            "about": "Golden output of 'stickmorph " + " ".join(["morph", source, target, "-o OUT.json",
                                                                  *options])
                     + "' without stats." + ", stats.".join(sorted(IGNORED_STATS))
                     + "; compared by tests/python/test_golden_morphs.py. Regenerate with "
                       "scripts/update_golden.sh.",
            "arguments": ["morph", source, target, *options],
            "inputs_sha256": inputs,
            "output": output,
        }
        golden_path.write_text(golden_text(record), encoding="utf-8")

    assert golden_path.exists(), f"{golden_path} is missing; run scripts/update_golden.sh"
    golden = json.loads(golden_path.read_text(encoding="utf-8"))
    assert golden["arguments"] == ["morph", source, target, *options], (
        f"{name}: the test's arguments changed; run scripts/update_golden.sh")
    assert golden["inputs_sha256"] == inputs, (
        f"{name}: an input file changed since the golden file was made "
        f"({golden['inputs_sha256']} then, {inputs} now); if intended, run scripts/update_golden.sh")

    scale = max(1.0, largest_coordinate(golden["output"]))
    found = list(differences(output, golden["output"], RELATIVE_TOLERANCE * scale))
    shown = "\n  ".join(found[:MAX_REPORTED])
    more = f"\n  ... and {len(found) - MAX_REPORTED} more" if len(found) > MAX_REPORTED else ""
    assert not found, (
        f"{name}: stickmorph morph drifted from {golden_path.relative_to(REPO)} "
        f"at {len(found)} place(s):\n  {shown}{more}\n"
        "If the change is intended, run scripts/update_golden.sh and commit the diff.")


def test_differences_detects_drift():
    # The comparison must be able to fail: a golden test whose comparator
    # accepted everything would pin nothing.
    golden = {"frames": [[[1.0, 2.0]]], "edges": [[0, 1]], "stats": {"method": "barycentric"}}
    assert list(differences(golden, golden, 1e-9)) == []
    assert list(differences({"frames": [[[1.0, 2.0 + 5e-10]]], "edges": [[0, 1]],
                             "stats": {"method": "barycentric"}}, golden, 1e-9)) == []
    drifted = {"frames": [[[1.0, 2.0 + 1e-8]]], "edges": [[1, 0]], "stats": {"method": "linear", "x": 1}}
    found = list(differences(drifted, golden, 1e-9))
    assert any(f.startswith("output.frames[0][0][1]") for f in found)
    assert any(f.startswith("output.edges[0][0]") for f in found)
    assert any(f.startswith("output.stats.method") for f in found)
    assert any(f.startswith("output.stats.x: new") for f in found)
    assert list(differences({"frames": [[[1.0, 2.0]]]}, golden, 1e-9)) == [
        "output.edges: missing, golden has it", "output.stats: missing, golden has it"]
    # An int where a float was (or the reverse) is a change of type, not of value.
    assert list(differences([1], [1.0], 1e-9)) and list(differences([1.0], [1], 1e-9))
