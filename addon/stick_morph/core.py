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
from .common import BakeSettings, StickMorphError, is_pin_group, next_pin_name, pin_names  # noqa: F401

PLANES = ("AUTO", "XY", "XZ", "YZ")
# How the meshes' vertices correspond (settings.correspondence; see
# choose_correspondence): AUTO, by index when that works, else matched;
# INDEX, vertex i of one mesh is vertex i of the other; MATCH, always
# matched by shape (stickmorph.correspond).
CORRESPONDENCES = ("AUTO", "INDEX", "MATCH")
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


@dataclass(frozen=True)
class Pin:
    """Two vertices that must match: a pin group of both meshes (read_pins)."""

    name: str  # the vertex group's name, the same in both meshes
    source: int  # the one vertex of the group in the source mesh
    target: int  # and in the target mesh


@dataclass
class Matching:
    """How the figure the engine morphs was made from the two meshes.

    By index it is the source mesh itself. Matched, it is
    stickmorph.correspond's figure on m vertices: the source mesh's vertices
    in order, then dummies on its edges for target vertices without a
    partner, each vertex with its place on both drawings."""

    matched: bool  # False: by index
    why: str  # why the bake matched ("the vertex counts differ", ...); "" when the setting said so
    source_vertex: np.ndarray  # (m,) the source mesh's vertex each vertex of the figure is, -1 a dummy
    target_vertex: np.ndarray  # (m,) the same in the target mesh
    source_count: int  # the meshes' own vertex counts
    target_count: int
    pins: tuple = ()  # the Pins the matching respected
    stats: dict = field(default_factory=dict)  # stickmorph.correspond's "stats"; {} by index


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


# ----------------------------------------------------------------- parts ----

def figure_parts(vertex_count: int, edges) -> list[list[int]]:
    """The parts (connected components) of a figure on vertex_count vertices,
    each as its sorted vertex indices, in order of their smallest vertex: the
    engine's numbering, "part 0", "part 1", ... A vertex on no edge (a dot)
    is a part of its own. Edges to vertices outside 0..vertex_count-1 are
    ignored (the engine refuses them, naming the edge)."""
    parent = list(range(int(vertex_count)))

    def root(v):
        while parent[v] != v:
            parent[v] = parent[parent[v]]
            v = parent[v]
        return v

    for a, b in np.asarray(edges, dtype=np.int64).reshape(-1, 2).tolist():
        if 0 <= a < vertex_count and 0 <= b < vertex_count:
            ra, rb = root(a), root(b)
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)  # the root is the part's smallest vertex
    parts = {}
    for v in range(int(vertex_count)):
        parts.setdefault(root(v), []).append(v)
    return [parts[r] for r in sorted(parts)]


