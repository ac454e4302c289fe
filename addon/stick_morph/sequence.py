"""Key poses (issue 28): one morph through K >= 2 poses of a stick figure,
free of bpy like the rest of core.

Two ways in, both operators thin over this module (sequence_operators.py):

- Bake Key Poses: K edge meshes are the keys, ordered by name (order_by_name)
  or taken in a collection's order, at key frames evenly spaced or each
  object's own (key_frames).
- Rebake Shape Keys: one mesh whose shape keys are animated pose to pose; the
  poses and their frames come from pose_to_pose.

prepare_keys checks the keys and projects them onto their common plane
(plane.fit_plane_of, as prepare_pair does for two), morph_keys runs the
engine's stickmorph.morph_key_poses and maps its frames back to world space.

Heights: each key keeps its vertices' distances h_k from the common plane
(for a matched sequence, a dummy's interpolated along its key's edge, as for
a pair). A frame f of the segment from key a (frame f_a) to key b (f_b) has
the height (1 - s) h_a + s h_b, s = (f - f_a) / (f_b - f_a) (eased as the
segment is, with Easing): the keys are exact, and keys drawn in one plane
stay in it. With local timing (issue 31: delay weights from a vertex group of
the first key, and the overlap) each vertex's s is its own local time in the
segment (timing.local_times), as the engine runs the delay on each segment's
own clock.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import numpy as np

from .common import BakeSettings, StickMorphError, is_pin_group
from .correspondence import CORRESPONDENCES, _names, check_pins, compare_edge_sets, matched_heights, read_pins
from .morph import ROTATIONS, refuse_faces, refuse_non_finite
from .native import load_engine
from .plane import Plane, check_planarity, fit_plane_of, project, unproject
from .timing import RIGID_EASINGS, ease, local_times

# An object's key frame (its Object property stick_morph_key_frame): 0 means
# automatic, evenly spaced from the start frame.
AUTO_KEY_FRAME = 0

# How far from 0 or 1 a shape key's value at a keyframe may be and still
# count as off or on (pose_to_pose).
POSE_VALUE_TOLERANCE = 1e-6


def key_label(names, k: int) -> str:
    """"key 2 ('Pose.001')": key k (0-based) as the user sees it, 1-based
    like the engine's messages."""
    return f"key {k + 1} ('{names[k]}')"


# ------------------------------------------------------------- ordering ----

def natural_key(name: str) -> tuple:
    """A sort key that orders digit runs by value: Pose_2 before Pose_10,
    Pose before Pose.001."""
    return tuple((0, int(part), part) if part.isdigit() else (1, 0, part)
                 for part in re.split(r"(\d+)", name) if part != "")


def order_by_name(names) -> list[int]:
    """The indices of names in natural name order (natural_key), the order of
    the keys when no collection gives one."""
    return sorted(range(len(names)), key=lambda k: (natural_key(names[k]), names[k]))


def key_frames(names, own_frames, start: int, step: int) -> list[int]:
    """The scene frame of every key: start + k * step when no key has a frame
    of its own (every own frame AUTO_KEY_FRAME), else every key's own frame,
    which must then be given for every key and increase strictly. Raises
    StickMorphError naming the key."""
    count = len(names)
    if count < 2:
        raise StickMorphError(
            "a key-pose sequence needs at least two edge meshes (the keys); got "
            + (f"only '{names[0]}'" if count else "none"))
    if step < 1:
        raise StickMorphError(f"the frames between keys must be at least 1, got {step}")
    own = [int(f) for f in own_frames]
    if all(f == AUTO_KEY_FRAME for f in own):
        return [start + k * step for k in range(count)]
    unset = [k for k, f in enumerate(own) if f == AUTO_KEY_FRAME]
    if unset:
        given = next(k for k, f in enumerate(own) if f != AUTO_KEY_FRAME)
        raise StickMorphError(
            f"{key_label(names, unset[0])} has no key frame of its own (Key Frame 0: automatic) but "
            f"{key_label(names, given)} has one (frame {own[given]}): give every key a key frame, or none")
    for k in range(1, count):
        if own[k] <= own[k - 1]:
            raise StickMorphError(
                f"the key frames must increase: {key_label(names, k)} is at frame {own[k]}, not after "
                f"{key_label(names, k - 1)} at frame {own[k - 1]}")
    return own


