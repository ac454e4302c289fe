"""Build the drawing samples of issue 32 in blend_samples/drawings/.

Run inside Blender (3.4, as make_samples.py; its Grease Pencil is the legacy
one, which Blender 4.3 and 5.2 convert when they open the file):

    blender -b --factory-startup --python-exit-code 1 \
        --python blend_samples/make_drawings.py -- [--output-dir blend_samples/drawings]

It writes
  - stick_figure_gp.blend: a stick figure drawn twice in Grease Pencil, as a
    person would draw it: a head (a closed stroke), a torso whose top stops
    short of the head, one stroke for both arms crossing the torso, one for
    the legs that the torso's bottom end stops short of, every point with a
    little hand-drawn jitter and the pen pressure varying along the stroke.
    Two objects, stick_pose_a (arms out) and stick_pose_b (arms up, a step),
    each with the layer "Lines" and one keyframe at frame 1, the head in the
    material "Head Red", the rest in "Ink"; the scene's Stick Morph settings
    name the pair (Output Auto: Grease Pencil).
  - letters_curves.blend: the letters D and O as curve objects (text
    converted to curves: an outline with a hole, two nested loops each),
    letter_D and letter_O, named by the scene's Stick Morph settings (Output
    Auto: a mesh with its tube).
Both have an orthographic camera looking at the figures (from the front for
the drawings in the XZ plane, from above for the letters in XY), Workbench at
960x540, frames 1 to 60. The strokes come from stick_figure_strokes (a fixed
seed), so rebuilding gives the same files; tests/blender/test_drawings.py
uses the same functions and files.
"""

import argparse
import math
import os
import random
import sys

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
DRAWINGS_DIR = "drawings"
STICK_NAME = "stick_figure_gp"
LETTERS_NAME = "letters_curves"
POSES = ("stick_pose_a", "stick_pose_b")
LETTERS = (("letter_D", "D"), ("letter_O", "O"))
LAYER = "Lines"
MATERIALS = (("Ink", (0.02, 0.02, 0.03, 1.0)), ("Head Red", (0.6, 0.05, 0.05, 1.0)))
LINE_WIDTH = 30  # legacy pixels: a radius of 0.015 at full pressure in 4.3 (line_width * pressure / 2000)
SPACING = 0.08  # about the distance between a drawn stroke's points
JITTER = 0.003  # hand-drawn wobble, about 0.1% of the figure's height
RESOLUTION = (960, 540)
WORLD_GRAY = (0.8, 0.8, 0.8)
FRAMES = (1, 60)


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="make_drawings.py", description=__doc__.splitlines()[0])
    parser.add_argument("--output-dir", default=os.path.join(HERE, DRAWINGS_DIR))
    return parser.parse_args(argv)


# ------------------------------------------------------------- strokes ----

def _polyline(corners, spacing=SPACING):
    """Points along a polyline, about `spacing` apart, corners kept."""
    points = [corners[0]]
    for (x0, z0), (x1, z1) in zip(corners, corners[1:]):
        steps = max(1, int(round(math.hypot(x1 - x0, z1 - z0) / spacing)))
        points += [(x0 + (x1 - x0) * k / steps, z0 + (z1 - z0) * k / steps) for k in range(1, steps + 1)]
    return points


def _circle(centre, radius, count):
    cx, cz = centre
    # From the bottom, counter-clockwise, as a pen would start a head.
    return [(cx + radius * math.sin(2 * math.pi * k / count), cz - radius * math.cos(2 * math.pi * k / count))
            for k in range(count)]


