"""What the add-on needs before numpy and the native module are known to load.

The property definitions (preferences.py) need the limits and every module
needs the error type; both live here, importing nothing but the standard
library, so that the add-on registers, and its panel can say what is missing,
in a Blender whose Python lacks numpy or cannot load the bundled module.
core.py re-exports all of these.
"""

MAX_ENGINE_FRAMES = 100000

# The engine's bound on the enclosure's sides (native/stickmorph/argument_limits.h):
# the annulus costs grow quadratically with them, so more is a hang.
MAX_ENCLOSURE_SIDES = 1000

# A figure deviating from its plane by more than this fraction of the size of
# both figures (the diagonal of their common bounding box) is not planar.
DEFAULT_PLANARITY_TOLERANCE = 1e-4


class StickMorphError(Exception):
    """A problem with the user's input, reported as an ERROR; message is for the user."""