def timeline(frames, step: int, loop: bool) -> tuple[int, list[int]]:
    """(the number of frames N of the whole motion, keys_at: each key's frame
    from 0) for keys at the scene frames `frames`. With loop the motion
    returns to the first key `step` frames after the last key, at frame N - 1."""
    first = frames[0]
    last = frames[-1] + (step if loop else 0)
    return last - first + 1, [f - first for f in frames]


# ------------------------------------------------------- pose to pose ----

@dataclass(frozen=True)
class Pose:
    frame: int  # the scene frame of the keyframe
    key: int  # -1: the basis, else the index of the non-basis shape key that is on


def pose_to_pose(object_name: str, frames, key_names, values, basis_name: str = "Basis") -> list[Pose]:
    """The poses of a shape-key animation that goes pose to pose.

    frames: the keyframes' frames (of every F-curve of a shape key's value,
    together), values: (len(frames), J) the J non-basis keys' values there.
    At every keyframe exactly one key is on (value 1, the others 0: that
    key's shape), or none (all 0: the basis). A value strictly between 0 and
    1 (or outside [0, 1]), two keys on at once, or a keyframe between whole
    frames is not pose to pose: StickMorphError naming the frame."""
    frames = [float(f) for f in frames]
    values = np.asarray(values, dtype=np.float64).reshape(len(frames), len(key_names))
    if not key_names:
        raise StickMorphError(f"'{object_name}' has no shape keys but the basis: a pose-to-pose animation "
                              "needs a shape key per pose, animated by its value")
    if len(frames) < 2:
        raise StickMorphError(
            f"'{object_name}': its shape keys have {len(frames)} keyframe{'' if len(frames) == 1 else 's'}; "
            "a pose-to-pose animation needs a keyframe at two frames or more")
    poses = []
    tolerance = POSE_VALUE_TOLERANCE
    for frame, row in zip(frames, values):
        shown = f"{frame:g}"
        if abs(frame - round(frame)) > 1e-4:
            raise StickMorphError(f"'{object_name}': frame {shown} holds a keyframe between whole frames; "
                                  "the poses of a pose-to-pose animation are on whole frames")
        partial = [j for j, value in enumerate(row) if min(abs(value), abs(value - 1.0)) > tolerance]
        if partial:
            j = partial[0]
            raise StickMorphError(
                f"'{object_name}' is not animated pose to pose: at frame {shown} the shape key "
                f"'{key_names[j]}' is {row[j]:.4g} (at a keyframe every shape key is 0 or 1)")
        on = [j for j, value in enumerate(row) if abs(value - 1.0) <= tolerance]
        if len(on) > 1:
            raise StickMorphError(
                f"'{object_name}' is not animated pose to pose: at frame {shown} the shape keys "
                f"{_names([key_names[j] for j in on])} are all on (at a keyframe at most one shape key "
                "is 1, the others 0)")
        poses.append(Pose(int(round(frame)), on[0] if on else -1))
    if len({pose.key for pose in poses}) < 2:
        only = basis_name if poses[0].key < 0 else key_names[poses[0].key]
        raise StickMorphError(f"'{object_name}' shows one pose only ('{only}') at all its keyframes: "
                              "nothing to morph")
    return poses


def pose_holds(poses) -> list[bool]:
    """Hold at a pose that the next or the previous keyframe repeats: the
    figure stays still between them (the engine's hold stops the motion at a
    key)."""
    hold = [False] * len(poses)
    for k in range(1, len(poses)):
        if poses[k].key == poses[k - 1].key:
            hold[k] = hold[k - 1] = True
    return hold


# --------------------------------------------------------------- keys ----

def _takes(argument: str, engine=None) -> bool:
    """Whether the module's morph_key_poses takes this keyword argument;
    read from its signature, the docstring's first line."""
    engine = engine or load_engine()
    doc = getattr(engine.morph_key_poses, "__doc__", None) or ""
    signature = doc.strip().splitlines()[0] if doc.strip() else ""
    return re.search(rf"\b{argument}\b", signature) is not None


def supports_matching(engine=None) -> bool:
    """Whether the module's morph_key_poses takes correspond= (keys drawn separately)."""
    return _takes("correspond", engine)


def supports_easing(engine=None) -> bool:
    """Whether the module's morph_key_poses takes easing= (eased segments)."""
    return _takes("easing", engine)


def supports_local_timing(engine=None) -> bool:
    """Whether the module's morph_key_poses takes delay= and overlap= (issue 31)."""
    return _takes("delay", engine) and _takes("overlap", engine)


