"""Writing a computed morph into Blender data: the result object, its shape
keys and keyframes, the renderable tubes and the triangulation helper.

Everything created here is plain Blender data (mesh, shape keys, an action
on the Key's eval_time, a Geometry Nodes group made of built-in nodes), so a
saved file renders in a Blender without this add-on: no handlers, no drivers,
no custom node types.

Shape keys: absolute keys on an eval_time F-curve, chosen by measurement
over one relative key per frame with constant interpolation. Measured with
tests/blender/measure_shape_keys.py (which holds the relative variant; the
add-on never bakes it) in Blender 3.4.1 on this 2-core machine
(bake = building keys and keyframes; step = scene.frame_set per frame with the
shape keys evaluated; error = largest difference from the baked frame):

    frames x vertices   absolute + eval_time           relative, one key per frame
    100 x 1000          bake   6 ms, step 0.05 ms      bake   7 ms, step 0.37 ms
    400 x 1000          bake  23 ms, step 0.05 ms      bake  30 ms, step 4.76 ms
    400 x 10000         bake 225 ms, step 0.37 ms      bake 223 ms, step 5.37 ms
    largest error       7.2e-7 (coordinates up to 7.5)  2.4e-7

Baking costs the same, but playback with per-frame relative keys grows with
the number of frames (every frame's F-curve and key block is visited on every
frame change: 95 times slower at 400 frames), while absolute keys only blend
the two keys around eval_time. Both reproduce the baked frames to float32
resolution at integer frames. Absolute keys also interpolate linearly between
consecutive frames at sub-frames (motion blur), where constant keys would
jump. So the result uses absolute keys.
"""

from __future__ import annotations

import bpy
import numpy as np

from . import core

NODE_GROUP_NAME = "StickMorph Tubes"
ROLE = "stick_morph_role"
SOURCE = "stick_morph_source"
TARGET = "stick_morph_target"

# The enum index of LINEAR in Keyframe.interpolation, for foreach_set.
_LINEAR = 1


# ------------------------------------------------------------------ read ----

def evaluated_depsgraph(context):
    """The evaluated depsgraph, brought up to date.

    Object.matrix_world of an original object is a copy the depsgraph writes
    back after evaluating; since Blender 4.x it is runtime data that undo
    does not restore. Adjust Last Operation undoes the bake and calls execute
    again before anything re-evaluates, so the original objects' matrix_world
    then reads the identity (measured in 4.3 and 5.2 under Xvfb: the redone
    result sat at the meshes' local coordinates, 2.5 off; 3.4 keeps the
    matrix in the file and was right). evaluated_depsgraph_get() evaluates
    what is tagged first, and the evaluated object carries the matrix that is
    shown."""
    return context.evaluated_depsgraph_get()


def world_matrix(obj, depsgraph=None):
    """(4, 4) float64 world matrix of obj as evaluated (parents, constraints,
    drivers), from the evaluated copy when a depsgraph is given; without one,
    or if the object is not in it, from matrix_basis and the parent chain."""
    if depsgraph is not None:
        try:
            return np.array(obj.evaluated_get(depsgraph).matrix_world, dtype=np.float64)
        except (ReferenceError, RuntimeError):
            pass  # not in the view layer's depsgraph: compose it below
    # Object parenting only (no bone or vertex parents, no constraints): the
    # depsgraph is the one that knows those.
    matrix = np.array(obj.matrix_basis, dtype=np.float64)
    if obj.parent is not None:
        matrix = world_matrix(obj.parent) @ np.array(obj.matrix_parent_inverse, dtype=np.float64) @ matrix
    return matrix


def _world_coords(points, matrix):
    """(V, 3) float64 world coordinates of a collection with .co (mesh
    vertices, a shape key's points) under a (4, 4) world matrix."""
    co = np.empty(len(points) * 3, dtype=np.float32)
    points.foreach_get("co", co)
    local = co.reshape(-1, 3).astype(np.float64)
    # A non-finite coordinate stays non-finite here and is reported, naming
    # the object and the vertex, by core's validation; numpy need not warn.
    with np.errstate(invalid="ignore", over="ignore"):
        return local @ matrix[:3, :3].T + matrix[:3, 3]


def shape_key_world(obj, block, depsgraph=None):
    """(V, 3) float64 world coordinates of a shape key's own shape (the
    mesh at that key alone, value 1), placed like mesh_world_data."""
    return _world_coords(block.data, world_matrix(obj, depsgraph))


