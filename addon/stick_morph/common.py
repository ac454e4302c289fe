"""What the add-on needs before numpy and the native module are known to load.

The property definitions (properties.py) need the limits and the defaults
(BakeSettings), every module needs the error type, and the panel and the pin
operators need the pin groups' naming rule (is_pin_group); they live here,
importing nothing but the standard library, so that the add-on registers, and
its panel can say what is missing, in a Blender whose Python lacks numpy or
cannot load the bundled module. core.py re-exports all of these.
"""

from dataclasses import dataclass

# The engine's limits (native/stickmorph/argument_limits.h) as the native
# module exports them, stickmorph.limits. A copy, because the properties
# (preferences.py) need their min, max and default when the add-on
# registers, and it registers without the module (dependencies.py); they and
# their help texts take the numbers from here. Where the module is loaded
# (core.compute_morph's range checks and messages) the add-on reads
# stickmorph.limits itself. tests/python/test_addon_core.py asserts that this
# table equals stickmorph.limits, so an engine limit that changes fails the
# tests until it is changed here too.
ENGINE_LIMITS = {
    "min_frames": 2,
    "max_frames": 100000,
    "default_frames": 50,
    "min_enclosure_sides": 3,
    # The annulus between figure and enclosure costs time quadratic in the
    # sides, so the engine refuses more than this rather than hang.
    "max_enclosure_sides": 1000,
    "default_enclosure_sides": 6,
    "min_smoothing_rounds": 0,
    "max_smoothing_rounds": 1000,
    "default_smoothing_rounds": 10,
    # Extra whole turns of the rigid motion, either way (turns = -100 to 100).
    "max_turns": 100,
    "max_coordinate_magnitude": 1e100,
}


# The add-on's properties that only some motions use, each with the engine
# option whose methods decide it (the engine's stickmorph.option_rules, read
# by native.option_methods). The triangulation exists where the
# triangulation's own options (steiner) apply. The add-on's easing is not
# here: it applies to every motion (for BARYCENTRIC and LINEAR the add-on
# picks frames itself, timing.ease_sample_indices).
PROPERTY_OPTIONS = {
    "rotation": "rotation",
    "turns": "turns",
    "steiner": "steiner",
    "weights": "weights",
    "enclosure_sides": "enclosure_sides",
    "show_triangulation": "steiner",
    # Local timing (issue 31): the delay weights and the overlap, one engine
    # option (its rule is under the keyword delay=; overlap= goes with it).
    "delay_group": "delay",
    "overlap": "delay",
}


def option_applies(option: str, motion: str, option_methods: dict) -> bool:
    """Whether the engine option `option` applies to the add-on's motion
    (RIGID, BARYCENTRIC, LINEAR: the engine's method in upper case).
    option_methods: the engine's rule, native.option_methods() (the methods
    each option of stickmorph.morph applies to); the add-on keeps no copy.
    An option the module does not know (an older module: no delay, no
    overlap) applies to no motion."""
    return motion.lower() in option_methods.get(option, ())


def property_applies(name: str, motion: str, option_methods: dict | None) -> bool:
    """Whether the add-on's property `name` has an effect with this motion.
    Without the engine's rule (option_methods None: the module does not
    load, so nothing can be baked and the panel says why) every property
    counts as applying: nothing is greyed out on a guess."""
    option = PROPERTY_OPTIONS.get(name)
    return option is None or option_methods is None or option_applies(option, motion, option_methods)


# A pin is a vertex group of this name prefix (any case) in both meshes,
# holding one vertex in each: those two vertices must match (core.read_pins).
# Here, not in core, because the panel counts pins and Pin Selected Vertices
# names them without numpy or the module.
PIN_PREFIX = "pin"


def is_pin_group(name: str) -> bool:
    """Whether a vertex group of this name is a pin ("pin.001", "Pin_hand", "PIN")."""
    return name[:len(PIN_PREFIX)].lower() == PIN_PREFIX


def next_pin_name(*taken) -> str:
    """The first of "pin.001", "pin.002", ... that is none of the names in the
    given collections (the vertex group names of both meshes), so that one new
    group of that name can be added to each."""
    used = set().union(*map(set, taken))
    k = 1
    while f"{PIN_PREFIX}.{k:03d}" in used:
        k += 1
    return f"{PIN_PREFIX}.{k:03d}"


def pin_names(source_names, target_names) -> tuple[list, list, list]:
    """(in both, only in the first, only in the second): the pin group names
    of two meshes' vertex group names, each list sorted. A pin is a group
    name in both; one in a single mesh is an error when baking (read_pins)."""
    a = {name for name in source_names if is_pin_group(name)}
    b = {name for name in target_names if is_pin_group(name)}
    return sorted(a & b), sorted(a - b), sorted(b - a)


