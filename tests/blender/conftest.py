"""Fixtures for the add-on tests that run inside Blender (see run_pytest.py).

The add-on's module name depends on the Blender: `stick_morph` for a legacy
add-on (Blender 3.x, 4.0, 4.1), `bl_ext.user_default.stick_morph` for an
extension (4.2+). Tests get the package module from the `addon` fixture
(`addon.core`, `addon.__name__` for preferences.addons[...]) or import a
submodule with addon_import("core"); they never import `stick_morph` by name.
"""

import glob
import importlib
import math
import os
import sys

import bpy
import numpy as np
import pytest
from mathutils import Matrix

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SANDBOX = os.environ.get("STICKMORPH_BLENDER_SANDBOX")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import blender_sandbox  # noqa: E402

# The name the add-on is enabled under in this Blender.
ADDON_MODULE = blender_sandbox.addon_module_name()

# gui/ holds scripts for a Blender with a window (gui/run_gui_tests.sh), not
# pytest tests: importing one in this headless Blender would start it.
collect_ignore = ["gui"]


def addon_package():
    """The package to test: $STICKMORPH_ADDON_ZIP, else the newest one in dist/
    built for this Blender and Python (build_addon.py names them so)."""
    path = os.environ.get("STICKMORPH_ADDON_ZIP")
    if path:
        return path
    try:
        return blender_sandbox.find_package(os.path.join(ROOT, "dist"))
    except FileNotFoundError as error:
        others = sorted(os.path.basename(p) for p in glob.glob(os.path.join(ROOT, "dist", "stick_morph-*.zip")))
        pytest.fail(f"{error} (dist/ holds: {', '.join(others) or 'nothing'})")


def addon_import(submodule=None):
    """The add-on's package, or one of its submodules ("core"), under the name
    it is installed as in this Blender."""
    return importlib.import_module(ADDON_MODULE + (f".{submodule}" if submodule else ""))


@pytest.fixture(scope="session")
def addon_name():
    """stick_morph (legacy add-on) or bl_ext.user_default.stick_morph (extension)."""
    return ADDON_MODULE


@pytest.fixture(scope="session")
def addon():
    """Installs the built package into the sandboxed user folders the way this
    Blender installs it (legacy add-on or extension) and enables it; returns
    the add-on's package module."""
    if not SANDBOX:
        pytest.fail("run through tests/blender/run_pytest.py (a sandboxed user config)")
    # Every user folder (config, scripts, datafiles, extension repositories)
    # must be in the sandbox, or installing would write into the real one.
    blender_sandbox.check_sandboxed()
    assert ADDON_MODULE not in sys.modules
    assert not any(m == "stick_morph" or m.startswith("stick_morph.") for m in sys.modules)
    try:
        name = blender_sandbox.install_package(addon_package())
    except RuntimeError as error:
        pytest.fail(str(error))
    assert name == ADDON_MODULE
    package = addon_import()
    # Loaded from the installed copy, with its bundled native module: inside
    # the legacy add-on's folder, or (an extension) from the wheel Blender
    # installed into the extensions' site-packages.
    assert os.path.realpath(package.__file__).startswith(os.path.realpath(SANDBOX))
    core = addon_import("core")
    engine = core.load_engine()
    assert os.path.realpath(engine.__file__).startswith(os.path.realpath(SANDBOX)), engine.__file__
    if blender_sandbox.uses_extensions():
        site_packages = os.path.join(bpy.utils.user_resource("EXTENSIONS"), ".local", "lib",
                                     f"python{sys.version_info[0]}.{sys.version_info[1]}", "site-packages")
        assert os.path.dirname(os.path.realpath(engine.__file__)) == os.path.realpath(site_packages), engine.__file__
    else:
        assert os.path.dirname(os.path.realpath(engine.__file__)) == os.path.dirname(os.path.realpath(package.__file__))
    assert hasattr(bpy.types, "OBJECT_OT_stick_morph_bake") or hasattr(bpy.ops.object, "stick_morph_bake")
    return package


@pytest.fixture
def scene(addon):
    """An empty scene (the add-on stays enabled)."""
    bpy.ops.wm.read_homefile(use_empty=True)
    assert addon.__name__ in bpy.context.preferences.addons
    return bpy.context.scene


# ---------------------------------------------------------------- figures ----
# 2D figures (source, target, edges): compatible pairs never seen by the engine's tests.

POLYLINE = (
    [[0, 0], [1, 0.3], [2, -0.2], [3, 0.5], [4, 0]],
    [[0, 0], [0.8, 1.0], [0.2, 2.0], [1.4, 2.6], [2.5, 2.2]],
    [[0, 1], [1, 2], [2, 3], [3, 4]],
)

# A tree: a junction at 0 with three arms, two edges each.
TREE = (
    [[0, 0], [1, 0], [2, 0.2], [-0.5, 0.9], [-1.0, 1.8], [-0.5, -0.9], [-0.8, -1.9]],
    [[0, 0], [0.9, 0.5], [1.5, 1.3], [-0.9, 0.4], [-1.9, 0.2], [0.1, -1.0], [0.9, -1.6]],
    [[0, 1], [1, 2], [0, 3], [3, 4], [0, 5], [5, 6]],
)

