"""The add-on keeps no copy of which morph option applies to which method:
it reads the engine's stickmorph.option_rules (native.option_methods), and
the panel's greying and compute_morph's options both follow it (issue 27)."""

import numpy as np

import stickmorph
from test_addon_core import common as addon_common
from test_addon_core import core


def engine_rule():
    return {name: tuple(rule["methods"]) for name, rule in stickmorph.option_rules.items()}


def test_the_addon_reads_the_engines_rule():
    assert core.option_methods() == engine_rule()
    assert not hasattr(addon_common, "OPTION_METHODS")


def test_properties_follow_the_engine():
    rule = engine_rule()
    for motion in ("RIGID", "BARYCENTRIC", "LINEAR"):
        applies = lambda name: addon_common.property_applies(name, motion, rule)
        assert applies("rotation") == applies("turns") == (motion == "RIGID")
        for name in ("steiner", "weights", "enclosure_sides", "show_triangulation"):
            assert applies(name) == (motion != "LINEAR")
        # Not engine options, or options of every motion in the add-on.
        for name in ("easing", "frame_count", "plane", "correspondence", "renderable"):
            assert applies(name)


def test_without_the_engine_nothing_is_greyed_out():
    for name in ("rotation", "steiner", "show_triangulation"):
        assert addon_common.property_applies(name, "LINEAR", None)


def test_compute_morph_sends_what_applies(monkeypatch):
    """The options compute_morph gives the engine are exactly those the
    engine's rule says apply to the motion (beyond frames and method)."""
    engine = core.load_engine()
    morph = engine.morph
    calls = []
    monkeypatch.setattr(engine, "morph", lambda *a, **k: calls.append(k) or morph(*a, **k))
    source = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]])
    target = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.2, 0.0]])
    edges = [[0, 1], [1, 2]]
    rule = engine_rule()
    for motion in ("RIGID", "BARYCENTRIC", "LINEAR"):
        settings = addon_common.BakeSettings(motion=motion, frame_count=3, correspondence="INDEX")
        prepared = core.prepare_pair(source, edges, 0, "a", target, edges, 0, "b", settings)
        core.compute_morph(prepared, settings)
        sent = set(calls[-1]) - {"frames", "method"}
        assert sent == {name for name in rule if motion.lower() in rule[name]
                        and name in ("steiner", "weights", "enclosure_sides", "verify", "rotation", "turns",
                                     "easing")}, motion
