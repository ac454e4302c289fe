"""The add-on's geometry and engine glue, free of bpy.

Everything here works on NumPy arrays and plain Python values, so it can be
imported and tested outside Blender. The Blender side (operators.py,
baking.py) reads meshes into arrays, calls `prepare_pair` and `compute_morph`,
and writes the arrays back.

World space and the plane
-------------------------
The engine morphs 2D figures. Both meshes are read in world space and
projected onto one plane with an orthonormal basis (u, v) and normal n, u x v
= n, so that 2D orientation is the orientation seen looking down -n. The
projection is the same for both figures, so a mirror image in 3D stays a
mirror image in 2D (and is refused by the engine).

Each vertex also keeps its height h = n . (p - origin) in its own figure. The
way back to world space at eased time s is

    p(s) = origin + x u + y v + ((1 - s) h_source + s h_target) n

so frame 0 is the source's world vertices and the last frame the target's
(up to floating-point roundoff), including the offset between two figures
that lie in parallel planes, e.g. side by side at different depths. s is the
engine frame's time for BARYCENTRIC and LINEAR (easing picks frames, see
ease_sample_indices), and the eased time ease(k / (N - 1)) for RIGID, whose
frames are evenly spaced along the motion with the easing on top: the
height then moves in step with the figure.
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass, field

import numpy as np

from . import dependencies
# The settings and the error type live in common.py, which imports without
# numpy; they are part of core's interface too.
from .common import BakeSettings, StickMorphError

PLANES = ("AUTO", "XY", "XZ", "YZ")
EASINGS = ("LINEAR", "EASE_IN_OUT")
# The add-on's motion modes and rotation directions; the engine's names
# (stickmorph.METHOD_NAMES, ROTATION_NAMES) are these in lower case.
MOTIONS = ("RIGID", "BARYCENTRIC", "LINEAR")
ROTATIONS = ("SHORT", "CCW", "CW")
# The engine's easing of a RIGID morph for each of EASINGS
# (stickmorph.EASING_NAMES).
RIGID_EASINGS = {"LINEAR": "none", "EASE_IN_OUT": "in-out"}

# Orthonormal (u, v) of the axis planes; n = u x v. XZ is seen from the front
# (looking along +Y), YZ from the right (looking along -X), as in Blender's
# front and right views.
_AXIS_PLANES = {
    "XY": ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0)),
    "XZ": ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0)),
    "YZ": ((0.0, 1.0, 0.0), (0.0, 0.0, 1.0)),
}

# With easing, BARYCENTRIC and LINEAR frames are picked from a finer uniform
# morph of this many samples per output frame interval (see
# ease_sample_indices).
EASE_OVERSAMPLING = 8


@dataclass
class Plane:
    origin: np.ndarray  # (3,)
    u: np.ndarray  # (3,)
    v: np.ndarray  # (3,)
    normal: np.ndarray  # (3,)
    name: str  # "AUTO", "XY", ...

    def describe(self) -> str:
        if self.name != "AUTO":
            return f"the {self.name} plane"
        n = self.normal
        return f"the best-fit plane (normal {n[0]:.3f}, {n[1]:.3f}, {n[2]:.3f})"


@dataclass
class PreparedPair:
    """Two figures ready for the engine."""

    source_name: str  # the objects' names, for the messages
    target_name: str
    plane: Plane
    source_xy: np.ndarray  # (V, 2) float64
    target_xy: np.ndarray  # (V, 2) float64
    source_h: np.ndarray  # (V,) heights above the plane
    target_h: np.ndarray  # (V,)
    edges: np.ndarray  # (E, 2) int64, the source mesh's edges in mesh order
    size: float  # diagonal of the common bounding box (world units)


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


# ---------------------------------------------------------------- engine ----

def load_engine():
    """The native `stickmorph` module: the copy shipped inside this package,
    else one on sys.path (a development build). Raises StickMorphError saying
    which Python the module was built for and how to rebuild it."""
    try:
        return dependencies.import_engine(__package__)
    except (ImportError, OSError):
        status = dependencies.check(os.path.dirname(os.path.abspath(__file__)), __package__)
        if status.engine_error is None:  # loaded on the second try (a transient failure)
            return dependencies.import_engine(__package__)
        raise StickMorphError(status.message()) from None


def engine_limits() -> dict:
    """The engine's bounds by name (stickmorph.limits: "max_frames", ...).
    From the module itself wherever it can be loaded, so that a check here
    cannot disagree with the engine's; common.ENGINE_LIMITS is the copy for
    registration, when the module may be missing."""
    return load_engine().limits


# ----------------------------------------------------------------- plane ----

def _unit(vector) -> np.ndarray:
    vector = np.asarray(vector, dtype=np.float64)
    return vector / np.linalg.norm(vector)


def _canonical_sign(vector: np.ndarray) -> np.ndarray:
    """The vector or its negation, whichever has a positive largest component."""
    k = int(np.argmax(np.abs(vector)))
    return vector if vector[k] >= 0 else -vector


def fit_plane(source_world: np.ndarray, target_world: np.ndarray, plane: str = "AUTO") -> Plane:
    """The common plane of both figures.

    AUTO: the normal is the smallest right-singular vector of both point sets,
    each centred on its own centroid, so that two figures in parallel planes
    (side by side at different depths) share the right normal. The normal
    points to the same side as the nearest axis plane's (XY: +Z, XZ: -Y, YZ:
    +X), and u is that plane's u axis projected into the fitted plane. If all
    points are collinear, the plane holds the line and is the one closest to
    an axis plane.
    """
    if plane not in PLANES:
        raise StickMorphError(f"unknown plane {plane!r} (choose one of {', '.join(PLANES)})")
    source_world = np.asarray(source_world, dtype=np.float64).reshape(-1, 3)
    target_world = np.asarray(target_world, dtype=np.float64).reshape(-1, 3)
    both = np.vstack([source_world, target_world])
    origin = both.mean(axis=0) if len(both) else np.zeros(3)
    if plane != "AUTO":
        u, v = (np.array(a) for a in _AXIS_PLANES[plane])
        return Plane(origin, u, v, np.cross(u, v), plane)

    centred = np.vstack([source_world - source_world.mean(axis=0),
                         target_world - target_world.mean(axis=0)])
    _, singular, vt = np.linalg.svd(centred, full_matrices=True)
    largest = singular[0] if len(singular) else 0.0
    if largest == 0.0:
        # Every figure is a single point: any plane; take XY.
        u, v = (np.array(a) for a in _AXIS_PLANES["XY"])
        return Plane(origin, u, v, np.cross(u, v), "AUTO")
    direction = _canonical_sign(vt[0])
    second = singular[1] if len(singular) > 1 else 0.0
    if second <= 1e-12 * largest:
        # Collinear: the axis most perpendicular to the line, made exactly
        # perpendicular, is the normal.
        axes = np.eye(3)
        k = int(np.argmin(np.abs(axes @ direction)))
        normal = _unit(axes[k] - (axes[k] @ direction) * direction)
    else:
        normal = _unit(vt[2])
    # The in-plane axes follow the nearest axis plane: its normal's side is
    # the viewing side and its u axis, projected into the plane, is u. A
    # figure drawn in an axis plane thus gets exactly that plane's 2D
    # coordinates, and a tilted one the view a user expects.
    nearest = max(_AXIS_PLANES, key=lambda p: abs(np.cross(*_AXIS_PLANES[p]) @ normal))
    axis_u, axis_v = (np.array(a) for a in _AXIS_PLANES[nearest])
    if np.cross(axis_u, axis_v) @ normal < 0:
        normal = -normal
    # |u| >= 1/sqrt(3): the nearest plane's normal axis holds at least 1/3 of
    # normal's squared length, so axis_u, another axis, at most 2/3.
    u = _unit(axis_u - (axis_u @ normal) * normal)
    v = np.cross(normal, u)
    return Plane(origin, u, _unit(v), normal, "AUTO")


def project(points_world: np.ndarray, plane: Plane) -> tuple[np.ndarray, np.ndarray]:
    """(V, 2) in-plane coordinates and (V,) heights of world points."""
    d = np.asarray(points_world, dtype=np.float64).reshape(-1, 3) - plane.origin
    xy = np.stack([d @ plane.u, d @ plane.v], axis=1)
    return xy, d @ plane.normal


def unproject(xy: np.ndarray, heights: np.ndarray, plane: Plane) -> np.ndarray:
    """World points from in-plane coordinates (..., V, 2) and heights (..., V)."""
    xy = np.asarray(xy, dtype=np.float64)
    heights = np.asarray(heights, dtype=np.float64)
    return (plane.origin + xy[..., 0:1] * plane.u + xy[..., 1:2] * plane.v
            + heights[..., None] * plane.normal)


def planarity_deviation(heights: np.ndarray) -> tuple[float, int]:
    """Largest distance of a vertex from the figure's own plane (parallel to the
    common one, through the figure's mean height), and that vertex."""
    heights = np.asarray(heights, dtype=np.float64)
    if len(heights) == 0:
        return 0.0, -1
    deviations = np.abs(heights - heights.mean())
    k = int(np.argmax(deviations))
    return float(deviations[k]), k


