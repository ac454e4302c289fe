"""Tests of the `stickmorph` Python module (native/python/module.cpp).

The module is a thin shell over the engine, so these tests check the shell:
conversion of arrays in and out, the exception classes and their attributes,
and that the module and the CLI report the same thing for the same input.
"""
import errno
import json
import math
import os
import pathlib
import shutil
import subprocess
import threading

import numpy as np
import pytest

import stickmorph

REPO = pathlib.Path(__file__).resolve().parents[2]

# A unit square, counter-clockwise.
SQUARE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
SQUARE_EDGES = [[0, 1], [1, 2], [2, 3], [3, 0]]

# A triangle 0 1 2 with vertex 3 inside, joined to all three corners: a
# triangulation of 3 triangles.
WHEEL = [[0.0, 0.0], [4.0, 0.0], [2.0, 4.0], [2.0, 1.0]]
WHEEL_EDGES = [[0, 1], [1, 2], [2, 0], [0, 3], [1, 3], [2, 3]]
# The same combinatorial map with another face outside: every vertex keeps
# its cyclic order (checked by hand and by test_rotation_systems_of_exterior_pair_agree),
# but the triangle 0 1 3 bounds the unbounded region and 2 is inside.
WHEEL_OTHER_EXTERIOR = [[0.0, 0.0], [2.0, 4.0], [2.0, 1.0], [4.0, 0.0]]


def write_figure(path, vertices, edges, name=None):
    document = {"vertices": vertices, "edges": edges}
    if name is not None:
        document["name"] = name
    path.write_text(json.dumps(document))
    return path


def run_cli(cli, *arguments):
    return subprocess.run([str(cli), *map(str, arguments)], capture_output=True, text=True,
                          stdin=subprocess.DEVNULL, timeout=60)


def sequences_by_kind(decomposition):
    interior = [s for s in decomposition if not s["exterior"]]
    exterior = [s for s in decomposition if s["exterior"]]
    return interior, exterior


def cyclic_rotations(sequence):
    sequence = list(sequence)
    return [sequence[k:] + sequence[:k] for k in range(len(sequence))]


# --------------------------------------------------------------------------
# Module surface


def test_version():
    assert stickmorph.__version__ == "0.1.0"


@pytest.mark.parametrize("name", ["JsonError", "InvalidFigureError", "InvalidArgumentError",
                                  "IncompatibleFiguresError", "FileError", "FigureFileNotFoundError",
                                  "FigureFileIsADirectoryError", "FigureFilePermissionError",
                                  "FigureFileNotADirectoryError"])
def test_input_errors_are_value_errors(name):
    cls = getattr(stickmorph, name)
    assert issubclass(cls, stickmorph.StickMorphError)
    assert issubclass(cls, ValueError)
    assert cls.__module__ == "stickmorph"
    assert cls.__doc__


def test_stickmorph_error_is_a_value_error():
    assert issubclass(stickmorph.StickMorphError, ValueError)
    assert not issubclass(stickmorph.StickMorphError, RuntimeError)


def test_internal_error_is_a_runtime_error_not_an_input_error():
    assert issubclass(stickmorph.InternalError, RuntimeError)
    assert not issubclass(stickmorph.InternalError, ValueError)
    assert not issubclass(stickmorph.InternalError, stickmorph.StickMorphError)


@pytest.mark.parametrize("function", ["validate", "rotation_system", "decompose",
                                      "check_compatibility"])
def test_docstrings_give_shapes(function):
    doc = getattr(stickmorph, function).__doc__
    assert "#V by 2" in doc
    assert "#E by 2" in doc


def test_load_figure_docstring_gives_shapes():
    doc = stickmorph.load_figure.__doc__
    assert "#V by 2 float64" in doc and "#E by 2 int64" in doc


# --------------------------------------------------------------------------
# validate and InvalidFigureError

# (id, vertices, edges, defect, named vertices, named edges, text in message)
DEFECTS = [
    ("no_vertices", [], [], "no_vertices", [], [], "no vertices"),
    ("nan", [[0, 0], [math.nan, 1]], [[0, 1]], "non_finite_coordinate", [1], [], "vertex 1"),
    ("infinity", [[0, 0], [1, -math.inf]], [[0, 1]], "non_finite_coordinate", [1], [],
     "vertex 1"),
    ("too_large", [[0, 0], [1e101, 0]], [[0, 1]], "coordinate_too_large", [1], [], "vertex 1"),
    ("out_of_range", [[0, 0], [1, 0]], [[0, 1], [1, 2]], "edge_index_out_of_range", [], [1],
     "edge 1"),
    ("negative", [[0, 0], [1, 0]], [[0, 1], [-1, 0]], "edge_index_out_of_range", [], [1], "-1"),
    ("self_loop", [[0, 0], [1, 0]], [[0, 1], [1, 1]], "self_loop", [1], [1], "edge 1"),
    ("duplicate", [[0, 0], [1, 0], [0, 1]], [[0, 1], [1, 2], [1, 0]], "duplicate_edge", [0, 1],
     [0, 2], "edges 0 and 2"),
    ("coincident", [[0, 0], [1, 0], [1, 0]], [[0, 1], [0, 2]], "coincident_vertices", [1, 2], [],
     "vertices 1 and 2"),
    ("crossing", SQUARE, SQUARE_EDGES + [[0, 2], [1, 3]], "crossing_edges", [], [4, 5], "cross"),
    ("overlap", [[0, 0], [2, 0], [1, 0], [3, 0]], [[0, 1], [2, 3]], "overlapping_edges", [],
     [0, 1], "overlap"),
    ("vertex_on_edge", [[0, 0], [2, 0], [1, 0], [1, 1]], [[0, 1], [2, 3]], "vertex_on_edge",
     [2], [0], "vertex 2"),
    ("part_crosses_part", [[0, 0], [4, 0], [0, 4], [2, -1], [2, 1]], [[0, 1], [1, 2], [2, 0], [3, 4]],
     "crossing_edges", [], [0, 3], "cross"),
]