@dataclass
class PreparedKeys:
    """K keys ready for the engine, in their common plane."""

    names: list  # the objects' names, key order
    plane: Plane
    keys_xy: list  # K (V_k, 2) float64
    heights: list  # K (V_k,) float64
    edges: list  # K (E_k, 2) int64, each key's own
    size: float  # diagonal of the keys' common bounding box
    matched: bool  # correspond="auto"
    why: str  # why by index or matched, for the report
    pins: list = field(default_factory=list)  # K - 1 tuples of Pin (key k with key k + 1)
    setting: str = "INDEX_OR_MATCH"
    # Local timing (issue 31): the delay weight of each vertex of key 1 (the
    # engine carries them onto a matched common figure), or None.
    delay: np.ndarray | None = None


def _not_supported(names, why: str) -> StickMorphError:
    return StickMorphError(
        f"the keys need matching by shape ({why}), and the stickmorph module in this add-on cannot "
        "match key poses yet (its morph_key_poses has no correspond=); draw every key as an edited "
        "copy of the first (same vertices and edges) with Match Automatic or By Index, or update the add-on")


def refuse_unsupported_options(settings: BakeSettings) -> None:
    """Key poses move with the Rigid motion at even speed only (the engine's
    morph_key_poses); other settings are refused, not ignored."""
    if settings.motion != "RIGID":
        raise StickMorphError(
            f"key poses move with the Rigid motion only (Motion is {settings.motion.title()}): the engine "
            "morphs a sequence of keys rigidly; set Motion to Rigid")
    if settings.easing not in RIGID_EASINGS:
        raise StickMorphError(f"unknown easing {settings.easing!r} (choose one of {', '.join(RIGID_EASINGS)})")
    if settings.easing != "NONE" and not supports_easing():
        raise StickMorphError(
            "Easing of key poses needs a newer stickmorph module (this one's morph_key_poses has no easing=); "
            "set Easing to Linear, or Hold at Keys to stop the motion at each key")
    if settings.rotation not in ROTATIONS:
        raise StickMorphError(f"unknown rotation {settings.rotation!r} (choose one of {', '.join(ROTATIONS)})")
    if settings.correspondence not in CORRESPONDENCES:
        raise StickMorphError(f"unknown correspondence {settings.correspondence!r} "
                              f"(choose one of {', '.join(CORRESPONDENCES)})")


