"""The engine's part of a bake in a worker thread, watched and cancelled from
Blender's main thread (issue 29: a 10^5-vertex bake takes minutes, most of
it the engine's triangulation).

Free of bpy, so that it is tested without Blender (tests/python) and in
headless Blender without a window (tests/blender/test_cancel.py). The modal
operators (operators.BakeExecute.invoke) start a BakeJob after reading the
meshes, poll it from a window-manager timer, and build the result in the
main thread once it is done: Blender data may only be written there.

The worker only computes: it reads NumPy arrays and calls the engine, which
releases the GIL, so Blender's UI keeps running. A stickmorph.Progress is
installed for the worker's engine calls (`with progress:`), so the add-on's
engine glue (core.prepare_pair, core.morph_pair, sequence.morph_keys) needs
no argument for it; cancel() makes the running engine call raise
stickmorph.CancelledError at its next check, and the job then holds no
result, whatever the worker was doing.
"""

import threading
import time
import weakref

# How the status bar names each stage: the add-on's own ("read", "check",
# "build") and the engine's (stickmorph.Progress.stage).
STAGE_WORDS = {
    "read": "reading the meshes",
    "check": "checking",
    "correspond": "matching the figures",
    "triangulate": "triangulating",
    "frames": "morphing",
    "morph": "morphing",
    "build": "building the result",
}


class StageTimer:
    """The bake's stages and their times, "read 12 ms, check 30 ms, morph
    3100 ms, build 900 ms" (the scene's last_stages, the benchmark's split
    between engine and Blender). stage(name, percent) ends the stage `name`,
    timed from the end of the previous one; `percent` is the whole bake's
    (0-100), kept for the progress indicator. Only appends and reads: the
    worker writes it, the main thread reads it, one at a time by the GIL."""

    # The stage that runs after each one: what the status bar says now.
    NEXT = {None: "read", "read": "check", "check": "morph", "morph": "build"}

    def __init__(self):
        self.stages = []  # (name, milliseconds)
        self.percent = 0
        self._started = time.perf_counter()

    def update(self, percent):
        self.percent = percent

    def stage(self, name, percent):
        """Ends the stage `name` (timed from the previous one) at `percent`."""
        now = time.perf_counter()
        self.stages.append((name, (now - self._started) * 1000.0))
        self._started = now
        self.update(percent)

    @property
    def current(self):
        """The stage running now: the one after the last that ended."""
        return self.NEXT.get(self.stages[-1][0] if self.stages else None)

    def summary(self):
        return ", ".join(f"{name} {ms:.0f} ms" for name, ms in self.stages)


_last_started = None  # weakref to the last job started, for tests (last_started)


def last_started():
    """The job started last, while something holds it (a running modal
    bake does), else None: a GUI test watches the bake's stage through it
    before it presses Esc (tests/blender/gui/cancel_bake.py)."""
    return _last_started() if _last_started is not None else None


class BakeJob:
    """work(timer) run in a daemon thread with `progress` (a
    stickmorph.Progress, or None for a module without one) installed for its
    engine calls. After the thread ends: `result` is work's return value, or
    `error` the exception it raised; `cancelled` says whether cancel() was
    called, in which case neither is to be used (the bake creates nothing)."""

    def __init__(self, work, progress=None, timer=None):
        self.progress = progress
        self.timer = timer if timer is not None else StageTimer()
        self.result = None
        self.error = None
        self._work = work
        self._cancel_requested = False
        self._started = None
        self._thread = threading.Thread(target=self._run, name="stick_morph_bake", daemon=True)

    def start(self):
        global _last_started
        self._started = time.perf_counter()
        self._thread.start()
        _last_started = weakref.ref(self)
        return self

    def _run(self):
        try:
            if self.progress is not None:
                with self.progress:
                    self.result = self._work(self.timer)
            else:
                self.result = self._work(self.timer)
        except BaseException as error:  # handed to the main thread, which reports it
            self.error = error

    def cancel(self):
        """Tells the engine to stop (it raises CancelledError at its next
        check, within a fraction of a second); returns at once. What the
        worker computes after this is dropped."""
        self._cancel_requested = True
        if self.progress is not None:
            self.progress.cancel()

    @property
    def running(self):
        return self._thread.is_alive()

    @property
    def cancelled(self):
        return self._cancel_requested

    def wait(self, timeout=None):
        """Waits for the worker; True when it has ended."""
        self._thread.join(timeout)
        return not self._thread.is_alive()

    @property
    def elapsed(self):
        return 0.0 if self._started is None else time.perf_counter() - self._started

    def stage(self):
        """(stage name, fraction in [0, 1] or None): the engine's stage while
        the add-on's is the morph (or its check, which may match figures),
        else the add-on's."""
        current = self.timer.current
        if self.progress is not None and current in ("check", "morph"):
            engine_stage = self.progress.stage
            if engine_stage is not None:
                return engine_stage, self.progress.fraction
        return current, None

    def percent(self):
        """The whole bake's progress for the window manager's indicator,
        0-100: the add-on's stages' marks, and within the morph the engine's
        count of its current stage (triangulation 15-55, frames 55-95)."""
        name, fraction = self.stage()
        if self.timer.current == "morph" and name in ("triangulate", "frames"):
            low, high = (15, 55) if name == "triangulate" else (55, 95)
            return int(low + (high - low) * (fraction or 0.0))
        return int(self.timer.percent)

    def status_text(self):
        """"Stick Morph: triangulating… 35% — Esc to cancel"; the elapsed
        seconds where nothing is counted."""
        if self.cancelled:
            return "Stick Morph: cancelling…"
        name, fraction = self.stage()
        words = STAGE_WORDS.get(name, name or "starting")
        amount = f"{fraction * 100:.0f}%" if fraction is not None else f"{self.elapsed:.0f} s"
        return f"Stick Morph: {words}… {amount} — Esc to cancel"