def mesh_world_data(obj, depsgraph=None):
    """(V, 3) float64 world coordinates, (E, 2) int64 edges and the face count
    of a mesh object's own mesh (no modifiers, no shape keys: the basis),
    placed by the object's evaluated world matrix (world_matrix)."""
    mesh = obj.data
    world = _world_coords(mesh.vertices, world_matrix(obj, depsgraph))
    edges = np.empty(len(mesh.edges) * 2, dtype=np.int32)
    mesh.edges.foreach_get("vertices", edges)
    return world, edges.reshape(-1, 2).astype(np.int64), len(mesh.polygons)


def vertex_groups(obj, only=None):
    """{name: [vertex index, ...]} of a mesh object's vertex groups, for
    core.read_pins; only(name) picks the groups to read (all without it).
    Membership, whatever the weight: a vertex assigned with weight 0 is in
    the group as the Vertex Groups panel's Select shows it. Object Mode data
    (the bake runs there): in Edit Mode the mesh's groups are stale."""
    names = {group.index: group.name for group in obj.vertex_groups if only is None or only(group.name)}
    members = {name: [] for name in names.values()}
    if names:
        for vertex in obj.data.vertices:
            for element in vertex.groups:
                name = names.get(element.group)
                if name is not None:
                    members[name].append(vertex.index)
    return members


def vertex_group_weights(obj, name):
    """[(vertex index, weight), ...] of the mesh object's vertex group `name`
    (its members, weight 0 included), or None when it has no group of that
    name: the delay weights of local timing (issue 31), which
    core.delay_weights checks and completes. Object Mode data, as
    vertex_groups."""
    group = obj.vertex_groups.get(name) if name else None
    if group is None:
        return None
    index = group.index
    return [(vertex.index, element.weight) for vertex in obj.data.vertices for element in vertex.groups
            if element.group == index]


def delay_weights(obj, vertex_count, group, role="the source mesh"):
    """The delay weights of obj's vertex group `group` (core.delay_weights:
    None for no group, StickMorphError for a group missing or empty)."""
    if not group:
        return None
    return core.delay_weights(vertex_count, vertex_group_weights(obj, group), group, obj.name, role,
                              [g.name for g in obj.vertex_groups])


# ----------------------------------------------------------------- helpers ----

def find_fcurve(anim_data, data_path):
    """The F-curve of data_path in the action of anim_data, for legacy actions
    (up to 4.3: Action.fcurves) and slotted actions (4.4+, through the
    assigned slot's channelbag; 5.0 removed Action.fcurves). None if absent."""
    action = anim_data.action
    if action is None:
        return None
    slot = getattr(anim_data, "action_slot", None)
    if slot is not None and hasattr(action, "layers"):
        for layer in action.layers:
            for strip in layer.strips:
                channelbag = strip.channelbag(slot)
                if channelbag is not None:
                    fcurve = channelbag.fcurves.find(data_path)
                    if fcurve is not None:
                        return fcurve
    legacy = getattr(action, "fcurves", None)  # gone in 5.0
    return legacy.find(data_path) if legacy is not None else None


def _fill_fcurve(fcurve, frames, values):
    """Makes fcurve hold exactly the given LINEAR keyframes (it holds one already)."""
    points = fcurve.keyframe_points
    missing = len(frames) - len(points)
    if missing > 0:
        points.add(missing)
    co = np.empty(2 * len(frames), dtype=np.float32)
    co[0::2] = frames
    co[1::2] = values
    points.foreach_set("co", co)
    points.foreach_set("handle_left", co)
    points.foreach_set("handle_right", co)
    points.foreach_set("interpolation", np.full(len(frames), _LINEAR, dtype=np.int32))
    fcurve.update()


def _new_mesh(name, coords_local, edges):
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(coords_local))
    mesh.vertices.foreach_set("co", np.asarray(coords_local, dtype=np.float32).ravel())
    mesh.edges.add(len(edges))
    mesh.edges.foreach_set("vertices", np.asarray(edges, dtype=np.int32).ravel())
    mesh.update()
    return mesh


# ------------------------------------------------------------ shape keys ----

