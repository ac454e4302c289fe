"""stickmorph.clean_drawing and clean_figure (issue 32): the module's face of
`stickmorph clean`, with the same results and InvalidDrawingError for bad
drawings."""
import json

import numpy as np
import pytest

import stickmorph


def test_crossing_strokes_share_a_vertex_and_the_result_reads_as_arrays():
    cleaned = stickmorph.clean_drawing([[[0, 0], [10, 10]], np.array([[0, 10], [10, 0]], dtype=float)])
    assert isinstance(cleaned.vertices, np.ndarray) and cleaned.vertices.shape == (5, 2)
    assert cleaned.vertices[4].tolist() == [5, 5]
    assert cleaned.edges.shape == (4, 2) and cleaned.edges.dtype == np.int64
    assert [path.tolist() for path in cleaned.stroke_vertices] == [[0, 4, 1], [2, 4, 3]]
    assert [points.tolist() for points in cleaned.point_vertex] == [[0, 1], [2, 3]]
    assert cleaned.cyclic == [False, False]
    assert (cleaned.junctions_made, cleaned.ends_snapped, cleaned.points_merged) == (1, 0, 0)
    assert cleaned.changes == [{"kind": "crossing", "stroke": 0, "point": None, "other_stroke": 1,
                                "at": (5.0, 5.0), "distance": 0.0}]
    assert cleaned.summary() == "1 junction made"
    assert "1 junction made" in repr(cleaned)
    stickmorph.validate(cleaned.vertices, cleaned.edges)


def test_the_module_and_the_cli_agree(cli, tmp_path, data_dir):
    drawing = data_dir / "drawings" / "stick_man_drawn.source.json"
    out = tmp_path / "out.json"
    import subprocess
    subprocess.run([str(cli), "clean", drawing, "-o", out], check=True, capture_output=True)
    document = json.loads(out.read_text())
    strokes = json.loads(drawing.read_text())["strokes"]
    cleaned = stickmorph.clean_drawing([s["points"] for s in strokes], [s.get("cyclic", False) for s in strokes])
    assert cleaned.vertices.tolist() == document["vertices"]
    assert cleaned.edges.tolist() == document["edges"]
    assert cleaned.tolerance == document["cleaning"]["tolerance"]
    assert [list(c["at"]) for c in cleaned.changes] == [c["at"] for c in document["cleaning"]["changes"]]


def test_a_stopped_short_end_snaps_and_tolerance_is_absolute():
    strokes = [[[0, 0], [10, 0]], [[4, -10], [4, -0.1]]]
    snapped = stickmorph.clean_drawing(strokes)
    assert snapped.ends_snapped == 1
    assert snapped.changes[0]["kind"] == "snap" and snapped.changes[0]["distance"] == pytest.approx(0.1)
    assert stickmorph.clean_drawing(strokes, tolerance=0.05).ends_snapped == 0
    assert stickmorph.clean_drawing(strokes, tolerance=0).changes == []


def test_a_cyclic_stroke_closes():
    cleaned = stickmorph.clean_drawing([[[0, 0], [4, 0], [0, 4]]], cyclic=[True])
    assert len(cleaned.edges) == 3 and cleaned.cyclic == [True]


def test_clean_figure_keeps_the_vertex_order():
    cleaned = stickmorph.clean_figure([[0, 0], [2, 2], [0, 2], [2, 0]], [[0, 1], [2, 3]])
    assert cleaned.vertices[:4].tolist() == [[0, 0], [2, 2], [0, 2], [2, 0]]
    assert cleaned.junctions_made == 1
    again = stickmorph.clean_figure(cleaned.vertices, cleaned.edges, tolerance=cleaned.tolerance)
    assert again.changes == [] and again.edges.tolist() == cleaned.edges.tolist()


@pytest.mark.parametrize("strokes,cyclic,defect,stroke,other,text", [
    ([], None, "no_strokes", None, None, "the drawing has no strokes"),
    ([[[0, 0], [1, 1]], [[3, 3]]], None, "too_few_points", 1, None, "stroke 1 has a single point"),
    ([[[0, 0], [1, 1]], []], None, "too_few_points", 1, None, "stroke 1 has no points"),
    ([[[0, 0], [5, 0]], [[2, 0], [8, 0]]], None, "overlap", 0, 1, "strokes 0 and 1 overlap along a length"),
    ([[[0, 0], [5, 0], [5, 5], [5, 1]]], None, "retrace", 0, 0, "stroke 0 retraces itself"),
    ([[[0, 0], [5, 0]]], [True], "retrace", 0, 0, "stroke 0 retraces itself"),
    ([[[0, 0], [np.inf, 0]]], None, "non_finite_coordinate", 0, None, "point 1 of stroke 0 is not finite"),
    ([[[0, 0], [1e101, 0]]], None, "coordinate_too_large", 0, None, "point 1 of stroke 0 is at"),
])
def test_bad_drawings_raise_invalid_drawing_error_naming_the_stroke(strokes, cyclic, defect, stroke, other, text):
    with pytest.raises(stickmorph.InvalidDrawingError) as caught:
        stickmorph.clean_drawing(strokes, cyclic)
    error = caught.value
    assert isinstance(error, ValueError) and isinstance(error, stickmorph.StickMorphError)
    assert text in str(error)
    assert (error.defect, error.stroke, error.other_stroke) == (defect, stroke, other)


def test_bad_arguments_raise_invalid_argument_error():
    with pytest.raises(stickmorph.InvalidArgumentError, match="cyclic has 2 entries for 1 strokes"):
        stickmorph.clean_drawing([[[0, 0], [1, 1]]], [True, False])
    with pytest.raises(stickmorph.InvalidArgumentError, match="tolerance is -1"):
        stickmorph.clean_drawing([[[0, 0], [1, 1]]], tolerance=-1)
    with pytest.raises(stickmorph.InvalidArgumentError, match="tolerance must be a number"):
        stickmorph.clean_drawing([[[0, 0], [1, 1]]], tolerance="big")
    with pytest.raises(stickmorph.InvalidArgumentError, match=r"strokes\[0\] must have shape"):
        stickmorph.clean_drawing([[[0, 0, 0], [1, 1, 1]]])
    with pytest.raises(stickmorph.InvalidArgumentError, match="strokes must be a list"):
        stickmorph.clean_drawing("strokes")
    with pytest.raises(stickmorph.InvalidDrawingError, match="vertex 7 does not exist") as caught:
        stickmorph.clean_figure([[0, 0], [1, 1]], [[0, 7]])
    assert caught.value.defect == "index_out_of_range" and caught.value.stroke == 0