# ----------------------------------------------------------------- edges ----

def edge_set(edges) -> set[tuple[int, int]]:
    return {(min(a, b), max(a, b)) for a, b in np.asarray(edges, dtype=np.int64).reshape(-1, 2).tolist()}


def compare_edge_sets(source_edges, target_edges, source_name: str = "source",
                      target_name: str = "target", limit: int = 5) -> str | None:
    """None if both edge lists hold the same undirected edges, else a message."""
    a, b = edge_set(source_edges), edge_set(target_edges)
    if a == b:
        return None

    def listing(edges):
        items = sorted(edges)
        text = ", ".join(f"{i}-{j}" for i, j in items[:limit])
        return text + (f" and {len(items) - limit} more" if len(items) > limit else "")

    parts = []
    if a - b:
        parts.append(f"edges only in '{source_name}': {listing(a - b)}")
    if b - a:
        parts.append(f"edges only in '{target_name}': {listing(b - a)}")
    return "the meshes have different edges (vertex i of one must be joined to the same " \
           "vertices as vertex i of the other): " + "; ".join(parts)


# ---------------------------------------------------------------- easing ----

def ease(t, easing: str = "LINEAR"):
    """Time remap of [0, 1] onto [0, 1]: identity or smoothstep (ease in-out)."""
    t = np.clip(np.asarray(t, dtype=np.float64), 0.0, 1.0)
    if easing == "LINEAR":
        return t
    if easing == "EASE_IN_OUT":
        return t * t * (3.0 - 2.0 * t)
    raise StickMorphError(f"unknown easing {easing!r} (choose one of {', '.join(EASINGS)})")