def bake_absolute_keys(obj, frames, frame_start, progress=None, origin=None):
    """Absolute shape keys, key k = frame k (frames[k] - origin: the object's
    local coordinates, origin its location), driven by an eval_time F-curve
    with one LINEAR keyframe per frame at the key's position. Each key is
    moved and rounded to float32 on its own, so that no second copy of all
    the frames is made (at 10^5 vertices and 250 frames, 600 MB)."""
    count = len(frames)
    shift = np.zeros(3) if origin is None else np.asarray(origin, dtype=np.float64)
    for k in range(count):
        block = obj.shape_key_add(name=f"Frame {k:04d}", from_mix=False)
        if k:
            block.data.foreach_set("co", (np.asarray(frames[k], dtype=np.float64) - shift).astype(np.float32).ravel())
        if progress and k % 16 == 0:
            progress(k)
    key = obj.data.shape_keys
    key.use_relative = False
    positions = np.empty(count, dtype=np.float32)
    key.key_blocks.foreach_get("frame", positions)
    key.eval_time = float(positions[0])
    key.keyframe_insert("eval_time", frame=frame_start)
    fcurve = find_fcurve(key.animation_data, "eval_time")
    _fill_fcurve(fcurve, frame_start + np.arange(count, dtype=np.float64), positions)
    return key


# -------------------------------------------------------------- renderable ----

def _new_socket(group, name, in_out, socket_type):
    """A group interface socket: ng.interface (4.0+) or ng.inputs/outputs (3.x)."""
    if hasattr(group, "interface"):
        return group.interface.new_socket(name=name, in_out=in_out, socket_type=socket_type)
    sockets = group.inputs if in_out == "INPUT" else group.outputs
    return sockets.new(socket_type, name)


def _group_input_identifier(group, name):
    if hasattr(group, "interface"):
        for item in group.interface.items_tree:
            if getattr(item, "in_out", None) == "INPUT" and item.name == name:
                return item.identifier
        raise KeyError(name)
    return group.inputs[name].identifier


# The tubes' node group as built now; a file may hold an older one (a group
# without this number is version 1: full quality in the viewport too;
# version 2 had 6 sides in the viewport), which its results keep, while a new
# bake builds this version beside it.
TUBES_VERSION = 3

# Render quality (what the tubes have always rendered): a 12-sided profile
# and a UV sphere of 12 segments and 6 rings at every vertex.
RENDER_PROFILE = 12
RENDER_SPHERE = (12, 6)
# Viewport quality (issue 29): a 4-sided profile, and joints (UV spheres of 8
# segments and 4 rings) only where an edge chain ends or branches: vertices
# on no edge (dots), one edge (ends) or three or more (junctions). Along a
# chain, Mesh to Curve makes one spline through the vertex and Curve to Mesh
# joins its tube there, so a sphere adds nothing seen but its vertices.
# Measured with bench/blender_bake.py at 10^4 vertices (Blender 3.4, frame_set
# plus the evaluated mesh): the full-quality spheres are 620,000 of the
# evaluated mesh's 740,000 vertices and hold playback at 2.8 fps; the tube
# alone plays at 27 fps with 12 sides, 86 with 4 (one machine). On another
# (version 2 of the group, 6 sides) the benchmark played at 32-34 fps when
# quiet and 18-24 while other work ran; Curve to Mesh's cost follows the
# sides (a 10^4-vertex chain, evaluated after a shape-key change: 39 fps with
# 6 sides, 58 with 4, 74 with 3), so version 3 has 4, which smooth shading
# still draws round.
VIEWPORT_PROFILE = 4
VIEWPORT_SPHERE = (8, 4)


