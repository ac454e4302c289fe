"""Drawings as stick figures (issue 32), free of bpy: Grease Pencil strokes
and curve splines read by drawing_io.py arrive here as world-space point
lists, are cleaned into valid figures by the engine
(stickmorph.clean_drawing: crossings and touchings become junctions, short
ends snap, duplicate points merge) and go on to the same correspondence and
morph as meshes (morph.prepare_projected, morph.morph_pair). On the way
back, a morph of a drawing becomes strokes again: each input stroke's path
through the morphed figure (output_strokes), with the stroke's thickness
interpolated at the points the cleaning and the matching inserted.

Why strokes and not their points as a mesh: a drawn stick figure is not a
valid plane graph (strokes cross without a shared point, an arm stops short
of the body, a pen pause repeats a point), and the engine refuses invalid
figures. Cleaning it is a change to the user's drawing, so every change is
reported (cleaning_summary), never made silently, and a drawing that
cannot be cleaned (no strokes, a single point, strokes overlapping along a
length) is refused naming the stroke, its layer and its frame.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .common import GREASE_PENCIL_TYPES, BakeSettings, StickMorphError
from .correspondence import _BY_INDEX, Pin, check_pins, compare_edge_sets
from .morph import PreparedPair, prepare_projected, refuse_faces
from .native import load_engine
from .plane import Plane, fit_plane_of, project

# The bake's Output setting (BakeSettings.output): AUTO is Grease Pencil for
# a Grease Pencil source and a mesh otherwise (meshes and curves, as before).
OUTPUTS = ("AUTO", "MESH", "GREASE_PENCIL")


def output_kind(setting: str, source_type: str) -> str:
    """"MESH" or "GREASE_PENCIL": what the bake makes of a source of this
    object type with the Output setting."""
    if setting not in OUTPUTS:
        raise StickMorphError(f"unknown output {setting!r} (choose one of {', '.join(OUTPUTS)})")
    if setting == "AUTO":
        return "GREASE_PENCIL" if source_type in GREASE_PENCIL_TYPES else "MESH"
    return setting


@dataclass(frozen=True)
class DrawingChoice:
    """Which drawing of a Grease Pencil object a bake reads: the operator's
    (and the panel's) Layer and Frame of that role. Curves have one drawing."""

    layer: str = ""  # a layer's name; "" the active layer
    frame: int = 0  # the drawing shown at this scene frame; 0 the one shown now (the active frame)


@dataclass
class Stroke:
    """One stroke (a Grease Pencil stroke, a curve's spline) as read."""

    world: np.ndarray  # (P, 3) float64 points in order, world space
    cyclic: bool = False  # a closing segment from the last point to the first
    # Per point values the output keeps and interpolates (Grease Pencil:
    # "radius" and "opacity", legacy "pressure" and "strength"), each (P,).
    point_values: dict = field(default_factory=dict)
    # Per stroke values the output keeps ("material_index", legacy "line_width").
    stroke_values: dict = field(default_factory=dict)


@dataclass
class Drawing:
    """The strokes of one drawing, with what the messages need to name it."""

    name: str  # the object's name
    object_type: str  # GPENCIL, GREASEPENCIL, CURVE or FONT
    strokes: list  # of Stroke, in drawing order
    where: str = ""  # "layer 'Lines', frame 1" for Grease Pencil; "" for a curve
    # How a stroke number reads to the user (the messages' note).
    numbering: str = "strokes count from 0 in drawing order"
    # (stroke, point) of the selected points in drawing order, for Pin
    # Selected Points (Grease Pencil only: a curve's points are not its
    # control points).
    selected: list = field(default_factory=list)
    layer: str = ""  # the layer's name (Grease Pencil), for the output's layer

    def label(self) -> str:
        return f"'{self.name}' ({self.where})" if self.where else f"'{self.name}'"

    def points(self) -> np.ndarray:
        """(sum P, 3) every stroke's points, stroke by stroke."""
        parts = [np.asarray(s.world, dtype=np.float64).reshape(-1, 3) for s in self.strokes]
        return np.vstack(parts) if parts else np.zeros((0, 3))


@dataclass
class MeshFigure:
    """A mesh side of a pair that involves a drawing (mesh + mesh is
    morph.prepare_pair's, unchanged)."""

    name: str
    world: np.ndarray  # (V, 3)
    edges: np.ndarray  # (E, 2)
    faces: int = 0
    pin_groups: tuple = ()  # names of its pin groups (refused here: pins join two meshes)
    delay: np.ndarray | None = None  # the delay group's weights (source only)


@dataclass
class CleanedSide:
    """A drawing cleaned into a figure: the engine's CleanedDrawing, its
    vertices' heights above the common plane, and the input strokes'
    values along each stroke (for the output)."""

    drawing: Drawing
    cleaned: object  # stickmorph.CleanedDrawing
    xy: np.ndarray  # (V, 2) the cleaned figure, in the common plane
    heights: np.ndarray  # (V,)
    edges: np.ndarray  # (E, 2)


@dataclass
class DrawingPair:
    """What prepare_drawings adds to the PreparedPair: each side's cleaning
    (None for a mesh side)."""

    source: CleanedSide | None
    target: CleanedSide | None


# ------------------------------------------------------------ cleaning ----

def _none_if_negative(value):
    return None if value is None or int(value) < 0 else int(value)


def invalid_drawing_message(error, role: str, drawing: Drawing) -> str:
    """A user message for stickmorph.InvalidDrawingError: the engine's
    reason (which names the stroke), after the object, layer and frame, and
    where the stroke starts in world space (the engine's coordinates are the
    common plane's, which the user never sees)."""
    text = f"cannot use the {role} {drawing.label()} as a stick figure: {error}"
    stroke = _none_if_negative(getattr(error, "stroke", None))
    if stroke is not None and stroke < len(drawing.strokes) and len(drawing.strokes[stroke].world):
        x, y, z = np.asarray(drawing.strokes[stroke].world, dtype=np.float64)[0]
        text += f" (stroke {stroke} starts at ({x:.4g}, {y:.4g}, {z:.4g}) in world space; {drawing.numbering})"
    return text


def clean(drawing: Drawing, xy_strokes, role: str, tolerance_fraction: float):
    """stickmorph.clean_drawing of the drawing's strokes in the common plane
    (xy_strokes: (P_i, 2) per stroke). tolerance_fraction: the setting
    Clean Tolerance, a fraction of the drawing's size (the diagonal of its
    bounding box in the plane); 0 is the engine's default (1% of the
    same). Raises StickMorphError naming the stroke, layer and frame."""
    engine = load_engine()
    tolerance = None
    if tolerance_fraction:
        if not (np.isfinite(tolerance_fraction) and tolerance_fraction > 0):
            raise StickMorphError(f"the clean tolerance must be positive (or 0 for the default), got "
                                  f"{tolerance_fraction!r}")
        every = np.vstack([s for s in xy_strokes if len(s)] or [np.zeros((0, 2))])
        diagonal = float(np.linalg.norm(every.max(axis=0) - every.min(axis=0))) if len(every) else 0.0
        tolerance = tolerance_fraction * diagonal
    try:
        return engine.clean_drawing([np.asarray(s, dtype=np.float64).reshape(-1, 2) for s in xy_strokes],
                                    cyclic=[bool(s.cyclic) for s in drawing.strokes], tolerance=tolerance)
    except engine.InvalidDrawingError as e:
        raise StickMorphError(invalid_drawing_message(e, role, drawing)) from e
    except (engine.StickMorphError, engine.InternalError) as e:
        raise StickMorphError(f"cannot use the {role} {drawing.label()} as a stick figure: {e}") from e


def cleaning_summary(role: str, side: CleanedSide | None) -> str:
    """"cleaned the source: 2 junctions made, 1 end snapped" ('' for a mesh)."""
    if side is None:
        return ""
    return f"cleaned the {role}: {side.cleaned.summary()}"


# ------------------------------------------- values along a stroke's path ----

def _arc_positions(xy: np.ndarray, path, cyclic: bool) -> tuple[np.ndarray, float]:
    """(positions, length): the arc length at each vertex of path (indices
    into xy) from its first, and the whole length (with the closing segment
    for a cyclic path)."""
    points = np.asarray(xy, dtype=np.float64)[np.asarray(path, dtype=np.int64)]
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1) if len(points) > 1 else np.zeros(0)
    positions = np.concatenate([[0.0], np.cumsum(steps)])
    closing = float(np.linalg.norm(points[0] - points[-1])) if cyclic and len(points) > 1 else 0.0
    return positions, float(positions[-1] + closing)


