"""What the add-on needs before numpy and the native module are known to load.

The property definitions (preferences.py) need the limits and the defaults
(BakeSettings) and every module needs the error type; they live here,
importing nothing but the standard library, so that the add-on registers, and
its panel can say what is missing, in a Blender whose Python lacks numpy or
cannot load the bundled module. core.py re-exports all of these.
"""

from dataclasses import dataclass

MAX_ENGINE_FRAMES = 100000

# The engine's bound on the enclosure's sides (native/stickmorph/argument_limits.h):
# the annulus costs grow quadratically with them, so more is a hang.
MAX_ENCLOSURE_SIDES = 1000


class StickMorphError(Exception):
    """A problem with the user's input, reported as an ERROR; message is for the user."""


@dataclass(frozen=True)
class BakeSettings:
    """The options of one bake, in one object.

    The operator reads its properties into one of these once
    (preferences.bake_settings) and core and baking take their options only
    from it, so a new option is a field here and a property in
    preferences.option_properties, not a keyword argument threaded through
    every call. The defaults are the properties' defaults: option_properties
    takes them from here. Frozen: one bake's options do not change while it
    runs. Values are not checked here: core checks the ranges (compute_morph)
    and the plane (fit_plane), where a script's values arrive too.
    """

    frame_count: int = 50  # output frames, source and target included
    frame_start: int = 1  # the frame that shows the source
    steiner: str = "improved"
    weights: str = "mvc"
    enclosure_sides: int = 6
    plane: str = "AUTO"
    easing: str = "LINEAR"
    renderable: bool = True
    tube_radius: float = 0.01  # a fraction of the figures' size
    show_triangulation: bool = False
    # A figure deviating from its plane by more than this fraction of the size
    # of both figures (the diagonal of their common bounding box) is not planar.
    planarity_tolerance: float = 1e-4
    set_frame_range: bool = True
