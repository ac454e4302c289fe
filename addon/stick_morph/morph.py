"""The two meshes made ready for the engine (prepare_pair) and the morph
itself (compute_morph, MorphResult), with what the bake reports of it.
core.py's docstring has the geometry of the way back to world space."""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from .common import BakeSettings, StickMorphError, is_pin_group, option_applies
from .correspondence import (_BY_INDEX, CORRESPONDENCES, Matching, _names, check_pins, choose_correspondence,
                             compare_edge_sets, matched_heights, read_pins)
from .messages import engine_error_message, match_error_message
from .native import load_engine, option_methods
from .plane import Plane, check_planarity, fit_plane, project, unproject
from .timing import (EASINGS, RIGID_EASINGS, ease, ease_sample_indices, engine_frame_count, frame_list,
                     local_times)

# The add-on's motion modes and rotation directions; the engine's names
# (stickmorph.METHOD_NAMES, ROTATION_NAMES) are these in lower case.
MOTIONS = ("RIGID", "BARYCENTRIC", "LINEAR")
ROTATIONS = ("SHORT", "CCW", "CW")


@dataclass(frozen=True)
class Fallback:
    """What morph_pair needs to fall back on the matching (INDEX_OR_MATCH)."""

    match: Callable  # (IndexReport) -> the matched PreparedPair; raises StickMorphError
    # Raises the by-index check's message for an invalid figure (the target
    # validated with its own edge list); returns if both are valid.
    refuse_invalid: Callable


@dataclass
class PreparedPair:
    """Two figures ready for the engine: the figure to morph, on its m
    vertices, in the source's and the target's pose (by index m is both
    meshes' vertex count; matched, see Matching)."""

    source_name: str  # the objects' names, for the messages
    target_name: str
    plane: Plane
    source_xy: np.ndarray  # (m, 2) float64
    target_xy: np.ndarray  # (m, 2) float64
    source_h: np.ndarray  # (m,) heights above the plane (a dummy's interpolated along its edge)
    target_h: np.ndarray  # (m,)
    edges: np.ndarray  # (E, 2) int64: by index the source mesh's edges in mesh order; matched, the matched figure's
    size: float  # diagonal of the common bounding box (world units)
    matching: Matching  # how the figure was made from the meshes
    # INDEX_OR_MATCH taken by index: the matching to fall back on if the
    # morph finds the pair incompatible by index (morph_pair). None otherwise.
    fallback: Fallback | None = None
    # Local timing (issue 31): the delay weight of each of the m vertices
    # (the source mesh's, a dummy's interpolated along its source edge, as
    # the engine does for correspond="auto"); None without a delay group.
    delay: np.ndarray | None = None


@dataclass(frozen=True)
class IndexReport:
    """Why a pair is not compatible by index: the IncompatibleFiguresError of
    the morph by index, in the shape of stickmorph.CompatibilityReport that
    match_error_message reads (false, kind, reason, vertices)."""

    kind: str
    reason: str
    vertices: tuple = ()

    def __bool__(self):
        return False


@dataclass
class MorphResult:
    frames_world: np.ndarray  # (N, V, 3) float64, world space
    triangulation: dict | None  # None for LINEAR
    stats: dict  # the engine's (stickmorph.morph's "stats"; "rigid" for RIGID)
    motion: str = "RIGID"  # settings.motion
    # LINEAR only: the output frames (0 to N - 1) that are not stick figures
    # compatible with the source (they self-intersect or fold over). Empty
    # for RIGID and BARYCENTRIC, whose every frame is verified exactly.
    invalid_frames: list = field(default_factory=list)
    # Wall time of the engine's call (the module's morph, which releases the
    # GIL): the bake's time is this and the Blender side (issue 29's split).
    engine_ms: float = 0.0
    # Local timing (issue 31): the overlap the engine was given with the
    # delay weights, None when it was given none (no delay group, or a
    # motion it does not apply to: local_timing_ignored says so).
    overlap: float | None = None
    local_timing_ignored: bool = False


def refuse_faces(name: str, faces: int) -> None:
    """Raises StickMorphError if the mesh `name` has faces."""
    if faces:
        raise StickMorphError(
            f"'{name}' has {faces} face{'s' if faces != 1 else ''}; Stick Morph needs "
            "edge-only meshes (in Edit Mode: Delete > Only Faces)")


