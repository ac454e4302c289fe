"""stickmorph.option_rules: the engine's rules of morph()'s options (issue 27).

The add-on reads this table to grey out and bound its rows; these tests pin
it and check, case by case derived from the table itself, that morph()
refuses an option given with a method outside its "methods", accepts it with
the others, and bounds the counts as "min" and "max" say, so that the table
and the checks cannot drift apart.
"""
import pytest

import stickmorph

METHODS = ("rigid", "barycentric", "linear")
TRIANGULATED = ("rigid", "barycentric")

EXPECTED = {
    "frames": {"methods": METHODS, "min": 2, "max": 100000, "default": 50},
    "method": {"methods": METHODS, "choices": METHODS, "default": "rigid"},
    "verify": {"methods": TRIANGULATED, "default": True},
    "frame_check": {"methods": TRIANGULATED, "choices": ("certificate", "full"), "default": "certificate"},
    "weights": {"methods": TRIANGULATED, "choices": ("mvc", "uniform", "floater"), "default": "mvc"},
    "steiner": {"methods": TRIANGULATED, "choices": ("improved", "sg2001", "aronov"), "default": "improved"},
    "enclosure_sides": {"methods": TRIANGULATED, "min": 3, "max": 1000, "default": 6},
    "rotation": {"methods": ("rigid",), "choices": ("short", "ccw", "cw"), "default": "short"},
    "turns": {"methods": ("rigid",), "min": -100, "max": 100, "default": 0},
    "easing": {"methods": ("rigid",), "choices": ("none", "in-out"), "default": "none"},
    "correspond": {"methods": METHODS, "choices": ("index", "auto"), "default": "index"},
    "pins": {"methods": METHODS},
    # Local timing (issue 31): delay= with overlap=; the CLI's --timing FILE.
    "delay": {"methods": ("rigid",)},
}

# A small pair: a bent polyline straightening out.
SOURCE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]
TARGET = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.2]]
EDGES = [[0, 1], [1, 2]]


def valid_value(name, rule, method):
    """A value of the option that is in range: its default, or a pin."""
    if name == "method":
        return method
    if name == "pins":
        return [[0, 0]]
    if name == "delay":
        return [0.0, 0.0, 1.0]
    return rule["default"]


def arguments(name, value, method):
    """morph()'s keywords giving `name` with `method` (pins need correspond='auto')."""
    kwargs = {"frames": 3, name: value}
    if name != "method":
        kwargs["method"] = method
    if name == "pins":
        kwargs["correspond"] = "auto"
    if name == "delay":
        kwargs["overlap"] = 0.3
    return kwargs


def test_option_rules_are_pinned():
    assert stickmorph.option_rules == EXPECTED


def test_option_rules_agree_with_the_other_tables():
    rules = stickmorph.option_rules
    assert set(rules) <= set(stickmorph.OPTION_NAMES)
    assert rules["method"]["choices"] == stickmorph.METHOD_NAMES
    assert rules["rotation"]["choices"] == stickmorph.ROTATION_NAMES
    assert rules["easing"]["choices"] == stickmorph.EASING_NAMES
    limits = stickmorph.limits
    assert (rules["frames"]["min"], rules["frames"]["max"]) == (limits["min_frames"], limits["max_frames"])
    assert rules["enclosure_sides"]["max"] == limits["max_enclosure_sides"]
    assert rules["turns"]["max"] == limits["max_turns"]


def test_every_keyword_of_morph_has_a_rule():
    doc = stickmorph.morph.__doc__
    for name in stickmorph.option_rules:
        assert f"{name}=" in doc.split("\n")[0] or f"  {name}:" in doc, name
    # The module's docstring lists them.
    assert "option_rules" in stickmorph.__doc__


REFUSED = [(name, method) for name, rule in EXPECTED.items() for method in METHODS
           if method not in rule["methods"]]
ACCEPTED = [(name, method) for name, rule in EXPECTED.items() for method in rule["methods"]]


def test_some_options_are_refused_by_some_method():
    assert len(REFUSED) == 5 + 2 * 4


@pytest.mark.parametrize("name,method", REFUSED)
def test_an_option_outside_its_methods_is_refused(name, method):
    rule = stickmorph.option_rules[name]
    assert method not in rule["methods"]
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.morph(SOURCE, TARGET, EDGES, **arguments(name, valid_value(name, rule, method), method))
    assert str(error.value).startswith(f"{name} has no effect with method='{method}' (")


@pytest.mark.parametrize("name,method", ACCEPTED)
def test_an_option_within_its_methods_is_accepted(name, method):
    rule = stickmorph.option_rules[name]
    result = stickmorph.morph(SOURCE, TARGET, EDGES, **arguments(name, valid_value(name, rule, method), method))
    assert result["stats"]["method"] == method


@pytest.mark.parametrize("name,method", [(n, m) for n, m in ACCEPTED if "choices" in EXPECTED[n]])
def test_every_choice_is_accepted_and_others_refused(name, method):
    rule = stickmorph.option_rules[name]
    for choice in rule["choices"]:
        stickmorph.morph(SOURCE, TARGET, EDGES, **arguments(name, choice, method))
    with pytest.raises(stickmorph.InvalidArgumentError):
        stickmorph.morph(SOURCE, TARGET, EDGES, **arguments(name, "no-such-name", method))


@pytest.mark.parametrize("name,method", [(n, m) for n, m in ACCEPTED if "min" in EXPECTED[n]])
def test_counts_are_bounded_by_min_and_max(name, method):
    rule = stickmorph.option_rules[name]
    with pytest.raises(stickmorph.InvalidArgumentError, match=f"^{name} must be at least {rule['min']}, got "):
        stickmorph.morph(SOURCE, TARGET, EDGES, **arguments(name, rule["min"] - 1, method))
    with pytest.raises(stickmorph.InvalidArgumentError, match=f"^{name} must be at most {rule['max']}, got "):
        stickmorph.morph(SOURCE, TARGET, EDGES, **arguments(name, rule["max"] + 1, method))
    if name != "frames":  # 100000 frames is accepted but slow
        stickmorph.morph(SOURCE, TARGET, EDGES, **arguments(name, rule["min"], method))


def test_a_count_outside_its_methods_is_refused_by_name_not_range():
    # The method decides first: enclosure_sides=2 with method='linear' is
    # refused as an option linear ignores, not as out of range.
    for name, rule in EXPECTED.items():
        if "min" not in rule:
            continue
        for method in METHODS:
            if method in rule["methods"]:
                continue
            with pytest.raises(stickmorph.InvalidArgumentError, match=f"^{name} has no effect with"):
                stickmorph.morph(SOURCE, TARGET, EDGES, **arguments(name, rule["min"] - 1, method))


def test_pins_need_correspond_auto():
    with pytest.raises(stickmorph.InvalidArgumentError, match=r"^pins need correspond='auto' \("):
        stickmorph.morph(SOURCE, TARGET, EDGES, frames=3, pins=[[0, 0]])
