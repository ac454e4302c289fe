"""Measures the two ways of baking a morph into shape keys (not a test).

    blender -b --factory-startup --python tests/blender/measure_shape_keys.py

absolute:  absolute shape keys, one per frame, on an eval_time F-curve
           (baking.bake_absolute_keys, what the add-on bakes)
relative:  a basis and one relative key per frame, value 1 on its frame only
           (constant interpolation; bake_relative_keys below, kept here
           because only this measurement uses it)

For each size it prints the bake time (keys and keyframes), the time of
scene.frame_set per frame with the shape keys evaluated, and the largest
difference between the evaluated mesh and the frame that was baked. The
results are quoted in addon/stick_morph/baking.py.
"""

import os
import sys
import time

import bpy
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "addon"))
from stick_morph import baking  # noqa: E402

# The enum index of CONSTANT in Keyframe.interpolation, for foreach_set.
CONSTANT = 0


def fill_constant_fcurve(fcurve, frames, values):
    """baking._fill_fcurve with CONSTANT keyframes: the add-on's fill, then
    every keyframe's interpolation switched (relative keys must not blend)."""
    baking._fill_fcurve(fcurve, frames, values)
    points = fcurve.keyframe_points
    points.foreach_set("interpolation", np.full(len(points), CONSTANT, dtype=np.int32))
    fcurve.update()


def bake_relative_keys(obj, frames_local, frame_start):
    """The alternative measured against baking.bake_absolute_keys: a basis
    (frame 0) and one relative key per further frame whose value is 1 on its
    frame only, with constant interpolation."""
    count = len(frames_local)
    obj.shape_key_add(name="Frame 0000", from_mix=False)
    key = obj.data.shape_keys
    for k in range(1, count):
        block = obj.shape_key_add(name=f"Frame {k:04d}", from_mix=False)
        block.data.foreach_set("co", np.asarray(frames_local[k], dtype=np.float32).ravel())
        block.value = 0.0
        block.keyframe_insert("value", frame=frame_start + k - 1)
        fcurve = baking.find_fcurve(key.animation_data, block.path_from_id("value"))
        frames = [frame_start + k - 1, frame_start + k] + ([frame_start + k + 1] if k + 1 < count else [])
        values = [0.0, 1.0] + ([0.0] if k + 1 < count else [])
        fill_constant_fcurve(fcurve, np.array(frames, dtype=np.float64), np.array(values))
    return key


def synthetic_frames(frames, vertices):
    t = np.linspace(0.0, 1.0, frames)[:, None]
    s = np.linspace(0.0, 2 * np.pi, vertices)[None, :]
    out = np.zeros((frames, vertices, 3))
    out[..., 0] = s * (1 + 0.3 * t)
    out[..., 1] = np.sin(s + 3 * t)
    return out


def measure(bake, frames, vertices):
    bpy.ops.wm.read_homefile(use_empty=True)
    data = synthetic_frames(frames, vertices)
    edges = np.stack([np.arange(vertices - 1), np.arange(1, vertices)], axis=1)
    mesh = baking._new_mesh("m", data[0], edges)
    obj = bpy.data.objects.new("m", mesh)
    bpy.context.scene.collection.objects.link(obj)
    start = time.perf_counter()
    bake(obj, data, 1)
    bake_ms = (time.perf_counter() - start) * 1000
    scene = bpy.context.scene
    depsgraph = bpy.context.evaluated_depsgraph_get()
    worst = 0.0
    start = time.perf_counter()
    for k in range(frames):
        scene.frame_set(1 + k)
        evaluated = obj.evaluated_get(depsgraph)
        if k % max(1, frames // 10) == 0:
            m = evaluated.to_mesh()
            co = np.empty(vertices * 3, dtype=np.float32)
            m.vertices.foreach_get("co", co)
            evaluated.to_mesh_clear()
            worst = max(worst, float(np.abs(co.reshape(-1, 3) - data[k]).max()))
    step_ms = (time.perf_counter() - start) * 1000 / frames
    return bake_ms, step_ms, worst


def main():
    print(f"Blender {bpy.app.version_string}")
    print(f"{'frames x vertices':>18} {'method':>9} {'bake ms':>9} {'step ms':>8} {'max error':>10}")
    for frames, vertices in ((100, 1000), (400, 1000), (400, 10000)):
        for name, bake in (("absolute", baking.bake_absolute_keys), ("relative", bake_relative_keys)):
            bake_ms, step_ms, worst = measure(bake, frames, vertices)
            print(f"{frames:>8} x {vertices:<7} {name:>9} {bake_ms:9.0f} {step_ms:8.2f} {worst:10.2e}", flush=True)


main()
