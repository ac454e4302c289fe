"""The add-on's bpy-free modules (addon/stick_morph/core.py, common.py) outside
Blender, in Debian's /usr/bin/python3 with the module built in
$STICKMORPH_BUILD_DIR/python (conftest.py puts it on sys.path).

core.py and common.py are loaded from the repository by path, as submodules of
a package object made here: the add-on's __init__.py is not run, so these
tests see only what core imports itself. That __init__.py imports no bpy at
import time is checked separately, in a child Python without bpy.

Blender-side behaviour (reading meshes, baking, the operator, the panel) is
tested in tests/blender, inside Blender.
"""
import dataclasses
import importlib
import json
import importlib.machinery
import pathlib
import subprocess
import sys
import types

import numpy as np
import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
ADDON = REPO / "addon" / "stick_morph"
# Not "stick_morph": an add-on of that name installed in this Python is not
# the one under test.
PACKAGE = "stick_morph_under_test"


def load_addon_module(name):
    """addon/stick_morph/<name>.py as PACKAGE.<name>, without running __init__.py."""
    if PACKAGE not in sys.modules:
        package = types.ModuleType(PACKAGE)
        package.__path__ = [str(ADDON)]
        package.__spec__ = importlib.machinery.ModuleSpec(PACKAGE, None, is_package=True)
        package.__spec__.submodule_search_locations = package.__path__
        sys.modules[PACKAGE] = package
    return importlib.import_module(f"{PACKAGE}.{name}")


core = load_addon_module("core")
common = load_addon_module("common")


