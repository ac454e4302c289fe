"""The bpy-free helpers of core.py, and that core.py imports without bpy."""

import dataclasses
import os
import subprocess

import bpy
import numpy as np
import pytest

ADDON_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "addon")


def test_core_imports_without_bpy(addon):
    # Debian's Python has numpy but no bpy; the repository's package is imported.
    code = ("import sys; sys.path.insert(0, sys.argv[1]); import stick_morph.core as c; "
            "assert 'bpy' not in sys.modules; print(c.ease(0.5, 'EASE_IN_OUT'))")
    out = subprocess.run(["/usr/bin/python3", "-c", code, ADDON_DIR], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "0.5"


def test_fit_plane_auto_tilted_and_parallel(addon):
    core = addon.core
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


def test_fit_plane_collinear_and_axis(addon):
    core = addon.core
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


def test_edge_sets_and_easing(addon):
    core = addon.core
    assert core.compare_edge_sets([[0, 1], [1, 2]], [[2, 1], [1, 0]]) is None
    message = core.compare_edge_sets([[0, 1], [1, 2]], [[0, 1], [0, 2]], "A", "B")
    assert "only in 'A': 1-2" in message and "only in 'B': 0-2" in message
    t = np.linspace(0, 1, 11)
    assert np.array_equal(core.ease(t, "LINEAR"), t)
    eased = core.ease(t, "EASE_IN_OUT")
    assert eased[0] == 0 and eased[-1] == 1 and np.all(np.diff(eased) > 0)
    index = core.ease_sample_indices(11, "EASE_IN_OUT")
    assert index[0] == 0 and index[-1] == core.engine_frame_count(11, "EASE_IN_OUT") - 1
    assert np.array_equal(core.ease_sample_indices(7, "LINEAR"), np.arange(7))


def test_registration_panel_and_defaults(scene, addon, addon_name):
    import bpy
    assert hasattr(bpy.types, "VIEW3D_PT_stick_morph")
    assert bpy.types.VIEW3D_PT_stick_morph.bl_category == "Stick Morph"
    prefs = bpy.context.preferences.addons[addon_name].preferences
    settings = scene.stick_morph
    saved = prefs.enclosure_sides
    prefs.enclosure_sides = 9
    try:
        assert bpy.ops.scene.stick_morph_load_defaults() == {"FINISHED"}
        assert settings.enclosure_sides == 9
    finally:
        prefs.enclosure_sides = saved
    # The operator shows in Object menu and its poll explains itself in Object Mode.
    assert bpy.ops.object.stick_morph_bake.poll()


def test_bake_settings_have_every_option_with_the_properties_defaults(scene, addon, addon_name):
    from conftest import addon_import
    common = addon_import("common")
    preferences = addon_import("preferences")
    fields = [field.name for field in dataclasses.fields(common.BakeSettings)]
    # bake_settings reads OPTION_NAMES and frame_start: a field outside them
    # would silently keep its default in every bake.
    assert sorted(fields) == sorted(preferences.OPTION_NAMES + ("frame_start",))
    defaults = common.BakeSettings()
    holders = {
        "operator": bpy.ops.object.stick_morph_bake.get_rna_type().properties,
        "scene settings": scene.stick_morph.bl_rna.properties,
        "preferences": bpy.context.preferences.addons[addon_name].preferences.bl_rna.properties,
    }
    for where, properties in holders.items():
        for name in fields:
            if name == "frame_start" and where == "preferences":
                continue
            expected = getattr(defaults, name)
            got = properties[name].default
            if isinstance(expected, float):  # a FloatProperty holds a float32
                assert got == pytest.approx(expected, rel=1e-6), (where, name)
            else:
                assert got == expected and type(got) is type(expected), (where, name, got)


def test_bake_settings_read_each_option_from_its_property(addon):
    from conftest import addon_import
    preferences = addon_import("preferences")
    # A distinct value per property: a field read from the wrong one shows.
    names = preferences.OPTION_NAMES + ("frame_start",)
    holder = type("Holder", (), {name: f"value of {name}" for name in names})()
    settings = preferences.bake_settings(holder)
    assert dataclasses.asdict(settings) == {name: f"value of {name}" for name in names}
    # And from the operator as it runs: the redo panel's values.
    op = bpy.context.window_manager.operator_properties_last("object.stick_morph_bake")
    assert dataclasses.asdict(preferences.bake_settings(op)) == {name: getattr(op, name) for name in names}