def point_slots(stroke_vertices, point_vertex, cyclic: bool = False) -> np.ndarray:
    """For each input point of a stroke, the index in the stroke's vertex
    path (stroke_vertices) of the vertex it became: input points and the
    path run in the same order, so each point's vertex is found at or after
    the previous point's (a junction the stroke passes twice is matched in
    order). Raises StickMorphError if the path does not hold the points in
    order (the engine's cleaning would be wrong)."""
    path = [int(v) for v in stroke_vertices]
    slots = np.empty(len(point_vertex), dtype=np.int64)
    at = 0
    for j, vertex in enumerate(int(v) for v in point_vertex):
        k = next((k for k in range(at, len(path)) if path[k] == vertex), None)
        if k is None and cyclic:
            # The closing point of a cyclic stroke may have merged into its first.
            k = next((k for k in range(0, at) if path[k] == vertex), None)
        if k is None:
            raise StickMorphError(f"internal error: point {j} of a stroke became vertex {vertex}, which its "
                                  f"path {path} does not hold in order")
        slots[j] = k
        at = k
    return slots


def path_values(values, slots, positions, length: float, cyclic: bool) -> np.ndarray:
    """Values at each vertex of a path from values at its input points:
    where points became a vertex (slots), their mean; elsewhere (junctions
    the cleaning inserted, dummies the matching inserted) linear in arc
    length between the nearest vertices that have points, around the
    closing segment for a cyclic path."""
    values = np.asarray(values, dtype=np.float64)
    count = len(positions)
    sums = np.zeros(count)
    counts = np.zeros(count)
    np.add.at(sums, slots, values)
    np.add.at(counts, slots, 1.0)
    known = counts > 0
    if not known.any():
        raise StickMorphError("internal error: a stroke has no input point on its path")
    mean = sums[known] / counts[known]
    if cyclic and length > 0:
        return np.interp(positions, positions[known], mean, period=length)
    return np.interp(positions, positions[known], mean)