def parts_summary(parts) -> str:
    """'' for one part; else '3 parts (1 dot)' or '2 parts', for the report."""
    count = len(parts)
    if count <= 1:
        return ""
    dots = sum(1 for part in parts if len(part) == 1)
    return f"{count} parts" + (f" ({dots} dot{'s' if dots != 1 else ''})" if dots else "")


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
                 settings: BakeSettings, source_groups=None, target_groups=None) -> PreparedPair:
    """Checks two meshes (world-space vertices, edges, face counts, and their
    vertex groups as {name: [vertex, ...]} for the pins), projects them onto
    their common plane (settings.plane, settings.planarity_tolerance) and
    makes the figure to morph: the source mesh itself by index, or the
    figure stickmorph.correspond matches, as settings.correspondence says
    (choose_correspondence). Raises StickMorphError with a user message."""
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
        if faces:
            raise StickMorphError(
                f"'{name}' has {faces} face{'s' if faces != 1 else ''}; Stick Morph needs "
                "edge-only meshes (in Edit Mode: Delete > Only Faces)")
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

    index_report = []  # the by-index check's report, when AUTO ran it

    def compatible_by_index():
        engine = load_engine()
        try:
            report = engine.check_compatibility(source_xy, target_xy, source_edges, target_edges)
        except (engine.StickMorphError, engine.InternalError) as e:
            # An invalid figure is invalid however it is matched.
            raise StickMorphError(engine_error_message(e, source_name, target_name)) from e
        index_report.append(report)
        return bool(report)

    matched, why = choose_correspondence(
        setting, len(source_world) == len(target_world),
        compare_edge_sets(source_edges, target_edges) is None, bool(pins), compatible_by_index)
    if not matched:
        # By index: the source's edges are the figure's (the target's are
        # the same set; the morph checks its compatibility as it starts).
        count = len(source_world)
        matching = Matching(False, why, np.arange(count), np.arange(count), count, count)
        return PreparedPair(source_name, target_name, fitted, source_xy, target_xy, source_h, target_h,
                            source_edges, size, matching)
    engine = load_engine()
    try:
        result = engine.correspond(source_xy, target_xy, source_edges, target_edges=target_edges,
                                   pins=[[pin.source, pin.target] for pin in pins] or None)
    except engine.IncompatibleFiguresError as e:
        raise StickMorphError(match_error_message(e, source_name, target_name, pins,
                                                  index_report[0] if index_report else None)) from e
    except (engine.StickMorphError, engine.InternalError) as e:
        raise StickMorphError(engine_error_message(e, source_name, target_name)) from e
    c = result["correspondence"]
    source_vertex = np.asarray(c["source"], dtype=np.int64)
    target_vertex = np.asarray(c["target"], dtype=np.int64)
    matching = Matching(True, why, source_vertex, target_vertex, len(source_world), len(target_world),
                        tuple(pins), dict(result["stats"]))
    return PreparedPair(
        source_name, target_name, fitted,
        np.asarray(result["source_xy"], dtype=np.float64), np.asarray(result["target_xy"], dtype=np.float64),
        matched_heights(source_h, source_edges, source_vertex, c["source_edge"], c["source_fraction"]),
        matched_heights(target_h, target_edges, target_vertex, c["target_edge"], c["target_fraction"]),
        np.asarray(result["edges"], dtype=np.int64).reshape(-1, 2), size, matching)


# Said after a refusal by index: the setting that would accept the pair.
_BY_INDEX = ("Correspondence (Match) is By Index, where vertex i of one mesh is vertex i of the other: "
             "Automatic or By Shape matches meshes drawn separately")


def _names(names, limit: int = 5) -> str:
    """'a', 'b' and 3 more: quoted names for a message."""
    names = list(names)
    text = ", ".join(f"'{name}'" for name in names[:limit])
    return text + (f" and {len(names) - limit} more" if len(names) > limit else "")


def _vertices(vertices, limit: int = 5) -> str:
    vertices = list(vertices)
    text = ", ".join(str(v) for v in vertices[:limit])
    return text + (f" and {len(vertices) - limit} more" if len(vertices) > limit else "")


# ------------------------------------------------------- correspondence ----

def choose_correspondence(setting: str, same_vertex_count: bool, same_edges: bool, pinned: bool,
                          compatible_by_index) -> tuple[bool, str]:
    """(matched, why): whether the bake matches the meshes (stickmorph.correspond)
    or takes them by index, and why it matches when the setting left it open.

    INDEX: by index (prepare_pair has refused meshes that cannot be). MATCH:
    matched. AUTO: by index when the meshes have the same vertex count and
    edge set, no pins, and are compatible by index; matched otherwise. Pins
    say that the vertices are not paired by number, so AUTO matches
    whenever there are any. compatible_by_index is called (once) only when
    the answer depends on it: the engine's check costs a pass over the
    figures."""
    if setting == "INDEX":
        return False, ""
    if setting == "MATCH":
        return True, ""
    if setting != "AUTO":
        raise StickMorphError(f"unknown correspondence {setting!r} (choose one of {', '.join(CORRESPONDENCES)})")
    if pinned:
        return True, "pins are given"
    if not same_vertex_count:
        return True, "the vertex counts differ"
    if not same_edges:
        return True, "the edges differ"
    if not compatible_by_index():
        return True, "they are not compatible by index"
    return False, "compatible by index"