# The object types a bake takes (issue 32): edge meshes; Grease Pencil,
# legacy (Blender before 4.3) and v3 (4.3 and later, which converts legacy
# files on load); curves and texts (their outlines). Here, not in
# drawings.py, because the panel and the Source/Target pickers need them
# without numpy or the module.
GREASE_PENCIL_TYPES = ("GPENCIL", "GREASEPENCIL")
CURVE_TYPES = ("CURVE", "FONT")
FIGURE_TYPES = ("MESH",) + GREASE_PENCIL_TYPES + CURVE_TYPES


def is_drawing_type(object_type: str) -> bool:
    """Whether objects of this type are read as drawings (strokes cleaned
    into a stick figure) rather than as edge meshes."""
    return object_type in GREASE_PENCIL_TYPES + CURVE_TYPES


class StickMorphError(Exception):
    """A problem with the user's input, reported as an ERROR; message is for the user."""


@dataclass(frozen=True)
class BakeSettings:
    """The options of one bake, in one object.

    The operator reads its properties into one of these once
    (properties.bake_settings) and core and baking take their options only
    from it, so a new option is a field here and a property in
    properties.option_properties, not a keyword argument threaded through
    every call. The defaults are the properties' defaults: option_properties
    takes them from here. Frozen: one bake's options do not change while it
    runs. Values are not checked here: core checks the ranges (compute_morph)
    and the plane (fit_plane), where a script's values arrive too.
    """

    # The engine's defaults: a bake and a `stickmorph morph` without options agree.
    frame_count: int = ENGINE_LIMITS["default_frames"]  # output frames, source and target included
    frame_start: int = 1  # the frame that shows the source
    # How the figure moves (core.MOTIONS): RIGID, the engine's default (as
    # rigid as validity allows, at even speed); BARYCENTRIC, the paper's
    # Floater-Gotsman morph; LINEAR, straight lines, not guaranteed valid.
    motion: str = "RIGID"
    # RIGID only: which way the figure turns as a whole (core.ROTATIONS) and
    # how many extra whole turns, counter-clockwise positive.
    rotation: str = "SHORT"
    turns: int = 0
    steiner: str = "improved"
    weights: str = "mvc"
    enclosure_sides: int = ENGINE_LIMITS["default_enclosure_sides"]
    plane: str = "AUTO"
    # How vertices of the source find their partners in the target
    # (core.CORRESPONDENCES): INDEX_OR_MATCH (labelled Automatic), by index where that works and matched
    # otherwise; INDEX, vertex i of one mesh is vertex i of the other; MATCH,
    # always matched by shape (stickmorph.correspond), pins respected.
    correspondence: str = "INDEX_OR_MATCH"
    easing: str = "NONE"  # timing.EASINGS: NONE or IN_OUT, the engine's "none" and "in-out"
    renderable: bool = True
    tube_radius: float = 0.01  # a fraction of the figures' size
    show_triangulation: bool = False
    # A figure deviating from its plane by more than this fraction of the size
    # of both figures (the diagonal of their common bounding box) is not planar.
    planarity_tolerance: float = 1e-4
    set_frame_range: bool = True
    # Local timing (issue 31, RIGID only): the name of a vertex group of the
    # source mesh (of the first key for key poses) whose weights are the
    # delay weights, weight 0 leading and weight 1 lagging by `overlap` of
    # the motion ("": none, every part on the same clock). Mesh data, not a
    # preference: a default group name would refuse every mesh without it.
    delay_group: str = ""
    # How far a part of weight 1 lags one of weight 0, as a fraction of the
    # motion (the engine's overlap d in [0, 1); 0 is the plain morph). Each
    # part moves at local time clamp((t - d w) / (1 - d), 0, 1).
    overlap: float = 0.3
    # Drawings (issue 32). What the bake makes (drawings.OUTPUTS): AUTO, a
    # Grease Pencil object for a Grease Pencil source and a mesh with its
    # tube otherwise (meshes and curves, as before); MESH; GREASE_PENCIL.
    output: str = "AUTO"
    # How far apart a Grease Pencil drawing's or a curve's strokes may be
    # and still be joined when it is cleaned into a stick figure
    # (stickmorph.clean_drawing: ends this close snap, crossings become
    # junctions), as a fraction of the drawing's size (the diagonal of its
    # bounding box); 0 is the engine's default, 1% of the same. Meshes are
    # not cleaned.
    clean_tolerance: float = 0.0
