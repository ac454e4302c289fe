"""The native module, loaded once the dependency check allows: the one place
the bpy-free modules get `stickmorph` from."""

from __future__ import annotations

import os

from . import dependencies
from .common import StickMorphError

def load_engine():
    """The native `stickmorph` module: the copy shipped inside this package,
    else one on sys.path (a development build). Raises StickMorphError saying
    which Python the module was built for and how to rebuild it."""
    try:
        return dependencies.import_engine(__package__)
    except (ImportError, OSError):
        status = dependencies.check(os.path.dirname(os.path.abspath(__file__)), __package__)
        if status.engine_error is None:  # loaded on the second try (a transient failure)
            return dependencies.import_engine(__package__)
        raise StickMorphError(status.message()) from None


def engine_limits() -> dict:
    """The engine's bounds by name (stickmorph.limits: "max_frames", ...).
    From the module itself wherever it can be loaded, so that a check here
    cannot disagree with the engine's; common.ENGINE_LIMITS is the copy for
    registration, when the module may be missing."""
    return load_engine().limits


def option_methods() -> dict:
    """Which methods ("rigid", "barycentric", "linear") each option of
    stickmorph.morph applies to, from the engine's own rule table
    (stickmorph.option_rules): the panel greys out and compute_morph leaves
    out exactly what the engine would refuse."""
    return {name: tuple(rule["methods"]) for name, rule in load_engine().option_rules.items()}