def read_pins(source_groups, target_groups, source_name: str = "source",
              target_name: str = "target") -> tuple:
    """The Pins of two meshes from their vertex groups ({name: [vertex, ...]},
    any groups; only those named as pins, common.is_pin_group, count), in
    order of name. A pin group must be in both meshes under the same name and
    hold exactly one vertex in each, and a vertex can be in one pin group
    only; anything else raises StickMorphError naming the group."""
    both, only_source, only_target = pin_names(source_groups, target_groups)
    one_sided = ([(n, source_name, target_name) for n in only_source]
                 + [(n, target_name, source_name) for n in only_target])
    if one_sided:
        name, present, missing = one_sided[0]
        raise StickMorphError(
            f"the pin group '{name}' is in '{present}' but not in '{missing}': a pin is a vertex group "
            "of the same name in both meshes, holding one vertex in each (Pin Selected Vertices makes "
            "them, Clear Pins removes them)")
    pins = []
    pinned = ({}, {})  # vertex -> the pin group holding it, per mesh
    for name in both:
        ends = []
        for k, (groups, mesh) in enumerate(((source_groups, source_name), (target_groups, target_name))):
            members = sorted({int(v) for v in groups[name]})
            if len(members) != 1:
                held = ("no vertex" if not members else
                        f"{len(members)} vertices ({_vertices(members)})")
                raise StickMorphError(
                    f"the pin group '{name}' of '{mesh}' holds {held}; a pin group holds exactly one "
                    "vertex in each mesh")
            vertex = members[0]
            if vertex in pinned[k]:
                raise StickMorphError(
                    f"vertex {vertex} of '{mesh}' is in two pin groups, '{pinned[k][vertex]}' and '{name}'; "
                    "a vertex can be pinned only once")
            pinned[k][vertex] = name
            ends.append(vertex)
        pins.append(Pin(name, ends[0], ends[1]))
    return tuple(pins)


def _vertex_kind(degree: int) -> str:
    if degree == 0:
        return "a lone vertex"
    if degree == 1:
        return "an end"
    if degree == 2:
        return "inside a stroke"
    return f"a junction of degree {degree}"


def check_pins(pins, source_edges, target_edges, source_count: int, target_count: int,
               source_name: str = "source", target_name: str = "target"):
    """Refuses, naming the pin group, a pin whose vertex is not in its mesh or
    that joins vertices of different kinds: the matching pairs an end or a
    junction only with one of the same degree, and a vertex inside a stroke
    (degree 2) only with another (the engine's rule; checked here so that
    the message names the group, which the engine does not know)."""
    if not pins:
        return
    degrees = []
    for edges, count in ((source_edges, source_count), (target_edges, target_count)):
        edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
        inside = edges[((edges >= 0) & (edges < count)).all(axis=1)]
        degrees.append(np.bincount(inside.ravel(), minlength=count))
    for pin in pins:
        for vertex, count, mesh in ((pin.source, source_count, source_name), (pin.target, target_count, target_name)):
            if not 0 <= vertex < count:
                raise StickMorphError(f"the pin group '{pin.name}' names vertex {vertex} of '{mesh}', "
                                      f"which has {count} vertices")
        a, b = int(degrees[0][pin.source]), int(degrees[1][pin.target])
        if a != b:
            raise StickMorphError(
                f"the pin '{pin.name}' joins vertex {pin.source} of '{source_name}', {_vertex_kind(a)}, to "
                f"vertex {pin.target} of '{target_name}', {_vertex_kind(b)}: a pin joins two ends, two "
                "junctions of the same degree or two vertices inside strokes")


def matched_heights(heights, edges, vertex, edge, fraction) -> np.ndarray:
    """The heights (distance from the plane) of a matched figure's vertices
    in one mesh: an original vertex's own (vertex[i] >= 0), a dummy's
    interpolated along the mesh edge it lies on, edges[edge[i]], at
    fraction[i] from its first vertex to its second (stickmorph.correspond's
    correspondence arrays for that mesh). Linear along the edge, as the
    dummy's place in the plane is, so the dummy lies on the mesh's edge in
    world space too."""
    heights = np.asarray(heights, dtype=np.float64)
    edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    vertex = np.asarray(vertex, dtype=np.int64)
    edge = np.asarray(edge, dtype=np.int64)
    fraction = np.asarray(fraction, dtype=np.float64)
    original = vertex >= 0
    if not (edge[~original] >= 0).all():
        raise StickMorphError("internal error: a matched vertex is neither a mesh vertex nor on an edge")
    out = np.empty(len(vertex))
    out[original] = heights[vertex[original]]
    ends = edges[edge[~original]]
    f = fraction[~original]
    out[~original] = (1.0 - f) * heights[ends[:, 0]] + f * heights[ends[:, 1]]
    return out


