"""Tests of the `stickmorph` command-line tool against its contract.

../shared/FORMAT.md: `check` prints `compatible` (exit 0) or
`incompatible: <reason>` (exit 1); bad input exits 2 with exactly one line
`error: <what and where>` on stderr, naming the offending indices; no input
may crash the program, hang it or print a stack trace. docs/CLI.md documents
the extensions tested here (--help, --version, usage errors).

Every subprocess runs with a timeout, so a hang fails the test instead of
stalling the suite.
"""
import json
import os
import re
import subprocess

import pytest

TIMEOUT_SECONDS = 60

# Golden pairs under tests/data/pairs/: <name>.source.json, <name>.target.json.
COMPATIBLE = [
    "letter_a",            # closed loop with two legs
    "letter_b",            # two loops sharing a spine, degree-4 junction
    "tree_junction",       # tree with a degree-4 and a degree-3 junction
    "polygon",             # convex hexagon -> non-convex hexagon
    "polyline",            # zigzag -> spiral
    "single_vertex",
    "single_edge",         # target lists the edge reversed
    "square_with_spikes",  # dangling edges inside and outside a loop, edges shuffled
    "wheel",               # a triangulation: hub joined to a square's corners
    "glyph_L_to_V",        # a stroke letter L into a V (bench/motion_corpus.py, seed 31)
    "glyph_7_to_L",        # a stroke letter 7 into an L (seed 5)
]

# name -> pattern the reason must match (it names the vertices involved).
INCOMPATIBLE = {
    "junction_rotation": r"vertex 0\b",        # two arms swapped around vertex 0
    "mirror_image": r"mirror",                 # letter A reflected
    "exterior_differs": r"exterior",           # same rotations, spike in the other face
    "polygon_reversed": r"mirror|exterior",    # hexagon traversed clockwise
    "edge_set_differs": r"\b1-2\b|\bedge",     # crossbar 1-2 replaced by 3-4
    "vertex_count_differs": r"\b6\b.*\b5\b|\b5\b.*\b6\b",  # hexagon vs pentagon
    "nesting_differs": r"part 1\b.*nest|nest.*part 1\b",  # the inner ring moved out
}


def run(cli, *args, stdout=subprocess.PIPE):
    """Runs the CLI; output is decoded leniently since inputs can be binary."""
    result = subprocess.run(
        [str(cli), *map(str, args)],
        stdout=stdout,
        stderr=subprocess.PIPE,
        timeout=TIMEOUT_SECONDS,
    )
    result.stdout = (result.stdout or b"").decode("utf-8", "replace")
    result.stderr = result.stderr.decode("utf-8", "replace")
    return result


def assert_single_error_line(result):
    """Exit 2, nothing on stdout, one `error: ` line on stderr, no crash."""
    assert result.returncode == 2, (result.returncode, result.stdout, result.stderr)
    assert result.stdout == ""
    assert result.stderr.startswith("error: "), result.stderr
    assert result.stderr.endswith("\n")
    assert result.stderr.count("\n") == 1, result.stderr
    for crash_sign in ("Traceback", "terminate called", "Aborted", "Segmentation", "what():"):
        assert crash_sign not in result.stderr
    return result.stderr[len("error: "):-1]


def pair(data_dir, kind, name):
    folder = data_dir / "pairs" / kind
    return folder / f"{name}.source.json", folder / f"{name}.target.json"


def test_every_golden_pair_is_listed(data_dir):
    for kind, names in (("compatible", COMPATIBLE), ("incompatible", INCOMPATIBLE)):
        on_disk = {p.name.rsplit(".", 2)[0] for p in (data_dir / "pairs" / kind).glob("*.json")}
        assert on_disk == set(names), kind
        for name in names:
            for path in pair(data_dir, kind, name):
                assert path.is_file(), path