@pytest.mark.parametrize("vertices,edges,defect,named_vertices,named_edges,text",
                         [d[1:] for d in DEFECTS], ids=[d[0] for d in DEFECTS])
def test_invalid_figure_error_attributes(vertices, edges, defect, named_vertices, named_edges,
                                         text):
    with pytest.raises(stickmorph.InvalidFigureError) as info:
        stickmorph.validate(vertices, edges)
    error = info.value
    assert error.defect == defect
    assert error.vertices == named_vertices
    assert error.edges == named_edges
    assert text in str(error)
    # Every index the error names appears in its message.
    for index in named_vertices + named_edges:
        assert str(index) in str(error)


def test_invalid_figure_error_class_defaults_are_none():
    error = stickmorph.InvalidFigureError("raised from Python")
    assert error.defect is None and error.vertices is None and error.edges is None
    assert str(error) == "raised from Python"


@pytest.mark.parametrize("function", [stickmorph.rotation_system, stickmorph.decompose])
def test_other_functions_validate_first(function):
    with pytest.raises(stickmorph.InvalidFigureError) as info:
        function(SQUARE, SQUARE_EDGES + [[0, 2], [1, 3]])
    assert info.value.defect == "crossing_edges"


def test_validate_accepts_valid_figures():
    assert stickmorph.validate(SQUARE, SQUARE_EDGES) is None
    assert stickmorph.validate(WHEEL, WHEEL_EDGES) is None
    assert stickmorph.validate([[0, 0], [1, 1]], [[1, 0]]) is None


@pytest.mark.parametrize("edges", [[], np.zeros((0,), dtype=np.int64),
                                   np.zeros((0, 2), dtype=np.int32), np.zeros((0, 2))],
                         ids=["list", "int64 (0,)", "int32 (0, 2)", "float (0, 2)"])
def test_single_vertex_without_edges(edges):
    assert stickmorph.validate([[3.5, -1.0]], edges) is None


@pytest.mark.parametrize("convert", [
    lambda v, e: (v, e),
    lambda v, e: (tuple(map(tuple, v)), tuple(map(tuple, e))),
    lambda v, e: (np.array(v, dtype=np.float32), np.array(e, dtype=np.uint8)),
    lambda v, e: (np.array(v, dtype=np.int16), np.array(e, dtype=np.int16)),
    lambda v, e: (np.asfortranarray(v), np.asfortranarray(e)),
    lambda v, e: (np.array(v)[::-1][::-1], np.array(e, dtype=np.uint64)),
    lambda v, e: (np.array(v), np.array(e, dtype=np.float64)),
    lambda v, e: (np.array(v), np.array(e, dtype=np.float32)),
], ids=["lists", "tuples", "float32+uint8", "int16", "fortran", "view+uint64", "float64 edges",
        "float32 edges"])
def test_array_likes_are_converted(convert):
    vertices, edges = convert(WHEEL, WHEEL_EDGES)
    stickmorph.validate(vertices, edges)
    # The converted figure is the same figure: same decomposition.
    assert ([s["vertices"].tolist() for s in stickmorph.decompose(vertices, edges)] ==
            [s["vertices"].tolist() for s in stickmorph.decompose(WHEEL, WHEEL_EDGES)])


def test_non_contiguous_vertices_are_read_by_value():
    # Every other row of a larger array: a strided view.
    padded = np.zeros((8, 2))
    padded[::2] = SQUARE
    padded[1::2] = [[5, 5], [6, 6], [7, 7], [8, 8]]
    view = padded[::2]
    assert not view.flags["C_CONTIGUOUS"]
    a = stickmorph.rotation_system(view, SQUARE_EDGES)
    b = stickmorph.rotation_system(SQUARE, SQUARE_EDGES)
    assert [x.tolist() for x in a] == [x.tolist() for x in b]


# --------------------------------------------------------------------------
# Wrong shapes and types