def tube_node_group():
    """The Geometry Nodes group that turns edges into tubes with round joints:
    Mesh to Curve -> Curve to Mesh (circle profile), joined with a sphere at
    the vertices. Is Viewport picks the quality: in a render every vertex gets
    a full sphere (RENDER_*); in the viewport (and in the evaluated mesh of
    the viewport's depsgraph, which playback evaluates) a coarser profile and
    spheres only at ends, junctions and dots (VIEWPORT_*). Reused when a
    previous bake made this version; built-in nodes only."""
    for group in bpy.data.node_groups:
        if (group.bl_idname == "GeometryNodeTree" and group.get(ROLE) == "tubes"
                and group.get("stick_morph_tubes_version", 1) == TUBES_VERSION):
            return group, False
    group = bpy.data.node_groups.new(NODE_GROUP_NAME, "GeometryNodeTree")
    group[ROLE] = "tubes"
    group["stick_morph_tubes_version"] = TUBES_VERSION
    _new_socket(group, "Geometry", "INPUT", "NodeSocketGeometry")
    radius = _new_socket(group, "Radius", "INPUT", "NodeSocketFloat")
    radius.default_value = 0.02
    radius.min_value = 0.0
    _new_socket(group, "Geometry", "OUTPUT", "NodeSocketGeometry")

    nodes, links = group.nodes, group.links
    group_in = nodes.new("NodeGroupInput")
    group_out = nodes.new("NodeGroupOutput")
    is_viewport = nodes.new("GeometryNodeIsViewport")

    def by_viewport(render, viewport, y):
        """A Math node giving `render` in a render and `viewport` in the
        viewport: render + (viewport - render) * is_viewport (a boolean
        linked to a float is 0 or 1)."""
        node = nodes.new("ShaderNodeMath")
        node.operation = "MULTIPLY_ADD"
        links.new(is_viewport.outputs[0], node.inputs[0])
        node.inputs[1].default_value = float(viewport - render)
        node.inputs[2].default_value = float(render)
        node.location = (200, y)
        return node.outputs[0]

    to_curve = nodes.new("GeometryNodeMeshToCurve")
    circle = nodes.new("GeometryNodeCurvePrimitiveCircle")
    links.new(by_viewport(RENDER_PROFILE, VIEWPORT_PROFILE, -200), circle.inputs["Resolution"])
    to_mesh = nodes.new("GeometryNodeCurveToMesh")

    # Which vertices get a sphere: all of them in a render, those whose edge
    # count is not 2 in the viewport.
    neighbours = nodes.new("GeometryNodeInputMeshVertexNeighbors")
    not_two = nodes.new("FunctionNodeCompare")
    not_two.data_type = "INT"
    not_two.operation = "NOT_EQUAL"
    int_inputs = [socket for socket in not_two.inputs if socket.type == "INT"]
    links.new(neighbours.outputs["Vertex Count"], int_inputs[0])
    int_inputs[1].default_value = 2
    in_render = nodes.new("FunctionNodeBooleanMath")
    in_render.operation = "NOT"
    links.new(is_viewport.outputs[0], in_render.inputs[0])
    joint = nodes.new("FunctionNodeBooleanMath")
    joint.operation = "OR"
    links.new(not_two.outputs[0], joint.inputs[0])
    links.new(in_render.outputs[0], joint.inputs[1])

    to_points = nodes.new("GeometryNodeMeshToPoints")
    sphere = nodes.new("GeometryNodeMeshUVSphere")
    links.new(by_viewport(RENDER_SPHERE[0], VIEWPORT_SPHERE[0], -500), sphere.inputs["Segments"])
    links.new(by_viewport(RENDER_SPHERE[1], VIEWPORT_SPHERE[1], -600), sphere.inputs["Rings"])
    instance = nodes.new("GeometryNodeInstanceOnPoints")
    realize = nodes.new("GeometryNodeRealizeInstances")
    join = nodes.new("GeometryNodeJoinGeometry")
    for x, node in enumerate((group_in, to_curve, to_mesh, join, group_out)):
        node.location = (200 * x, 0)
    for x, node in enumerate((circle, to_points, sphere, instance, realize)):
        node.location = (200 * x + 200, -300)
    for x, node in enumerate((is_viewport, neighbours, not_two, in_render, joint)):
        node.location = (200 * x - 200, -800)

    geometry = group_in.outputs["Geometry"]
    radius_out = group_in.outputs["Radius"]
    links.new(geometry, to_curve.inputs["Mesh"])
    links.new(to_curve.outputs["Curve"], to_mesh.inputs["Curve"])
    links.new(radius_out, circle.inputs["Radius"])
    links.new(circle.outputs["Curve"], to_mesh.inputs["Profile Curve"])
    links.new(geometry, to_points.inputs["Mesh"])
    links.new(joint.outputs[0], to_points.inputs["Selection"])
    links.new(radius_out, sphere.inputs["Radius"])
    links.new(to_points.outputs["Points"], instance.inputs["Points"])
    links.new(sphere.outputs["Mesh"], instance.inputs["Instance"])
    links.new(instance.outputs["Instances"], realize.inputs["Geometry"])
    links.new(to_mesh.outputs["Mesh"], join.inputs["Geometry"])
    links.new(realize.outputs["Geometry"], join.inputs["Geometry"])
    links.new(join.outputs["Geometry"], group_out.inputs["Geometry"])
    return group, True