def refuse_non_finite(name: str, world: np.ndarray) -> None:
    """Raises StickMorphError naming the first vertex of `name` with a
    non-finite coordinate."""
    bad = np.flatnonzero(~np.isfinite(world).all(axis=1))
    if len(bad):
        raise StickMorphError(
            f"'{name}': vertex {int(bad[0])} has a non-finite coordinate "
            f"({', '.join(repr(float(c)) for c in world[bad[0]])})"
            + (f" and {len(bad) - 1} more vertices too" if len(bad) > 1 else ""))


def prepare_pair(source_world, source_edges, source_faces: int, source_name: str,
                 target_world, target_edges, target_faces: int, target_name: str,
                 settings: BakeSettings, source_groups=None, target_groups=None, source_delay=None) -> PreparedPair:
    """Checks two meshes (world-space vertices, edges, face counts, and their
    vertex groups as {name: [vertex, ...]} for the pins), projects them onto
    their common plane (settings.plane, settings.planarity_tolerance) and
    makes the figure to morph: the source mesh itself by index, or the
    figure stickmorph.correspond matches, as settings.correspondence says
    (choose_correspondence). source_delay: the source mesh's delay weights
    (timing.delay_weights), one per source vertex, or None; carried onto
    the matched figure. Raises StickMorphError with a user message."""
    plane, planarity_tolerance = settings.plane, settings.planarity_tolerance
    setting = settings.correspondence
    if setting not in CORRESPONDENCES:
        raise StickMorphError(f"unknown correspondence {setting!r} (choose one of {', '.join(CORRESPONDENCES)})")
    source_world = np.asarray(source_world, dtype=np.float64).reshape(-1, 3)
    target_world = np.asarray(target_world, dtype=np.float64).reshape(-1, 3)
    source_edges = np.asarray(source_edges, dtype=np.int64).reshape(-1, 2)
    target_edges = np.asarray(target_edges, dtype=np.int64).reshape(-1, 2)
    source_groups, target_groups = dict(source_groups or {}), dict(target_groups or {})
    for name, faces in ((source_name, source_faces), (target_name, target_faces)):
        refuse_faces(name, faces)
    if setting == "INDEX":
        # Pins only steer a matching; by index they would silently do
        # nothing, and a user who made them meant the meshes to be matched.
        groups = sorted(set(filter(is_pin_group, source_groups)) | set(filter(is_pin_group, target_groups)))
        if groups:
            raise StickMorphError(
                f"pins need Correspondence (Match) Automatic or By Shape: with By Index vertex i of "
                f"'{source_name}' is vertex i of '{target_name}' and the pin group"
                f"{'s' if len(groups) > 1 else ''} {_names(groups)} would have no effect "
                "(Clear Pins removes them)")
        if len(source_world) != len(target_world):
            raise StickMorphError(
                f"different vertex counts: '{source_name}' has {len(source_world)} vertices, "
                f"'{target_name}' has {len(target_world)}; {_BY_INDEX}")
    for name, world in ((source_name, source_world), (target_name, target_world)):
        if len(world) == 0:
            raise StickMorphError(f"'{name}' has no vertices")
    if setting == "INDEX":
        message = compare_edge_sets(source_edges, target_edges, source_name, target_name)
        if message:
            raise StickMorphError(f"{message}; {_BY_INDEX}")
    pins = () if setting == "INDEX" else read_pins(source_groups, target_groups, source_name, target_name)
    check_pins(pins, source_edges, target_edges, len(source_world), len(target_world), source_name, target_name)
    for name, world in ((source_name, source_world), (target_name, target_world)):
        refuse_non_finite(name, world)
    if source_delay is not None:
        source_delay = np.asarray(source_delay, dtype=np.float64).reshape(-1)
        if len(source_delay) != len(source_world):
            raise StickMorphError(f"the delay weights of '{source_name}' are {len(source_delay)}, for "
                                  f"{len(source_world)} vertices")

    fitted = fit_plane(source_world, target_world, plane)
    source_xy, source_h = project(source_world, fitted)
    target_xy, target_h = project(target_world, fitted)
    both = np.vstack([source_world, target_world])
    size = float(np.linalg.norm(both.max(axis=0) - both.min(axis=0)))
    check_planarity(((source_name, source_h), (target_name, target_h)), size, planarity_tolerance, fitted, plane)

    return prepare_projected(source_xy, source_h, source_edges, source_name, target_xy, target_h, target_edges,
                             target_name, fitted, size, setting, pins, source_delay)


