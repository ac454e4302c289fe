"""The bundled samples (blend_samples/*.blend) bake into the engine's morph.

Each sample is opened as a user would open it, baked over its own frame range
with object.stick_morph_bake, and every frame of the result (shape keys only)
is compared with stickmorph.morph on the sample's figures in the baked plane
(test_bake.expected_frames), checked to be a valid stick figure compatible with
the source, and to start and end at the source and target in world space.
"""

import glob
import json
import os

import bpy
import numpy as np
import pytest

from conftest import ROOT, evaluated_world, world_coords
from test_bake import expected_frames, figure_size

SAMPLES_DIR = os.path.join(ROOT, "blend_samples")
SAMPLES = ("monkey_to_player", "scorpion_to_dragonfly", "s_to_u", "polygon", "triangulation")


def test_every_sample_is_tested():
    found = {os.path.splitext(os.path.basename(p))[0] for p in glob.glob(os.path.join(SAMPLES_DIR, "*.blend"))}
    assert found == set(SAMPLES), f"blend_samples/ holds {sorted(found)}; update SAMPLES"


def open_sample(name, addon_name):
    path = os.path.join(SAMPLES_DIR, f"{name}.blend")
    assert os.path.isfile(path), path
    assert bpy.ops.wm.open_mainfile(filepath=path, load_ui=False) == {"FINISHED"}
    assert addon_name in bpy.context.preferences.addons
    source = bpy.data.objects[f"{name}_source"]
    target = bpy.data.objects[f"{name}_target"]
    return bpy.context.scene, source, target


def figure_json(name, role):
    with open(os.path.join(SAMPLES_DIR, "figures", f"{name}.{role}.json")) as f:
        return json.load(f)


@pytest.mark.parametrize("name", SAMPLES)
def test_sample_bakes_to_the_engine_morph(addon, addon_name, name):
    scene, source, target = open_sample(name, addon_name)
    edges = sorted(tuple(sorted(e.vertices)) for e in source.data.edges)
    # The meshes are the sample's figures (single precision), in the JSON's order.
    for obj, role in ((source, "source"), (target, "target")):
        figure = figure_json(name, role)
        local = np.array([v.co[:] for v in obj.data.vertices])
        xy = np.asarray(figure["vertices"], dtype=np.float64)
        scale = float(np.abs(xy).max())
        assert local.shape == (len(xy), 3), (role, local.shape)
        assert np.abs(local[:, :2] - xy).max() <= 1e-6 * scale, role
        assert np.abs(local[:, 2]).max() == 0.0, role
        assert sorted(tuple(sorted(e)) for e in figure["edges"]) == edges, role
        assert len(obj.data.polygons) == 0, role

    frame_start, frame_end = scene.frame_start, scene.frame_end
    frame_count = frame_end - frame_start + 1
    assert frame_count == 60
    before = {obj.name: (world_coords(obj).tobytes(), tuple(map(tuple, obj.matrix_world)))
              for obj in (source, target)}

    for obj in bpy.context.view_layer.objects:
        obj.select_set(False)
    result = bpy.ops.object.stick_morph_bake(source=source.name, target=target.name, frame_start=frame_start,
                                             frame_count=frame_count, easing="NONE", renderable=True)
    assert result == {"FINISHED"}, result
    baked = bpy.context.view_layer.objects.active
    assert baked is not None and baked.get("stick_morph_role") == "result"
    assert baked not in (source, target)
    assert len(baked.data.vertices) == len(source.data.vertices)
    assert sorted(tuple(sorted(e.vertices)) for e in baked.data.edges) == edges
    assert [m.type for m in baked.modifiers] == ["NODES"]
    # Source and target are untouched, the frame range is the morph's.
    assert {obj.name: (world_coords(obj).tobytes(), tuple(map(tuple, obj.matrix_world)))
            for obj in (source, target)} == before
    assert source.data.shape_keys is None and target.data.shape_keys is None
    assert (scene.frame_start, scene.frame_end) == (frame_start, frame_end)

    # The engine's morph of the figures in the baked plane, in world space.
    expected, _, src_xy, edge_array, morph = expected_frames(addon, source, target, frame_count)
    fitted = addon.core.fit_plane(world_coords(source), world_coords(target), "AUTO")
    # The samples are drawn in the XY plane at z = 0: that is the plane found.
    assert abs(abs(float(fitted.normal[2])) - 1.0) < 1e-9
    size = figure_size(source, target)
    tolerance = 1e-5 * size
    engine = addon.core.load_engine()
    for k in range(frame_count):
        got = evaluated_world(baked, frame_start + k)
        error = float(np.abs(got - expected[k]).max())
        assert error <= tolerance, f"{name} frame {k}: off the engine's morph by {error} (size {size})"
        assert np.abs(got[:, 2]).max() <= tolerance, f"{name} frame {k} leaves the plane z = 0"
        d = got - fitted.origin
        xy = np.stack([d @ fitted.u, d @ fitted.v], axis=1)
        engine.validate(xy, edge_array)  # raises InvalidFigureError, naming the defect
        report = engine.check_compatibility(src_xy, xy, edge_array)
        assert report, f"{name} frame {k}: not compatible with the source: {report.kind}: {report.reason}"

    # Starts at the source and ends at the target, in world space.
    first = evaluated_world(baked, frame_start)
    last = evaluated_world(baked, frame_end)
    assert np.abs(first - world_coords(source)).max() <= tolerance
    assert np.abs(last - world_coords(target)).max() <= tolerance
    # The morph actually moves: the middle frame is neither end.
    middle = evaluated_world(baked, frame_start + frame_count // 2)
    assert np.abs(middle - first).max() > 100 * tolerance
    assert np.abs(middle - last).max() > 100 * tolerance