def vertex_heights(cleaned, stroke_heights, xy) -> np.ndarray:
    """(V,) the height above the common plane of each cleaned vertex: the
    mean of the heights of the input points that became it; a junction made
    where strokes crossed (no input point) takes its height along the first
    stroke through it, linear in arc length."""
    count = len(xy)
    sums = np.zeros(count)
    counts = np.zeros(count)
    for vertices, heights in zip(cleaned.point_vertex, stroke_heights):
        vertices = np.asarray(vertices, dtype=np.int64)
        np.add.at(sums, vertices, np.asarray(heights, dtype=np.float64))
        np.add.at(counts, vertices, 1.0)
    heights = np.divide(sums, counts, out=np.zeros(count), where=counts > 0)
    missing = set(np.flatnonzero(counts == 0).tolist())
    for i, path in enumerate(cleaned.stroke_vertices):
        if not missing:
            break
        path = np.asarray(path, dtype=np.int64)
        on_path = [k for k, v in enumerate(path.tolist()) if v in missing]
        if not on_path:
            continue
        cyclic = bool(cleaned.cyclic[i])
        positions, length = _arc_positions(xy, path, cyclic)
        slots = point_slots(path, cleaned.point_vertex[i], cyclic)
        along = path_values(stroke_heights[i], slots, positions, length, cyclic)
        for k in on_path:
            heights[path[k]] = along[k]
            missing.discard(int(path[k]))
    if missing:
        raise StickMorphError(f"internal error: the cleaned vertices {sorted(missing)} lie on no stroke")
    return heights


