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
import random
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
]

# name -> pattern the reason must match (it names the vertices involved).
INCOMPATIBLE = {
    "junction_rotation": r"vertex 0\b",        # two arms swapped around vertex 0
    "mirror_image": r"mirror",                 # letter A reflected
    "exterior_differs": r"exterior",           # same rotations, spike in the other face
    "polygon_reversed": r"mirror|exterior",    # hexagon traversed clockwise
    "edge_set_differs": r"\b1-2\b|\bedge",     # crossbar 1-2 replaced by 3-4
    "vertex_count_differs": r"\b6\b.*\b5\b|\b5\b.*\b6\b",  # hexagon vs pentagon
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


# Malformed files under tests/data/malformed/ -> fragments the message must
# contain. Line and column point at the offending token; figure-rule
# messages name the vertex and edge indices.
MALFORMED = {
    # not JSON
    "empty.json": ["line 1, column 1", "empty input"],
    "whitespace_only.json": ["no JSON value"],
    "binary.bin": ["line 1, column 1", "unexpected byte 0x00"],
    "syntax_missing_comma.json": ["line 8, column 3", "expected ',' or '}'"],
    "unclosed.json": ["end of input", "line 8, column 12 is not closed"],
    "trailing_comma.json": ["line 11, column 11", "trailing comma"],
    "comment.json": ["line 2, column 3", "comments are not allowed"],
    "duplicate_key.json": ["line 9, column 3", 'duplicate key "edges"'],
    "trailing_garbage.json": ["line 14, column 1", "after the JSON value"],
    "single_quotes.json": ["line 2, column 3", "double quotes"],
    "leading_zero.json": ["line 4, column 6", "leading zero"],
    "nan.json": ["line 4, column 6", "NaN is not a JSON number"],
    "infinity.json": ["line 5, column 9", "-Infinity is not a JSON number"],
    "overflow.json": ["line 6, column 9", "number 1e400 overflows a double"],
    # JSON of the wrong shape
    "top_level_array.json": ["line 1, column 1", "JSON object", "got an array"],
    "missing_vertices.json": ['missing field "vertices"'],
    "missing_edges.json": ['missing field "edges"'],
    "vertices_not_array.json": ["line 2, column 15", '"vertices" must be an array', "got an object"],
    "edges_not_array.json": ["line 3, column 12", '"edges" must be an array', "got a string"],
    "vertex_wrong_length.json": ["line 5, column 5", "vertex 2 must be an array of 2 numbers",
                                 "got an array of 3 values"],
    "vertex_not_array.json": ["line 4, column 5", "vertex 1 must be an array of 2 numbers",
                              "got a string"],
    "string_coordinate.json": ["line 6, column 9", "vertex 3: expected a number for y",
                               "got a string"],
    "null_coordinate.json": ["line 3, column 6", "vertex 0: expected a number for x", "got null"],
    "edge_wrong_length.json": ["line 10, column 5", "edge 1 must be an array of 2 vertex indices"],
    "string_index.json": ["line 11, column 6", "edge 2: expected a vertex index", "got a string"],
    "non_integer_index.json": ["line 10, column 6", "edge 1: vertex index 1.5 is not an integer"],
    "huge_index.json": ["line 11, column 9", "edge 2", "outside the 64-bit integer range"],
    "name_not_string.json": ["line 2, column 11", '"name" must be a string'],
    # valid JSON, invalid figure
    "no_vertices.json": ["no vertices"],
    "coordinate_too_large.json": ["vertex 2", "1e+101"],
    "negative_index.json": ["edge 2", "-1"],
    "index_out_of_range.json": ["edge 1", "vertex 4", "out of range"],
    "self_loop.json": ["edge 3", "self-loop", "vertex 3"],
    "duplicate_edge.json": ["edges 0 and 3", "vertices 0 and 1"],
    "duplicate_edge_reversed.json": ["edges 1 and 3", "vertices 1 and 2"],
    "coincident_vertices.json": ["vertices 1 and 3", "coincide"],
    "crossing_edges.json": ["edges 3 (0-2) and 4 (1-3)", "cross"],
    "collinear_overlap.json": ["edges 0 (0-1) and 3 (0-4)", "overlap"],
    "vertex_on_edge.json": ["vertex 4", "edge 0 (0-1)"],
    "disconnected.json": ["disconnected", "vertex 4"],
}


def test_every_malformed_file_is_listed(data_dir):
    on_disk = {p.name for p in (data_dir / "malformed").iterdir()}
    assert on_disk == set(MALFORMED)


@pytest.mark.parametrize("name", sorted(MALFORMED))
@pytest.mark.parametrize("position", ["source", "target"])
def test_malformed_file_is_one_error_line(cli, data_dir, name, position):
    bad = data_dir / "malformed" / name
    good = pair(data_dir, "compatible", "letter_a")[0]
    arguments = (bad, good) if position == "source" else (good, bad)
    message = assert_single_error_line(run(cli, "check", *arguments))
    assert message.startswith(f"{bad}: "), message
    for fragment in MALFORMED[name]:
        assert fragment in message, (fragment, message)


def test_missing_file(cli, data_dir, tmp_path):
    missing = tmp_path / "missing.json"
    good = pair(data_dir, "compatible", "letter_a")[0]
    message = assert_single_error_line(run(cli, "check", good, missing))
    assert message == f"{missing}: cannot read file: No such file or directory"


def test_directory_instead_of_file(cli, data_dir, tmp_path):
    good = pair(data_dir, "compatible", "letter_a")[0]
    message = assert_single_error_line(run(cli, "check", tmp_path, good))
    assert message == f"{tmp_path}: cannot read file: Is a directory"


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads files regardless of permissions")
def test_unreadable_file(cli, data_dir, tmp_path):
    locked = tmp_path / "locked.json"
    locked.write_text('{"vertices": [[0, 0]], "edges": []}')
    locked.chmod(0)
    message = assert_single_error_line(run(cli, "check", locked, locked))
    assert message == f"{locked}: cannot read file: Permission denied"


# Hostile inputs built at test time: each must end in one error line, fast.
def deep_arrays():
    return "[" * 100000


def deep_objects():
    return '{"vertices":' * 100000


def long_number():
    return '{"vertices": [[1' + "0" * 1000000 + ', 0]], "edges": []}'


def random_bytes():
    return bytes(random.Random(7).randrange(256) for _ in range(1 << 20))


def nul_bytes():
    return b"\0" * 4096


HOSTILE = {
    "deep_arrays": (deep_arrays, ["line 1, column 257", "nest deeper than 256 levels"]),
    "deep_objects": (deep_objects, ["nest deeper than 256 levels"]),
    "long_number": (long_number, ["overflows a double"]),
    "random_bytes": (random_bytes, ["line 1, column 1"]),
    "nul_bytes": (nul_bytes, ["unexpected byte 0x00"]),
}


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_hostile_input_is_one_error_line(cli, tmp_path, name):
    make, fragments = HOSTILE[name]
    content = make()
    path = tmp_path / f"{name}.json"
    if isinstance(content, bytes):
        path.write_bytes(content)
    else:
        path.write_text(content)
    message = assert_single_error_line(run(cli, "check", path, path))
    assert len(message) < 1000  # hostile content is not echoed in full
    for fragment in fragments:
        assert fragment in message, (fragment, message)


def test_oversized_file_is_refused(cli, tmp_path):
    big = tmp_path / "big.json"
    with open(big, "wb") as sparse:
        sparse.truncate((64 << 20) + 1)
    message = assert_single_error_line(run(cli, "check", big, big))
    assert message == f"{big}: cannot read file: larger than 64 MiB"


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="needs /dev/zero")
def test_endless_input_is_refused(cli):
    message = assert_single_error_line(run(cli, "check", "/dev/zero", "/dev/zero"))
    assert message == "/dev/zero: cannot read file: larger than 64 MiB"


