"""Registration, the preferences' defaults and the settings object a bake
reads from the operator (preferences.bake_settings, common.BakeSettings).

core.py's and common.py's own logic needs no Blender: tests/python/test_addon_core.py.
"""

import dataclasses

import bpy
import pytest

from conftest import addon_import


def test_registration_panel_and_defaults(scene, addon, addon_name):
    assert hasattr(bpy.types, "VIEW3D_PT_stick_morph")
    assert bpy.types.VIEW3D_PT_stick_morph.bl_category == "Stick Morph"
    prefs = bpy.context.preferences.addons[addon_name].preferences
    settings = scene.stick_morph
    saved = prefs.enclosure_sides
    prefs.enclosure_sides = 9
    try:
        assert bpy.ops.scene.stick_morph_load_defaults() == {"FINISHED"}
        assert settings.enclosure_sides == 9
    finally:
        prefs.enclosure_sides = saved
    # The operator shows in Object menu and its poll explains itself in Object Mode.
    assert bpy.ops.object.stick_morph_bake.poll()


def test_bake_settings_have_every_option_with_the_properties_defaults(scene, addon, addon_name):
    common = addon_import("common")
    preferences = addon_import("preferences")
    fields = [field.name for field in dataclasses.fields(common.BakeSettings)]
    # bake_settings reads OPTION_NAMES, MESH_OPTIONS (the delay group, issue
    # 31) and frame_start: a field outside them would silently keep its
    # default in every bake.
    assert sorted(fields) == sorted(preferences.OPTION_NAMES + preferences.MESH_OPTIONS + ("frame_start",))
    defaults = common.BakeSettings()
    holders = {
        "operator": bpy.ops.object.stick_morph_bake.get_rna_type().properties,
        "scene settings": scene.stick_morph.bl_rna.properties,
        "preferences": bpy.context.preferences.addons[addon_name].preferences.bl_rna.properties,
    }
    for where, properties in holders.items():
        for name in fields:
            if name in ("frame_start",) + preferences.MESH_OPTIONS and where == "preferences":
                assert name not in properties, (where, name)  # no preference: set per bake
                continue
            expected = getattr(defaults, name)
            got = properties[name].default
            if isinstance(expected, float):  # a FloatProperty holds a float32
                assert got == pytest.approx(expected, rel=1e-6), (where, name)
            else:
                assert got == expected and type(got) is type(expected), (where, name, got)


def test_renamed_enum_items_keep_their_order_and_defaults(scene, addon, addon_name):
    # Issue 27 renamed Correspondence AUTO to INDEX_OR_MATCH (the engine's
    # correspond="auto" is MATCH here) and Easing LINEAR / EASE_IN_OUT to
    # NONE / IN_OUT (the engine's easing names; LINEAR is a motion). A saved
    # file stores an enum's index, so the order and the defaults must stay.
    holders = {
        "operator": bpy.ops.object.stick_morph_bake.get_rna_type().properties,
        "scene settings": scene.stick_morph.bl_rna.properties,
        "preferences": bpy.context.preferences.addons[addon_name].preferences.bl_rna.properties,
    }
    for where, properties in holders.items():
        correspondence, easing = properties["correspondence"], properties["easing"]
        assert [item.identifier for item in correspondence.enum_items] == ["INDEX_OR_MATCH", "INDEX", "MATCH"], where
        assert [item.name for item in correspondence.enum_items] == ["Automatic", "By Index", "By Shape"], where
        assert correspondence.default == "INDEX_OR_MATCH", where
        assert [item.identifier for item in easing.enum_items] == ["NONE", "IN_OUT"], where
        assert [item.name for item in easing.enum_items] == ["Linear", "Ease In-Out"], where
        assert easing.default == "NONE", where


def test_bake_settings_read_each_option_from_its_property(addon):
    preferences = addon_import("preferences")
    # A distinct value per property: a field read from the wrong one shows.
    names = preferences.OPTION_NAMES + preferences.MESH_OPTIONS + ("frame_start",)
    holder = type("Holder", (), {name: f"value of {name}" for name in names})()
    settings = preferences.bake_settings(holder)
    assert dataclasses.asdict(settings) == {name: f"value of {name}" for name in names}
    # And from the operator as it runs: the redo panel's values.
    op = bpy.context.window_manager.operator_properties_last("object.stick_morph_bake")
    assert dataclasses.asdict(preferences.bake_settings(op)) == {name: getattr(op, name) for name in names}


def test_property_ranges_and_help_texts_are_the_engines_limits(scene, addon, addon_name):
    # Registered from common.ENGINE_LIMITS (the module may be missing then);
    # here the module is loaded, so compare with what the engine enforces.
    limits = addon_import("core").load_engine().limits
    holders = {
        "operator": bpy.ops.object.stick_morph_bake.get_rna_type().properties,
        "scene settings": scene.stick_morph.bl_rna.properties,
        "preferences": bpy.context.preferences.addons[addon_name].preferences.bl_rna.properties,
    }
    for where, properties in holders.items():
        for name, option in (("frame_count", "frames"), ("enclosure_sides", "enclosure_sides")):
            prop = properties[name]
            least, most = limits[f"min_{option}"], limits[f"max_{option}"]
            assert (prop.hard_min, prop.hard_max) == (least, most), (where, name)
            assert f"({least} to {most})" in prop.description, (where, name, prop.description)
        # The rigid motion's extra turns, either way.
        prop = properties["turns"]
        most = limits["max_turns"]
        assert (prop.hard_min, prop.hard_max, prop.default) == (-most, most, 0), where
        assert f"({-most} to {most})" in prop.description, (where, prop.description)