def prepare_projected(source_xy, source_h, source_edges, source_name: str, target_xy, target_h, target_edges,
                      target_name: str, fitted: Plane, size: float, setting: str, pins=(),
                      source_delay=None) -> PreparedPair:
    """The figure to morph from two figures already checked and projected
    onto their common plane `fitted` (in-plane points (V, 2), heights (V,),
    edges): by index, or matched by stickmorph.correspond with the pins, as
    the correspondence setting says (choose_correspondence). prepare_pair's
    last step, and the drawings' (drawings.prepare_drawings: a Grease Pencil
    drawing or a curve cleaned into a figure first). Raises StickMorphError."""
    def by_index(why):
        # The source's edges are the figure's (the target's are the same
        # set; the morph checks its compatibility as it starts).
        count = len(source_xy)
        matching = Matching(False, why, np.arange(count), np.arange(count), count, count)
        return PreparedPair(source_name, target_name, fitted, source_xy, target_xy, source_h, target_h,
                            source_edges, size, matching, delay=source_delay)

    def matched(why, index_report=None):
        engine = load_engine()
        try:
            result = engine.correspond(source_xy, target_xy, source_edges, target_edges=target_edges,
                                       pins=[[pin.source, pin.target] for pin in pins] or None)
        except engine.IncompatibleFiguresError as e:
            raise StickMorphError(match_error_message(e, source_name, target_name, pins, index_report)) from e
        except (engine.StickMorphError, engine.InternalError) as e:
            raise StickMorphError(engine_error_message(e, source_name, target_name)) from e
        c = result["correspondence"]
        source_vertex = np.asarray(c["source"], dtype=np.int64)
        target_vertex = np.asarray(c["target"], dtype=np.int64)
        matching = Matching(True, why, source_vertex, target_vertex, len(source_xy), len(target_xy),
                            tuple(pins), dict(result["stats"]))
        return PreparedPair(
            source_name, target_name, fitted,
            np.asarray(result["source_xy"], dtype=np.float64), np.asarray(result["target_xy"], dtype=np.float64),
            matched_heights(source_h, source_edges, source_vertex, c["source_edge"], c["source_fraction"]),
            matched_heights(target_h, target_edges, target_vertex, c["target_edge"], c["target_fraction"]),
            np.asarray(result["edges"], dtype=np.int64).reshape(-1, 2), size, matching,
            delay=None if source_delay is None else matched_heights(
                source_delay, source_edges, source_vertex, c["source_edge"], c["source_fraction"]))

    def refuse_invalid():
        # What the by-index check said of an invalid figure before the morph
        # took its place: the target validated with its own edge list, so
        # that a message naming edges names the target mesh's (the morph by
        # index has only the source's list). Raises, or returns if valid.
        engine = load_engine()
        try:
            engine.check_compatibility(source_xy, target_xy, source_edges, target_edges)
        except (engine.StickMorphError, engine.InternalError) as e:
            raise StickMorphError(engine_error_message(e, source_name, target_name)) from e

    # Whether an INDEX_OR_MATCH pair is compatible by index is not checked
    # here: the morph by index checks it as it starts (one check per bake),
    # and morph_pair falls back on the matching when it refuses the pair.
    is_matched, why = choose_correspondence(
        setting, len(source_xy) == len(target_xy),
        compare_edge_sets(source_edges, target_edges) is None, bool(pins), lambda: True)
    if is_matched:
        return matched(why)
    prepared = by_index(why)
    if setting == "INDEX_OR_MATCH":
        prepared.fallback = Fallback(lambda report: matched("they are not compatible by index", report),
                                     refuse_invalid)
    return prepared


def morph_pair(prepared: PreparedPair, settings: BakeSettings) -> tuple[PreparedPair, MorphResult]:
    """(the pair morphed, its MorphResult): compute_morph, and for a pair that
    INDEX_OR_MATCH took by index (prepared.fallback), the matching if the
    morph's own compatibility check refuses it by index: the bake's one
    check decides (its reason is said if the matching fails too)."""
    if prepared.fallback is None:
        return prepared, compute_morph(prepared, settings)
    engine = load_engine()
    try:
        return prepared, compute_morph(prepared, settings)
    except StickMorphError as error:
        cause = error.__cause__
        if isinstance(cause, engine.InvalidFigureError):
            prepared.fallback.refuse_invalid()
            raise
        if not isinstance(cause, engine.IncompatibleFiguresError):
            raise
        report = IndexReport(cause.kind, cause.reason or "", tuple(cause.vertices or ()))
    matched = prepared.fallback.match(report)
    return matched, compute_morph(matched, settings)