def engine_frame_count(frame_count: int, easing: str, motion: str) -> int:
    """How many frames the engine computes for `frame_count` output frames.

    RIGID: exactly frame_count, the engine eases them itself
    (compute_morph). BARYCENTRIC and LINEAR: with easing, an oversampled
    uniform morph to pick from (ease_sample_indices)."""
    if easing == "LINEAR" or motion == "RIGID":
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


# ------------------------------------------------------------ preparation ----

def prepare_pair(source_world, source_edges, source_faces: int, source_name: str,
                 target_world, target_edges, target_faces: int, target_name: str,
                 settings: BakeSettings) -> PreparedPair:
    """Checks two meshes (world-space vertices, edges, face counts) and projects
    them onto their common plane (settings.plane, settings.planarity_tolerance).
    Raises StickMorphError with a user message."""
    plane, planarity_tolerance = settings.plane, settings.planarity_tolerance
    source_world = np.asarray(source_world, dtype=np.float64).reshape(-1, 3)
    target_world = np.asarray(target_world, dtype=np.float64).reshape(-1, 3)
    for name, faces in ((source_name, source_faces), (target_name, target_faces)):
        if faces:
            raise StickMorphError(
                f"'{name}' has {faces} face{'s' if faces != 1 else ''}; Stick Morph needs "
                "edge-only meshes (in Edit Mode: Delete > Only Faces)")
    if len(source_world) != len(target_world):
        raise StickMorphError(
            f"different vertex counts: '{source_name}' has {len(source_world)} vertices, "
            f"'{target_name}' has {len(target_world)}; vertex i of one corresponds to "
            "vertex i of the other")
    if len(source_world) == 0:
        raise StickMorphError(f"'{source_name}' has no vertices")
    message = compare_edge_sets(source_edges, target_edges, source_name, target_name)
    if message:
        raise StickMorphError(message)
    for name, world in ((source_name, source_world), (target_name, target_world)):
        bad = np.flatnonzero(~np.isfinite(world).all(axis=1))
        if len(bad):
            raise StickMorphError(
                f"'{name}': vertex {int(bad[0])} has a non-finite coordinate "
                f"({', '.join(repr(float(c)) for c in world[bad[0]])})"
                + (f" and {len(bad) - 1} more vertices too" if len(bad) > 1 else ""))

    fitted = fit_plane(source_world, target_world, plane)
    source_xy, source_h = project(source_world, fitted)
    target_xy, target_h = project(target_world, fitted)
    both = np.vstack([source_world, target_world])
    size = float(np.linalg.norm(both.max(axis=0) - both.min(axis=0)))
    worst = (0.0, -1, source_name)
    for name, heights in ((source_name, source_h), (target_name, target_h)):
        deviation, vertex = planarity_deviation(heights)
        if deviation > worst[0]:
            worst = (deviation, vertex, name)
    limit = planarity_tolerance * size
    if worst[0] > limit:
        raise StickMorphError(
            f"the meshes are not planar: vertex {worst[1]} of '{worst[2]}' is {worst[0]:.6g} "
            f"away from {fitted.describe()} (largest deviation {worst[0]:.6g}; allowed "
            f"{limit:.3g}, {planarity_tolerance:g} of the size {size:.6g})"
            + ("" if plane == "AUTO" else "; try plane AUTO"))
    edges = np.asarray(source_edges, dtype=np.int64).reshape(-1, 2)
    return PreparedPair(source_name, target_name, fitted, source_xy, target_xy, source_h, target_h, edges, size)