def _modifier_input(modifier, identifier):
    """The 5.x holder of a Geometry Nodes modifier input: the item of
    modifier.properties.inputs whose .value is the input's value; None in
    3.x/4.x, where the value is an ID property, modifier[identifier]."""
    properties = getattr(modifier, "properties", None)
    inputs = getattr(properties, "inputs", None) if properties is not None else None
    if inputs is None:
        return None
    # An RNA struct per input, by attribute (measured in 5.2: inputs[identifier]
    # is the raw ID property group, without .value).
    item = getattr(inputs, identifier, None)
    if item is None:
        raise KeyError(f"the modifier '{modifier.name}' has no input {identifier}")
    return item


def set_modifier_input(modifier, identifier, value):
    """Sets a Geometry Nodes modifier input (5.x: properties.inputs.<id>.value;
    before: the ID property modifier[identifier], refused by 5.x with
    "id properties not supported for this type")."""
    item = _modifier_input(modifier, identifier)
    if item is None:
        modifier[identifier] = value
    else:
        item.value = value


def get_modifier_input(modifier, identifier):
    """The value set_modifier_input set."""
    item = _modifier_input(modifier, identifier)
    return modifier[identifier] if item is None else item.value


def radius_identifier(group):
    return _group_input_identifier(group, "Radius")


def add_tubes(obj, radius):
    group, created = tube_node_group()
    modifier = obj.modifiers.new("Stick Morph Tubes", "NODES")
    modifier.node_group = group
    set_modifier_input(modifier, radius_identifier(group), float(radius))
    return group, created


# The result mesh's integer point attributes saying, for a matched pair,
# which vertex of the source and of the target each of its vertices is (-1:
# a dummy on that mesh's edge); plain attributes, readable without the add-on.
SOURCE_VERTEX_ATTRIBUTE = "stick_morph_source_vertex"
TARGET_VERTEX_ATTRIBUTE = "stick_morph_target_vertex"


def _add_vertex_attribute(mesh, name, values):
    attribute = mesh.attributes.new(name=name, type="INT", domain="POINT")
    attribute.data.foreach_set("value", np.asarray(values, dtype=np.int32))


# ------------------------------------------------------------- the result ----

class Created:
    """Data-blocks made by one bake, removed again if the bake fails."""

    def __init__(self):
        self.objects = []
        self.names = {}  # object -> the name it should have once a previous result is gone
        self.node_group = None
        self.material = None  # the ink of a Grease Pencil result made from a mesh or a curve (drawing_io)

    def remove(self):
        for obj in reversed(self.objects):
            remove_result_object(obj)
        self.objects.clear()
        self.names.clear()
        if self.node_group is not None and self.node_group.users == 0:
            bpy.data.node_groups.remove(self.node_group)
        self.node_group = None
        if self.material is not None and self.material.users == 0:
            bpy.data.materials.remove(self.material)
        self.material = None


def remove_result_object(obj):
    """Removes a result or helper object with its mesh, shape keys and action
    (or its Grease Pencil data, issue 32)."""
    mesh = obj.data if obj.type == "MESH" else None
    pencil = obj.data if obj.type in ("GPENCIL", "GREASEPENCIL") else None
    action = None
    if mesh is not None and mesh.shape_keys is not None and mesh.shape_keys.animation_data is not None:
        action = mesh.shape_keys.animation_data.action
    bpy.data.objects.remove(obj)
    if mesh is not None and mesh.users == 0:
        bpy.data.meshes.remove(mesh)
    if pencil is not None and pencil.users == 0:
        # bpy.data.grease_pencils in 3.x and 5.x, grease_pencils_v3 in 4.3.
        # (Not `a or b`: an empty collection is false.)
        v3 = getattr(bpy.data, "grease_pencils_v3", None)
        (v3 if v3 is not None else bpy.data.grease_pencils).remove(pencil)
    if action is not None and action.users == 0:
        bpy.data.actions.remove(action)


def previous_results(source_name, target_name):
    return [obj for obj in bpy.data.objects
            if obj.get(ROLE) in ("result", "triangulation")
            and obj.get(SOURCE) == source_name and obj.get(TARGET) == target_name]


def new_result_object(context, created, name, data, origin, tags):
    """A new object `name` of `data` (recorded in created, so that a failed
    bake removes it), located at origin, with the custom properties `tags`,
    linked into the context's collection: what every kind of result starts as."""
    collection = context.collection or context.scene.collection
    obj = bpy.data.objects.new(name, data)
    created.objects.append(obj)
    created.names[obj] = name
    obj.location = origin
    for key, value in tags.items():
        obj[key] = value
    collection.objects.link(obj)
    return obj


