"""What the operators and the sidebar panel both ask of Blender's state: the
dependency check's cached status, the source and target a bake would use,
the meshes in Edit Mode.

In a module of their own so that ui.py reads them without importing
operators.py (which imports ui.py for the redo panel): the add-on's import
graph has no cycle (tests/python/test_addon_imports.py).
"""

import os

import bpy

from . import dependencies
from .common import FIGURE_TYPES, GREASE_PENCIL_TYPES, StickMorphError

PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))

# The status of the last dependency check (set by register(), refreshed by a
# bake that finds it failing); the panel shows it.
_status = None


def dependency_status(refresh=False, force=False):
    """dependencies.check() of this package, cached: importing a missing
    module again on every redraw of the panel would cost a file system scan.
    refresh: check again if the last check failed; force: check again."""
    global _status
    if force or _status is None or (refresh and not _status.ok):
        _status = dependencies.check(PACKAGE_DIR, __package__, bpy.app.binary_path or None)
    return _status


def resolve_pair(context, source_name, target_name):
    """The source and target objects, from the names or else the selection
    (the target is the active object). The panel's preview calls this too, so
    it shows exactly what a bake would use. Raises StickMorphError."""
    def named(name, role):
        obj = bpy.data.objects.get(name)
        if obj is None:
            raise StickMorphError(f"there is no object named '{name}' ({role})")
        return obj

    if source_name or target_name:
        if not (source_name and target_name):
            raise StickMorphError("give both source and target, or neither (then the "
                                  "selection is used)")
        source, target = named(source_name, "source"), named(target_name, "target")
    else:
        selected = list(context.selected_objects)
        active = context.active_object
        if len(selected) != 2 or active not in selected:
            raise StickMorphError(
                f"select two mesh objects, the target last (active); {len(selected)} selected"
                + ("" if active in selected or not selected else ", none of them active"))
        target = active
        source = selected[0] if selected[1] == active else selected[1]
    for obj, role in ((source, "source"), (target, "target")):
        if obj.type not in FIGURE_TYPES:
            raise StickMorphError(
                f"not two mesh objects (nor Grease Pencil objects or curves): the {role} '{obj.name}' is a "
                f"{obj.type.lower()}, not a mesh, a Grease Pencil object or a curve")
    # One Grease Pencil object may hold both drawings (two layers, or two
    # keyframes of a layer: the Drawing panel's Source and Target Layer and
    # Frame say which; drawing_io.read_pair refuses the same drawing twice).
    if source == target and source.type not in GREASE_PENCIL_TYPES:
        raise StickMorphError(f"source and target are the same object '{source.name}'")
    return source, target


def edited_meshes(context):
    """The mesh objects in Edit Mode (multi-object editing), in the order
    Blender lists them."""
    return [obj for obj in (getattr(context, "objects_in_mode", None) or ()) if obj.type == "MESH"]