@pytest.mark.parametrize("vertices,shape", [
    (np.zeros((5, 3)), "(5, 3)"),
    (np.zeros((4,)), "(4,)"),
    (np.zeros((2, 2, 2)), "(2, 2, 2)"),
    (np.float64(1.0), "()"),
    (np.zeros((0, 3)), "(0, 3)"),
])
def test_vertices_of_wrong_shape(vertices, shape):
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.validate(vertices, [])
    assert str(info.value) == f"vertices must have shape (#V, 2), got {shape}"


@pytest.mark.parametrize("edges,shape", [
    ([0, 1], "(2,)"),
    ([[0, 1, 2]], "(1, 3)"),
    (np.zeros((1, 2, 2), dtype=int), "(1, 2, 2)"),
    (7, "()"),
])
def test_edges_of_wrong_shape(edges, shape):
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.validate(SQUARE, edges)
    assert str(info.value) == f"edges must have shape (#E, 2), got {shape}"


def test_fractional_edge_index_is_refused_not_truncated():
    edges = np.array(SQUARE_EDGES, dtype=float)
    edges[3, 1] = 1.5
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.validate(SQUARE, edges)
    assert str(info.value) == "edge 3: index 1.5 is not an integer"


@pytest.mark.parametrize("value,text", [(math.nan, "nan"), (math.inf, "inf"), (-0.25, "-0.25")])
def test_non_integral_float_edge_index(value, text):
    edges = np.array(SQUARE_EDGES, dtype=float)
    edges[1, 0] = value
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.validate(SQUARE, edges)
    assert str(info.value) == f"edge 1: index {text} is not an integer"


def test_float_edge_index_beyond_int64_is_refused():
    edges = np.array(SQUARE_EDGES, dtype=float)
    edges[2, 1] = 1e30
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.validate(SQUARE, edges)
    assert str(info.value) == "edge 2: index 1e+30 does not fit in a 64-bit signed integer"


def test_uint64_edge_index_beyond_int64_is_refused():
    edges = np.array(SQUARE_EDGES, dtype=np.uint64)
    edges[0, 1] = np.uint64(2**64 - 1)
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.validate(SQUARE, edges)
    assert str(info.value) == ("edge 0: index 18446744073709551615 does not fit in a 64-bit "
                               "signed integer")


def test_large_integer_index_reaches_the_engine_intact():
    # 2^40 would become 0 if truncated to 32 bits; the engine must see it.
    for edges in ([[0, 1], [1, 2**40]], np.array([[0, 1], [1, 2**40]], dtype=float)):
        with pytest.raises(stickmorph.InvalidFigureError) as info:
            stickmorph.validate([[0, 0], [1, 0]], edges)
        assert info.value.defect == "edge_index_out_of_range"
        assert info.value.edges == [1]
        assert str(2**40) in str(info.value)


@pytest.mark.parametrize("edges,dtype", [
    (np.array([[True, False]]), "bool"),
    ([["0", "1"]], "<U1"),
    (np.array([[0, 1]], dtype=object), "object"),
    ([[0, 2**70]], "object"),
    (np.array([[0, 1]], dtype=np.complex128), "complex128"),
], ids=["bool", "str", "object", "python bigint", "complex"])
def test_edges_of_wrong_dtype(edges, dtype):
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.validate([[0, 0], [1, 0]], edges)
    assert str(info.value) == f"edges must hold integer vertex indices, got dtype {dtype}"


@pytest.mark.parametrize("vertices,dtype", [
    (np.array([[True, False], [False, True]]), "bool"),
    ([["0", "0"], ["1", "0"]], "<U1"),
    (np.array([[0, 0], [1, 0]], dtype=object), "object"),
    (np.array([[0, 0], [1, 0]], dtype=np.complex64), "complex64"),
], ids=["bool", "str", "object", "complex"])
def test_vertices_of_wrong_dtype(vertices, dtype):
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.validate(vertices, [[0, 1]])
    assert str(info.value) == f"vertices must hold real numbers, got dtype {dtype}"


def test_ragged_vertices_are_refused():
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.validate([[0, 0], [1]], [[0, 1]])
    assert str(info.value).startswith("vertices cannot be converted to an array: ")


# --------------------------------------------------------------------------
# load_figure


def test_load_figure(tmp_path):
    path = write_figure(tmp_path / "wheel.json", WHEEL, WHEEL_EDGES, name="wheel")
    for argument in (path, str(path)):
        figure = stickmorph.load_figure(argument)
        assert set(figure) == {"name", "vertices", "edges"}
        assert figure["name"] == "wheel"
        assert figure["vertices"].dtype == np.float64
        assert figure["vertices"].shape == (4, 2)
        assert figure["edges"].dtype == np.int64
        assert figure["edges"].shape == (6, 2)
        np.testing.assert_array_equal(figure["vertices"], WHEEL)
        np.testing.assert_array_equal(figure["edges"], WHEEL_EDGES)


def test_load_figure_keeps_every_bit(tmp_path):
    vertices = [[0.1, 1 / 3], [1e-300, 2.0**0.5], [-7.25e99, 0.0]]
    path = write_figure(tmp_path / "exact.json", vertices, [[0, 1], [1, 2]])
    figure = stickmorph.load_figure(path)
    assert figure["vertices"].tolist() == vertices