def test_the_package_imports_without_bpy():
    # The real package this time, __init__.py included, in a Python whose
    # sys.modules holds no bpy (there is none outside Blender: an `import bpy`
    # at import time fails the child).
    code = ("import sys; sys.path.insert(0, sys.argv[1]); import stick_morph; import stick_morph.core as c; "
            "assert 'bpy' not in sys.modules, 'bpy imported'; "
            "print(stick_morph.bl_info['name'], c.ease(0.5, 'IN_OUT'))")
    out = subprocess.run([sys.executable, "-c", code, str(ADDON.parent)], capture_output=True, text=True,
                         timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "Stick Morph 0.5"
    # And the loader above did not run __init__.py.
    assert not hasattr(sys.modules[PACKAGE], "bl_info")
    assert "bpy" not in sys.modules


def test_core_finds_the_built_engine():
    engine = core.load_engine()
    assert pathlib.Path(engine.__file__).parent.name == "python"
    assert hasattr(engine, "morph") and hasattr(engine, "check_compatibility")


# ------------------------------------------------------------- settings ----

def test_the_addons_copy_of_the_limits_is_the_engines():
    # common.ENGINE_LIMITS gives the properties their ranges at registration,
    # before the module is known to load: it must be stickmorph.limits exactly.
    engine = core.load_engine()
    assert common.ENGINE_LIMITS == engine.limits
    assert core.engine_limits() == engine.limits
    # The settings' defaults are the engine's (and hence the properties').
    assert core.BakeSettings().frame_count == engine.limits["default_frames"]
    assert core.BakeSettings().enclosure_sides == engine.limits["default_enclosure_sides"]


def test_bake_settings_defaults_and_frozen():
    settings = core.BakeSettings()
    assert core.BakeSettings is common.BakeSettings
    assert (settings.frame_count, settings.frame_start, settings.easing, settings.plane) == (50, 1, "NONE", "AUTO")
    # The engine's default motion, turning the short way with no extra turns.
    assert (settings.motion, settings.rotation, settings.turns) == ("RIGID", "SHORT", 0)
    engine = core.load_engine()
    assert settings.motion.lower() == engine.METHOD_NAMES[0] == "rigid"
    assert tuple(m.lower() for m in core.MOTIONS) == engine.METHOD_NAMES
    assert tuple(r.lower() for r in core.ROTATIONS) == engine.ROTATION_NAMES
    assert set(core.RIGID_EASINGS) == set(core.EASINGS)
    assert sorted(core.RIGID_EASINGS.values()) == sorted(engine.EASING_NAMES)
    assert settings.planarity_tolerance == 1e-4
    # One bake's options cannot change under it.
    with pytest.raises(dataclasses.FrozenInstanceError):
        settings.frame_count = 3
    assert dataclasses.replace(settings, frame_count=3).frame_count == 3


@pytest.mark.parametrize("changes, fragment", [
    ({"frame_count": 1}, "between 2 and 100000, got 1"),
    ({"frame_count": 100001}, "between 2 and 100000, got 100001"),
    ({"frame_count": 5, "enclosure_sides": 2}, "3 to 1000 sides, got 2"),
    ({"frame_count": 5, "enclosure_sides": 1001}, "3 to 1000 sides, got 1001"),
    ({"easing": "BOUNCE"}, "unknown easing 'BOUNCE'"),
    ({"motion": "SPLINE"}, "unknown motion 'SPLINE'"),
    ({"motion": "rigid"}, "unknown motion 'rigid'"),  # the add-on's names are upper case
    ({"rotation": "LEFT"}, "unknown rotation 'LEFT'"),
    ({"turns": 101}, "whole number from -100 to 100, got 101"),
    ({"turns": -101}, "whole number from -100 to 100, got -101"),
    ({"turns": 1.5}, "whole number from -100 to 100, got 1.5"),
    # Out of range is refused whatever the motion, like the enclosure for LINEAR.
    ({"turns": 1000, "motion": "BARYCENTRIC"}, "got 1000"),
])
def test_compute_morph_refuses_settings_out_of_range(changes, fragment):
    # Blender clamps the operator's frame_count and enclosure_sides to their
    # hard limits, so out-of-range values reach core only from scripts that
    # call it directly; it refuses them before any engine work (no pair).
    with pytest.raises(core.StickMorphError, match=fragment):
        core.compute_morph(None, core.BakeSettings(**changes))


# ----------------------------------------------------------------- plane ----

def test_fit_plane_auto_tilted_and_parallel():
    rng = np.random.default_rng(1)
    normal = np.array([0.3, -0.4, 0.866])
    normal /= np.linalg.norm(normal)
    u = np.cross(normal, [1.0, 0.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    a = rng.normal(size=(6, 2)) @ np.array([u, v])
    b = rng.normal(size=(6, 2)) @ np.array([u, v]) + 5 * normal + [1, 2, 3]  # a parallel plane far off
    plane = core.fit_plane(a, b, "AUTO")
    assert abs(plane.normal @ normal) == pytest.approx(1.0, abs=1e-12)
    assert plane.normal @ normal > 0  # the side of the nearest axis plane (XY: +Z)
    x_in_plane = np.array([1.0, 0, 0]) - plane.normal[0] * plane.normal  # X projected into the plane
    assert np.allclose(np.cross(plane.u, x_in_plane), 0, atol=1e-12) and plane.u[0] > 0
    xy, h = core.project(a, plane)
    assert np.allclose(core.unproject(xy, h, plane), a, atol=1e-12)
    _, hb = core.project(b, plane)
    assert core.planarity_deviation(hb)[0] < 1e-12


def test_fit_plane_collinear_and_axis():
    line = np.array([[0, 0, 0], [1, 1, 0], [2, 2, 0.0]])
    plane = core.fit_plane(line, line + [0, 0, 0], "AUTO")
    assert abs(plane.normal @ plane.u) < 1e-12 and np.linalg.norm(plane.normal) == pytest.approx(1)
    assert abs(plane.normal[2]) == pytest.approx(1.0)
    # A figure in an axis plane gets exactly that plane's axes.
    square = np.array([[0, 5, 0], [1, 5, 0], [1, 5, 1], [0, 5, 1.0]])
    auto = core.fit_plane(square, square + [3, 0, 0], "AUTO")
    assert np.allclose(auto.u, [1, 0, 0], atol=1e-12) and np.allclose(auto.v, [0, 0, 1], atol=1e-12)
    assert np.allclose(auto.normal, [0, -1, 0], atol=1e-12)
    xz = core.fit_plane(line, line, "XZ")
    assert np.allclose(xz.normal, [0, -1, 0])
    with pytest.raises(core.StickMorphError):
        core.fit_plane(line, line, "UV")


@pytest.mark.parametrize("normal", [[0, 0, 1], [1, 0, 0], [0, 1, 0], [1, 1, 1], [1, -1, 0.01], [0.577, 0.577, -0.578]])
def test_fit_plane_gives_an_orthonormal_right_handed_frame(normal):
    # The nearest axis plane's u, projected into the plane, is never too
    # short to normalise, whatever the normal (fit_plane relies on it).
    normal = np.array(normal, dtype=np.float64) / np.linalg.norm(normal)
    helper = np.array([1.0, 0, 0]) if abs(normal[0]) < 0.9 else np.array([0, 1.0, 0])
    u = np.cross(normal, helper)
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    points = np.array([[0, 0], [1, 0.2], [0.3, 1.5], [-1, 0.7]]) @ np.array([u, v])
    plane = core.fit_plane(points, points + 2 * u, "AUTO")
    frame = np.array([plane.u, plane.v, plane.normal])
    assert np.allclose(frame @ frame.T, np.eye(3), atol=1e-12)
    assert np.allclose(np.cross(plane.u, plane.v), plane.normal, atol=1e-12)
    assert abs(plane.normal @ normal) == pytest.approx(1.0, abs=1e-9)


# ---------------------------------------------------------- edges, easing ----

def test_edge_sets_and_easing():
    assert core.compare_edge_sets([[0, 1], [1, 2]], [[2, 1], [1, 0]]) is None
    message = core.compare_edge_sets([[0, 1], [1, 2]], [[0, 1], [0, 2]], "A", "B")
    assert "only in 'A': 1-2" in message and "only in 'B': 0-2" in message
    t = np.linspace(0, 1, 11)
    assert np.array_equal(core.ease(t, "NONE"), t)
    eased = core.ease(t, "IN_OUT")
    assert eased[0] == 0 and eased[-1] == 1 and np.all(np.diff(eased) > 0)
    for motion in ("BARYCENTRIC", "LINEAR"):
        index = core.ease_sample_indices(11, "IN_OUT", motion)
        assert core.engine_frame_count(11, "IN_OUT", motion) == 10 * core.EASE_OVERSAMPLING + 1
        assert index[0] == 0 and index[-1] == core.engine_frame_count(11, "IN_OUT", motion) - 1
        assert np.array_equal(core.ease_sample_indices(7, "NONE", motion), np.arange(7))
    # RIGID: the engine eases, exactly the output frames are computed.
    for easing in core.EASINGS:
        assert core.engine_frame_count(11, easing, "RIGID") == 11
        assert np.array_equal(core.ease_sample_indices(11, easing, "RIGID"), np.arange(11))


# ------------------------------------------------------------ the morph ----

# A tree (a junction at 0 with three arms) and its target pose, in 2D.
TREE_SOURCE = np.array([[0, 0], [1, 0], [2, 0.2], [-0.5, 0.9], [-1.0, 1.8], [-0.5, -0.9], [-0.8, -1.9]])
TREE_TARGET = np.array([[0, 0], [0.9, 0.5], [1.5, 1.3], [-0.9, 0.4], [-1.9, 0.2], [0.1, -1.0], [0.9, -1.6]])
TREE_EDGES = np.array([[0, 1], [1, 2], [0, 3], [3, 4], [0, 5], [5, 6]])

# A tilted plane; the target lies in a parallel plane 0.7 above the source's.
_N = np.array([0.2, -0.5, 0.84]) / np.linalg.norm([0.2, -0.5, 0.84])
_U = np.cross(_N, [1.0, 0, 0]) / np.linalg.norm(np.cross(_N, [1.0, 0, 0]))
_V = np.cross(_N, _U)


def in_space(xy, offset):
    return np.asarray(xy, dtype=np.float64) @ np.array([_U, _V]) + offset


SOURCE_WORLD = in_space(TREE_SOURCE, [1.0, -2.0, 0.5])
TARGET_WORLD = in_space(TREE_TARGET * 0.8, [4.0, 1.0, -0.5] + 0.7 * _N)


def prepare(source=SOURCE_WORLD, target=TARGET_WORLD, settings=core.BakeSettings(), source_faces=0,
            target_edges=TREE_EDGES):
    return core.prepare_pair(source, TREE_EDGES, source_faces, "Arm", target, target_edges, 0, "Arm pose",
                             settings)


def test_morph_starts_at_the_source_and_ends_at_the_target_in_world_space():
    prepared = prepare()
    assert (prepared.source_name, prepared.target_name) == ("Arm", "Arm pose")
    settings = core.BakeSettings(frame_count=7)
    morph = core.compute_morph(prepared, settings)
    assert morph.frames_world.shape == (7, len(TREE_SOURCE), 3)
    size = prepared.size
    assert np.abs(morph.frames_world[0] - SOURCE_WORLD).max() <= 1e-9 * size
    assert np.abs(morph.frames_world[-1] - TARGET_WORLD).max() <= 1e-9 * size
    # Every frame lies in a plane parallel to the figures' planes, moving from
    # the source's to the target's in equal steps (uniform times, linear easing).
    heights = (morph.frames_world - prepared.plane.origin) @ prepared.plane.normal
    assert np.ptp(heights, axis=1).max() <= 1e-9 * size
    assert abs(heights[-1, 0] - heights[0, 0]) > 0.1
    assert np.allclose(np.diff(heights[:, 0]), (heights[-1, 0] - heights[0, 0]) / 6, atol=1e-9 * size)
    assert morph.stats["steiner_vertices"] >= 0 and morph.triangulation is not None
    # Easing picks frames of a finer uniform morph: the first step is shorter.
    eased = core.compute_morph(prepared, dataclasses.replace(settings, easing="IN_OUT"))
    assert np.abs(eased.frames_world[[0, -1]] - morph.frames_world[[0, -1]]).max() <= 1e-9 * size
    step = np.linalg.norm(np.diff(eased.frames_world, axis=0), axis=2).max(axis=1)
    linear_step = np.linalg.norm(np.diff(morph.frames_world, axis=0), axis=2).max(axis=1)
    assert step[0] < 0.7 * linear_step[0] and step[3] > 1.2 * linear_step[3]


@pytest.mark.parametrize("motion, changes", [
    ("BARYCENTRIC", {"weights": "uniform"}), ("BARYCENTRIC", {"enclosure_sides": 9}),
    ("BARYCENTRIC", {"steiner": "aronov"}), ("BARYCENTRIC", {"motion": "RIGID"}),
    ("BARYCENTRIC", {"motion": "LINEAR"}),
    ("RIGID", {"rotation": "CW"}), ("RIGID", {"rotation": "CCW", "turns": 1}), ("RIGID", {"turns": -1}),
    ("RIGID", {"easing": "IN_OUT"}),
])
def test_the_settings_reach_the_engine(motion, changes):
    # (The tree's short way is counterclockwise: CCW alone would change nothing.)
    prepared = prepare()
    base = core.compute_morph(prepared, core.BakeSettings(frame_count=5, motion=motion))
    other = core.compute_morph(prepared, core.BakeSettings(**{"frame_count": 5, "motion": motion, **changes}))
    assert np.abs(other.frames_world[[0, -1]] - base.frames_world[[0, -1]]).max() <= 1e-9 * prepared.size
    # (Frame 1: easing in-out keeps the middle frame where it is.)
    assert np.abs(other.frames_world[1] - base.frames_world[1]).max() > 1e-6 * prepared.size, changes


def test_an_engine_refusal_is_a_user_message():
    with pytest.raises(core.StickMorphError, match="stickmorph"):
        core.compute_morph(prepare(), core.BakeSettings(frame_count=5, weights="nonsense"))


def test_options_a_motion_does_not_use_are_not_given_to_the_engine(monkeypatch):
    # The engine refuses rotation/turns/easing with another method than
    # rigid, and steiner/weights/enclosure_sides/verify with linear.
    engine = core.load_engine()
    calls = []
    morph = engine.morph
    monkeypatch.setattr(engine, "morph", lambda *args, **kwargs: calls.append(kwargs) or morph(*args, **kwargs))
    prepared = prepare()
    settings = core.BakeSettings(frame_count=4, rotation="CW", turns=3, easing="IN_OUT", steiner="sg2001",
                                 weights="uniform", enclosure_sides=7)
    for motion in core.MOTIONS:
        core.compute_morph(prepared, dataclasses.replace(settings, motion=motion))
    rigid, barycentric, linear = calls
    assert rigid == {"frames": 4, "method": "rigid", "steiner": "sg2001", "weights": "uniform",
                     "enclosure_sides": 7, "verify": True, "rotation": "cw", "turns": 3, "easing": "in-out"}
    assert barycentric == {"frames": 3 * core.EASE_OVERSAMPLING + 1, "method": "barycentric",
                           "steiner": "sg2001", "weights": "uniform", "enclosure_sides": 7, "verify": True}
    assert linear == {"frames": 3 * core.EASE_OVERSAMPLING + 1, "method": "linear"}


def plane_xy(morph, prepared):
    """The frames' in-plane coordinates (F, V, 2)."""
    return np.array([core.project(frame, prepared.plane)[0] for frame in morph.frames_world])


def test_the_default_motion_is_rigid_and_is_the_engines_rigid_morph():
    prepared = prepare()
    engine = core.load_engine()
    for easing, engine_easing in (("NONE", None), ("IN_OUT", "in-out")):
        morph = core.compute_morph(prepared, core.BakeSettings(frame_count=9, easing=easing))
        assert morph.motion == "RIGID" and morph.stats["method"] == "rigid"
        assert morph.stats["rigid"]["easing"] == (engine_easing or "none")
        # Exactly frame_count engine frames, not picked from a finer morph.
        expected = engine.morph(prepared.source_xy, prepared.target_xy, prepared.edges, frames=9,
                                method="rigid", easing=engine_easing)
        xy = plane_xy(morph, prepared)
        assert np.abs(xy - expected["frames"]).max() <= 1e-9 * prepared.size
        for frame in xy:  # valid: a stick figure compatible with the source
            assert engine.check_compatibility(prepared.source_xy, frame, prepared.edges)
        # The height moves with the eased time, in step with the figure.
        heights = (morph.frames_world - prepared.plane.origin) @ prepared.plane.normal
        t = core.ease(np.linspace(0, 1, 9), easing)
        h0, h1 = prepared.source_h.mean(), prepared.target_h.mean()
        assert np.allclose(heights.mean(axis=1), (1 - t) * h0 + t * h1, atol=1e-9 * prepared.size)
        assert morph.invalid_frames == []


def test_barycentric_reproduces_the_previous_bakes():
    # Before the motion option the add-on always baked method="barycentric",
    # easing by picking frames of an oversampled morph.
    prepared = prepare()
    engine = core.load_engine()
    for easing in core.EASINGS:
        morph = core.compute_morph(prepared, core.BakeSettings(frame_count=7, motion="BARYCENTRIC", easing=easing))
        m = 7 if easing == "NONE" else 6 * core.EASE_OVERSAMPLING + 1
        old = engine.morph(prepared.source_xy, prepared.target_xy, prepared.edges, frames=m,
                           steiner="improved", weights="mvc", enclosure_sides=6, method="barycentric",
                           verify=True)
        index = np.rint(core.ease(np.arange(7) / 6, easing) * (m - 1)).astype(int)
        assert np.abs(plane_xy(morph, prepared) - old["frames"][index]).max() <= 1e-9 * prepared.size
        assert morph.stats["method"] == "barycentric" and "rigid" not in morph.stats
        assert core.motion_summary(morph) == ("Barycentric", "barycentric")


def turning_angles(frames):
    """The figure's orientation in each frame relative to the first (2D
    Procrustes angle about the centroid), unwrapped: the total turn so far."""
    first = frames[0] - frames[0].mean(axis=0)
    angles = []
    for frame in frames:
        d = frame - frame.mean(axis=0)
        cross = np.sum(first[:, 0] * d[:, 1] - first[:, 1] * d[:, 0])
        dot = np.sum(first * d)
        angles.append(np.arctan2(cross, dot))
    return np.degrees(np.unwrap(angles))


def quarter_turn_pair():
    """The tree and the tree turned by -90 degrees (clockwise) in its plane."""
    turned = TREE_SOURCE @ np.array([[0.0, -1.0], [1.0, 0.0]])  # (x, y) -> (y, -x)
    return prepare(target=in_space(turned, [1.0, -2.0, 0.5]))


@pytest.mark.parametrize("rotation, turns, degrees", [
    ("SHORT", 0, -90), ("CW", 0, -90), ("CCW", 0, 270), ("SHORT", 1, 270), ("CCW", 1, 630), ("CW", -1, -450),
])
def test_rotation_and_turns_choose_the_way_round(rotation, turns, degrees):
    prepared = quarter_turn_pair()
    morph = core.compute_morph(prepared, core.BakeSettings(frame_count=25, rotation=rotation, turns=turns))
    rigid = morph.stats["rigid"]
    assert (rigid["rotation"], rigid["turns"]) == (rotation.lower(), turns)
    assert rigid["similarity"]["angle_degrees"] == pytest.approx(degrees)
    # The figure really turns that far, in even steps (a pure rotation is rigid).
    angles = turning_angles(plane_xy(morph, prepared))
    assert angles[-1] == pytest.approx(degrees, abs=1e-6)
    assert np.allclose(np.diff(angles), degrees / 24, atol=1e-6)
    short, text = core.motion_summary(morph)
    assert short == "Rigid guide: 23/23" and text == "rigid: 23/23 frames follow the rigid guide"



def test_motion_summary_of_the_rigid_guide():
    def summary(guide, frames=30):
        morph = core.MorphResult(np.zeros((frames, 1, 3)), None, {"rigid": {"guide_frames": guide}}, "RIGID")
        return core.motion_summary(morph)

    assert summary({"exact": 20, "blended": 8, "barycentric": 0}) == (
        "Rigid guide: 28/28", "rigid: 28/28 frames follow the rigid guide")
    assert summary({"exact": 20, "blended": 5, "barycentric": 3}) == (
        "Rigid guide: 25/28",
        "rigid: 25/28 frames follow the rigid guide (3 fall back to barycentric where it is not valid)")
    # Two frames are the figures themselves: nothing to follow.
    assert summary({"exact": 0, "blended": 0, "barycentric": 0}, frames=2) == ("Rigid", "rigid")


def half_turn_pair():
    """The tree and the tree turned by 180 degrees: straight lines collapse
    it onto one point half way."""
    return prepare(target=in_space(-TREE_SOURCE, [1.5, -2.0, 0.5]))


def test_linear_motion_lists_its_invalid_frames():
    prepared = half_turn_pair()
    engine = core.load_engine()
    for frame_count, easing, invalid in ((5, "NONE", [2]), (7, "IN_OUT", [3]), (6, "NONE", [])):
        morph = core.compute_morph(prepared, core.BakeSettings(frame_count=frame_count, motion="LINEAR",
                                                               easing=easing, show_triangulation=True))
        assert morph.motion == "LINEAR" and morph.triangulation is None
        assert morph.stats["method"] == "linear"
        assert morph.invalid_frames == invalid, (frame_count, easing)
        xy = plane_xy(morph, prepared)
        for k, frame in enumerate(xy):
            valid = bool(engine.check_compatibility(prepared.source_xy, frame, prepared.edges)) \
                if np.unique(np.round(frame, 12), axis=0).shape[0] == len(frame) else False
            assert valid == (k not in invalid), k
        # Straight lines: every vertex moves along its own segment, at the
        # picked engine frame's time.
        m = core.engine_frame_count(frame_count, easing, "LINEAR")
        t = core.ease_sample_indices(frame_count, easing, "LINEAR") / (m - 1)
        straight = (1 - t)[:, None, None] * prepared.source_xy + t[:, None, None] * prepared.target_xy
        assert np.abs(xy - straight).max() <= 1e-9 * prepared.size
    morph = core.compute_morph(prepared, core.BakeSettings(frame_count=5, motion="LINEAR"))
    assert core.motion_summary(morph, frame_start=10) == (
        "Linear: 1 invalid", "linear: 1 of 5 frames cross or fold the figure (frames 12)")
    valid = core.compute_morph(prepared, core.BakeSettings(frame_count=6, motion="LINEAR"))
    assert core.motion_summary(valid) == ("Linear: all valid", "linear: every frame is valid")


def test_frame_list():
    assert core.frame_list([3, 4, 5, 9]) == "3-5, 9"
    assert core.frame_list([7]) == "7"
    assert core.frame_list([1, 3, 5, 6, 7, 9], limit=2) == "1, 3 and 4 more"


def test_triangulation_world_keeps_the_figure_vertices():
    prepared = prepare()
    morph = core.compute_morph(prepared, core.BakeSettings(frame_count=3))
    source_nodes, target_nodes, triangles = core.triangulation_world(morph.triangulation, prepared)
    n = len(TREE_SOURCE)
    assert np.abs(source_nodes[:n] - SOURCE_WORLD).max() <= 1e-9 * prepared.size
    assert np.abs(target_nodes[:n] - TARGET_WORLD).max() <= 1e-9 * prepared.size
    assert triangles.shape[1] == 3 and triangles.max() < len(source_nodes) == len(target_nodes)


def test_plane_and_tolerance_come_from_the_settings():
    bent = SOURCE_WORLD.copy()
    bent[4] += 0.01 * _N
    size = prepare(bent, settings=core.BakeSettings(planarity_tolerance=0.5)).size
    with pytest.raises(core.StickMorphError, match="not planar: vertex 4 of 'Arm'"):
        prepare(bent, settings=core.BakeSettings(planarity_tolerance=0.001 / size))
    assert prepare(bent, settings=core.BakeSettings(planarity_tolerance=0.02 / size)).size == size
    # An axis plane the tilted figures do not lie in.
    with pytest.raises(core.StickMorphError, match="the XY plane.*try plane AUTO"):
        prepare(settings=core.BakeSettings(plane="XY"))
    with pytest.raises(core.StickMorphError, match="unknown plane 'UV'"):
        prepare(settings=core.BakeSettings(plane="UV"))


def test_prepare_pair_names_the_object_at_fault():
    with pytest.raises(core.StickMorphError, match="'Arm' has 2 faces"):
        prepare(source_faces=2)
    # By index the meshes must have the same vertices and edges; the message
    # says which setting would take them.
    by_index = core.BakeSettings(correspondence="INDEX")
    with pytest.raises(core.StickMorphError, match="'Arm' has 7 vertices, 'Arm pose' has 6") as error:
        prepare(target=TARGET_WORLD[:6], settings=by_index, target_edges=TREE_EDGES[:5])
    assert "Correspondence (Match) is By Index" in str(error.value)
    assert "Automatic or By Shape matches meshes drawn separately" in str(error.value)
    with pytest.raises(core.StickMorphError, match="edges only in 'Arm pose': 1-3") as error:
        prepare(target_edges=np.array([[0, 1], [1, 3], [0, 3], [3, 4], [0, 5], [5, 6]]), settings=by_index)
    assert "Correspondence (Match) is By Index" in str(error.value)
    # Matched, an edge to a vertex the mesh lacks is the engine's invalid figure.
    with pytest.raises(core.StickMorphError, match="invalid figure: 'Arm pose': edge 5 refers to vertex 6"):
        prepare(target=TARGET_WORLD[:6])
    broken = TARGET_WORLD.copy()
    broken[2, 1] = np.nan
    with pytest.raises(core.StickMorphError, match="'Arm pose': vertex 2 has a non-finite coordinate"):
        prepare(target=broken)


def crossing(figure):
    """figure with vertices 2 and 6 swapped across the junction: arms 0-1-2
    and 0-5-6 then cross."""
    figure = np.array(figure, dtype=np.float64)
    figure[2] = [-1.0, -1.0]
    figure[6] = [1.0, 1.0]
    return figure


def morph_fails(**changes):
    """compute_morph's message for the tree pair with the given changes."""
    with pytest.raises(core.StickMorphError) as error:
        core.compute_morph(prepare(**changes), core.BakeSettings(frame_count=3))
    return str(error.value)


def test_engine_errors_name_the_objects_by_role():
    # The engine validates both figures as the morph starts; its message says
    # "source: ..." or "target: ...", the report puts the object's name there.
    engine = core.load_engine()
    message = morph_fails(source=in_space(crossing(TREE_SOURCE), [1.0, -2.0, 0.5]))
    with pytest.raises(engine.InvalidFigureError) as error:
        engine.validate(crossing(TREE_SOURCE), TREE_EDGES)
    assert message == f"crossing edges: 'Arm': {error.value} (mesh edge indices)"
    message = morph_fails(target=in_space(crossing(TREE_TARGET), [4.0, 1.0, -0.5]))
    assert message.startswith("crossing edges: 'Arm pose': edges ") and "target" not in message


def test_an_incompatible_pair_is_reported_from_the_morphs_own_check():
    # By index: Automatic would match this pair instead (its three arms
    # can be paired the other way round), test_addon_correspondence.py.
    engine = core.load_engine()
    mirrored = TREE_TARGET * [-1.0, 1.0]
    message = morph_fails(target=in_space(mirrored, [4.0, 1.0, -0.5]),
                          settings=core.BakeSettings(correspondence="INDEX"))
    report = engine.check_compatibility(TREE_SOURCE, mirrored, TREE_EDGES)
    assert report.kind == "mirror_image" and len(report.vertices) == 1
    assert message == (f"incompatible figures: 'Arm pose' is a mirror image of 'Arm' "
                       f"(vertex {report.vertices[0]}): {report.reason}")


INCOMPATIBLE = REPO / "tests" / "data" / "pairs" / "incompatible"


@pytest.mark.parametrize("name", ["mirror_image", "polygon_reversed", "junction_rotation", "exterior_differs"])
def test_the_morphs_exception_carries_the_compatibility_report(name):
    # What engine_error_message reads instead of checking the pair again.
    engine = core.load_engine()
    source, target = (json.loads((INCOMPATIBLE / f"{name}.{role}.json").read_text())
                      for role in ("source", "target"))
    report = engine.check_compatibility(source["vertices"], target["vertices"], source["edges"])
    with pytest.raises(engine.IncompatibleFiguresError) as error:
        engine.morph(source["vertices"], target["vertices"], source["edges"], frames=2)
    e = error.value
    assert (e.kind, e.vertices, e.reason) == (report.kind, report.vertices, report.reason)
    assert str(e) == f"incompatible figures: {report.reason}"
    message = core.engine_error_message(e, "S", "T")
    assert message.endswith(f": {report.reason}") and "incompatible figures: incompatible" not in message


@pytest.mark.parametrize("role", ["source", "target"])
def test_invalid_figure_detail_is_the_message_without_the_role(role):
    engine = core.load_engine()
    figures = {"source": TREE_SOURCE, "target": TREE_TARGET}
    figures[role] = crossing(figures[role])
    with pytest.raises(engine.InvalidFigureError) as error:
        engine.morph(figures["source"], figures["target"], TREE_EDGES, frames=2)
    e = error.value
    assert (e.role, e.defect) == (role, "crossing_edges")
    assert str(e) == f"{role}: {e.detail}" and e.detail.startswith("edges ")
    # A figure on its own has no role: the detail is the whole message.
    with pytest.raises(engine.InvalidFigureError) as error:
        engine.validate(figures[role], TREE_EDGES)
    assert error.value.role is None and error.value.detail == str(error.value) == e.detail


def test_tube_radius():
    assert core.tube_radius(10.0, 0.01) == pytest.approx(0.1)
    assert core.tube_radius(0.0, 0.01) == 0.01  # a figure of no size: the factor itself
    assert core.tube_radius(1e-9, 0.01) == 1e-6  # never thinner than 1e-6
    assert core.tube_radius(float("nan"), 0.02) == 0.02


# ---------------------------------------------------------- result name ----

@pytest.mark.parametrize("source, target, expected", [
    ("monkey_to_player_source", "monkey_to_player_target", "monkey_to_player_morph"),
    ("Cube.001", "Cube.002", "Cube_morph"),
    ("source_arm", "target_arm", "arm_morph"),
    ("walk_start_pose", "walk_end_pose", "walk_pose_morph"),
    ("Fig", "Fig_2", "Fig_morph"),
    ("Source", "Target", "Source_to_Target"),
    ("S", "U", "S_to_U"),
    ("1_a", "1_b", "1_a_to_1_b"),  # one shared digit says nothing
    ("a" * 50, "b" * 50, "a" * 18 + "_to_" + "b" * 18),
    ("\u00e9" * 30, "x", "\u00e9" * 17 + "_to_x"),  # cut by UTF-8 bytes, never inside a character
])
def test_result_name(source, target, expected):
    name = core.result_name(source, target)
    assert name == expected
    assert len(name.encode("utf-8")) <= core.MAX_RESULT_NAME_BYTES
    # With the helper's suffix it still fits Blender's 63-byte names.
    assert len((name + "_triangulation").encode("utf-8")) <= 63


def test_fit_plane_of_many_points_matches_the_full_svd_and_stays_small():
    """The plane of a large figure comes from the points reduced to 3 by 3 (QR), not from an
    SVD of all of them, whose M by M U would not fit in memory at 10^4 vertices per key; the
    normal is the full SVD's. Two points (fewer rows than coordinates) still give a plane."""
    rng = np.random.default_rng(29)
    tilt = np.linalg.qr(rng.normal(size=(3, 3)))[0]
    flat = np.c_[rng.uniform(-1, 1, size=(400, 2)), 1e-3 * rng.normal(size=400)] @ tilt.T
    plane = core.fit_plane(flat, flat + [0.5, 0, 0], "AUTO")
    centred = np.vstack([flat - flat.mean(axis=0)] * 2)
    expected = np.linalg.svd(centred, full_matrices=True)[2][2]
    assert abs(abs(plane.normal @ expected) - 1) < 1e-12
    big = np.c_[rng.uniform(-1, 1, size=(200_000, 2)), np.zeros(200_000)]
    assert np.allclose(core.fit_plane(big, big, "AUTO").normal, [0, 0, 1], atol=1e-12)  # would need 320 GB
    two = np.array([[0, 0, 0], [1, 0, 0.0]])
    line_plane = core.fit_plane(two, two, "AUTO")  # collinear: a plane holding the line
    assert abs(line_plane.normal @ [1, 0, 0]) < 1e-12 and np.linalg.norm(line_plane.normal) == pytest.approx(1)
