"""The bake options as Blender properties: defined once here and read by the
preferences, the operator and the sidebar's per-scene settings.

The data (defaults, limits, which motion uses which option) comes from
common.py, which imports without bpy; this module adds only the property
definitions and imports no other module of the add-on that has bpy classes,
so that preferences.py, operators.py and ui.py can all read it without
importing each other (tests/python/test_addon_imports.py keeps the import
graph free of cycles).

Every property is defined with options=set(), i.e. not ANIMATABLE: these are
settings, not animation channels, and an animatable property gets a keyframe
dot (and an "Insert Keyframe" entry) next to it in every property-split
layout. Names are short enough for the sidebar's label column at its default
width in 3.4 (ui.py); the descriptions say the rest.
"""

from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, StringProperty

from . import common

# The options copied from the preferences into an operator call (when the
# caller did not set them) and into the scene settings (Load Defaults): the
# fields of common.BakeSettings but frame_start and MESH_OPTIONS, which have
# no preference.
OPTION_NAMES = ("motion", "correspondence", "rotation", "turns", "frame_count", "steiner", "weights",
                "enclosure_sides", "plane", "easing", "renderable", "tube_radius", "show_triangulation",
                "planarity_tolerance", "set_frame_range", "overlap", "output", "clean_tolerance")

# Which drawing of a Grease Pencil source or target a pair bake reads (issue
# 32), and whether its selected points are pins: like source and target,
# choices of the pair's data, not options of the morph (no preference, not
# in BakeSettings: drawing_io.drawing_choices reads them); the operator and
# the scene settings have them (drawing_properties), the Drawing sub-panel
# draws them.
DRAWING_OPTIONS = ("source_layer", "source_frame", "target_layer", "target_frame", "pin_selected")

# The options that name data of the meshes (issue 31's delay group, a vertex
# group of the source): like frame_start, no preference (a default group
# name would refuse every mesh without that group); the operators, the
# scene settings and BakeSettings have them (mesh_option_properties).
MESH_OPTIONS = ("delay_group",)

# The options of Bake Key Poses (sequence_operators.py): motion and easing
# too, so that a setting key poses cannot follow is refused with a report,
# not ignored (the panel passes the scene's). Rebake Shape Keys: one mesh,
# by index, Rigid.
SEQUENCE_OPTIONS = ("motion", "correspondence", "rotation", "turns", "steiner", "weights", "enclosure_sides",
                    "plane", "easing", "renderable", "tube_radius", "planarity_tolerance", "set_frame_range",
                    "overlap")
REBAKE_OPTIONS = ("rotation", "turns", "steiner", "weights", "enclosure_sides", "plane", "easing", "renderable",
                  "tube_radius", "planarity_tolerance", "set_frame_range", "overlap")

# The properties' defaults, defined once (common.BakeSettings).
_DEFAULTS = common.BakeSettings()

# The engine's ranges: registration may run without the native module, so
# from common's copy of stickmorph.limits.
_LIMITS = common.ENGINE_LIMITS

# The Overlap slider's largest value: the engine takes [0, 1), and near 1 a
# lagging part would wait for almost the whole motion and then jump.
OVERLAP_MAX = 0.95


def bake_settings(data):
    """The bake options of the operator (any holder of option_properties,
    mesh_option_properties and frame_start) as the one object core and
    baking take: read once per bake."""
    return common.BakeSettings(frame_start=data.frame_start,
                               **{name: getattr(data, name) for name in OPTION_NAMES + MESH_OPTIONS})


