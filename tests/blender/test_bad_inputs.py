"""The bad-input catalogue (tests/data/bad_inputs/catalogue.json) at the add-on.

Every kind whose Blender entry is not a `skip` becomes two meshes (or a
selection, or operator arguments); the bake operator must be cancelled with
an ERROR report holding the catalogue's fragments, and the scene must be
exactly as before. Kinds that Blender's own property system refuses
(`rejected_by_rna`: an unknown enum value) must be refused before the
operator runs, also leaving the scene unchanged.
"""

import json
import math
import os

import bpy
import numpy as np
import pytest

from conftest import make_mesh_object, select, snapshot

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(ROOT, "tests", "data")
with open(os.path.join(DATA, "bad_inputs", "catalogue.json")) as _file:
    CATALOGUE = json.load(_file)
KINDS = {kind["id"]: kind for kind in CATALOGUE["kinds"] if "skip" not in kind["blender"]}


def decode(value):
    if isinstance(value, list):
        return [decode(v) for v in value]
    if isinstance(value, dict) and "$float" in value:
        return float(value["$float"])
    return value


def read_json(*parts):
    with open(os.path.join(DATA, *parts)) as file:
        return json.load(file)


def figure_for(kind, spec):
    """(xy, z, edges, faces) of one mesh of a kind's Blender entry."""
    if "file" in spec:
        if spec["file"] == "self":
            document = read_json(kind["input"]["file"])
        else:
            document = read_json("pairs", f"{kind['input']['pair']}.{spec['file']}.json")
        return document["vertices"], None, document["edges"], ()
    if "xyz" in spec:
        xyz = decode(spec["xyz"])
        return [p[:2] for p in xyz], [p[2] for p in xyz], spec.get("edges", []), spec.get("faces", ())
    xy = spec["xy"] if spec["xy"] else np.zeros((0, 2))
    return xy, None, spec.get("edges", []), [tuple(f) for f in spec.get("faces", ())]


def build_scene(kind):
    spec = kind["blender"]
    objects = {}
    for role, name in (("source", "Source"), ("target", "Target")):
        xy, z, edges, faces = figure_for(kind, spec[role])
        objects[name] = make_mesh_object(name, xy, edges, faces=faces, z=z)
    if spec.get("extra") == "Camera":
        camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
        bpy.context.scene.collection.objects.link(camera)
        objects["Camera"] = camera
    bpy.context.view_layer.update()
    select(*(objects[name] for name in spec.get("select", ["Source", "Target"])))


@pytest.mark.parametrize("kind_id", sorted(KINDS))
def test_bad_input_is_an_error_report_and_changes_nothing(scene, addon, kind_id):
    kind = KINDS[kind_id]
    spec = kind["blender"]
    build_scene(kind)
    before = snapshot()
    if "rejected_by_rna" in spec:
        with pytest.raises(TypeError) as error:
            bpy.ops.object.stick_morph_bake(**spec.get("operator", {}))
        assert spec["rejected_by_rna"] in str(error.value)
    else:
        with pytest.raises(RuntimeError) as error:
            bpy.ops.object.stick_morph_bake(**spec.get("operator", {}))
        message = str(error.value)
        assert message.startswith("Error:") and "Stick Morph: " in message, message
        assert "Traceback" not in message
        for fragment in spec["message"]:
            assert fragment in message, (fragment, message)
    # Blender turns an ERROR report into this RuntimeError; a cancelled
    # operator that created anything would show here.
    assert snapshot() == before, "the scene changed"


def test_decode_infinity():
    assert decode([{"$float": "inf"}, 1]) == [math.inf, 1]