def test_load_single_vertex(tmp_path):
    path = write_figure(tmp_path / "dot.json", [[2.0, 3.0]], [])
    figure = stickmorph.load_figure(path)
    assert figure["vertices"].shape == (1, 2)
    assert figure["edges"].shape == (0, 2)
    assert figure["edges"].dtype == np.int64


def test_load_figure_round_trips_through_the_other_functions(tmp_path):
    path = write_figure(tmp_path / "square.json", SQUARE, SQUARE_EDGES)
    figure = stickmorph.load_figure(path)
    assert stickmorph.check_compatibility(figure["vertices"], figure["vertices"] * 2.0,
                                          figure["edges"])


def test_load_figure_path_that_is_not_utf8(tmp_path):
    # Linux file names are bytes; Python shows undecodable ones with
    # surrogate escapes. Both spellings must reach the same file.
    path = os.fsencode(tmp_path) + b"/n\xffme.json"
    with open(path, "w") as file:
        json.dump({"vertices": SQUARE, "edges": SQUARE_EDGES}, file)
    for argument in (path, os.fsdecode(path)):
        assert stickmorph.load_figure(argument)["vertices"].shape == (4, 2)
    missing = os.fsencode(tmp_path) + b"/gone\xff.json"
    with pytest.raises(stickmorph.FileError) as info:
        stickmorph.load_figure(missing)
    # The undecodable byte is shown escaped, not lost with the message.
    assert "gone\\xff.json" in str(info.value)


def test_load_figure_name_that_is_not_utf8(tmp_path):
    path = tmp_path / "latin1.json"
    path.write_bytes(b'{"name": "caf\xe9", "vertices": [[0, 0]], "edges": []}')
    # JSON text is UTF-8 (RFC 8259, section 8.1): Latin-1 bytes are an error
    # that says where.
    with pytest.raises(stickmorph.JsonError, match="line 1, column 14: invalid UTF-8"):
        stickmorph.load_figure(path)


def test_load_figure_malformed_json(tmp_path):
    path = tmp_path / "broken.json"
    path.write_text('{"vertices": [[0, 0]], "edges": [}')
    with pytest.raises(stickmorph.JsonError) as info:
        stickmorph.load_figure(path)
    assert "line 1" in str(info.value)


def test_load_figure_missing_file(tmp_path):
    # An OSError like open()'s, so `except FileNotFoundError` works, and a
    # StickMorphError like every other stickmorph failure; the message is the
    # CLI's.
    path = tmp_path / "absent.json"
    with pytest.raises(FileNotFoundError) as info:
        stickmorph.load_figure(path)
    error = info.value
    assert isinstance(error, stickmorph.FigureFileNotFoundError)
    assert isinstance(error, stickmorph.FileError) and isinstance(error, stickmorph.StickMorphError)
    assert not isinstance(error, stickmorph.JsonError)
    assert error.errno == errno.ENOENT and error.filename == str(path)
    assert error.strerror == "No such file or directory"
    assert str(error) == f"{path}: cannot read file: No such file or directory"


def test_load_figure_directory_and_oversized(tmp_path):
    with pytest.raises(IsADirectoryError) as info:
        stickmorph.load_figure(tmp_path)
    assert isinstance(info.value, stickmorph.FigureFileIsADirectoryError)
    assert info.value.errno == errno.EISDIR
    with pytest.raises(NotADirectoryError):
        stickmorph.load_figure(write_figure(tmp_path / "f.json", SQUARE, SQUARE_EDGES) / "x.json")
    big = tmp_path / "big.json"
    with open(big, "wb") as file:
        file.truncate(65 << 20)
    with pytest.raises(stickmorph.FileError) as info:
        stickmorph.load_figure(big)
    # Over the size limit is no built-in OSError subclass, but an OSError.
    assert type(info.value) is stickmorph.FileError and isinstance(info.value, OSError)
    assert info.value.errno == errno.EFBIG
    assert "larger than 64 MiB" in str(info.value)


def test_load_figure_invalid_figure(tmp_path):
    path = write_figure(tmp_path / "cross.json", SQUARE, SQUARE_EDGES + [[0, 2], [1, 3]])
    with pytest.raises(stickmorph.InvalidFigureError) as info:
        stickmorph.load_figure(path)
    assert info.value.defect == "crossing_edges"
    assert info.value.edges == [4, 5]


# --------------------------------------------------------------------------
# rotation_system


def test_rotation_system_of_a_star():
    # Leaves listed out of angular order; counter-clockwise from the positive
    # x axis the centre sees east (3), north (1), west (2), south (4).
    vertices = [[0, 0], [0, 1], [-1, 0], [1, 0], [0, -1]]
    edges = [[0, 1], [2, 0], [0, 3], [4, 0]]
    rotation = stickmorph.rotation_system(vertices, edges)
    assert len(rotation) == 5
    assert all(isinstance(r, np.ndarray) and r.dtype == np.int64 for r in rotation)
    assert rotation[0].tolist() == [3, 1, 2, 4]
    assert [r.tolist() for r in rotation[1:]] == [[0], [0], [0], [0]]