def option_properties():
    """Fresh property definitions for the bake options (a dict for __annotations__)."""
    defaults = _DEFAULTS
    return {
        "motion": EnumProperty(
            name="Motion", description="How the figure moves from the source to the target",
            items=(("RIGID", "Rigid",
                    "As rigid as possible: edges keep their lengths wherever they can, the figure turns "
                    "as a whole and moves at even speed; it never crosses itself"),
                   ("BARYCENTRIC", "Barycentric",
                    "The paper's morph (Floater-Gotsman): it never crosses itself, but edges stretch "
                    "and shrink and the speed is uneven"),
                   ("LINEAR", "Linear",
                    "Every vertex on a straight line: the simplest motion, but the figure may cross "
                    "itself (the bake warns, naming the frames)")),
            default=defaults.motion, options=set()),
        "correspondence": EnumProperty(
            name="Correspondence",
            description="Which vertex of the target each vertex of the source becomes",
            # The panel's label is "Match" (ui.py): item names read after it.
            items=(("INDEX_OR_MATCH", "Automatic",
                    "By index when the meshes have the same vertices and edges and are compatible that way; "
                    "otherwise matched by shape"),
                   ("INDEX", "By Index",
                    "Vertex i of the source becomes vertex i of the target: the meshes need the same vertex "
                    "count and edges (a target made by editing a copy of the source)"),
                   ("MATCH", "By Shape",
                    "Matched by shape, for meshes drawn separately: vertex counts, numbering and edges may "
                    "differ; a vertex without a partner gets one on the other mesh's edge; pins (vertex "
                    "groups pin.*) are respected")),
            default=defaults.correspondence, options=set()),
        "rotation": EnumProperty(
            name="Rotation",
            description="Which way the figure turns as a whole on its way to the target "
                        "(Rigid motion only)",
            # Item names of at most 11 characters: "Counterclockwise" is cut
            # in the sidebar's value column at 3.4's default width.
            items=(("SHORT", "Short Way", "The smaller turn, whichever way that is"),
                   ("CCW", "Left (CCW)",
                    "Counterclockwise as the plane is seen, even when that is the long way round"),
                   ("CW", "Right (CW)",
                    "Clockwise as the plane is seen, even when that is the long way round")),
            default=defaults.rotation, options=set()),
        "turns": IntProperty(
            name="Extra Turns",
            description="Whole turns added to the figure's rotation, positive counterclockwise, negative "
                        f"clockwise; Rigid motion only ({-_LIMITS['max_turns']} to {_LIMITS['max_turns']})",
            default=defaults.turns, options=set(), min=-_LIMITS["max_turns"], max=_LIMITS["max_turns"],
            soft_min=-10, soft_max=10),
        "frame_count": IntProperty(
            name="Frames",
            description="Number of frames of the morph, source and target included "
                        f"({_LIMITS['min_frames']} to {_LIMITS['max_frames']})",
            default=defaults.frame_count, options=set(), min=_LIMITS["min_frames"], max=_LIMITS["max_frames"],
            soft_max=1000),
        "steiner": EnumProperty(
            name="Steiner",
            description="How the compatible triangulation places Steiner vertices (not for Linear motion)",
            items=(("improved", "Improved", "Fewest Steiner vertices (section 4.2 and further)"),
                   ("sg2001", "SG2001", "The reduced spiderweb of Surazhsky & Gotsman 2001"),
                   ("aronov", "Aronov", "The universal spiderweb of Aronov, Seidel & Souvaine")),
            default=defaults.steiner, options=set()),
        "weights": EnumProperty(
            name="Weights",
            description="Convex-combination weights of the Floater-Gotsman morph (not for Linear motion)",
            items=(("mvc", "Mean Value", "Mean value coordinates"),
                   ("uniform", "Uniform", "Uniform (Tutte) weights"),
                   ("floater", "Floater", "Floater's shape-preserving weights")),
            default=defaults.weights, options=set()),
        "enclosure_sides": IntProperty(
            name="Enclosure Sides",
            description="Sides of the regular polygon enclosing both figures; not for Linear motion "
                        f"({_LIMITS['min_enclosure_sides']} to {_LIMITS['max_enclosure_sides']})",
            default=defaults.enclosure_sides, options=set(), min=_LIMITS["min_enclosure_sides"],
            max=_LIMITS["max_enclosure_sides"], soft_max=64),
        "plane": EnumProperty(
            name="Plane", description="The plane the figures are drawn in",
            items=(("AUTO", "Auto", "The best-fit plane of both meshes"),
                   ("XY", "XY", "The XY plane (seen from above)"),
                   ("XZ", "XZ", "The XZ plane (seen from the front)"),
                   ("YZ", "YZ", "The YZ plane (seen from the right)")),
            default=defaults.plane, options=set()),
        "easing": EnumProperty(
            name="Easing", description="How the speed changes over the morph",
            items=(("NONE", "Linear", "Constant speed (for Rigid motion: even speed along the motion)"),
                   ("IN_OUT", "Ease In-Out", "Slow at the start and the end (smoothstep)")),
            default=defaults.easing, options=set()),
        "renderable": BoolProperty(
            name="Renderable", description="Give the edges geometry (Geometry Nodes tubes) so that they render",
            default=defaults.renderable, options=set()),
        "tube_radius": FloatProperty(
            name="Tube Radius", description="Tube radius as a fraction of the figures' size",
            default=defaults.tube_radius, options=set(), min=1e-5, max=1.0, soft_max=0.1, precision=4),
        "show_triangulation": BoolProperty(
            name="Show Triangulation",
            description="Add a wireframe helper object with the compatible triangulation "
                        "(source shape, with a Target shape key; not for Linear motion)",
            default=defaults.show_triangulation, options=set()),
        "planarity_tolerance": FloatProperty(
            name="Planarity Tolerance",
            description="Largest allowed distance of a vertex from the plane, as a fraction of the figures' size",
            default=defaults.planarity_tolerance, options=set(), min=0.0, max=0.5, precision=6),
        "set_frame_range": BoolProperty(
            name="Set Frame Range", description="Set the scene's frame range to the morph's frames",
            default=defaults.set_frame_range, options=set()),
        # Local timing (issue 31), with the delay group (mesh_option_properties).
        "overlap": FloatProperty(
            name="Overlap",
            description="With a Delay Group: how far the parts of weight 1 lag those of weight 0, as a fraction "
                        "of the motion (0: no lag, the plain morph); Rigid motion only",
            default=defaults.overlap, options=set(), min=0.0, max=OVERLAP_MAX, subtype="FACTOR", precision=3),
        # Drawings (issue 32).
        "output": EnumProperty(
            name="Output", description="What the bake makes",
            items=(("AUTO", "Auto",
                    "Grease Pencil for a Grease Pencil source, otherwise a mesh with shape keys (and its tube)"),
                   ("MESH", "Mesh", "A mesh with one shape key per frame (and its tube with Renderable)"),
                   ("GREASE_PENCIL", "Grease Pencil",
                    "A Grease Pencil object with one drawing per frame, with the source's materials and "
                    "stroke thickness (a mesh or curve source: black strokes of the Tube Radius)")),
            default=defaults.output, options=set()),
        "clean_tolerance": FloatProperty(
            name="Clean Tolerance",
            description="Grease Pencil and curve figures are cleaned into stick figures: stroke ends this close "
                        "to a stroke snap onto it, crossings become junctions (the bake reports every change). "
                        "A fraction of the drawing's size; 0: the default, 0.01. Meshes are not cleaned",
            default=defaults.clean_tolerance, options=set(), min=0.0, max=0.2, soft_max=0.05, precision=4),
    }