def prepare_keys(worlds, edges, faces, names, settings: BakeSettings, groups=None, delay=None) -> PreparedKeys:
    """Checks K keys (world-space vertices, edges, face counts, vertex groups
    {name: [vertex, ...]} for the pins) and projects them onto their common
    plane. By index when settings.correspondence is INDEX, or Automatic and
    every key has the first key's vertex count and edges and there are no
    pins; matched otherwise. delay: the delay weights of key 1's vertices
    (timing.delay_weights) or None. Raises StickMorphError naming the key."""
    names = list(names)
    count = len(names)
    if count < 2:
        key_frames(names, [AUTO_KEY_FRAME] * count, 1, 1)  # raises, naming what there is
    refuse_unsupported_options(settings)
    setting = settings.correspondence
    worlds = [np.asarray(w, dtype=np.float64).reshape(-1, 3) for w in worlds]
    edges = [np.asarray(e, dtype=np.int64).reshape(-1, 2) for e in edges]
    groups = [dict(g or {}) for g in (groups or [{}] * count)]
    for name, face_count in zip(names, faces):
        refuse_faces(name, face_count)
    for name, world in zip(names, worlds):
        if len(world) == 0:
            raise StickMorphError(f"'{name}' has no vertices")
    pinned = sorted({g for key_groups in groups for g in key_groups if is_pin_group(g)})
    same_counts = all(len(w) == len(worlds[0]) for w in worlds)
    if setting == "INDEX":
        if pinned:
            raise StickMorphError(
                f"pins need Correspondence (Match) Automatic or By Shape: with By Index the pin group"
                f"{'s' if len(pinned) > 1 else ''} {_names(pinned)} would have no effect (Clear Pins removes them)")
        for k in range(1, count):
            if len(worlds[k]) != len(worlds[0]):
                raise StickMorphError(
                    f"different vertex counts: {key_label(names, 0)} has {len(worlds[0])} vertices, "
                    f"{key_label(names, k)} has {len(worlds[k])}; with Correspondence (Match) By Index every "
                    "key needs the same vertices and edges (Automatic or By Shape matches keys drawn separately)")
    same_edges = same_counts and all(compare_edge_sets(edges[0], e) is None for e in edges[1:])
    if setting == "INDEX" and not same_edges:
        for k in range(1, count):
            message = compare_edge_sets(edges[0], edges[k], names[0], names[k])
            if message:
                raise StickMorphError(f"{key_label(names, 0)} and {key_label(names, k)}: {message}; with "
                                      "Correspondence (Match) By Index every key needs the same edges")
    pins = []
    if setting != "INDEX":
        for k in range(count - 1):
            pair = read_pins(groups[k], groups[k + 1], names[k], names[k + 1])
            check_pins(pair, edges[k], edges[k + 1], len(worlds[k]), len(worlds[k + 1]), names[k], names[k + 1])
            pins.append(tuple(pair))
    for name, world in zip(names, worlds):
        refuse_non_finite(name, world)
    if setting == "MATCH":
        matched, why = True, "Match is By Shape"
    elif setting == "INDEX":
        matched, why = False, "Match is By Index"
    elif not same_counts:
        matched, why = True, "the vertex counts differ"
    elif not same_edges:
        matched, why = True, "the edges differ"
    elif pinned:
        matched, why = True, "the keys have pins"
    else:
        matched, why = False, "the same vertices and edges"
    if matched and not supports_matching():
        raise _not_supported(names, why)
    if delay is not None:
        delay = np.asarray(delay, dtype=np.float64).reshape(-1)
        if len(delay) != len(worlds[0]):
            raise StickMorphError(f"the delay weights of {key_label(names, 0)} are {len(delay)}, for "
                                  f"{len(worlds[0])} vertices")
        if not supports_local_timing():
            raise StickMorphError(
                "local timing (Delay Group) needs a newer stickmorph module: this one's morph_key_poses has no "
                "delay= or overlap=; clear Delay Group, or update the add-on")

    fitted = fit_plane_of(worlds, settings.plane)
    projected = [project(world, fitted) for world in worlds]
    every = np.vstack(worlds)
    size = float(np.linalg.norm(every.max(axis=0) - every.min(axis=0)))
    check_planarity([(name, h) for name, (_, h) in zip(names, projected)], size, settings.planarity_tolerance,
                    fitted, settings.plane)
    return PreparedKeys(names, fitted, [xy for xy, _ in projected], [h for _, h in projected], edges, size,
                        matched, why, pins, setting, delay)


# -------------------------------------------------------------- morph ----

@dataclass
class SequenceResult:
    frames_world: np.ndarray  # (N, m, 3) world space
    edges: np.ndarray  # (E, 2) the result's edges (matched: the common figure's)
    keys_at: list  # K frames from 0
    segments: list  # the engine's segment dicts
    matched: bool
    why: str
    places: list | None = None  # matched: the engine's "places", one dict per key
    overlap: float | None = None  # local timing's overlap (issue 31), None without a delay group


def key_error_message(error: Exception, names) -> str:
    """The engine's message with every "key k" followed by the object's name."""
    engine = load_engine()
    text = str(error)

    def named(match):
        k = int(match.group(1)) - 1
        return f"{match.group(0)} ('{names[k]}')" if 0 <= k < len(names) else match.group(0)

    text = re.sub(r"\bkey (\d+)\b(?! \(')", named, text)
    if isinstance(error, engine.InvalidFigureError):
        return f"invalid key pose: {text}"
    if isinstance(error, engine.IncompatibleFiguresError):
        return f"incompatible key poses: {text}"
    if isinstance(error, engine.InternalError):
        return f"internal error in the stickmorph engine (a bug): {text}"
    return f"stickmorph: {text}"


def _frame_heights(heights, segments, frame_count: int, easing: str = "NONE", delay=None,
                   overlap: float = 0.0) -> np.ndarray:
    """(N, m) heights: each segment's keys' heights, blended by frame (eased
    as the segments are: timing.ease), each vertex on its own clock in the
    segment with delay weights (m,) (timing.local_times)."""
    out = np.empty((frame_count, len(heights[0])))
    for segment in segments:
        first, last = int(segment["first_frame"]), int(segment["last_frame"])
        a, b = heights[int(segment["from_key"])], heights[int(segment["to_key"])]
        s = local_times(ease((np.arange(first, last + 1) - first) / max(last - first, 1), easing), delay, overlap)
        out[first:last + 1] = (1.0 - s) * a[None, :] + s * b[None, :]
    return out