@pytest.mark.parametrize("name", COMPATIBLE)
def test_check_compatible_pair(cli, data_dir, name):
    source, target = pair(data_dir, "compatible", name)
    result = run(cli, "check", source, target)
    assert (result.returncode, result.stdout, result.stderr) == (0, "compatible\n", "")
    # Compatibility is symmetric.
    assert run(cli, "check", target, source).stdout == "compatible\n"


@pytest.mark.parametrize("name", COMPATIBLE)
def test_compatible_targets_really_move(data_dir, name):
    # A target identical to its source would not test anything.
    source, target = (json.loads(p.read_text()) for p in pair(data_dir, "compatible", name))
    assert source["vertices"] != target["vertices"]


@pytest.mark.parametrize("name", sorted(INCOMPATIBLE))
def test_check_incompatible_pair(cli, data_dir, name):
    source, target = pair(data_dir, "incompatible", name)
    for first, second in ((source, target), (target, source)):
        result = run(cli, "check", first, second)
        assert result.returncode == 1, result
        assert result.stderr == ""
        assert result.stdout.startswith("incompatible: ")
        assert result.stdout.count("\n") == 1 and result.stdout.endswith("\n")
        assert re.search(INCOMPATIBLE[name], result.stdout), result.stdout


@pytest.mark.parametrize(
    "path", sorted(f"{kind}/{name}" for kind, names in
                   (("compatible", COMPATIBLE), ("incompatible", INCOMPATIBLE)) for name in names))
def test_every_figure_is_compatible_with_itself(cli, data_dir, path):
    for role in ("source", "target"):
        figure = data_dir / "pairs" / f"{path}.{role}.json"
        assert run(cli, "check", figure, figure).stdout == "compatible\n"


# Malformed files, unreadable and hostile inputs and usage errors are in the
# bad-input catalogue (tests/data/bad_inputs/catalogue.json), which
# test_bad_inputs.py runs against every command.


def write_figure(path, vertices, edges, **extra):
    path.write_text(json.dumps({"vertices": vertices, "edges": edges, **extra}))
    return path


def test_single_vertex_and_single_edge_are_valid(cli, tmp_path):
    dot = write_figure(tmp_path / "dot.json", [[0, 0]], [])
    stick = write_figure(tmp_path / "stick.json", [[0, 0], [1, 1]], [[0, 1]])
    assert run(cli, "check", dot, dot).stdout == "compatible\n"
    assert run(cli, "check", stick, stick).stdout == "compatible\n"


def test_vertex_count_differs_is_incompatible_not_an_error(cli, tmp_path):
    dot = write_figure(tmp_path / "dot.json", [[0, 0]], [])
    stick = write_figure(tmp_path / "stick.json", [[0, 0], [1, 1]], [[0, 1]])
    result = run(cli, "check", dot, stick)
    assert result.returncode == 1 and result.stdout.startswith("incompatible: ")


def test_unknown_fields_bom_and_crlf_are_accepted(cli, tmp_path):
    path = tmp_path / "windows.json"
    text = '{"name": "x", "colour": "red", "vertices": [[0, 0], [1, 0]],\r\n "edges": [[0, 1]]}'
    path.write_bytes(b"\xef\xbb\xbf" + text.encode())
    result = run(cli, "check", path, path)
    assert (result.returncode, result.stdout) == (0, "compatible\n")


def test_large_figure_is_checked_quickly(cli, tmp_path):
    # A 20000-vertex zigzag and a stretched copy: linear-size work, well
    # within the timeout.
    n = 20000
    source = [[i, i % 2] for i in range(n)]
    target = [[2 * i, 3 * (i % 2)] for i in range(n)]
    edges = [[i, i + 1] for i in range(n - 1)]
    a = write_figure(tmp_path / "a.json", source, edges)
    b = write_figure(tmp_path / "b.json", target, edges)
    assert run(cli, "check", a, b).stdout == "compatible\n"


