"""stickmorph.Progress and CancelledError (issue 29): a long morph watched and
cancelled from another thread, and the add-on's bpy-free bake job
(addon/stick_morph/bake_job.py) that the modal bake operators run."""
import threading
import time

import numpy as np
import pytest

import stickmorph
from test_addon_core import load_addon_module

bake_job = load_addon_module("bake_job")


def waves(n):
    """Two graphs of functions of x: valid polylines, compatible. At 20000
    vertices the triangulation takes about a second."""
    x = np.linspace(0.0, 100.0, n)
    source = np.stack([x, 3 * np.sin(0.7 * x) + 1.5 * np.sin(2.3 * x)], axis=1)
    target = np.stack([x, -2 * np.cos(0.3 * x) + 0.5 * np.sin(1.1 * x)], axis=1)
    edges = np.stack([np.arange(n - 1), np.arange(1, n)], axis=1)
    return source, target, edges


def cancel_when(progress, ready, call, timeout=120):
    """call() in a worker thread; progress.cancel() once ready(progress).
    Returns (the exception the call raised or None, seconds from the
    cancel to the call's end)."""
    outcome = {}

    def run():
        try:
            call()
            outcome["error"] = None
        except BaseException as error:  # handed back to the test
            outcome["error"] = error

    worker = threading.Thread(target=run)
    worker.start()
    deadline = time.monotonic() + timeout
    while worker.is_alive() and not ready(progress) and time.monotonic() < deadline:
        time.sleep(0.001)
    cancelled_at = time.monotonic()
    progress.cancel()
    worker.join(timeout)
    assert not worker.is_alive()
    return outcome["error"], time.monotonic() - cancelled_at


def test_cancelled_error_is_neither_bad_input_nor_a_bug():
    assert issubclass(stickmorph.CancelledError, Exception)
    assert not issubclass(stickmorph.CancelledError, ValueError)
    assert not issubclass(stickmorph.CancelledError, stickmorph.StickMorphError)
    assert not issubclass(stickmorph.CancelledError, RuntimeError)


@pytest.mark.parametrize("method", ["rigid", "barycentric"])
def test_a_cancel_during_the_triangulation_raises_cancelled_error(method):
    source, target, edges = waves(20000)
    progress = stickmorph.Progress()
    error, seconds = cancel_when(progress, lambda p: p.stage == "triangulate",
                                 lambda: stickmorph.morph(source, target, edges, frames=10, method=method,
                                                          progress=progress))
    assert isinstance(error, stickmorph.CancelledError), error
    assert str(error) == "cancelled while in stage 'triangulate'"
    assert progress.cancelled
    assert seconds < 5  # measured: milliseconds


@pytest.mark.parametrize("method", ["rigid", "barycentric", "linear"])
def test_a_cancel_during_the_frames_raises_cancelled_error(method):
    source, target, edges = waves(300)
    progress = stickmorph.Progress()
    error, _ = cancel_when(progress, lambda p: p.stage == "frames" and p.done >= 2,
                           lambda: stickmorph.morph(source, target, edges, frames=5000, method=method,
                                                    progress=progress))
    assert isinstance(error, stickmorph.CancelledError), error
    assert str(error) == "cancelled while in stage 'frames'"
    assert progress.total == 5000 and 2 <= progress.done < 5000
    assert 0 < progress.fraction < 1


def test_morph_key_poses_and_its_solver_are_cancellable():
    a, b, edges = waves(300)
    keys = [a, b, a + [0.0, 1.0]]
    progress = stickmorph.Progress()
    error, _ = cancel_when(progress, lambda p: p.stage == "frames" and p.done >= 2,
                           lambda: stickmorph.morph_key_poses(keys, edges, frames=4001, progress=progress))
    assert isinstance(error, stickmorph.CancelledError), error
    progress = stickmorph.Progress()
    progress.cancel()
    with pytest.raises(stickmorph.CancelledError):
        stickmorph.KeyPoseMorphSolver(keys, edges, progress=progress)