# ------------------------------------------------------------ the pair ----

def _world_of(figure) -> np.ndarray:
    return figure.world if isinstance(figure, MeshFigure) else figure.points()


def _refuse_non_finite(figure, role: str) -> None:
    if isinstance(figure, MeshFigure):
        bad = np.flatnonzero(~np.isfinite(figure.world).all(axis=1))
        if len(bad):
            raise StickMorphError(f"'{figure.name}': vertex {int(bad[0])} has a non-finite coordinate")
        return
    for i, stroke in enumerate(figure.strokes):
        bad = np.flatnonzero(~np.isfinite(np.asarray(stroke.world, dtype=np.float64)).all(axis=1))
        if len(bad):
            raise StickMorphError(f"the {role} {figure.label()}: point {int(bad[0])} of stroke {i} has a "
                                  f"non-finite coordinate ({figure.numbering})")


def _check_planarity(figures, heights, size: float, settings: BakeSettings, fitted: Plane) -> None:
    """Refuses, naming the mesh vertex or the stroke's point farthest from
    its figure's own plane, a figure deviating by more than the planarity
    tolerance (plane.check_planarity's rule, with strokes named)."""
    worst = (0.0, None, None)
    for figure, h in zip(figures, heights):
        if len(h) == 0:
            continue
        deviations = np.abs(h - h.mean())
        k = int(np.argmax(deviations))
        if deviations[k] > worst[0]:
            worst = (float(deviations[k]), figure, k)
    limit = settings.planarity_tolerance * size
    deviation, figure, k = worst
    if figure is None or deviation <= limit:
        return
    if isinstance(figure, MeshFigure):
        what = f"vertex {k} of '{figure.name}'"
    else:
        sizes = np.cumsum([len(s.world) for s in figure.strokes])
        stroke = int(np.searchsorted(sizes, k, side="right"))
        point = k - (int(sizes[stroke - 1]) if stroke else 0)
        what = f"point {point} of stroke {stroke} of {figure.label()}"
    raise StickMorphError(
        f"the figures are not planar: {what} is {deviation:.6g} away from {fitted.describe()} (allowed "
        f"{limit:.3g}, {settings.planarity_tolerance:g} of the size {size:.6g})"
        + ("" if settings.plane == "AUTO" else "; try plane AUTO"))


def _selected_pins(source: CleanedSide, target: CleanedSide) -> tuple:
    """Pin Selected Points: the k-th selected point of the source drawing
    (in drawing order: stroke, then point) pins the k-th of the target."""
    counts = [len(side.drawing.selected) for side in (source, target)]
    for side, count in zip((source, target), counts):
        if count == 0:
            raise StickMorphError(
                f"Pin Selected Points is on, but no point of {side.drawing.label()} is selected: select the "
                "points to pin in Edit Mode, or turn Pin Selected Points off")
    if counts[0] != counts[1]:
        raise StickMorphError(
            f"Pin Selected Points pairs the selected points in drawing order, but {source.drawing.label()} has "
            f"{counts[0]} selected and {target.drawing.label()} {counts[1]}: select as many in both")
    pins = []
    for k, ((si, sj), (ti, tj)) in enumerate(zip(source.drawing.selected, target.drawing.selected)):
        pins.append(Pin(f"selected point {k + 1} (point {sj} of stroke {si} to point {tj} of stroke {ti})",
                        int(source.cleaned.point_vertex[si][sj]), int(target.cleaned.point_vertex[ti][tj])))
    for side, end in ((source, "source"), (target, "target")):
        vertices = [getattr(pin, end) for pin in pins]
        if len(set(vertices)) != len(vertices):
            raise StickMorphError(f"two selected points of {side.drawing.label()} became one vertex when it was "
                                  "cleaned (they are closer than the clean tolerance): select one of them")
    return tuple(pins)