# A quadrilateral with a dangling edge inside; the target is not convex.
POLYGON_DANGLING = (
    [[0, 0], [2, 0], [2, 2], [0, 2], [1, 1]],
    [[0, 0], [3, 0], [1.5, 0.8], [0, 2.5], [0.6, 0.9]],
    [[0, 1], [1, 2], [2, 3], [3, 0], [0, 4]],
)

PAIRS = {"polyline": POLYLINE, "tree": TREE, "polygon_dangling": POLYGON_DANGLING}

# The plane both figures lie in: tilted about two axes.
TILT = Matrix.Rotation(0.6, 4, "X") @ Matrix.Rotation(-0.35, 4, "Y")


def source_matrix():
    return Matrix.Translation((1.0, -2.0, 0.5)) @ TILT @ Matrix.Diagonal((1.5, 1.5, 1.5, 1.0))


def target_matrix():
    # The same plane orientation, turned within the plane, scaled, and moved
    # along the plane's normal too (a parallel plane).
    normal = (np.array(TILT.to_3x3()) @ np.array([0.0, 0.0, 1.0]))
    offset = Matrix.Translation(tuple(np.array([4.0, 1.0, -0.5]) + 0.7 * np.array(normal)))
    return offset @ TILT @ Matrix.Rotation(0.4, 4, "Z") @ Matrix.Diagonal((0.8, 0.8, 0.8, 1.0))


def make_mesh_object(name, xy, edges, matrix=None, faces=(), z=None):
    coords = np.zeros((len(xy), 3))
    coords[:, :2] = np.asarray(xy, dtype=np.float64)
    if z is not None:
        coords[:, 2] = z
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(coords.tolist(), [tuple(e) for e in edges] if not faces else [], list(faces))
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    if matrix is not None:
        obj.matrix_world = matrix
    return obj


def make_pair(key, source_name="Source", target_name="Target", tilted=True):
    source_xy, target_xy, edges = PAIRS[key]
    source = make_mesh_object(source_name, source_xy, edges, source_matrix() if tilted else None)
    target = make_mesh_object(target_name, target_xy, edges, target_matrix() if tilted else None)
    bpy.context.view_layer.update()
    select(source, target)
    return source, target


def select(*objects, active=None):
    for obj in bpy.context.view_layer.objects:
        obj.select_set(False)
    for obj in objects:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = active if active is not None else (objects[-1] if objects else None)


def world_coords(obj):
    """World coordinates of a mesh object's own vertices, computed here (not by the add-on)."""
    matrix = np.array(obj.matrix_world)
    co = np.array([v.co[:] for v in obj.data.vertices], dtype=np.float64)
    return co @ matrix[:3, :3].T + matrix[:3, 3]


def evaluated_world(obj, frame):
    """The evaluated mesh (shape keys only: modifiers off) at a frame, in world space."""
    scene = bpy.context.scene
    saved = [(m, m.show_viewport) for m in obj.modifiers]
    for modifier, _ in saved:
        modifier.show_viewport = False
    try:
        scene.frame_set(frame)
        depsgraph = bpy.context.evaluated_depsgraph_get()
        evaluated = obj.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
        mesh.vertices.foreach_get("co", co)
        matrix = np.array(evaluated.matrix_world)
        evaluated.to_mesh_clear()
    finally:
        for modifier, shown in saved:
            modifier.show_viewport = shown
    return co.reshape(-1, 3).astype(np.float64) @ matrix[:3, :3].T + matrix[:3, 3]


def snapshot():
    """Everything an operator could change in the file, for before/after comparison."""
    def matrix(obj):
        return tuple(round(x, 9) for row in obj.matrix_world for x in row)

    def coords(mesh):
        co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
        mesh.vertices.foreach_get("co", co)
        return co.tobytes()

    scene = bpy.context.scene
    view_layer = bpy.context.view_layer
    return {
        "objects": sorted((o.name, o.type, o.data.name if o.data else None, matrix(o), o.select_get(),
                           tuple(m.name for m in o.modifiers), tuple(sorted(o.keys())))
                          for o in bpy.data.objects),
        "meshes": sorted((m.name, len(m.vertices), len(m.edges), len(m.polygons), coords(m),
                          m.shape_keys.name if m.shape_keys else None) for m in bpy.data.meshes),
        "shape_keys": sorted(k.name for k in bpy.data.shape_keys),
        "actions": sorted(a.name for a in bpy.data.actions),
        "node_groups": sorted(g.name for g in bpy.data.node_groups),
        "materials": sorted(m.name for m in bpy.data.materials),
        "collections": sorted((c.name, tuple(sorted(o.name for o in c.objects))) for c in bpy.data.collections),
        "scene_objects": tuple(sorted(o.name for o in scene.collection.objects)),
        "active": view_layer.objects.active.name if view_layer.objects.active else None,
        "frames": (scene.frame_start, scene.frame_end, scene.frame_current),
    }