def morph_keys(prepared: PreparedKeys, settings: BakeSettings, frame_count: int, keys_at, loop: bool = False,
               hold=None) -> SequenceResult:
    """The engine's morph through the prepared keys, in world space. With
    Match Automatic, keys taken by index that the engine finds incompatible
    that way are matched instead, where the module can."""
    engine = load_engine()
    options = dict(frames=int(frame_count), keys_at=[int(f) for f in keys_at], loop=bool(loop),
                   hold=None if hold is None else [bool(h) for h in hold],
                   rotation=settings.rotation.lower(), turns=int(settings.turns), steiner=settings.steiner,
                   weights=settings.weights, enclosure_sides=int(settings.enclosure_sides), verify=True)
    if settings.easing != "NONE":  # every segment eased (a module without easing= was refused)
        options["easing"] = RIGID_EASINGS[settings.easing]
    if prepared.delay is not None:  # key 1's weights (a module without delay= was refused)
        options.update(delay=prepared.delay, overlap=float(settings.overlap))

    def run(matched):
        if matched:
            pins = [[[p.source, p.target] for p in pair] for pair in prepared.pins]
            return engine.morph_key_poses(prepared.keys_xy, prepared.edges, correspond="auto",
                                          pins=pins if any(pins) else None, **options)
        return engine.morph_key_poses(prepared.keys_xy, prepared.edges[0], **options)

    matched, why = prepared.matched, prepared.why
    try:
        result = run(matched)
    except engine.IncompatibleFiguresError as e:
        # Automatic took the keys by index; matched, they may still be
        # compatible (a symmetric figure numbered otherwise).
        by_index = key_error_message(e, prepared.names)
        if matched or prepared.setting != "INDEX_OR_MATCH" or not supports_matching(engine):
            raise StickMorphError(by_index) from e
        matched, why = True, "they are not compatible by index"
        try:
            result = run(True)
        except (engine.StickMorphError, engine.InternalError) as again:
            raise StickMorphError(f"{by_index} (nor can they be matched by shape: "
                                  f"{key_error_message(again, prepared.names)})") from again
    except (engine.StickMorphError, engine.InternalError) as e:
        raise StickMorphError(key_error_message(e, prepared.names)) from e
    places = result.get("places") if matched else None
    delay = prepared.delay
    if matched:
        heights = [matched_heights(prepared.heights[k], prepared.edges[k], place["vertex"], place["edge"],
                                   place["fraction"]) for k, place in enumerate(places)]
        if delay is not None:  # onto the common figure, as the engine carries them
            first = places[0]
            delay = matched_heights(delay, prepared.edges[0], first["vertex"], first["edge"], first["fraction"])
    else:
        heights = prepared.heights
    frames_xy = np.asarray(result["frames"], dtype=np.float64)
    frame_heights = _frame_heights(heights, result["segments"], len(frames_xy), settings.easing, delay,
                                   float(settings.overlap))
    return SequenceResult(unproject(frames_xy, frame_heights, prepared.plane),
                          np.asarray(result["edges"], dtype=np.int64).reshape(-1, 2), list(result["keys_at"]),
                          list(result["segments"]), matched, why, places,
                          None if prepared.delay is None else float(settings.overlap))


def segment_summary(result: SequenceResult, names, frame_start: int) -> list[str]:
    """One line per segment: its keys, scene frames, Steiner vertices, how
    many inner frames follow the rigid guide, and its milliseconds."""
    lines = []
    for segment in result.segments:
        a, b = int(segment["from_key"]), int(segment["to_key"])
        guide = segment.get("guide_frames") or {}
        follow = int(guide.get("exact", 0)) + int(guide.get("blended", 0))
        inner = follow + int(guide.get("barycentric", 0))
        ms = segment.get("milliseconds") or {}
        total = float(ms.get("triangulate", 0.0)) + float(ms.get("morph", 0.0))
        lines.append(f"key {a + 1} '{names[a]}' \u2192 key {b + 1} '{names[b]}': frames "
                     f"{frame_start + int(segment['first_frame'])}-{frame_start + int(segment['last_frame'])}, "
                     f"{int(segment.get('steiner_vertices', 0))} Steiner, rigid {follow}/{inner}, {total:.0f} ms")
    return lines