# (head centre, head radius, torso top, torso bottom, arm corners, leg corners), in the XZ plane.
# The torso's top stops 0.012 short of the head's bottom, its bottom about 0.015 short of the
# legs' corner: ends that stop short, which the cleaning snaps on (the default tolerance is 1%
# of the drawing's size, about 0.024). The arms cross the torso once.
POSE_SHAPES = {
    "stick_pose_a": ((0.0, 1.78), 0.26, (0.0, 1.508), (0.01, 0.612),
                     [(-0.62, 1.05), (0.62, 1.25)], [(-0.38, 0.0), (0.0, 0.60), (0.40, 0.0)]),
    "stick_pose_b": ((0.15, 1.75), 0.25, (0.13, 1.488), (0.01, 0.632),
                     [(-0.6, 1.55), (0.06, 1.2), (0.68, 1.5)], [(-0.5, 0.02), (0.02, 0.62), (0.3, 0.05)]),
}


def stick_figure_strokes(pose, seed=32):
    """The strokes of a pose, [(points [(x, z), ...], cyclic, material index,
    pressures), ...]: head, torso, arms, legs, each point jittered."""
    head_centre, head_radius, top, bottom, arms, legs = POSE_SHAPES[pose]
    rng = random.Random(f"{seed}-{pose}")
    shapes = [(_circle(head_centre, head_radius, 20), True, 1),
              (_polyline([top, bottom]), False, 0),
              (_polyline(arms), False, 0),
              (_polyline(legs), False, 0)]
    strokes = []
    for points, cyclic, material in shapes:
        last = len(points) - 1
        jittered = [(x + rng.uniform(-JITTER, JITTER), z + rng.uniform(-JITTER, JITTER)) if 0 < k < last or cyclic
                    else (x, z) for k, (x, z) in enumerate(points)]
        # A pen presses harder in the middle of a stroke.
        pressures = [0.55 + 0.45 * math.sin(math.pi * (k + 0.5) / len(points)) for k in range(len(points))]
        strokes.append((jittered, cyclic, material, pressures))
    return strokes


# ------------------------------------------------------- Grease Pencil ----

def grease_pencil_data(name):
    """New Grease Pencil data of this Blender: legacy before 4.3 (bpy.data.grease_pencils),
    v3 in 4.3 (grease_pencils_v3) and 5.x (grease_pencils)."""
    collection = getattr(bpy.data, "grease_pencils_v3", None)  # not `or`: an empty collection is false
    if collection is None:
        collection = bpy.data.grease_pencils
    return collection.new(name)


def ink_materials():
    """The samples' Grease Pencil materials (made once, by name)."""
    made = []
    for name, color in MATERIALS:
        material = bpy.data.materials.get(name)
        if material is None:
            material = bpy.data.materials.new(name)
            bpy.data.materials.create_gpencil_data(material)
            material.grease_pencil.color = color
        made.append(material)
    return made


def add_grease_pencil(name, strokes, location=(0.0, 0.0, 0.0), layer=LAYER, frame=1, obj=None, materials=None):
    """A Grease Pencil object `name` (or another drawing of `obj`: a layer and frame of it) with
    strokes [(points [(x, z)], cyclic, material, pressures)] in its XZ plane (y = 0), in this
    Blender's Grease Pencil: legacy (line width and pressure) or v3 (radius = line width *
    pressure / 2000, as 4.3 converts legacy files)."""
    if obj is None:
        data = grease_pencil_data(name)
        obj = bpy.data.objects.new(name, data)
        bpy.context.scene.collection.objects.link(obj)
        obj.location = location
        for material in materials if materials is not None else ink_materials():
            data.materials.append(material)
    data = obj.data
    found = data.layers.get(layer)
    target_layer = found if found is not None else data.layers.new(layer)
    keyframe = target_layer.frames.new(frame)
    legacy = obj.type == "GPENCIL"
    if legacy:
        for points, cyclic, material, pressures in strokes:
            stroke = keyframe.strokes.new()
            stroke.display_mode = "3DSPACE"
            stroke.line_width = LINE_WIDTH
            stroke.material_index = material
            stroke.use_cyclic = cyclic
            stroke.points.add(len(points))
            for point, (x, z), pressure in zip(stroke.points, points, pressures):
                point.co = (x, 0.0, z)
                point.pressure = pressure
                point.strength = 1.0
    else:
        drawing = keyframe.drawing
        if strokes:
            drawing.add_strokes([len(points) for points, *_ in strokes])
        for stroke, (points, cyclic, material, pressures) in zip(drawing.strokes, strokes):
            stroke.cyclic = cyclic
            stroke.material_index = material
            for point, (x, z), pressure in zip(stroke.points, points, pressures):
                point.position = (x, 0.0, z)
                point.radius = LINE_WIDTH * pressure / 2000.0
                point.opacity = 1.0
                point.select = False
    return obj