def test_rotation_system_of_a_square():
    rotation = stickmorph.rotation_system(SQUARE, SQUARE_EDGES)
    # Counter-clockwise from east: at 0 (origin) 1 east, 3 north; at 3 (top
    # left) 2 east, 0 south.
    assert [r.tolist() for r in rotation] == [[1, 3], [2, 0], [3, 1], [2, 0]]


def test_rotation_system_of_a_single_vertex():
    rotation = stickmorph.rotation_system([[0, 0]], [])
    assert len(rotation) == 1 and rotation[0].tolist() == []


def test_rotation_systems_of_exterior_pair_agree():
    # The premise of the exterior-differs test below.
    a = stickmorph.rotation_system(WHEEL, WHEEL_EDGES)
    b = stickmorph.rotation_system(WHEEL_OTHER_EXTERIOR, WHEEL_EDGES)
    for x, y in zip(a, b):
        assert x.tolist() in cyclic_rotations(y.tolist())


# --------------------------------------------------------------------------
# decompose


@pytest.mark.parametrize("n", [3, 4, 7])
def test_decompose_polygon(n):
    vertices = [[math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)] for k in range(n)]
    edges = [[k, (k + 1) % n] for k in range(n)]
    decomposition = stickmorph.decompose(vertices, edges)
    assert len(decomposition) == 2
    interior, exterior = sequences_by_kind(decomposition)
    assert len(interior) == 1 and len(exterior) == 1
    assert interior[0]["angle_sum"] == pytest.approx(math.pi * (n - 2))
    assert exterior[0]["angle_sum"] == pytest.approx(math.pi * (n + 2))
    # The interior runs counter-clockwise (increasing index on this polygon),
    # the exterior clockwise.
    assert interior[0]["vertices"].tolist() in cyclic_rotations(range(n))
    assert exterior[0]["vertices"].tolist() in cyclic_rotations(reversed(range(n)))
    for sequence in decomposition:
        assert set(sequence) == {"vertices", "exterior", "angle_sum"}
        assert sequence["vertices"].dtype == np.int64
        assert isinstance(sequence["exterior"], bool)
        assert isinstance(sequence["angle_sum"], float)


def test_decompose_is_in_algorithm_1_order():
    # Algorithm 1 starts from dart 0 (edge 0 traversed from its first vertex):
    # 0 -> 1 on a counter-clockwise square has the interior on its left.
    decomposition = stickmorph.decompose(SQUARE, SQUARE_EDGES)
    assert [s["exterior"] for s in decomposition] == [False, True]
    assert decomposition[0]["vertices"].tolist() == [1, 2, 3, 0]
    # Listing edge 0 the other way round starts with the exterior.
    flipped = [[1, 0]] + SQUARE_EDGES[1:]
    assert [s["exterior"] for s in stickmorph.decompose(SQUARE, flipped)] == [True, False]


def test_decompose_polyline():
    vertices = [[0, 0], [1, 0], [1, 1], [3, 2]]
    edges = [[0, 1], [1, 2], [2, 3]]
    decomposition = stickmorph.decompose(vertices, edges)
    assert len(decomposition) == 1
    (sequence,) = decomposition
    assert sequence["exterior"] is True
    # Out and back: every edge twice, the tips once, the inner vertices twice.
    assert sequence["vertices"].tolist() in cyclic_rotations([1, 2, 3, 2, 1, 0])
    assert sequence["angle_sum"] == pytest.approx(math.pi * (6 + 2))


def test_decompose_triangulation():
    decomposition = stickmorph.decompose(WHEEL, WHEEL_EDGES)
    interior, exterior = sequences_by_kind(decomposition)
    assert len(interior) == 3 and len(exterior) == 1
    for sequence in interior:
        assert len(sequence["vertices"]) == 3
        assert sequence["angle_sum"] == pytest.approx(math.pi)
    assert sorted(sorted(s["vertices"].tolist()) for s in interior) == [[0, 1, 3], [0, 2, 3],
                                                                        [1, 2, 3]]
    assert exterior[0]["vertices"].tolist() in cyclic_rotations([0, 2, 1])
    assert exterior[0]["angle_sum"] == pytest.approx(5 * math.pi)


def test_decompose_grid_triangulation():
    # A 3 by 3 grid of points, each cell split by a diagonal: t = 8 triangles.
    vertices = [[x, y] for y in range(3) for x in range(3)]
    edges = []
    for y in range(3):
        for x in range(3):
            v = 3 * y + x
            if x < 2:
                edges.append([v, v + 1])
            if y < 2:
                edges.append([v, v + 3])
            if x < 2 and y < 2:
                edges.append([v, v + 4])
    decomposition = stickmorph.decompose(vertices, edges)
    interior, exterior = sequences_by_kind(decomposition)
    assert len(interior) == 8 and len(exterior) == 1
    assert all(len(s["vertices"]) == 3 for s in interior)
    assert len(exterior[0]["vertices"]) == 8
    assert exterior[0]["angle_sum"] == pytest.approx(10 * math.pi)