def test_a_progress_not_cancelled_changes_nothing():
    source, target, edges = waves(500)
    for method in ("rigid", "barycentric"):
        plain = stickmorph.morph(source, target, edges, frames=20, method=method)
        progress = stickmorph.Progress()
        watched = stickmorph.morph(source, target, edges, frames=20, method=method, progress=progress)
        assert np.array_equal(plain["frames"], watched["frames"])  # bit for bit
        # The call ends its last stage: the summary is the call's.
        assert progress.stage is None and progress.fraction is None
        assert [name for name, _ in progress.stages] == ["check", "triangulate", "frames"]
        assert all(ms >= 0 for _, ms in progress.stages)
        summary = progress.summary()
        assert summary.startswith("check ") and " ms, triangulate " in summary and summary.endswith(" ms")


def test_with_progress_installs_it_for_every_call_of_the_thread():
    source, target, edges = waves(50)
    progress = stickmorph.Progress()
    with progress:
        stickmorph.morph(source, target, edges, frames=5)
        assert progress.stage == "frames" and progress.done == 5 and progress.fraction == 1.0
    assert progress.stage is None
    progress.cancel()
    with progress:
        with pytest.raises(stickmorph.CancelledError):
            stickmorph.morph(source, target, edges, frames=5)
    # Outside the block the thread has none again.
    assert stickmorph.morph(source, target, edges, frames=5)["frames"].shape == (5, 50, 2)


def test_a_progress_elsewhere_in_the_thread_is_not_this_threads():
    source, target, edges = waves(50)
    progress = stickmorph.Progress()
    progress.cancel()
    result = {}
    with progress:
        other = threading.Thread(target=lambda: result.update(r=stickmorph.morph(source, target, edges, frames=5)))
        other.start()
        other.join()
    assert result["r"]["frames"].shape == (5, 50, 2)


def test_caller_stages_and_argument_checks():
    progress = stickmorph.Progress()
    assert progress.stage is None and progress.fraction is None and progress.stages == []
    progress.begin_stage("build", 4)
    progress.set_progress(1, 4)
    assert progress.stage == "build" and progress.fraction == 0.25
    progress.finish()
    assert [name for name, _ in progress.stages] == ["build"]
    with pytest.raises(stickmorph.InvalidArgumentError):
        progress.begin_stage("")
    with pytest.raises(stickmorph.InvalidArgumentError):
        progress.set_progress(-1, 3)
    source, target, edges = waves(20)
    with pytest.raises(stickmorph.InvalidArgumentError, match="progress must be a stickmorph.Progress"):
        stickmorph.morph(source, target, edges, progress="yes")


# ------------------------------------------------------ the add-on's job ----

def test_stage_timer_summary_is_the_bakes_stage_line():
    timer = bake_job.StageTimer()
    assert timer.current == "read"
    timer.stage("read", 5)
    timer.stage("check", 15)
    assert timer.current == "morph" and timer.percent == 15
    timer.stage("morph", 60)
    timer.stage("build", 100)
    names = [part.split(" ")[0] for part in timer.summary().split(", ")]
    assert names == ["read", "check", "morph", "build"]
    assert all(part.endswith(" ms") for part in timer.summary().split(", "))


def test_bake_job_cancelled_during_the_triangulation_holds_no_result():
    source, target, edges = waves(20000)

    def work(timer):
        timer.stage("read", 5)
        timer.stage("check", 15)
        result = stickmorph.morph(source, target, edges, frames=10)  # the job's Progress, by `with`
        timer.stage("morph", 60)
        return result

    job = bake_job.BakeJob(work, stickmorph.Progress()).start()
    deadline = time.monotonic() + 60
    while job.running and job.stage()[0] != "triangulate" and time.monotonic() < deadline:
        time.sleep(0.001)
    text = job.status_text()
    assert text.startswith("Stick Morph: triangulating… ") and text.endswith(" — Esc to cancel"), text
    assert 15 <= job.percent() <= 55
    job.cancel()
    assert job.status_text() == "Stick Morph: cancelling…"
    assert job.wait(30)
    assert job.cancelled and job.result is None
    assert isinstance(job.error, stickmorph.CancelledError)


def test_bake_job_not_cancelled_returns_the_work():
    source, target, edges = waves(100)
    job = bake_job.BakeJob(lambda timer: stickmorph.morph(source, target, edges, frames=8),
                           stickmorph.Progress()).start()
    assert job.wait(60)
    assert not job.cancelled and job.error is None
    assert np.array_equal(job.result["frames"], stickmorph.morph(source, target, edges, frames=8)["frames"])
    # Without a Progress (a module that has none) the job still runs, uncancellable.
    job = bake_job.BakeJob(lambda timer: 42).start()
    assert job.wait(10) and job.result == 42
