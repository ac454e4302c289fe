"""Extreme coordinates (issue 26; docs/FORMAT.md, "Numeric range").

Every pair the reader accepts (coordinates up to 1e100 in magnitude, down to
the smallest doubles) either morphs, every frame verified, or is refused with
exit 2 (NumericRangeError from the module) saying why; never an internal
error. Pairs out of the numeric stages' comfortable range are morphed in an
exact power-of-two working scale, so their frames are the same figures as at
ordinary scale; size ratios beyond each method's limit are refused up front.
"""
import json
import math
import subprocess

import numpy as np
import pytest

import stickmorph

TIMEOUT_SECONDS = 120
METHODS = ["rigid", "barycentric", "linear"]
PAIRS = ["letter_a", "square_with_spikes", "polyline", "wheel", "tree_junction"]
RIGID_LIMIT, BARYCENTRIC_LIMIT = 1e12, 1e6


def figure(data_dir, name, role):
    return json.loads((data_dir / "pairs" / "compatible" / f"{name}.{role}.json").read_text())


def placed(document, size, offset=(0.0, 0.0)):
    """The figure scaled so that its bounding box's larger side is `size`, centred at `offset`."""
    points = np.array(document["vertices"], dtype=float)
    low, high = points.min(axis=0), points.max(axis=0)
    extent = max(high - low) or 1.0
    moved = (points - (low + high) / 2) / extent * size + np.array(offset)
    return {"vertices": moved.tolist(), "edges": document["edges"]}