def test_decompose_tree():
    # A star with an extra branch: 5 edges, so one sequence of 10 darts.
    vertices = [[0, 0], [1, 0], [0, 1], [-1, 0], [0, -1], [2, 1]]
    edges = [[0, 1], [0, 2], [0, 3], [0, 4], [1, 5]]
    decomposition = stickmorph.decompose(vertices, edges)
    assert len(decomposition) == 1
    (sequence,) = decomposition
    assert sequence["exterior"] is True
    assert len(sequence["vertices"]) == 10
    assert sorted(sequence["vertices"].tolist()) == [0, 0, 0, 0, 1, 1, 2, 3, 4, 5]
    assert sequence["angle_sum"] == pytest.approx(math.pi * 12)


def test_decompose_single_vertex():
    decomposition = stickmorph.decompose([[1, 1]], [])
    assert len(decomposition) == 1
    assert decomposition[0]["vertices"].tolist() == [0]
    assert decomposition[0]["exterior"] is True


def test_decompose_from_threads():
    # The engine runs without the GIL; concurrent calls must not interfere.
    expected = [s["vertices"].tolist() for s in stickmorph.decompose(WHEEL, WHEEL_EDGES)]
    results, failures = [], []

    def work():
        try:
            for _ in range(200):
                results.append([s["vertices"].tolist()
                                for s in stickmorph.decompose(WHEEL, WHEEL_EDGES)])
        except Exception as error:  # reported below, with the thread's error
            failures.append(error)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert failures == []
    assert len(results) == 800 and all(r == expected for r in results)


# --------------------------------------------------------------------------
# check_compatibility


def affine(vertices, matrix, offset):
    return (np.asarray(vertices, dtype=float) @ np.asarray(matrix, dtype=float).T
            + np.asarray(offset, dtype=float))


def test_compatible_moved_figure():
    angle = 0.7
    rotate = [[math.cos(angle), -math.sin(angle)], [math.sin(angle), math.cos(angle)]]
    target = affine(WHEEL, rotate, [10, -3]) * 2.5
    target[3] += [0.3, -0.2]  # the centre moves within its triangle
    report = stickmorph.check_compatibility(WHEEL, target, WHEEL_EDGES)
    assert isinstance(report, stickmorph.CompatibilityReport)
    assert report.compatible is True
    assert bool(report) is True
    assert report.kind == "none"
    assert report.reason == ""
    assert report.vertices == []
    assert repr(report) == "CompatibilityReport(compatible=True)"


def test_compatible_with_reordered_target_edges():
    target_edges = [[b, a] for a, b in reversed(WHEEL_EDGES)]
    report = stickmorph.check_compatibility(WHEEL, affine(WHEEL, [[2, 0], [0, 1]], [1, 1]),
                                            WHEEL_EDGES, target_edges)
    assert report


def test_mirror_image():
    mirrored = affine(WHEEL, [[-1, 0], [0, 1]], [0, 0])
    report = stickmorph.check_compatibility(WHEEL, mirrored, WHEEL_EDGES)
    assert not report
    assert report.compatible is False
    assert report.kind == "mirror_image"
    assert "mirror" in report.reason
    assert len(report.vertices) == 1
    assert repr(report).startswith("CompatibilityReport(compatible=False, kind='mirror_image'")
    assert repr(report.reason) in repr(report)


def test_mirror_image_of_a_polygon():
    mirrored = affine(SQUARE, [[1, 0], [0, -1]], [0, 0])
    report = stickmorph.check_compatibility(SQUARE, mirrored, SQUARE_EDGES)
    assert report.kind == "mirror_image"


def test_rotation_differs_names_the_vertex():
    # Vertex 2 is a hub with four leaves; the target swaps two neighbouring
    # leaves, which is not a reflection of the cyclic order.
    source = [[5, 5], [0, 2], [0, 0], [0, 1], [-1, 0], [1, 0], [0, -1]]
    edges = [[0, 1], [1, 3], [2, 3], [2, 4], [2, 5], [2, 6]]
    target = [list(p) for p in source]
    target[5], target[6] = [0, -1], [1, 0]  # east and south leaves change places
    report = stickmorph.check_compatibility(source, target, edges)
    assert report.kind == "rotation_differs"
    assert report.vertices == [2]
    assert "vertex 2" in report.reason


def test_exterior_differs():
    report = stickmorph.check_compatibility(WHEEL, WHEEL_OTHER_EXTERIOR, WHEEL_EDGES)
    assert report.kind == "exterior_differs"
    assert "exterior" in report.reason
    assert not report


def test_edge_set_differs():
    # A square and the same square with a diagonal.
    report = stickmorph.check_compatibility(SQUARE, SQUARE, SQUARE_EDGES,
                                            SQUARE_EDGES + [[0, 2]])
    assert report.kind == "edge_set_differs"
    assert sorted(report.vertices) == [0, 2]
    assert "0-2" in report.reason