def _where(vertices) -> str:
    """' (vertex 3)', ' (vertices 0, 2)' or '' for the vertices a report names."""
    listed = ", ".join(str(v) for v in vertices)
    if len(vertices) == 1:
        return f" (vertex {listed})"
    return f" (vertices {listed})" if listed else ""


def engine_error_message(error: Exception, source_name: str, target_name: str) -> str:
    """A user message for an exception raised by the native module, naming the
    objects where the engine says "source" or "target" (the exceptions' role,
    detail, kind, vertices and reason attributes; the text is not parsed)."""
    engine = load_engine()
    text = str(error)
    if isinstance(error, engine.InvalidFigureError):
        if error.role in ("source", "target"):
            text = f"'{source_name if error.role == 'source' else target_name}': {error.detail}"
        defect = error.defect or ""
        if defect == "crossing_edges":
            return f"crossing edges: {text} (mesh edge indices)"
        if defect in ("overlapping_edges", "vertex_on_edge", "coincident_vertices"):
            return f"the figure touches itself: {text}"
        if defect == "disconnected":
            return f"the figure is not connected: {text}"
        return f"invalid figure: {text}"
    if isinstance(error, engine.IncompatibleFiguresError):
        # The morph's own compatibility check, the only one a bake runs: its
        # exception carries the report (kind, vertices, reason).
        where = _where(error.vertices or [])
        if error.kind == "mirror_image":
            return (f"incompatible figures: '{target_name}' is a mirror image of '{source_name}'"
                    f"{where}: {error.reason}")
        return f"incompatible figures '{source_name}' and '{target_name}'{where}: {error.reason}"
    if isinstance(error, engine.VerificationError):
        return f"the morph failed exact verification: {text}"
    if isinstance(error, engine.InternalError):
        return f"internal error in the stickmorph engine (a bug): {text}"
    return f"stickmorph: {text}"


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
    options = {}
    if motion != "LINEAR":
        # verify: every frame is checked exactly; easing for BARYCENTRIC
        # picks engine frames instead of interpolating (ease_sample_indices)
        # so that what is baked is what was verified. LINEAR takes none of
        # these (the engine refuses an option it would ignore).
        options.update(steiner=settings.steiner, weights=settings.weights, enclosure_sides=enclosure_sides,
                       verify=True)
    if motion == "RIGID":
        # The engine spaces a rigid morph's frames evenly along the motion
        # (by how far the figure has moved, not by time), and its in-out
        # easing is applied to that even-speed parameter. Picking frames of a
        # finer uniform morph, as for BARYCENTRIC, would ease the engine's
        # time instead, which for RIGID is already reparametrised: the figure
        # would ease by the wrong clock and cost 8x the frames. So the engine
        # gets exactly frame_count frames and easing="in-out".
        options.update(rotation=rotation.lower(), turns=turns, easing=RIGID_EASINGS[easing])
    try:
        result = engine.morph(prepared.source_xy, prepared.target_xy, prepared.edges, frames=m,
                              method=motion.lower(), **options)
    except (engine.StickMorphError, engine.InternalError) as e:
        raise StickMorphError(engine_error_message(e, prepared.source_name, prepared.target_name)) from e
    indices = ease_sample_indices(frame_count, easing, motion)
    frames_xy = np.asarray(result["frames"])[indices]
    if motion == "RIGID":
        # The engine's times are k / (N - 1); the figure is at the eased
        # fraction of its motion, and so is its height.
        times = ease(np.asarray(result["times"]), easing)
    else:
        times = np.asarray(result["times"])[indices]
    heights = ((1.0 - times)[:, None] * prepared.source_h[None, :]
               + times[:, None] * prepared.target_h[None, :])
    frames_world = unproject(frames_xy, heights, prepared.plane)
    stats = result["stats"]
    invalid = []
    if motion == "LINEAR":
        bad = set(int(k) for k in stats.get("invalid_frames", ()))
        invalid = [k for k, index in enumerate(indices.tolist()) if index in bad]
    return MorphResult(frames_world, result["triangulation"], stats, motion, invalid)


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