def prepare_drawings(source, target, settings: BakeSettings, pin_selected: bool = False):
    """(PreparedPair, DrawingPair): a pair of which at least one side is a
    Drawing (the other may be a MeshFigure), projected onto their common
    plane, the drawings cleaned, then by index or matched as meshes are
    (morph.prepare_projected). pin_selected: the selected points of two
    Grease Pencil drawings pin them (Pin Selected Points). Everything is
    checked before the engine morphs: raises StickMorphError naming the
    object, layer, frame and stroke."""
    roles = (("source", source), ("target", target))
    for role, figure in roles:
        if isinstance(figure, MeshFigure):
            refuse_faces(figure.name, figure.faces)
            if len(figure.world) == 0:
                raise StickMorphError(f"'{figure.name}' has no vertices")
            if figure.pin_groups:
                names = ", ".join(f"'{name}'" for name in figure.pin_groups)
                raise StickMorphError(
                    f"'{figure.name}' has pin groups ({names}), but the other figure is not a mesh: pins join two "
                    "meshes (vertex groups) or two Grease Pencil drawings (Pin Selected Points); Clear Pins "
                    "removes them")
        _refuse_non_finite(figure, role)
    if isinstance(target, MeshFigure) and target.delay is not None:
        raise StickMorphError("internal error: delay weights on the target")
    if not isinstance(source, MeshFigure) and settings.delay_group:
        raise StickMorphError(
            f"the Delay Group '{settings.delay_group}' names a vertex group of a source mesh, and the source "
            f"{source.label()} is not a mesh: clear Delay Group (local timing needs a mesh source)")
    if pin_selected and not all(isinstance(f, Drawing) and f.object_type in GREASE_PENCIL_TYPES
                                for _, f in roles):
        raise StickMorphError("Pin Selected Points pins two Grease Pencil drawings; meshes are pinned with vertex "
                              "groups (Pin Selected Vertices), and curves cannot be pinned: turn it off")
    if pin_selected and settings.correspondence == "INDEX":
        raise StickMorphError(f"pins need Correspondence (Match) Automatic or By Shape: with By Index the selected "
                              f"points would have no effect (turn Pin Selected Points off); {_BY_INDEX}")

    worlds = [_world_of(figure) for _, figure in roles]
    fitted = fit_plane_of(worlds, settings.plane)
    both = np.vstack(worlds)
    size = float(np.linalg.norm(both.max(axis=0) - both.min(axis=0)))
    heights = [project(world, fitted)[1] for world in worlds]
    _check_planarity([source, target], heights, size, settings, fitted)

    sides = []
    projected = []
    for role, figure in roles:
        if isinstance(figure, MeshFigure):
            xy, h = project(figure.world, fitted)
            projected.append((xy, h, np.asarray(figure.edges, dtype=np.int64).reshape(-1, 2)))
            sides.append(None)
            continue
        stroke_xy, stroke_h = [], []
        for stroke in figure.strokes:
            xy, h = project(stroke.world, fitted)
            stroke_xy.append(xy)
            stroke_h.append(h)
        cleaned = clean(figure, stroke_xy, role, settings.clean_tolerance)
        xy = np.asarray(cleaned.vertices, dtype=np.float64).reshape(-1, 2)
        edges = np.asarray(cleaned.edges, dtype=np.int64).reshape(-1, 2)
        h = vertex_heights(cleaned, stroke_h, xy)
        sides.append(CleanedSide(figure, cleaned, xy, h, edges))
        projected.append((xy, h, edges))
    (source_xy, source_h, source_edges), (target_xy, target_h, target_edges) = projected

    pins = _selected_pins(sides[0], sides[1]) if pin_selected else ()
    if settings.correspondence == "INDEX":
        if len(source_xy) != len(target_xy):
            raise StickMorphError(
                f"different vertex counts: {_figure_words(source, sides[0])} has {len(source_xy)} vertices, "
                f"{_figure_words(target, sides[1])} has {len(target_xy)}; {_BY_INDEX}")
        message = compare_edge_sets(source_edges, target_edges, source.name, target.name)
        if message:
            raise StickMorphError(f"{message}; {_BY_INDEX}")
    check_pins(pins, source_edges, target_edges, len(source_xy), len(target_xy), source.name, target.name)
    prepared = prepare_projected(source_xy, source_h, source_edges, source.name, target_xy, target_h, target_edges,
                                 target.name, fitted, size, settings.correspondence, pins,
                                 source.delay if isinstance(source, MeshFigure) else None)
    return prepared, DrawingPair(sides[0], sides[1])