def test_target_edges_are_validated():
    target_edges = WHEEL_EDGES[:-1] + [[3, 0]]  # drops 2-3, repeats 0-3 the other way
    with pytest.raises(stickmorph.InvalidFigureError) as info:
        stickmorph.check_compatibility(WHEEL, WHEEL, WHEEL_EDGES, target_edges)
    assert info.value.defect == "duplicate_edge"
    assert str(info.value).startswith("target: ")


def test_vertex_count_differs():
    report = stickmorph.check_compatibility([[0, 0], [1, 0]], [[0, 0], [1, 0], [2, 1]], [[0, 1]],
                                            [[0, 1], [1, 2]])
    assert report.kind == "vertex_count_differs"


@pytest.mark.parametrize("which", ["source", "target"])
def test_invalid_figure_is_reported_with_its_role(which):
    # The 4-cycle 0 1 2 3 drawn as a bow tie: edges 0 (0-1) and 2 (2-3) cross.
    crossed = [[0, 0], [1, 1], [1, 0], [0, 1]]
    edges = [[0, 1], [1, 2], [2, 3], [3, 0]]
    args = (crossed, SQUARE) if which == "source" else (SQUARE, crossed)
    with pytest.raises(stickmorph.InvalidFigureError) as info:
        stickmorph.check_compatibility(*args, edges)
    assert info.value.defect == "crossing_edges"
    assert info.value.edges == [0, 2]
    assert str(info.value).startswith(which + ": ")
    with pytest.raises(stickmorph.InvalidFigureError) as plain:
        stickmorph.validate(crossed, edges)
    assert str(info.value) == f"{which}: {plain.value}"


def test_check_compatibility_names_the_bad_argument():
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.check_compatibility(SQUARE, np.zeros((4, 3)), SQUARE_EDGES)
    assert str(info.value) == "target_vertices must have shape (#V, 2), got (4, 3)"
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.check_compatibility(SQUARE, SQUARE, SQUARE_EDGES, [[0, 1.5]])
    assert str(info.value) == "target_edges: edge 0: index 1.5 is not an integer"


def test_compatibility_report_is_read_only():
    report = stickmorph.check_compatibility(SQUARE, SQUARE, SQUARE_EDGES)
    with pytest.raises(AttributeError):
        report.compatible = False
    with pytest.raises(TypeError):
        stickmorph.CompatibilityReport()


# --------------------------------------------------------------------------
# The module and the CLI say the same thing


@pytest.mark.parametrize("vertices,edges", [d[1:3] for d in DEFECTS if d[0] != "nan" and
                                            d[0] != "infinity"],
                         ids=[d[0] for d in DEFECTS if d[0] not in ("nan", "infinity")])
def test_invalid_figure_message_matches_cli(cli, tmp_path, vertices, edges):
    # JSON has no NaN or infinity, so those two defects cannot be in a file.
    bad = write_figure(tmp_path / "bad.json", vertices, edges)
    good = write_figure(tmp_path / "good.json", SQUARE, SQUARE_EDGES)
    result = run_cli(cli, "check", bad, good)
    assert result.returncode == 2, result
    assert result.stdout == ""
    with pytest.raises(stickmorph.InvalidFigureError) as loaded:
        stickmorph.load_figure(bad)
    assert result.stderr == f"error: {loaded.value}\n"
    # The file reader adds only where the figure came from to the engine's
    # message, so the message validate() gives ends the CLI's line.
    with pytest.raises(stickmorph.InvalidFigureError) as validated:
        stickmorph.validate(vertices, edges)
    assert result.stderr.rstrip("\n").endswith(str(validated.value))


def test_json_error_message_matches_cli(cli, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"vertices": [[0, 0], [1, 0]],\n "edges": [[0, 1]], "edges": []}')
    good = write_figure(tmp_path / "good.json", SQUARE, SQUARE_EDGES)
    result = run_cli(cli, "check", bad, good)
    assert result.returncode == 2, result
    with pytest.raises(stickmorph.JsonError) as info:
        stickmorph.load_figure(bad)
    assert result.stderr == f"error: {info.value}\n"


@pytest.mark.parametrize("target,expected_kind", [
    (affine(WHEEL, [[1, 0.5], [0, 2]], [3, 4]).tolist(), "none"),
    (affine(WHEEL, [[-1, 0], [0, 1]], [0, 0]).tolist(), "mirror_image"),
    (WHEEL_OTHER_EXTERIOR, "exterior_differs"),
], ids=["compatible", "mirror", "exterior"])
def test_check_matches_cli(cli, tmp_path, target, expected_kind):
    source_path = write_figure(tmp_path / "source.json", WHEEL, WHEEL_EDGES)
    target_path = write_figure(tmp_path / "target.json", target, WHEEL_EDGES)
    source = stickmorph.load_figure(source_path)
    loaded = stickmorph.load_figure(target_path)
    report = stickmorph.check_compatibility(source["vertices"], loaded["vertices"],
                                            source["edges"], loaded["edges"])
    assert report.kind == expected_kind
    result = run_cli(cli, "check", source_path, target_path)
    if report:
        assert (result.returncode, result.stdout) == (0, "compatible\n")
    else:
        assert (result.returncode, result.stdout) == (1, f"incompatible: {report.reason}\n")


