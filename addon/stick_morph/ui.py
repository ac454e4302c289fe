"""The sidebar panel: View3D > Sidebar > Stick Morph."""

import bpy

from .preferences import OPTION_NAMES


class VIEW3D_PT_stick_morph(bpy.types.Panel):
    bl_label = "Stick Morph"
    bl_idname = "VIEW3D_PT_stick_morph"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Stick Morph"

    def draw(self, context):
        layout = self.layout
        settings = context.scene.stick_morph
        column = layout.column(align=True)
        column.prop(settings, "source")
        column.prop(settings, "target")
        if settings.source is None and settings.target is None:
            layout.label(text="Empty: selected mesh -> active mesh", icon="INFO")

        box = layout.box()
        box.use_property_split = True
        box.prop(settings, "frame_start")
        for name in OPTION_NAMES:
            box.prop(settings, name)
        box.operator("scene.stick_morph_load_defaults", icon="LOOP_BACK")

        op = layout.operator("object.stick_morph_bake", icon="MOD_SIMPLEDEFORM")
        op.source = settings.source.name if settings.source else ""
        op.target = settings.target.name if settings.target else ""
        op.frame_start = settings.frame_start
        for name in OPTION_NAMES:
            setattr(op, name, getattr(settings, name))

        if settings.last_result:
            box = layout.box()
            box.label(text=f"Last: {settings.last_result}")
            box.label(text=f"{settings.last_vertices} vertices, {settings.last_steiner} Steiner")
            box.label(text=f"{settings.last_frames} frames, {settings.last_milliseconds:.0f} ms")


classes = (VIEW3D_PT_stick_morph,)


register, unregister = bpy.utils.register_classes_factory(classes)
