"""stickmorph.RigidMorphSolver: the rigid morph at any time, for scrubbing (issue 12).

Pinned to morph(): solving morph()'s times in order from a new solver gives morph()'s frames bit
for bit, in any other order to the solvers' tolerance (each solve iterates from the last one);
every scrubbed frame is checked exactly (the module's own checker is run on it again here).
"""
import json
import math

import numpy as np
import pytest

import stickmorph

from conftest import DATA

PAIRS = ["tree_junction", "letter_a", "s_to_u"]


def pair(name):
    folder = DATA / ("paper" if name == "s_to_u" else "pairs/compatible")
    source = json.loads((folder / f"{name}.source.json").read_text())
    target = json.loads((folder / f"{name}.target.json").read_text())
    return (np.array(source["vertices"], dtype=float), np.array(target["vertices"], dtype=float),
            np.array(source["edges"], dtype=np.int64))


@pytest.mark.parametrize("name", PAIRS)
def test_in_order_gives_the_morph_frames_bit_for_bit_and_any_order_nearly(name):
    source, target, edges = pair(name)
    frames = 9
    morph = stickmorph.morph(source, target, edges, frames=frames)
    solver = stickmorph.RigidMorphSolver(source, target, edges)
    for k in range(frames):
        np.testing.assert_array_equal(solver.solve(k / (frames - 1)), morph["frames"][k])
    scale = np.abs(morph["frames"]).max()
    shuffled = stickmorph.RigidMorphSolver(source, target, edges)
    for k in (4, 8, 0, 1, 7, 3, 5, 2, 6):
        frame = shuffled.solve(k / (frames - 1))
        if k in (0, frames - 1):
            np.testing.assert_array_equal(frame, morph["frames"][k])  # the inputs themselves
        else:
            np.testing.assert_allclose(frame, morph["frames"][k], rtol=0, atol=1e-7 * scale)
    for key in ("triangles", "source", "target"):
        np.testing.assert_array_equal(solver.triangulation[key], morph["triangulation"][key])


@pytest.mark.parametrize("name", PAIRS)
def test_scrubbed_frames_are_valid_stick_figures(name):
    source, target, edges = pair(name)
    solver = stickmorph.RigidMorphSolver(source, target, edges)
    for t in np.linspace(0, 1, 23):
        frame = solver.solve(float(t))
        # A frame that crossed itself would raise InvalidFigureError here.
        assert stickmorph.check_compatibility(source, frame, edges).compatible, t


def test_all_nodes_and_the_moving_enclosure():
    source, target, edges = pair("letter_a")
    solver = stickmorph.RigidMorphSolver(source, target, edges)
    tri = solver.triangulation
    n, k = tri["figure_vertices"], tri["enclosure_vertices"]
    nodes = solver.solve(0.5, all_nodes=True)
    assert nodes.shape == (n + k + tri["steiner_vertices"], 2)
    np.testing.assert_array_equal(nodes[:n], solver.solve(0.5))
    np.testing.assert_array_equal(solver.solve(0.0, all_nodes=True), np.asarray(tri["source"]))
    np.testing.assert_array_equal(solver.solve(1.0, all_nodes=True), np.asarray(tri["target"]))
    # The enclosure at t = 1/2 is the source's moved by a similarity (the fitted one at the
    # morph's parameter for that time, which even speed puts near, not at, 1/2): fit it as a
    # complex affine map z -> a z + b and check that it is exact.
    ring0 = np.asarray(tri["source"][n:n + k])
    ring = nodes[n:n + k]
    z0 = ring0[:, 0] + 1j * ring0[:, 1]
    z = ring[:, 0] + 1j * ring[:, 1]
    a, b = np.linalg.lstsq(np.stack([z0, np.ones_like(z0)], axis=1), z, rcond=None)[0]
    assert np.abs(a * z0 + b - z).max() <= 1e-12 * np.abs(z).max()
    sim = solver.similarity
    turn = math.degrees(np.angle(a))
    assert min(sim["angle_degrees"], 0) - 1e-9 <= turn <= max(sim["angle_degrees"], 0) + 1e-9
    assert min(1, sim["scale"]) - 1e-12 <= abs(a) <= max(1, sim["scale"]) + 1e-12


def test_options_reach_the_solver():
    source = np.array([[0.0, 0.0], [1.0, 0.0], [1.5, 1.0]])
    # The same figure turned by -90 degrees about the origin.
    target = source @ np.array([[0.0, -1.0], [1.0, 0.0]])
    edges = np.array([[0, 1], [1, 2]])
    short = stickmorph.RigidMorphSolver(source, target, edges)
    ccw = stickmorph.RigidMorphSolver(source, target, edges, rotation="ccw", turns=1)
    assert short.similarity["angle_degrees"] == pytest.approx(-90)
    assert ccw.similarity["angle_degrees"] == pytest.approx(270 + 360)
    eased = stickmorph.RigidMorphSolver(source, target, edges, easing="in-out")
    first = np.abs(eased.solve(0.05) - source).max()
    even_first = np.abs(short.solve(0.05) - source).max()
    assert first < 0.5 * even_first


def test_bad_arguments():
    source, target, edges = pair("tree_junction")
    solver = stickmorph.RigidMorphSolver(source, target, edges)
    for bad in (-0.1, 1.5, float("nan")):
        with pytest.raises(stickmorph.InvalidArgumentError, match="t must be"):
            solver.solve(bad)
    with pytest.raises(stickmorph.InvalidArgumentError, match="turns must be at most 100"):
        stickmorph.RigidMorphSolver(source, target, edges, turns=101)
    with pytest.raises(stickmorph.InvalidArgumentError, match="unknown rotation direction 'left'"):
        stickmorph.RigidMorphSolver(source, target, edges, rotation="left")
    incompatible = target[::-1].copy()
    with pytest.raises(ValueError):
        stickmorph.RigidMorphSolver(source, incompatible, edges)