def compute_morph(prepared: PreparedPair, settings: BakeSettings) -> MorphResult:
    """The morph's frames in world space. The engine validates both figures and
    checks their compatibility as it starts (one check per bake; its
    exceptions become messages naming the objects, engine_error_message).
    Raises StickMorphError, before any engine work for settings out of range."""
    frame_count, enclosure_sides, easing = settings.frame_count, settings.enclosure_sides, settings.easing
    motion, rotation, turns = settings.motion, settings.rotation, settings.turns
    engine = load_engine()
    limits = engine.limits
    # frame_count here, not only in the engine: with easing the engine sees
    # engine_frame_count's oversampled number, clamped to its maximum, and
    # would accept a frame_count beyond it.
    if not limits["min_frames"] <= frame_count <= limits["max_frames"]:
        raise StickMorphError(f"the number of frames must be between {limits['min_frames']} and "
                              f"{limits['max_frames']}, got {frame_count}")
    if not limits["min_enclosure_sides"] <= enclosure_sides <= limits["max_enclosure_sides"]:
        raise StickMorphError(f"the enclosure needs {limits['min_enclosure_sides']} to "
                              f"{limits['max_enclosure_sides']} sides, got {enclosure_sides}")
    if easing not in EASINGS:
        raise StickMorphError(f"unknown easing {easing!r}")
    if motion not in MOTIONS:
        raise StickMorphError(f"unknown motion {motion!r} (choose one of {', '.join(MOTIONS)})")
    if rotation not in ROTATIONS:
        raise StickMorphError(f"unknown rotation {rotation!r} (choose one of {', '.join(ROTATIONS)})")
    # Checked whatever the motion, like the enclosure for LINEAR: a value out
    # of range is a mistake even where it has no effect. (Blender clamps the
    # properties to the same range; this catches scripts calling core and a
    # module whose limits differ from common.ENGINE_LIMITS.)
    if not (isinstance(turns, int) and -limits["max_turns"] <= turns <= limits["max_turns"]):
        raise StickMorphError(f"the extra turns must be a whole number from {-limits['max_turns']} to "
                              f"{limits['max_turns']}, got {turns!r}")
    m = engine_frame_count(frame_count, easing, motion)
    # Only the options that apply to the motion (the engine's rule,
    # native.option_methods): the engine refuses an option it would ignore, so
    # LINEAR gets none of these. verify: every frame is checked exactly;
    # easing for BARYCENTRIC picks engine frames instead of interpolating
    # (ease_sample_indices) so that what is baked is what was verified.
    #
    # RIGID's easing goes to the engine: it may space a rigid morph's frames
    # along the motion (by how far the figure has moved, where its speed
    # would be uneven in the motion's own time), and its in-out easing is
    # applied to time before that.
    # Picking frames of a finer uniform morph, as for BARYCENTRIC, would ease
    # the engine's time instead, which for RIGID is already reparametrised:
    # the figure would ease by the wrong clock and cost 8x the frames. So the
    # engine gets exactly frame_count frames and easing="in-out".
    candidates = dict(steiner=settings.steiner, weights=settings.weights, enclosure_sides=enclosure_sides,
                      verify=True, rotation=rotation.lower(), turns=turns, easing=RIGID_EASINGS[easing])
    applies = option_methods()
    options = {name: value for name, value in candidates.items() if option_applies(name, motion, applies)}
    # Local timing (issue 31): the delay weights and the overlap together,
    # where the engine's rule says they apply (Rigid); with another motion
    # they are greyed out in the panel and not given, like Rotate.
    overlap = None
    if prepared.delay is not None:
        if "delay" not in applies:  # the rule of delay= and overlap= together
            raise StickMorphError(
                "local timing (Delay Group) needs a newer stickmorph module: this one's morph has no delay= "
                "or overlap=; clear Delay Group, or update the add-on")
        if option_applies("delay", motion, applies):
            overlap = float(settings.overlap)
            options.update(delay=prepared.delay, overlap=overlap)
    started = time.perf_counter()
    try:
        result = engine.morph(prepared.source_xy, prepared.target_xy, prepared.edges, frames=m,
                              method=motion.lower(), **options)
    except (engine.StickMorphError, engine.InternalError) as e:
        raise StickMorphError(engine_error_message(e, prepared.source_name, prepared.target_name)) from e
    engine_ms = (time.perf_counter() - started) * 1000.0
    indices = ease_sample_indices(frame_count, easing, motion)
    frames_xy = np.asarray(result["frames"])
    if len(indices) != len(frames_xy) or np.any(indices != np.arange(len(frames_xy))):
        frames_xy = frames_xy[indices]  # a copy: only when easing picks frames
    if motion == "RIGID":
        # The engine's times are k / (N - 1); the figure is at the eased
        # fraction of its motion, and so is its height.
        times = ease(np.asarray(result["times"]), easing)
    else:
        times = np.asarray(result["times"])[indices]
    # Each vertex's height moves on its own clock, as the engine moves it in
    # the plane (timing.local_times; without local timing every vertex's
    # clock is the frame's time).
    s = local_times(times, prepared.delay if overlap is not None else None, overlap or 0.0)
    heights = (1.0 - s) * prepared.source_h[None, :] + s * prepared.target_h[None, :]
    frames_world = unproject(frames_xy, heights, prepared.plane)
    stats = result["stats"]
    invalid = []
    if motion == "LINEAR":
        bad = set(int(k) for k in stats.get("invalid_frames", ()))
        invalid = [k for k, index in enumerate(indices.tolist()) if index in bad]
    return MorphResult(frames_world, result["triangulation"], stats, motion, invalid, engine_ms, overlap,
                       prepared.delay is not None and overlap is None)


