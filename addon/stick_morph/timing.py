"""Frame timing: the easing, how many frames the engine computes for the
output frames and which of them each output frame shows; frame lists for
messages."""

from __future__ import annotations

import numpy as np

from .common import StickMorphError
from .native import engine_limits

EASINGS = ("NONE", "IN_OUT")


# The engine's easing of a RIGID morph for each of EASINGS
# (stickmorph.EASING_NAMES).
RIGID_EASINGS = {"NONE": "none", "IN_OUT": "in-out"}


# With easing, BARYCENTRIC and LINEAR frames are picked from a finer uniform
# morph of this many samples per output frame interval (see
# ease_sample_indices).
EASE_OVERSAMPLING = 8


def ease(t, easing: str = "NONE"):
    """Time remap of [0, 1] onto [0, 1]: identity or smoothstep (ease in-out)."""
    t = np.clip(np.asarray(t, dtype=np.float64), 0.0, 1.0)
    if easing == "NONE":
        return t
    if easing == "IN_OUT":
        return t * t * (3.0 - 2.0 * t)
    raise StickMorphError(f"unknown easing {easing!r} (choose one of {', '.join(EASINGS)})")


def engine_frame_count(frame_count: int, easing: str, motion: str) -> int:
    """How many frames the engine computes for `frame_count` output frames.

    RIGID: exactly frame_count, the engine eases them itself
    (compute_morph). BARYCENTRIC and LINEAR: with easing, an oversampled
    uniform morph to pick from (ease_sample_indices)."""
    if easing == "NONE" or motion == "RIGID":
        return frame_count
    return min(engine_limits()["max_frames"], (frame_count - 1) * EASE_OVERSAMPLING + 1)


def ease_sample_indices(frame_count: int, easing: str, motion: str) -> np.ndarray:
    """Which frame of the engine's morph (engine_frame_count frames) each
    output frame shows.

    BARYCENTRIC and LINEAR: the engine computes frames at uniform times only,
    and every frame it returns is verified exactly (LINEAR: checked, its
    invalid frames listed); easing therefore picks, for output frame k, the
    engine frame nearest to the eased time ease(k / (N - 1)) from an
    oversampled uniform morph, instead of interpolating between frames (which
    could make an invalid figure). Linear easing is the identity. The first
    and last frames are always the source and target. RIGID: the identity,
    the engine eases (compute_morph says why).
    """
    m = engine_frame_count(frame_count, easing, motion)
    if m == frame_count:
        return np.arange(frame_count, dtype=np.int64)
    k = np.arange(frame_count, dtype=np.float64)
    eased = ease(k / (frame_count - 1), easing)
    return np.rint(eased * (m - 1)).astype(np.int64)


def frame_list(frames, limit: int = 12) -> str:
    """Frame numbers as ranges: [3, 4, 5, 9] -> "3-5, 9"; after `limit`
    ranges, "and N more" (frames)."""
    runs = []
    for frame in sorted(frames):
        if runs and frame == runs[-1][1] + 1:
            runs[-1][1] = frame
        else:
            runs.append([frame, frame])
    shown = [f"{a}-{b}" if b > a else f"{a}" for a, b in runs[:limit]]
    rest = sum(b - a + 1 for a, b in runs[limit:])
    return ", ".join(shown) + (f" and {rest} more" if rest else "")
