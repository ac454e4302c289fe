"""Stick Morph: bake self-intersection-free morphs of planar stick figures.

Select two edge meshes (the target active), then Object > Bake Stick Morph
or View3D > Sidebar > Stick Morph. They may share their vertices and edges
(vertex i of one is vertex i of the other) or be drawn separately (they are
matched by shape, steered by pins: vertex groups pin.* in both). The result
is a new object whose absolute shape keys hold the morph of Surazhsky &
Gotsman (2001), computed by the bundled native `stickmorph` module. Grease
Pencil drawings and curves work too (issue 32): cleaned into stick figures
first (every change reported), and a Grease Pencil source bakes into a
Grease Pencil object with one drawing per frame.

This file imports no bpy-dependent module at import time, so `core` can be
imported outside Blender (tests, tools).

Registration never fails for a missing numpy or a native module built for
another Python: register() only checks them (dependencies.check, which
catches ImportError and OSError); the sidebar panel and the preferences then
say what is missing and how to rebuild, and a bake reports it as an ERROR.
"""

bl_info = {
    "name": "Stick Morph",
    "author": "stickmorph",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > Stick Morph; Object > Bake Stick Morph",
    "description": "Morph planar stick figures (edge meshes, Grease Pencil drawings, curves) without "
                   "self-intersection, baked to shape keys or Grease Pencil drawings",
    "category": "Animation",
}

_modules = ()


def _menu(self, context):
    self.layout.operator("object.stick_morph_bake")
    self.layout.operator("object.stick_morph_bake_sequence")
    self.layout.operator("object.stick_morph_rebake_shape_keys")


def register():
    global _modules
    import bpy
    # None of these import numpy or the native module at import time.
    from . import helpers, operators, preferences, sequence_operators, ui
    _modules = (preferences, operators, sequence_operators, ui)
    for module in _modules:
        module.register()
    bpy.types.VIEW3D_MT_object.append(_menu)
    status = helpers.dependency_status(force=True)
    if not status.ok:
        # The console too: enabling from a script shows no panel.
        print(f"Stick Morph: {status.message()}")


def unregister():
    global _modules
    import bpy
    bpy.types.VIEW3D_MT_object.remove(_menu)
    for module in reversed(_modules):
        module.unregister()
    _modules = ()