# -------------------------------------------------------------- curves ----

def add_letter_curve(name, text, location):
    """The letter `text` as a curve object: a text object converted to a curve (its
    outlines as Bezier splines, a hole as a spline inside), as Object > Convert does."""
    for other in bpy.context.view_layer.objects:
        other.select_set(False)
    bpy.ops.object.text_add(location=location)
    obj = bpy.context.view_layer.objects.active
    obj.data.body = text
    obj.data.align_x = "CENTER"
    bpy.ops.object.convert(target="CURVE")
    obj = bpy.context.view_layer.objects.active
    obj.name = name
    obj.data.name = name
    return obj


# --------------------------------------------------------------- scenes ----

def set_up_scene(scene, camera_location, camera_rotation, scale, name):
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.render.resolution_x, scene.render.resolution_y = RESOLUTION
    scene.render.resolution_percentage = 100
    scene.frame_start, scene.frame_end = FRAMES
    if scene.world is None:
        scene.world = bpy.data.worlds.new(f"{name}_world")
    scene.world.color = WORLD_GRAY
    camera = bpy.data.objects.new(f"{name}_camera", bpy.data.cameras.new(f"{name}_camera"))
    camera.data.type = "ORTHO"
    camera.data.ortho_scale = scale
    camera.location = camera_location
    camera.rotation_euler = camera_rotation
    scene.collection.objects.link(camera)
    scene.camera = camera


def name_pair(scene, objects):
    """The add-on's scene settings (preferences.StickMorphSceneSettings),
    stored as the ID properties it reads when it is enabled: Source, Target."""
    source, target = objects
    scene["stick_morph"] = {"source": source, "target": target}
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj in objects)
    bpy.context.view_layer.objects.active = target


def build_stick_figure():
    bpy.ops.wm.read_homefile(use_empty=True)
    scene = bpy.context.scene
    materials = ink_materials()
    objects = [add_grease_pencil(pose, stick_figure_strokes(pose), (-0.9 + 1.8 * k, 0.0, 0.0), materials=materials)
               for k, pose in enumerate(POSES)]
    # Looking along +Y at the XZ plane (the front view), where the strokes are drawn.
    set_up_scene(scene, (0.0, -10.0, 0.95), (math.pi / 2, 0.0, 0.0), 4.2, STICK_NAME)
    name_pair(scene, objects)
    return objects


def build_letters():
    bpy.ops.wm.read_homefile(use_empty=True)
    scene = bpy.context.scene
    objects = [add_letter_curve(name, text, (-0.6 + 1.2 * k, 0.0, 0.0)) for k, (name, text) in enumerate(LETTERS)]
    set_up_scene(scene, (0.0, 0.35, 10.0), (0.0, 0.0, 0.0), 3.2, LETTERS_NAME)
    name_pair(scene, objects)
    return objects


def main():
    args = parse_args()
    os.makedirs(args.output_dir, exist_ok=True)
    for name, build in ((STICK_NAME, build_stick_figure), (LETTERS_NAME, build_letters)):
        build()
        bpy.context.preferences.filepaths.save_version = 0  # no .blend1 backup
        path = os.path.join(args.output_dir, f"{name}.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path, compress=True)
        print(f"wrote {path}", flush=True)


if __name__ == "__main__":
    main()