def add_result_object(context, created, name, frames_world, edges, origin, frame_start, settings, size, tags,
                      report_progress=None):
    """A new object `name` (recorded in created) in the context's collection:
    a mesh with the given edges, located at origin, holding the frames
    (world space, (N, V, 3)) as absolute shape keys from frame_start, with
    the tubes if settings.renderable (radius settings.tube_radius of size)
    and the custom properties `tags`. The caller removes `created` on failure."""
    mesh = _new_mesh(name, np.asarray(frames_world[0], dtype=np.float64) - origin, edges)
    obj = new_result_object(context, created, name, mesh, origin, tags)
    bake_absolute_keys(obj, frames_world, frame_start, report_progress, origin)
    if settings.renderable:
        group, made = add_tubes(obj, core.tube_radius(size, settings.tube_radius))
        if made:
            created.node_group = group
    return obj


def build_result(context, source, target, prepared, morph, settings, report_progress=None, make_result=None):
    """Creates the result (and helper) objects from a computed morph, as
    settings (a core.BakeSettings) say: frame_start, renderable, tube_radius,
    show_triangulation. Returns (result object, Created). On failure
    everything created is removed and the exception re-raised.
    make_result(created, name, origin, tags): makes the result object
    instead of the mesh with shape keys (a Grease Pencil result, issue 32:
    drawing_io.build_grease_pencil_result, which needs this module)."""
    created = Created()
    collection = context.collection or context.scene.collection
    name = core.result_name(source.name, target.name)
    origin = prepared.plane.origin
    tags = {ROLE: "result", SOURCE: source.name, TARGET: target.name}
    try:
        if make_result is not None:
            obj = make_result(created, name, origin, tags)
        else:
            # The matched figure's m vertices and edges (by index, the source's).
            obj = add_result_object(context, created, name, morph.frames_world, prepared.edges, origin,
                                    settings.frame_start, settings, prepared.size, tags, report_progress)
        if prepared.matching.matched and make_result is None:
            _add_vertex_attribute(obj.data, SOURCE_VERTEX_ATTRIBUTE, prepared.matching.source_vertex)
            _add_vertex_attribute(obj.data, TARGET_VERTEX_ATTRIBUTE, prepared.matching.target_vertex)
        if settings.show_triangulation and morph.triangulation is not None:
            source_nodes, target_nodes, triangles = core.triangulation_world(morph.triangulation, prepared)
            helper_mesh = bpy.data.meshes.new(name + "_triangulation")
            helper_mesh.from_pydata((source_nodes - origin).tolist(), [], triangles.tolist())
            helper_mesh.update()
            helper = bpy.data.objects.new(name + "_triangulation", helper_mesh)
            created.objects.append(helper)
            created.names[helper] = name + "_triangulation"
            helper.location = origin
            helper[ROLE] = "triangulation"
            helper[SOURCE] = source.name
            helper[TARGET] = target.name
            helper.display_type = "WIRE"
            helper.hide_render = True
            collection.objects.link(helper)
            helper.shape_key_add(name="Source", from_mix=False)
            target_key = helper.shape_key_add(name="Target", from_mix=False)
            target_key.data.foreach_set("co", (target_nodes - origin).astype(np.float32).ravel())
    except BaseException:
        created.remove()
        raise
    return obj, created


def results_tagged(role, key, value):
    """The objects a bake made with ROLE `role` and the custom property key = value."""
    return [obj for obj in bpy.data.objects if obj.get(ROLE) == role and obj.get(key) == value]


def build_tagged_result(context, name, frames_world, edges, origin, frame_start, settings, size, tags):
    """(object, Created): add_result_object, everything removed again if it fails."""
    created = Created()
    try:
        obj = add_result_object(context, created, name, frames_world, edges, origin, frame_start, settings,
                                size, tags)
    except BaseException:
        created.remove()
        raise
    return obj, created


def replace_previous(previous, created):
    """Removes the previous results and gives the new objects their plain
    names, which the previous ones held."""
    for obj in previous:
        remove_result_object(obj)
    for obj, name in created.names.items():
        if obj.name != name and name not in bpy.data.objects:
            obj.name = name
            obj.data.name = name


def select_only(context, obj):
    for other in context.view_layer.objects:
        if other.select_get():
            other.select_set(False)
    obj.select_set(True)
    context.view_layer.objects.active = obj