def motion_summary(morph: MorphResult, frame_start: int = 1) -> tuple[str, str]:
    """(short, long): what the motion did, for the panel's last-bake box (a
    line of about 24 characters) and the bake's report.

    RIGID: how many inner frames (the ends are the figures themselves) are
    the rigid guide or follow it where it is valid, and how many fell back
    to the barycentric frame (stats["rigid"]["guide_frames"]). LINEAR: the
    frames (scene frame numbers) that are not valid, if any."""
    count = len(morph.frames_world)
    if morph.motion == "RIGID":
        guide = (morph.stats.get("rigid") or {}).get("guide_frames") or {}
        follow = int(guide.get("exact", 0)) + int(guide.get("blended", 0))
        inner = follow + int(guide.get("barycentric", 0))
        if inner == 0:  # two frames: the figures themselves
            return "Rigid", "rigid"
        text = f"rigid: {follow}/{inner} frames follow the rigid guide"
        if inner > follow:
            text += f" ({inner - follow} fall back to barycentric where it is not valid)"
        return f"Rigid guide: {follow}/{inner}", text
    if morph.motion == "LINEAR":
        if not morph.invalid_frames:
            return "Linear: all valid", "linear: every frame is valid"
        frames = [frame_start + k for k in morph.invalid_frames]
        return (f"Linear: {len(frames)} invalid",
                f"linear: {len(frames)} of {count} frames cross or fold the figure (frames {frame_list(frames)})")
    return "Barycentric", "barycentric"


def local_timing_summary(morph: MorphResult, group: str) -> str:
    """For the bake's report: what local timing did (issue 31), or "" when
    no delay group was named."""
    if morph.overlap is not None:
        return f"local timing: the delay group '{group}' lags by {morph.overlap:.3g} of the motion"
    if morph.local_timing_ignored:
        return (f"local timing off: the delay group '{group}' applies to the Rigid motion only "
                f"(Motion is {morph.motion.title()})")
    return ""


def triangulation_world(triangulation: dict, prepared: PreparedPair) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The compatible triangulation's nodes in world space, in the source and in
    the target, and its triangles. Figure vertices keep their own heights;
    enclosure and Steiner nodes get the mean height of their figure."""
    n = int(triangulation["figure_vertices"])
    source = np.asarray(triangulation["source"], dtype=np.float64)
    target = np.asarray(triangulation["target"], dtype=np.float64)
    count = len(source)
    hs = np.full(count, prepared.source_h.mean())
    ht = np.full(count, prepared.target_h.mean())
    hs[:n] = prepared.source_h
    ht[:n] = prepared.target_h
    return (unproject(source, hs, prepared.plane), unproject(target, ht, prepared.plane),
            np.asarray(triangulation["triangles"], dtype=np.int64))


def tube_radius(size: float, factor: float) -> float:
    """Radius of the renderable tubes: a fraction of the figures' size."""
    return max(size * factor, 1e-6) if math.isfinite(size) and size > 0 else factor
