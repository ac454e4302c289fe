"""Frame timing: the easing, how many frames the engine computes for the
output frames and which of them each output frame shows; local timing (issue
31: the delay weights from a vertex group, each vertex's local time); frame
lists for messages."""

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


# ------------------------------------------------------- local timing ----
# Issue 31: a vertex group of the source mesh (of the first key) gives every
# vertex a delay weight w in [0, 1], and with the overlap d in [0, 1) a part
# moves at local time clamp((t - d w) / (1 - d), 0, 1): weight 0 leads,
# weight 1 lags by d, and d = 0 is the plain morph. The engine applies it to
# the figure (stickmorph.morph's delay= and overlap=); the add-on reads the
# weights (delay_weights) and moves the heights above the plane on the same
# clocks (local_times).

def _owner(object_name: str, role: str) -> str:
    return f"{role} '{object_name}'" if role else f"'{object_name}'"


def delay_weights(vertex_count: int, members, group: str, object_name: str,
                  role: str = "the source mesh", groups=()) -> list[float] | None:
    """The delay weight of each of a mesh's vertex_count vertices, from its
    vertex group `group`: members, that group's (vertex index, weight) pairs,
    or None when the mesh has no vertex group of that name (groups: the names
    it has, for the message). A vertex not in the group weighs 0. None when
    no group is named (group "": no local timing).

    Raises StickMorphError, naming the group and the object (role: "the
    source mesh", "the first key", ...): the group is missing, or holds no
    vertex (assigned with any weight, 0 included, a vertex is in it); or, for
    data not from Blender (which keeps weights in [0, 1]), a vertex index
    outside the mesh or a weight outside [0, 1]."""
    if not group:
        return None
    owner = _owner(object_name, role)
    if members is None:
        names = ", ".join(f"'{name}'" for name in groups)
        raise StickMorphError(
            f"the delay group '{group}' is not a vertex group of {owner} "
            f"({'its vertex groups: ' + names if names else 'it has no vertex groups'}): choose one of its "
            "groups as Delay Group, or clear Delay Group for no local timing")
    members = list(members)
    if not members:
        raise StickMorphError(
            f"the delay group '{group}' of {owner} holds no vertex: assign the vertices that lag to it "
            "(paint their weights in Weight Paint mode, or Edit Mode > Vertex Groups > Assign), or clear "
            "Delay Group for no local timing")
    weights = [0.0] * int(vertex_count)
    for vertex, weight in members:
        vertex, weight = int(vertex), float(weight)
        if not 0 <= vertex < len(weights):
            raise StickMorphError(f"the delay group '{group}' of {owner} names vertex {vertex}, but the mesh has "
                                  f"{len(weights)} vertices")
        if not 0.0 <= weight <= 1.0:  # NaN too
            raise StickMorphError(f"vertex {vertex} of {owner} has the weight {weight!r} in the delay group "
                                  f"'{group}', outside [0, 1]")
        weights[vertex] = weight
    return weights


def local_times(times, delay=None, overlap: float = 0.0) -> np.ndarray:
    """(N, m) each vertex's local time at each of the N times (the fraction
    of the motion, [0, 1]): clamp((t - d w) / (1 - d), 0, 1) for the delay
    weights w (m,) and the overlap d; without weights (delay None) the
    times themselves, (N, 1). The ends stay exact: every vertex is at 0 at
    t = 0 and at 1 at t = 1."""
    t = np.asarray(times, dtype=np.float64).reshape(-1, 1)
    if delay is None:
        return t
    w = np.asarray(delay, dtype=np.float64).reshape(1, -1)
    d = float(overlap)
    if not 0.0 <= d < 1.0:
        raise StickMorphError(f"the overlap must be at least 0 and less than 1, got {overlap!r}")
    return np.clip((t - d * w) / (1.0 - d), 0.0, 1.0)