def morph_cli(cli, tmp_path, source, target, method):
    a, b, out = tmp_path / "a.json", tmp_path / "b.json", tmp_path / "o.json"
    a.write_text(json.dumps(source))
    b.write_text(json.dumps(target))
    result = subprocess.run([str(cli), "morph", str(a), str(b), "-o", str(out), "--method", method, "--frames", "9"],
                            capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    assert result.returncode in (0, 2), result
    assert "internal error" not in result.stderr, result.stderr
    if result.returncode == 0:
        assert result.stderr == ""
        document = json.loads(out.read_text())
        assert document["frames"][0] == source["vertices"]
        assert document["frames"][-1] == target["vertices"]
        return document
    assert result.stderr.startswith("error: ") and result.stderr.count("\n") == 1
    return result.stderr


# (source size, target size, offset): sizes and positions to the reader's limit.
EXTREMES = [(1e60, 1.0, (0, 0)), (1.0, 1e60, (0, 0)), (1e-50, 1e50, (0, 0)), (5e99, 0.1, (0, 0)),
            (1e-300, 1e-300, (0, 0)), (1e-200, 1e-100, (0, 0)), (1e99, 1e99, (0, 0)), (1e90, 1e90, (9e99, -9e99)),
            (1.0, 1e100, (0, 0)), (1e-100, 1.0, (0, 0)), (1e-307, 1e-307, (0, 0)), (1e-320, 1e-320, (0, 0)),
            (3e-5, 7e4, (0, 0)), (1e30, 1e30, (0, 0)), (1e-30, 1e-30, (1e-29, 0))]


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("case", EXTREMES, ids=[f"{a:g}-{b:g}-{o[0]:g}" for a, b, o in EXTREMES])
def test_extreme_pairs_morph_or_are_refused_with_a_reason(cli, data_dir, tmp_path, case, method):
    source_size, target_size, offset = case
    for name in PAIRS:
        source = placed(figure(data_dir, name, "source"), source_size, offset)
        target = placed(figure(data_dir, name, "target"), target_size, offset)
        outcome = morph_cli(cli, tmp_path, source, target, method)
        if isinstance(outcome, str):
            assert any(reason in outcome for reason in
                       ("differ in size by a factor", "too close to 0", "smallest magnitude", "coincide", "overlap", "cross",
                        "lies on", "beyond the supported magnitude")), (name, outcome)


@pytest.mark.parametrize("method", ["rigid", "barycentric"])
@pytest.mark.parametrize("name", PAIRS)
def test_both_figures_tiny_or_huge_morph_like_at_unit_scale(data_dir, method, name):
    # The working scale is exact: a pair at 2^-900 or 2^300 morphs into the
    # same frames as at unit scale, multiplied by that power of two.
    source = placed(figure(data_dir, name, "source"), 2.0)
    target = placed(figure(data_dir, name, "target"), 2.0)
    edges = np.array(source["edges"], dtype=np.int64).reshape(-1, 2)
    unit = stickmorph.morph(np.array(source["vertices"]), np.array(target["vertices"]), edges, frames=7,
                            method=method)
    for exponent in (-890, 300):
        factor = math.ldexp(1.0, exponent)
        far = stickmorph.morph(np.array(source["vertices"]) * factor, np.array(target["vertices"]) * factor, edges,
                               frames=7, method=method)
        assert len(far["frames"]) == 7
        assert far["frames"][0].tolist() == (np.array(source["vertices"]) * factor).tolist()
        assert far["frames"][-1].tolist() == (np.array(target["vertices"]) * factor).tolist()
        for frame in far["frames"]:
            stickmorph.validate(frame, edges)
        np.testing.assert_allclose(np.array(far["frames"]) / factor, np.array(unit["frames"]), rtol=0, atol=1e-9)


@pytest.mark.parametrize("method,limit", [("rigid", RIGID_LIMIT), ("barycentric", BARYCENTRIC_LIMIT)])
@pytest.mark.parametrize("name", PAIRS)
def test_size_ratio_limit_edges(cli, data_dir, tmp_path, method, limit, name):
    source = placed(figure(data_dir, name, "source"), 1.0)
    inside = placed(figure(data_dir, name, "target"), limit / 2)
    outcome = morph_cli(cli, tmp_path, source, inside, method)
    assert isinstance(outcome, dict), outcome
    beyond = placed(figure(data_dir, name, "target"), limit * 2)
    outcome = morph_cli(cli, tmp_path, source, beyond, method)
    assert isinstance(outcome, str) and "differ in size by a factor of" in outcome and "limit of" in outcome
    # The straight-line morph takes any ratio.
    assert isinstance(morph_cli(cli, tmp_path, source, placed(figure(data_dir, name, "target"), 1e100), "linear"),
                      dict)


def test_module_raises_numeric_range_error(data_dir):
    source = placed(figure(data_dir, "letter_a", "source"), 1.0)
    target = placed(figure(data_dir, "letter_a", "target"), 1e60)
    edges = np.array(source["edges"], dtype=np.int64)
    assert issubclass(stickmorph.NumericRangeError, stickmorph.StickMorphError)
    assert issubclass(stickmorph.NumericRangeError, ValueError)
    for method in ("rigid", "barycentric"):
        with pytest.raises(stickmorph.NumericRangeError, match="differ in size by a factor"):
            stickmorph.morph(np.array(source["vertices"]), np.array(target["vertices"]), edges, method=method)
    tiny = np.array(source["vertices"]) * 1e-300
    with pytest.raises(stickmorph.NumericRangeError, match="below the smallest magnitude the morph carries"):
        stickmorph.morph(tiny, tiny * 2, edges)
    # A coordinate far below the others cannot be carried to the working scale.
    spread = np.array(source["vertices"]) * 1e100
    zero = np.argwhere(spread == 0)[0]
    spread[tuple(zero)] = 1e-300  # far below 2^-1022 times the largest
    with pytest.raises(stickmorph.NumericRangeError, match="too close to 0"):
        stickmorph.morph(spread, spread, edges)


def test_check_decides_tiny_and_huge_figures(cli, data_dir, tmp_path):
    # Algorithm 1's angle sums no longer underflow (the decomposition was an
    # internal error for figures of size 1e-200).
    for size in (1e-300, 1e-200, 1e99):
        for name in PAIRS:
            a, b = tmp_path / "a.json", tmp_path / "b.json"
            a.write_text(json.dumps(placed(figure(data_dir, name, "source"), size)))
            b.write_text(json.dumps(placed(figure(data_dir, name, "target"), size)))
            result = subprocess.run([str(cli), "check", str(a), str(b)], capture_output=True, text=True,
                                    timeout=TIMEOUT_SECONDS)
            assert (result.returncode, result.stdout) == (0, "compatible\n"), (size, name, result)


def test_solver_time_argument_errors(data_dir):
    source = np.array(figure(data_dir, "letter_a", "source")["vertices"], dtype=float)
    target = np.array(figure(data_dir, "letter_a", "target")["vertices"], dtype=float)
    edges = np.array(figure(data_dir, "letter_a", "source")["edges"], dtype=np.int64)
    solver = stickmorph.RigidMorphSolver(source, target, edges)
    with pytest.raises(stickmorph.InvalidArgumentError, match="t must be one number"):
        solver.solve(np.array([0.1, 0.2]))
    assert solver.solve(np.float64(0.5)).shape == source.shape
    # None means the default for method as for every other option.
    default = stickmorph.morph(source, target, edges, frames=3, method=None)
    assert default["stats"]["method"] == "rigid"


@pytest.mark.parametrize("size", [1e-250, 1e-100, 1e99])
@pytest.mark.parametrize("command", ["correspond", "morph"])
def test_correspond_auto_at_extreme_magnitudes(cli, data_dir, tmp_path, size, command):
    # The matching runs in the working scale too: at 1e99 its similarity fit
    # overflowed into a NaN residual ("JSON cannot represent the number NaN").
    for name in ("letter_a", "square_with_spikes", "wheel"):
        a, b, out = tmp_path / "a.json", tmp_path / "b.json", tmp_path / "o.json"
        a.write_text(json.dumps(placed(figure(data_dir, name, "source"), size)))
        b.write_text(json.dumps(placed(figure(data_dir, name, "target"), size)))
        extra = ["--correspond", "auto", "--frames", "5"] if command == "morph" else []
        result = subprocess.run([str(cli), command, str(a), str(b), "-o", str(out), *extra], capture_output=True,
                                text=True, timeout=TIMEOUT_SECONDS)
        assert result.returncode == 0, (name, result.stderr)
        document = json.loads(out.read_text())
        assert "correspondence" in document


@pytest.mark.parametrize("factor", [1e-250, 2.0 ** -890, 1e99])
@pytest.mark.parametrize("name", ["letter_a", "square_with_spikes", "wheel", "polyline"])
def test_triangulation_and_solvers_in_the_working_scale(data_dir, name, factor):
    # triangulate_figures, MorphSolver and RigidMorphSolver work in the same
    # exact working scale as morph(): at 1e-250 the triangulation's own
    # verification failed before ("the triangles around ... turn 0 times").
    source = figure(data_dir, name, "source")
    edges = np.array(source["edges"], dtype=np.int64).reshape(-1, 2)
    a = np.array(source["vertices"], dtype=float) * factor
    b = np.array(figure(data_dir, name, "target")["vertices"], dtype=float) * factor
    triangulation = stickmorph.triangulate_figures(a, b, edges)
    assert np.array_equal(np.asarray(triangulation["source"])[: len(a)], a)
    solvers = [stickmorph.MorphSolver(triangulation, edges), stickmorph.RigidMorphSolver(a, b, edges)]
    for solver in solvers:
        assert np.array_equal(solver.solve(0.0), a) and np.array_equal(solver.solve(1.0), b)
        for t in (0.25, 0.5, 0.75):
            stickmorph.validate(solver.solve(t), edges)


def test_rigid_solver_refuses_a_ratio_naming_the_sizes_as_given(data_dir):
    source = figure(data_dir, "letter_a", "source")
    edges = np.array(source["edges"], dtype=np.int64)
    a = np.array(source["vertices"], dtype=float)
    b = np.array(figure(data_dir, "letter_a", "target")["vertices"], dtype=float) * 1e60
    with pytest.raises(stickmorph.NumericRangeError, match=r"and the target \(size [0-9.]+e\+60\)"):
        stickmorph.RigidMorphSolver(a, b, edges)


@pytest.mark.parametrize("size", [1e-250, 1e99])
def test_triangulate_command_at_extreme_magnitudes(cli, data_dir, tmp_path, size):
    for name in PAIRS:
        a, b, out = tmp_path / "a.json", tmp_path / "b.json", tmp_path / "o.json"
        a.write_text(json.dumps(placed(figure(data_dir, name, "source"), size)))
        b.write_text(json.dumps(placed(figure(data_dir, name, "target"), size)))
        result = subprocess.run([str(cli), "triangulate", str(a), str(b), "-o", str(out)], capture_output=True,
                                text=True, timeout=TIMEOUT_SECONDS)
        assert result.returncode == 0, (name, result.stderr)