# The morph's options: the same check in the engine for both interfaces
# (check_morph_options), the options named by keyword or by flag.
@pytest.mark.parametrize("keywords", [
    {"method": "barycentric", "turns": 1}, {"method": "barycentric", "rotation": "ccw"},
    {"method": "barycentric", "easing": "in-out"}, {"method": "linear", "turns": 0},
    {"method": "linear", "rotation": "short"}, {"method": "linear", "easing": "none"},
    {"turns": 101}, {"turns": -101}, {"rotation": "left"}, {"easing": "smooth"}, {"method": "spline"},
], ids=lambda keywords: "-".join(f"{k}={v}" for k, v in keywords.items()))
def test_morph_option_messages_match_cli(cli, tmp_path, keywords):
    source = write_figure(tmp_path / "source.json", WHEEL, WHEEL_EDGES)
    target = write_figure(tmp_path / "target.json", affine(WHEEL, [[0, -1], [1, 0]], [1, 2]).tolist(), WHEEL_EDGES)
    with pytest.raises(stickmorph.InvalidArgumentError) as info:
        stickmorph.morph(WHEEL, affine(WHEEL, [[0, -1], [1, 0]], [1, 2]), WHEEL_EDGES, **keywords)
    flags = []
    for keyword, value in keywords.items():
        flags += [stickmorph.OPTION_NAMES[keyword], str(value)]
    out = tmp_path / "out.json"
    result = run_cli(cli, "morph", source, target, "-o", out, *flags)
    assert (result.returncode, result.stdout) == (2, "")
    expected = str(info.value)
    if "method" in keywords:
        expected = expected.replace(f"method='{keywords['method']}'", f"--method {keywords['method']}")
    for keyword in ("turns", "rotation", "easing"):
        if expected.startswith(f"{keyword} "):
            expected = f"option {stickmorph.OPTION_NAMES[keyword]}{expected[len(keyword):]}"
    assert result.stderr == f"error: {expected}\n"
    assert not out.exists()


# --------------------------------------------------------------------------
# Blender embeds Debian's Python: the same module must import there.


def test_module_imports_in_blender():
    blender = shutil.which("blender")
    if blender is None:
        pytest.fail("blender is not installed: run scripts/install_deps.sh")
    module_dir = pathlib.Path(stickmorph.__file__).parent
    script = (f"import sys; sys.path.insert(0, {str(module_dir)!r}); import stickmorph; "
              "print('stickmorph', stickmorph.__version__, "
              "len(stickmorph.decompose([[0, 0], [1, 0], [0, 1]], [[0, 1], [1, 2], [2, 0]])))")
    result = subprocess.run([blender, "-b", "--factory-startup", "--python-exit-code", "1",
                             "--python-expr", script], capture_output=True, text=True,
                            stdin=subprocess.DEVNULL, timeout=300,
                            env={**os.environ, "PYTHONNOUSERSITE": "1"})
    assert result.returncode == 0, result.stdout + result.stderr
    assert "stickmorph 0.1.0 2" in result.stdout


# --------------------------------------------------------------------------
# The shared test data: the module agrees with the CLI on every file.

KINDS = {"none", "vertex_count_differs", "edge_set_differs", "mirror_image", "rotation_differs",
         "exterior_differs"}


def test_malformed_files_match_cli(cli, data_dir, tmp_path):
    files = sorted((data_dir / "malformed").iterdir())
    assert files, "tests/data/malformed is empty"
    good = write_figure(tmp_path / "good.json", SQUARE, SQUARE_EDGES)
    for path in files:
        with pytest.raises(stickmorph.StickMorphError) as info:
            stickmorph.load_figure(path)
        assert type(info.value) in (stickmorph.JsonError, stickmorph.InvalidFigureError), path
        result = run_cli(cli, "check", path, good)
        assert result.returncode == 2, path
        assert result.stderr == f"error: {info.value}\n", path


def test_pairs_match_cli(cli, data_dir):
    sources = sorted((data_dir / "pairs").glob("*/*.source.json"))
    assert sources, "tests/data/pairs has no pairs"
    for source_path in sources:
        target_path = source_path.with_name(source_path.name.replace(".source.", ".target."))
        source = stickmorph.load_figure(source_path)
        target = stickmorph.load_figure(target_path)
        report = stickmorph.check_compatibility(source["vertices"], target["vertices"],
                                                source["edges"], target["edges"])
        expected_compatible = source_path.parent.name == "compatible"
        assert bool(report) == expected_compatible, (source_path, report)
        stem = source_path.name[:-len(".source.json")]
        if stem in KINDS:
            assert report.kind == stem, (source_path, report)
        result = run_cli(cli, "check", source_path, target_path)
        if report:
            assert (result.returncode, result.stdout) == (0, "compatible\n"), source_path
        else:
            assert (result.returncode, result.stdout) == (1, f"incompatible: {report.reason}\n"), \
                source_path