# Command-line usage.
def test_help(cli):
    for flag in ("--help", "-h"):
        result = run(cli, flag)
        assert result.returncode == 0 and result.stderr == ""
        assert result.stdout.startswith("usage: stickmorph")
        assert "check SOURCE.json TARGET.json" in result.stdout


def test_command_help(cli):
    for arguments in (["check", "--help"], ["check", "a.json", "-h"]):
        result = run(cli, *arguments)
        assert result.returncode == 0 and result.stderr == ""
        assert result.stdout.startswith("usage: stickmorph check SOURCE.json TARGET.json")


def test_version(cli):
    result = run(cli, "--version")
    assert (result.returncode, result.stdout, result.stderr) == (0, "stickmorph 0.1.0\n", "")


def test_double_dash_ends_options(cli, data_dir, tmp_path):
    source, target = pair(data_dir, "compatible", "polygon")
    dashed = tmp_path / "-dashed.json"
    dashed.write_text(target.read_text())
    result = subprocess.run([str(cli), "check", "--", str(source), "-dashed.json"],
                            capture_output=True, text=True, cwd=tmp_path, timeout=TIMEOUT_SECONDS)
    assert (result.returncode, result.stdout) == (0, "compatible\n")


# The argument parser (CLI11) reports its errors in this CLI's words: one
# line naming the command and the option, never CLI11's own text.
@pytest.mark.parametrize("arguments, fragment", [
    (["check", "-1", "b.json"], "check: unknown option '-1'"),
    (["check", "a.json", "-7"], "check: unknown option '-7'"),
    (["morph", "a.json", "b.json", "--output="], "morph: option '--output' needs a value OUT.json"),
    (["morph", "a.json", "b.json", "-o"], "morph: option '--output' needs a value OUT.json"),
    (["morph", "a.json", "b.json", "-o", "x.json", "--output=y.json"], "option '--output' given twice"),
    (["morph", "a.json", "b.json", "-o", "x.json", "--no-verify", "--no-verify"],
     "option '--no-verify' given twice"),
    (["morph", "a.json", "b.json", "-o", "x.json", "--svg-triangulation=yes"],
     "option '--svg-triangulation' takes no value"),
    (["triangulate", "a.json", "b.json", "-o", "x.json", "--framez=3"], "triangulate: unknown option '--framez'"),
    (["morph", "-o", "x.json", "a.json"], "morph: missing argument TARGET.json"),
    (["morph", "a.json", "b.json", "-o", "x.json", "--turns"], "morph: option '--turns' needs a value K"),
    (["morph", "a.json", "b.json", "-o", "x.json", "--rotation="], "morph: option '--rotation' needs a value DIR"),
    (["morph", "a.json", "b.json", "-o", "x.json", "--easing", "in-out", "--easing=none"],
     "morph: option '--easing' given twice"),
    (["morph", "a.json", "b.json", "-o", "x.json", "--turns=1", "--turns", "2"], "morph: option '--turns' given twice"),
    (["check", "a.json", "b.json", "--rotation", "ccw"], "check: unknown option '--rotation'"),
])
def test_parser_errors_are_one_line_in_our_words(cli, arguments, fragment):
    result = run(cli, *arguments)
    assert_single_error_line(result)
    assert fragment in result.stderr, result.stderr
    assert "CLI11" not in result.stderr and "required" not in result.stderr


def test_a_dash_number_after_double_dash_is_a_file(cli):
    result = run(cli, "check", "--", "-1", "b.json")
    assert_single_error_line(result)
    assert result.stderr == "error: -1: cannot read file: No such file or directory\n"


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
def test_failed_write_to_stdout_is_an_error(cli, data_dir):
    source, target = pair(data_dir, "compatible", "polygon")
    with open("/dev/full", "wb") as full:
        result = run(cli, "check", source, target, stdout=full)
    message = assert_single_error_line(result)
    assert message == "cannot write to standard output"
