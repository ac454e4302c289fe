"""Add-on preferences: the defaults of the bake options.

The option properties are defined once here (option_properties) and shared by
the preferences, the operator and the sidebar's per-scene settings.

Every property is defined with options=set(), i.e. not ANIMATABLE: these are
settings, not animation channels, and an animatable property gets a keyframe
dot (and an "Insert Keyframe" entry) next to it in every property-split
layout. Names are short enough for the sidebar's label column at its default
width in 3.4 (ui.py); the descriptions say the rest.
"""

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty, StringProperty

from . import common

# The options copied from the preferences into an operator call (when the
# caller did not set them) and into the scene settings (Load Defaults): the
# fields of common.BakeSettings but frame_start, which has no preference.
OPTION_NAMES = ("motion", "correspondence", "rotation", "turns", "frame_count", "steiner", "weights",
                "enclosure_sides", "plane", "easing", "renderable", "tube_radius", "show_triangulation",
                "planarity_tolerance", "set_frame_range")

# The properties' defaults, defined once (common.BakeSettings).
_DEFAULTS = common.BakeSettings()

# The engine's ranges: registration may run without the native module, so
# from common's copy of stickmorph.limits.
_LIMITS = common.ENGINE_LIMITS


def bake_settings(data):
    """The bake options of the operator (any holder of option_properties and
    frame_start) as the one object core and baking take: read once per bake."""
    return common.BakeSettings(frame_start=data.frame_start,
                               **{name: getattr(data, name) for name in OPTION_NAMES})


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
            items=(("AUTO", "Automatic",
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
            items=(("LINEAR", "Linear", "Constant speed (for Rigid motion: even speed along the motion)"),
                   ("EASE_IN_OUT", "Ease In-Out", "Slow at the start and the end (smoothstep)")),
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
    }


def addon_preferences(context):
    addon = context.preferences.addons.get(__package__)
    return addon.preferences if addon is not None else None


class StickMorphPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__
    __annotations__ = option_properties()

    def draw(self, context):
        layout = self.layout
        from . import ui
        ui.draw_dependency_box(layout, context)
        layout.label(text="Defaults of the Stick Morph bake options:")
        layout.use_property_split = True
        layout.use_property_decorate = False
        for name in OPTION_NAMES:
            layout.prop(self, name)


def _is_mesh(self, obj):
    return obj.type == "MESH"


class StickMorphSceneSettings(bpy.types.PropertyGroup):
    """Per-scene choices of the sidebar panel and the last bake's statistics."""
    __annotations__ = {
        **option_properties(),
        "source": PointerProperty(name="Source", type=bpy.types.Object, poll=_is_mesh, options=set(),
                                  description="Edge mesh the morph starts from (empty: the selected non-active mesh)"),
        "target": PointerProperty(name="Target", type=bpy.types.Object, poll=_is_mesh, options=set(),
                                  description="Edge mesh the morph ends at (empty: the active object)"),
        "frame_start": IntProperty(name="Start", description="Frame showing the source",
                                   default=_DEFAULTS.frame_start, options=set()),
        "last_result": StringProperty(name="Last Result", options=set()),
        "last_vertices": IntProperty(name="Vertices", options=set()),
        "last_steiner": IntProperty(name="Steiner Vertices", options=set()),
        "last_frames": IntProperty(name="Frames", options=set()),
        # What the motion did (core.motion_summary), e.g. "Rigid guide: 28/28".
        "last_motion": StringProperty(name="Motion", options=set()),
        # How the pair was matched (core.correspondence_summary), e.g. "By index".
        "last_correspondence": StringProperty(name="Correspondence", options=set()),
        "last_milliseconds": FloatProperty(name="Milliseconds", options=set()),
    }


class STICKMORPH_OT_load_defaults(bpy.types.Operator):
    """Copy the add-on preferences' defaults into this scene's Stick Morph options"""
    bl_idname = "scene.stick_morph_load_defaults"
    bl_label = "Load Defaults"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        prefs = addon_preferences(context)
        if prefs is None:
            self.report({"ERROR"}, "Stick Morph preferences are not available")
            return {"CANCELLED"}
        settings = context.scene.stick_morph
        for name in OPTION_NAMES:
            setattr(settings, name, getattr(prefs, name))
        return {"FINISHED"}


classes = (StickMorphPreferences, StickMorphSceneSettings, STICKMORPH_OT_load_defaults)


_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()
    bpy.types.Scene.stick_morph = PointerProperty(type=StickMorphSceneSettings)


def unregister():
    del bpy.types.Scene.stick_morph
    _unregister_classes()