def correspondence_summary(matching: Matching, source_name: str = "source",
                           target_name: str = "target") -> tuple[str, str]:
    """(short, long): how the pair was matched, for the panel's last-bake box
    (about 24 characters) and the bake's report: "By index", or "Matched: 37
    (12 dummies)" and "matched (the vertex counts differ): 37 vertices, 12
    dummies (5 on 'A', 7 on 'B'), 2 pins"."""
    if not matching.matched:
        return "By index", "by index"
    stats = matching.stats
    on_source, on_target = int(stats.get("source_dummies", 0)), int(stats.get("target_dummies", 0))
    dummies = on_source + on_target
    count = len(matching.source_vertex)
    text = f"matched{f' ({matching.why})' if matching.why else ''}: {count} vertices, {dummies} " \
           f"dumm{'y' if dummies == 1 else 'ies'}"
    if dummies:
        text += f" ({on_source} on '{source_name}', {on_target} on '{target_name}')"
    if matching.pins:
        text += f", {len(matching.pins)} pin{'s' if len(matching.pins) != 1 else ''}"
    return f"Matched: {count} ({dummies} dumm{'y' if dummies == 1 else 'ies'})", text


def _without_prefix(text: str, prefix: str) -> str:
    return text[len(prefix):] if text.startswith(prefix) else text


def match_error_message(error: Exception, source_name: str, target_name: str, pins=(),
                        index_report=None) -> str:
    """A user message for stickmorph.correspond's IncompatibleFiguresError
    (kind topology_differs, mirror_image, exterior_differs or
    pins_unsatisfiable). index_report: the by-index check's report when the
    bake tried that first (Correspondence Automatic), said too."""
    # The engine prefixes its reason with "correspond: ", the function's
    # name, which means nothing in Blender.
    reason = _without_prefix(getattr(error, "reason", None) or str(error), "correspond: ")
    kind = getattr(error, "kind", None)
    if index_report is not None and not index_report and getattr(index_report, "kind", None) == NESTING_DIFFERS:
        # Automatic checked by index first (the meshes have the same edges,
        # so the same parts) and found a part in another face: that is what
        # the user changed, in the meshes' own vertex numbers; the matching
        # (whose numbers are the matched figure's) cannot undo it.
        text = nesting_message(index_report.reason, source_name, target_name)
        if kind == NESTING_DIFFERS:
            return text + " (matched by shape, the parts nest differently too)"
        return text + f" (nor can they be matched by shape: {reason})"
    if kind == "pins_unsatisfiable":
        listing = "; ".join(f"'{pin.name}': vertex {pin.source} of '{source_name}' to vertex {pin.target} "
                            f"of '{target_name}'" for pin in pins)
        text = f"the pins cannot all hold: {reason} (pins {listing})"
    elif kind == "mirror_image":
        text = f"cannot match '{source_name}' and '{target_name}': '{target_name}' is a mirror image of " \
               f"'{source_name}': {reason}"
    elif kind == NESTING_DIFFERS:
        text = nesting_message(reason, source_name, target_name)
    else:
        text = f"cannot match '{source_name}' and '{target_name}': {reason}"
    if index_report is not None and not index_report:
        text += f" (nor are they compatible by index: {_without_prefix(index_report.reason, 'incompatible figures: ')})"
    return text


# The kind of IncompatibleFiguresError (and CompatibilityReport) for a pair
# of figures with several parts where a part lies in another face of another
# part in the target than in the source (issue 14).
NESTING_DIFFERS = "nesting_differs"


def nesting_message(reason: str, source_name: str, target_name: str) -> str:
    """The message for kind nesting_differs: the engine's reason names the
    part ("part 1", parts numbered by their smallest vertex, figure_parts)."""
    reason = _without_prefix(_without_prefix(reason, "correspond: "), "incompatible figures: ")
    return f"'{source_name}' and '{target_name}': a part changes face: {reason}"


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
        return f"invalid figure: {text}"
    if isinstance(error, engine.IncompatibleFiguresError):
        # The morph's own compatibility check of the pair it is given (a
        # matched pair passes it): its exception carries the report (kind,
        # vertices, reason). A matching's refusal is match_error_message's.
        where = _where(error.vertices or [])
        if error.kind == NESTING_DIFFERS:
            return nesting_message(error.reason or text, source_name, target_name)
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
