"""Cancelling a long bake leaves the scene as it was (issue 29).

Headless Blender has no window, so the operators' modal invoke (Esc in the
GUI, tested under Xvfb by tests/blender/gui/cancel_bake.py) falls back to
execute here. These tests run the pieces the modal bake runs, the
operators' own start() (reads the meshes, main thread) and the worker's job
(bake_job.BakeJob: the engine in a thread), on a figure large enough to be
still triangulating when it is cancelled, and compare everything in the file
before and after. A bake that is not cancelled is finished by the
operators' own finish(), as the modal bake does, and matches execute's.
"""

import json
import time

import bpy
import numpy as np
import pytest

from conftest import addon_import, make_mesh_object, select, snapshot

# Large enough that its triangulation runs for a second or more (a few
# hundred ms for the module alone at 2 * 10^4: the polygon's constrained
# Delaunay triangulation and the shared diagonals), small enough to make
# the meshes quickly.
VERTICES = 20000


def waves(n, offset=0.0):
    x = np.linspace(0.0, 100.0, n)
    source = np.stack([x, 3 * np.sin(0.7 * x) + 1.5 * np.sin(2.3 * x)], axis=1)
    target = np.stack([x, -2 * np.cos(0.3 * x) + 0.5 * np.sin(1.1 * x) + offset], axis=1)
    edges = np.stack([np.arange(n - 1), np.arange(1, n)], axis=1)
    return source, target, edges


class StandIn:
    """The operator's properties on a plain object, with its start() and
    finish() (and the helpers they call): bpy.ops cannot make an operator
    instance outside a call, and in background mode invoke is execute."""

    def __init__(self, operator_class, **properties):
        for name in ("start", "finish", "_key_objects"):
            if hasattr(operator_class, name):
                setattr(self, name, getattr(operator_class, name).__get__(self))
        self.reports = []
        self.properties = _AllSet()
        for name, value in properties.items():
            setattr(self, name, value)

    def report(self, kind, text):
        self.reports.append((set(kind), text))


class _AllSet:
    @staticmethod
    def is_property_set(name):
        return True


def options(scene, names):
    return {name: getattr(scene.stick_morph, name) for name in names}


def cancelled_job(work, timer):
    """The job started on work (an operator's start() made it, with timer),
    cancelled while triangulating; waits for it."""
    bake_job = addon_import("bake_job")
    engine = addon_import("core").load_engine()
    job = bake_job.BakeJob(work, engine.Progress(), timer).start()
    deadline = time.monotonic() + 120
    while job.running and job.stage()[0] != "triangulate" and time.monotonic() < deadline:
        time.sleep(0.002)
    assert job.running, f"the bake ended before it was cancelled ({job.timer.summary()})"
    assert job.stage()[0] == "triangulate"
    assert job.status_text().startswith("Stick Morph: triangulating… ")
    cancelled = time.monotonic()
    job.cancel()
    assert job.wait(60)
    return job, time.monotonic() - cancelled


def test_a_pair_bake_cancelled_while_triangulating_changes_nothing(scene):
    operators = addon_import("operators")
    properties = addon_import("properties")
    engine = addon_import("core").load_engine()
    source_xy, target_xy, edges = waves(VERTICES)
    source = make_mesh_object("Source", source_xy, edges)
    target = make_mesh_object("Target", target_xy, edges, z=0.0)
    target.location.x = 150.0
    bpy.context.view_layer.update()
    select(source, target)
    before = snapshot()
    stages_before = scene.stick_morph.last_stages

    op = StandIn(operators.STICKMORPH_OT_bake, source="Source", target="Target", frame_start=1,
                 **options(scene, properties.OPTION_NAMES + properties.MESH_OPTIONS))
    timer = addon_import("bake_job").StageTimer()
    work = op.start(bpy.context, timer)
    job, seconds = cancelled_job(work, timer)

    assert job.cancelled and job.result is None
    assert isinstance(job.error, engine.CancelledError), job.error
    assert seconds < 5, seconds  # measured: tens of milliseconds
    assert snapshot() == before
    assert scene.stick_morph.last_stages == stages_before


def test_a_key_pose_bake_cancelled_while_triangulating_changes_nothing(scene):
    sequence_operators = addon_import("sequence_operators")
    properties = addon_import("properties")
    engine = addon_import("core").load_engine()
    a, b, edges = waves(VERTICES)
    keys = [make_mesh_object(f"Key {k + 1}", xy, edges) for k, xy in enumerate((a, b, a + [0.0, 1.0]))]
    bpy.context.view_layer.update()
    select(*keys)
    before = snapshot()

    op = StandIn(sequence_operators.STICKMORPH_OT_bake_sequence, keys=json.dumps([k.name for k in keys]),
                 collection="", frame_start=1, frame_step=24, loop=False, hold=False,
                 **options(scene, properties.SEQUENCE_OPTIONS + properties.MESH_OPTIONS))
    timer = addon_import("bake_job").StageTimer()
    work = op.start(bpy.context, timer)
    job, seconds = cancelled_job(work, timer)

    assert job.cancelled and job.result is None
    assert isinstance(job.error, engine.CancelledError), job.error
    assert seconds < 5, seconds
    assert snapshot() == before


def test_a_modal_bake_not_cancelled_builds_what_execute_builds(scene):
    # The modal bake's split (start, the job, finish) against execute, on a
    # small pair: the same frames, and the stage line in last_stages.
    operators = addon_import("operators")
    properties = addon_import("properties")
    bake_job = addon_import("bake_job")
    engine = addon_import("core").load_engine()
    source_xy, target_xy, edges = waves(200)
    source = make_mesh_object("Source", source_xy, edges)
    target = make_mesh_object("Target", target_xy, edges)
    bpy.context.view_layer.update()
    select(source, target)
    assert bpy.ops.object.stick_morph_bake(source="Source", target="Target") == {"FINISHED"}
    by_execute = bpy.context.view_layer.objects.active
    executed = [np.array([v.co[:] for v in block.data]) for block in by_execute.data.shape_keys.key_blocks]
    stages = scene.stick_morph.last_stages.split(", ")
    # "engine": the part of morph spent in the module's call (issue 29's split).
    assert [part.split(" ")[0] for part in stages] == ["read", "check", "morph", "build", "engine"]
    assert all(part.endswith(" ms") for part in stages)
    times = {part.split(" ")[0]: float(part.split(" ")[1]) for part in stages}
    assert 0 < times["engine"] <= times["morph"]
    bpy.data.objects.remove(by_execute)

    op = StandIn(operators.STICKMORPH_OT_bake, source="Source", target="Target", frame_start=1,
                 **options(scene, properties.OPTION_NAMES + properties.MESH_OPTIONS))
    timer = bake_job.StageTimer()
    work = op.start(bpy.context, timer)
    job = bake_job.BakeJob(work, engine.Progress(), timer).start()
    assert job.wait(120) and job.error is None and not job.cancelled
    with operators.Progress(bpy.context, job.timer) as progress:
        assert op.finish(bpy.context, progress, job.result) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    assert result.name != "Source" and result.data.shape_keys is not None
    modal = [np.array([v.co[:] for v in block.data]) for block in result.data.shape_keys.key_blocks]
    assert len(modal) == len(executed)
    for a, b in zip(modal, executed):
        assert np.array_equal(a, b)
    names = [part.split(" ")[0] for part in scene.stick_morph.last_stages.split(", ")]
    assert names == ["read", "check", "morph", "build", "engine"]
