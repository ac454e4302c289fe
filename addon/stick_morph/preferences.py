"""Add-on preferences (the defaults of the bake options) and the sidebar's
per-scene settings: the property groups only.

The property definitions they share with the operator are properties.py's;
the Load Defaults operator is in operators.py with the others.
"""

import bpy
from bpy.props import FloatProperty, IntProperty, PointerProperty, StringProperty

from .common import FIGURE_TYPES
from .properties import (_DEFAULTS, MESH_OPTIONS, OPTION_NAMES, addon_preferences, bake_settings,  # noqa: F401
                         drawing_properties, key_pose_properties, mesh_option_properties, option_properties)


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


def _is_figure(self, obj):
    # Edge meshes, and (issue 32) Grease Pencil objects, curves and texts.
    return obj.type in FIGURE_TYPES


class StickMorphSceneSettings(bpy.types.PropertyGroup):
    """Per-scene choices of the sidebar panel and the last bake's statistics."""
    __annotations__ = {
        **option_properties(),
        # The delay group (issue 31): picked in the Local Timing sub-panel
        # from the source's vertex groups.
        **mesh_option_properties(),
        "source": PointerProperty(name="Source", type=bpy.types.Object, poll=_is_figure, options=set(),
                                  description="Edge mesh, Grease Pencil object or curve the morph starts from "
                                              "(empty: the selected non-active object)"),
        "target": PointerProperty(name="Target", type=bpy.types.Object, poll=_is_figure, options=set(),
                                  description="Edge mesh, Grease Pencil object or curve the morph ends at (empty: "
                                              "the active object); may be the source's Grease Pencil object, "
                                              "another layer or frame of it"),
        # Which drawing of a Grease Pencil source and target (issue 32):
        # the Drawing sub-panel.
        **drawing_properties(),
        "frame_start": IntProperty(name="Start", description="Frame showing the source",
                                   default=_DEFAULTS.frame_start, options=set()),
        # Bake Key Poses (sequence_operators.py): where its keys come from and
        # how they are timed; drawn in the Key Poses sub-panel.
        "key_collection": PointerProperty(
            name="Collection", type=bpy.types.Collection, options=set(),
            description="Take the mesh objects of this collection as the key poses, in its order "
                        "(empty: the selected meshes, ordered by name)"),
        **key_pose_properties(),
        "last_result": StringProperty(name="Last Result", options=set()),
        "last_vertices": IntProperty(name="Vertices", options=set()),
        "last_steiner": IntProperty(name="Steiner Vertices", options=set()),
        "last_frames": IntProperty(name="Frames", options=set()),
        # What the motion did (core.motion_summary), e.g. "Rigid guide: 28/28".
        "last_motion": StringProperty(name="Motion", options=set()),
        # How the pair was matched (core.correspondence_summary), e.g. "By index".
        "last_correspondence": StringProperty(name="Correspondence", options=set()),
        "last_milliseconds": FloatProperty(name="Milliseconds", options=set()),
        # The last bake's stages and their times, "read 12 ms, check 30 ms,
        # morph 3100 ms, build 900 ms" (engine against Blender, for the
        # benchmark; operators.Progress.summary()); the pair bake adds
        # "engine 2800 ms", the part of morph spent in the module's call.
        "last_stages": StringProperty(name="Stages", options=set()),
    }


classes = (StickMorphPreferences, StickMorphSceneSettings)


_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()
    bpy.types.Scene.stick_morph = PointerProperty(type=StickMorphSceneSettings)


def unregister():
    del bpy.types.Scene.stick_morph
    _unregister_classes()