def _figure_words(figure, side) -> str:
    if side is None:
        return f"'{figure.name}'"
    return f"{figure.label()}, cleaned,"


# ------------------------------------------------------------- output ----

@dataclass
class OutputStroke:
    """One stroke of a Grease Pencil result: its points are vertices of the
    morph's figure (the same in every frame), with the values the source
    stroke had, interpolated where points were inserted."""

    vertices: np.ndarray  # (K,) int64 indices into the morph's vertices
    cyclic: bool
    point_values: dict  # name -> (K,) float64
    stroke_values: dict  # name -> value


def figure_chains(vertex_count: int, edges) -> list[tuple[list[int], bool]]:
    """The strokes of a figure that was not drawn as strokes (a mesh): its
    chains, each a path from an end or junction to the next (vertices of
    degree 2 inside), a loop of degree-2 vertices as one cyclic stroke, and
    a vertex on no edge as a stroke of one point. In order of their first
    edge (of the vertex for a dot); every edge in exactly one chain."""
    edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    neighbours = [[] for _ in range(int(vertex_count))]
    for e, (a, b) in enumerate(edges.tolist()):
        neighbours[a].append((b, e))
        neighbours[b].append((a, e))
    used = np.zeros(len(edges), dtype=bool)
    chains = []

    def walk(start, first_edge):
        path = [start]
        vertex, edge = start, first_edge
        while True:
            used[edge] = True
            a, b = edges[edge]
            vertex = int(b if a == vertex else a)
            path.append(vertex)
            if len(neighbours[vertex]) != 2:
                return path, False
            nxt = next(((v, e) for v, e in neighbours[vertex] if not used[e]), None)
            if nxt is None:  # back at the start of a loop
                return path[:-1], True
            edge = nxt[1]

    for e, (a, b) in enumerate(edges.tolist()):
        if used[e]:
            continue
        # Start a path at an end or junction if this edge's chain has one.
        start = a if len(neighbours[a]) != 2 else b if len(neighbours[b]) != 2 else None
        if start is None:
            # Inside a chain: walk back to its end, or around a loop.
            vertex, edge = a, e
            while len(neighbours[vertex]) == 2:
                other = next(((v, f) for v, f in neighbours[vertex] if f != edge), None)
                edge = other[1]
                vertex = int(edges[edge][0] if edges[edge][1] == vertex else edges[edge][1])
                if vertex == a:
                    break
            start, e_start = vertex, edge
            if len(neighbours[start]) == 2:  # a loop: start at a, along e
                start, e_start = a, e
        else:
            e_start = e
        chains.append(walk(start, e_start))
    for v in range(int(vertex_count)):
        if not neighbours[v]:
            chains.append(([v], False))
    return chains


def _adjacency(count: int, edges) -> list:
    neighbours = [[] for _ in range(count)]
    for e, (a, b) in enumerate(np.asarray(edges, dtype=np.int64).reshape(-1, 2).tolist()):
        neighbours[a].append((b, e))
        neighbours[b].append((a, e))
    return neighbours