def test_line_breaks_in_a_path_stay_on_one_line(cli, tmp_path):
    odd = tmp_path / "two\nlines.json"
    message = assert_single_error_line(run(cli, "check", odd, odd))
    assert "two\\nlines.json" in message


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


@pytest.mark.parametrize("arguments, fragments", [
    ([], ["missing command", "check"]),
    (["frobnicate"], ["unknown command 'frobnicate'", "commands: check"]),
    (["--frobnicate"], ["unknown option '--frobnicate'"]),
    (["--version", "extra"], ["--version takes no arguments"]),
    (["check"], ["check: missing argument SOURCE.json"]),
    (["check", "a.json"], ["check: missing argument TARGET.json"]),
    (["check", "a.json", "b.json", "c.json"], ["unexpected extra argument 'c.json'"]),
    (["check", "--frames", "3", "a.json", "b.json"], ["check: unknown option '--frames'"]),
    (["check", "-x", "a.json", "b.json"], ["check: unknown option '-x'"]),
])
def test_usage_errors(cli, arguments, fragments):
    message = assert_single_error_line(run(cli, *arguments))
    for fragment in fragments:
        assert fragment in message, (fragment, message)


def test_double_dash_ends_options(cli, data_dir, tmp_path):
    source, target = pair(data_dir, "compatible", "polygon")
    dashed = tmp_path / "-dashed.json"
    dashed.write_text(target.read_text())
    result = subprocess.run([str(cli), "check", "--", str(source), "-dashed.json"],
                            capture_output=True, text=True, cwd=tmp_path, timeout=TIMEOUT_SECONDS)
    assert (result.returncode, result.stdout) == (0, "compatible\n")


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
def test_failed_write_to_stdout_is_an_error(cli, data_dir):
    source, target = pair(data_dir, "compatible", "polygon")
    with open("/dev/full", "wb") as full:
        result = run(cli, "check", source, target, stdout=full)
    message = assert_single_error_line(result)
    assert message == "cannot write to standard output"