# ---------------------------------------------------------- result name ----

# Blender's object names hold 63 bytes (up to 4.x); the triangulation helper
# appends "_triangulation" (14) to the result's name.
MAX_RESULT_NAME_BYTES = 40
RESULT_SUFFIX = "morph"
_SEPARATORS = "_-. "


def _tokens(name: str) -> list[str]:
    """name split after each separator, keeping it: "a_b.c" -> ["a_", "b.", "c"]."""
    return re.findall(r"[^_\-. ]*[_\-. ]+|[^_\-. ]+$", name)


def _clip(text: str, max_bytes: int) -> str:
    """text cut to at most max_bytes of UTF-8 without splitting a character."""
    data = text.encode("utf-8")
    if len(data) <= max_bytes:
        return text
    return data[:max_bytes].decode("utf-8", errors="ignore")


def result_name(source_name: str, target_name: str, max_bytes: int = MAX_RESULT_NAME_BYTES) -> str:
    """A short name for the result of morphing source_name into target_name.

    Names that share whole leading or trailing words (split at _ - . and
    spaces) keep what they share and end in "_morph":
    monkey_to_player_source + monkey_to_player_target -> monkey_to_player_morph,
    Cube.001 + Cube.002 -> Cube_morph, source_arm + target_arm -> arm_morph.
    Otherwise it is <source>_to_<target>, each side clipped so that the
    whole stays within max_bytes (UTF-8, so it fits Blender's name field with
    the helper's suffix); only ASCII is added to the given names.
    """
    a, b = _tokens(source_name), _tokens(target_name)
    prefix = []
    for x, y in zip(a, b):
        if x.rstrip(_SEPARATORS) != y.rstrip(_SEPARATORS):
            break
        prefix.append(x)
    rest_a, rest_b = a[len(prefix):], b[len(prefix):]
    suffix = []
    for x, y in zip(reversed(rest_a), reversed(rest_b)):
        if x.rstrip(_SEPARATORS) != y.rstrip(_SEPARATORS):
            break
        suffix.insert(0, x)
    common = "".join(prefix) + "".join(suffix)
    common = common.strip(_SEPARATORS)
    # A shared word that is only a digit run or a single character ("1_a",
    # "1_b") says nothing about the pair.
    if len(common) >= 2 and not common.isdigit():
        stem = re.sub(r"[_\-. ]+", "_", common)
        return _clip(stem, max_bytes - len(RESULT_SUFFIX) - 1).rstrip(_SEPARATORS) + "_" + RESULT_SUFFIX
    half = (max_bytes - len("_to_")) // 2
    left = _clip(source_name, max(half, max_bytes - len("_to_") - len(target_name.encode("utf-8"))))
    right = _clip(target_name, max_bytes - len("_to_") - len(left.encode("utf-8")))
    return f"{left}_to_{right}"