def _subdivided(a: int, b: int, neighbours, dummy, used) -> list[int]:
    """The morph figure's vertices from a to b (both the source's own
    vertices, joined by an edge of the source figure), with the dummies the
    matching put on that edge between them: a chain of dummies (degree 2)
    from a that ends at b. Marks its edges used."""
    for first, edge in neighbours[a]:
        if used[edge]:
            continue
        chain, edges_on = [first], [edge]
        previous, vertex = a, first
        while dummy[vertex]:
            step = next(((v, e) for v, e in neighbours[vertex] if v != previous), None)
            if step is None:
                break
            previous, vertex = vertex, step[0]
            chain.append(vertex)
            edges_on.append(step[1])
        if vertex == b:
            used[edges_on] = True
            return [a] + chain[:-1]
    raise StickMorphError(f"internal error: the morph's figure has no edge path from vertex {a} to {b}")


def output_strokes(prepared: PreparedPair, strokes) -> list[OutputStroke]:
    """The Grease Pencil result's strokes on the morph's figure.

    strokes: per source stroke (vertex path in the source figure, cyclic,
    point slots, point values, stroke values) as source_strokes makes them.
    Each edge of the source figure becomes the path the matching made of
    it (dummies subdivide edges; by index the figure is the source's own),
    and every edge of the morph's figure must be on exactly one stroke."""
    matching = prepared.matching
    count = len(prepared.source_xy)
    original = np.asarray(matching.source_vertex, dtype=np.int64)
    if not np.array_equal(original[:matching.source_count], np.arange(matching.source_count)):
        raise StickMorphError("internal error: the morph's figure does not start with the source's vertices")
    dummy = original < 0
    neighbours = _adjacency(count, prepared.edges)
    used = np.zeros(len(prepared.edges), dtype=bool)
    result = []
    for path, cyclic, slots, point_values, stroke_values in strokes:
        path = [int(v) for v in path]
        vertices, marks = [], []
        pairs = list(zip(path, path[1:])) + ([(path[-1], path[0])] if cyclic and len(path) > 1 else [])
        for k, (a, b) in enumerate(pairs):
            piece = _subdivided(a, b, neighbours, dummy, used)
            marks.append(len(vertices))
            vertices.extend(piece)
        if not cyclic or len(path) == 1:
            marks.append(len(vertices))
            vertices.append(path[-1])
        # marks[k]: where source path vertex k sits in the output path.
        marks = np.asarray(marks[:len(path)], dtype=np.int64)
        positions, length = _arc_positions(prepared.source_xy, vertices, cyclic)
        values = {}
        for name, per_point in point_values.items():
            along = path_values(per_point, slots, positions[marks], length, cyclic)
            values[name] = np.interp(positions, positions[marks], along, period=length if cyclic and length else None)
        result.append(OutputStroke(np.asarray(vertices, dtype=np.int64), bool(cyclic), values, dict(stroke_values)))
    if not used.all():
        missing = np.flatnonzero(~used)
        raise StickMorphError(f"internal error: {len(missing)} edges of the morph's figure are on no stroke "
                              f"(edge {int(missing[0])})")
    return result


def source_strokes(side: CleanedSide | None, mesh_vertex_count: int = 0, mesh_edges=None):
    """The source's strokes as output_strokes takes them: a drawing's own
    strokes through its cleaned figure (side), each with its input points'
    slots and values; for a mesh source (side None: its vertex count and
    edges), its chains (figure_chains), without values. The source's
    vertices are the morph figure's first, in order, by index and matched."""
    if side is None:
        return [(path, cyclic, np.arange(len(path)), {}, {})
                for path, cyclic in figure_chains(mesh_vertex_count, mesh_edges)]
    cleaned = side.cleaned
    out = []
    for i, stroke in enumerate(side.drawing.strokes):
        path = [int(v) for v in cleaned.stroke_vertices[i]]
        cyclic = bool(cleaned.cyclic[i])
        slots = point_slots(path, cleaned.point_vertex[i], cyclic)
        out.append((path, cyclic, slots, stroke.point_values, stroke.stroke_values))
    return out
