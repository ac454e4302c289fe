"""How the two meshes' vertices correspond: the edge sets, the parts, the
pins, the choice between by index and matched (choose_correspondence), and
the matched figure's heights and summary."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .common import StickMorphError, pin_names
from .native import load_engine

# How the meshes' vertices correspond (settings.correspondence; see
# choose_correspondence): INDEX_OR_MATCH ("Automatic" in the panel), by
# index when that works, else matched (not the engine's correspond="auto",
# which always matches: that is MATCH here);
# INDEX, vertex i of one mesh is vertex i of the other; MATCH, always
# matched by shape (stickmorph.correspond).
CORRESPONDENCES = ("INDEX_OR_MATCH", "INDEX", "MATCH")


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


# ----------------------------------------------------------------- edges ----

def _mesh_named(message: str, source_name: str, target_name: str) -> str:
    """An engine message about the edge lists, with the meshes' names."""
    return message.replace("source_edges", f"'{source_name}'").replace("target_edges", f"'{target_name}'")


def compare_edge_sets(source_edges, target_edges, source_name: str = "source",
                      target_name: str = "target", limit: int = 5) -> str | None:
    """None if both edge lists hold the same undirected edges, else a message.
    The comparison is the engine's (stickmorph.edge_set_difference, section
    2.1's first test); the wording, with the mesh names, is the add-on's."""
    engine = load_engine()
    try:
        only_source, only_target = engine.edge_set_difference(source_edges, target_edges)
    except engine.StickMorphError as e:
        raise StickMorphError(_mesh_named(str(e), source_name, target_name)) from e
    if len(only_source) == 0 and len(only_target) == 0:
        return None

    def listing(edges):
        items = [tuple(e) for e in edges.tolist()]
        text = ", ".join(f"{i}-{j}" for i, j in items[:limit])
        return text + (f" and {len(items) - limit} more" if len(items) > limit else "")

    parts = []
    if len(only_source):
        parts.append(f"edges only in '{source_name}': {listing(only_source)}")
    if len(only_target):
        parts.append(f"edges only in '{target_name}': {listing(only_target)}")
    return "the meshes have different edges (vertex i of one must be joined to the same " \
           "vertices as vertex i of the other): " + "; ".join(parts)


# ----------------------------------------------------------------- parts ----

def figure_parts(vertex_count: int, edges) -> list[list[int]]:
    """The parts (connected components) of a figure on vertex_count vertices,
    each as its sorted vertex indices, in order of their smallest vertex: the
    engine's numbering, "part 0", "part 1", ... A vertex on no edge (a dot)
    is a part of its own. The engine's own function (stickmorph.figure_parts),
    so the numbering the report says is the one the engine's messages use.
    Edges to vertices outside 0..vertex_count-1 are ignored here (the
    engine's figure_parts refuses them; a morph names such an edge)."""
    edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    inside = edges[((edges >= 0) & (edges < int(vertex_count))).all(axis=1)]
    return [list(part) for part in load_engine().figure_parts(int(vertex_count), inside)]


def parts_summary(parts) -> str:
    """'' for one part; else '3 parts (1 dot)' or '2 parts', for the report."""
    count = len(parts)
    if count <= 1:
        return ""
    dots = sum(1 for part in parts if len(part) == 1)
    return f"{count} parts" + (f" ({dots} dot{'s' if dots != 1 else ''})" if dots else "")


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


def choose_correspondence(setting: str, same_vertex_count: bool, same_edges: bool, pinned: bool,
                          compatible_by_index) -> tuple[bool, str]:
    """(matched, why): whether the bake matches the meshes (stickmorph.correspond)
    or takes them by index, and why it matches when the setting left it open.

    INDEX: by index (prepare_pair has refused meshes that cannot be). MATCH:
    matched. INDEX_OR_MATCH: by index when the meshes have the same vertex count and
    edge set, no pins, and are compatible by index; matched otherwise. Pins
    say that the vertices are not paired by number, so INDEX_OR_MATCH matches
    whenever there are any. compatible_by_index is called (once) only when
    the answer depends on it. The bake (prepare_pair) answers True: the
    morph by index is the check, and morph_pair falls back on the matching
    when it refuses the pair, so that a bake checks compatibility once."""
    if setting == "INDEX":
        return False, ""
    if setting == "MATCH":
        return True, ""
    if setting != "INDEX_OR_MATCH":
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
    """Refuses, naming the pin group, a pin the matching would refuse: the
    engine's rule (stickmorph.check_pins: a vertex not in its mesh, pinned
    twice, or a pin joining vertices of different kinds: an end or a
    junction pairs only with one of the same degree, a vertex inside a
    stroke only with another), worded with the group's and meshes' names,
    which the engine does not know."""
    if not pins:
        return
    engine = load_engine()
    try:
        problem = engine.check_pins(source_count, source_edges, target_count, target_edges,
                                    [[pin.source, pin.target] for pin in pins])
    except engine.StickMorphError as e:
        raise StickMorphError(_mesh_named(str(e), source_name, target_name)) from e
    if problem is None:
        return
    pin = pins[problem["pin"]]
    defect = problem["defect"]
    if defect in ("missing_source_vertex", "missing_target_vertex"):
        vertex, count, mesh = ((pin.source, source_count, source_name) if defect == "missing_source_vertex"
                               else (pin.target, target_count, target_name))
        raise StickMorphError(f"the pin group '{pin.name}' names vertex {vertex} of '{mesh}', "
                              f"which has {count} vertices")
    if defect == "kinds_differ":
        raise StickMorphError(
            f"the pin '{pin.name}' joins vertex {pin.source} of '{source_name}', "
            f"{_vertex_kind(problem['source_degree'])}, to vertex {pin.target} of '{target_name}', "
            f"{_vertex_kind(problem['target_degree'])}: a pin joins two ends, two junctions of the same degree "
            "or two vertices inside strokes")
    # Pinned twice: read_pins refuses a vertex in two groups first; a caller
    # with Pins of its own still gets the engine's reason.
    raise StickMorphError(f"the pin '{pin.name}': {problem['reason']}")


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
