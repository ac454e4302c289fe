"""The add-on's copy of which morph option applies to which method
(common.OPTION_METHODS) is the engine's (stickmorph.option_rules), and the
panel's greying and compute_morph's options both follow it (issue 27)."""

import numpy as np
import pytest

import stickmorph
from test_addon_core import common as addon_common


def test_the_copy_equals_the_engines_option_rules():
    rules = getattr(stickmorph, "option_rules", None)
    if rules is None:
        pytest.skip("the loaded stickmorph module has no option_rules (a build from before issue 27's "
                    "engine side); the copy is checked once the module exports it")
    assert addon_common.OPTION_METHODS == {name: tuple(rule["methods"]) for name, rule in rules.items()}


def test_the_copy_names_methods_the_engine_knows():
    methods = set(stickmorph.METHOD_NAMES)
    for name, applies in addon_common.OPTION_METHODS.items():
        assert applies and set(applies) <= methods, name


def test_properties_follow_the_copy():
    applies = addon_common.property_applies
    for motion in ("RIGID", "BARYCENTRIC", "LINEAR"):
        assert applies("rotation", motion) == applies("turns", motion) == (motion == "RIGID")
        for name in ("steiner", "weights", "enclosure_sides", "show_triangulation"):
            assert applies(name, motion) == (motion != "LINEAR")
        # Not engine options, or options of every motion in the add-on.
        for name in ("easing", "frame_count", "plane", "correspondence", "renderable"):
            assert applies(name, motion)


def test_compute_morph_sends_what_applies(monkeypatch):
    """The options compute_morph gives the engine are exactly those the copy
    says apply to the motion (beyond frames and method)."""
    from test_addon_core import core
    engine = core.load_engine()
    morph = engine.morph
    calls = []
    monkeypatch.setattr(engine, "morph", lambda *a, **k: calls.append(k) or morph(*a, **k))
    source = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]])
    target = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.2, 0.0]])
    edges = [[0, 1], [1, 2]]
    for motion in ("RIGID", "BARYCENTRIC", "LINEAR"):
        settings = addon_common.BakeSettings(motion=motion, frame_count=3, correspondence="INDEX")
        prepared = core.prepare_pair(source, edges, 0, "a", target, edges, 0, "b", settings)
        core.compute_morph(prepared, settings)
        sent = set(calls[-1]) - {"frames", "method"}
        assert sent == {name for name in addon_common.OPTION_METHODS if addon_common.option_applies(name, motion)
                        and name in ("steiner", "weights", "enclosure_sides", "verify", "rotation", "turns",
                                     "easing")}, motion