def mesh_option_properties():
    """Fresh definitions of MESH_OPTIONS (the operators and the scene
    settings; not the preferences)."""
    return {
        "delay_group": StringProperty(
            name="Delay Group", default=_DEFAULTS.delay_group, options=set(),
            description="Local timing: a vertex group of the source mesh (for key poses, of the first key) whose "
                        "weights say which parts lag: weight 0 leads, weight 1 lags by Overlap; vertices not in "
                        "the group weigh 0 (empty: every part on the same clock). Paint it in Weight Paint mode; "
                        "Rigid motion only"),
    }


def drawing_properties(options=frozenset()):
    """Fresh definitions of DRAWING_OPTIONS (the pair bake and the scene
    settings; not the preferences: they name the pair's data). options: the
    properties' options (the operator's are SKIP_SAVE)."""
    options = set(options)

    def layer(role):
        return StringProperty(
            name=f"{role.title()} Layer", default="", options=options,
            description=f"The Grease Pencil layer of the {role} to morph (empty: the active layer)")

    def frame(role):
        return IntProperty(
            name=f"{role.title()} Frame", default=0, options=options,
            description=f"The {role}'s drawing shown at this frame (its last keyframe at or before it); "
                        "0: the drawing shown at the current frame")

    return {
        "source_layer": layer("source"), "source_frame": frame("source"),
        "target_layer": layer("target"), "target_frame": frame("target"),
        "pin_selected": BoolProperty(
            name="Pin Selected Points", default=False, options=options,
            description="Grease Pencil source and target: the selected points pin the matching, the first "
                        "selected point of the source (in drawing order) to the first of the target, and so on"),
    }


def key_pose_properties():
    """Fresh definitions of the key-pose operators' own timing options (the
    operators and the scene's settings for the Key Poses sub-panel)."""
    return {
        "frame_step": IntProperty(
            name="Frames Between Keys", default=24, min=1, max=10000, soft_max=500, options=set(),
            description="Frames from one key to the next when the keys have no key frames of their own; "
                        "with Loop also from the last key back to the first"),
        "loop": BoolProperty(name="Loop", default=False, options=set(),
                             description="After the last key return smoothly to the first"),
        "hold": BoolProperty(name="Hold at Keys", default=False, options=set(),
                             description="Stop the motion at every key (otherwise it passes through the keys at "
                                         "continuous speed; Rebake Shape Keys always holds a pose repeated at "
                                         "the next keyframe)"),
    }


def addon_preferences(context):
    addon = context.preferences.addons.get(__package__)
    return addon.preferences if addon is not None else None
