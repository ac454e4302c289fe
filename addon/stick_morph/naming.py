"""The result object's name."""

from __future__ import annotations

import re

# Blender's object names hold 63 bytes (up to 4.x); the triangulation helper
# appends "_triangulation" (14) to the result's name.
MAX_RESULT_NAME_BYTES = 40
RESULT_SUFFIX = "morph"
_SEPARATORS = "_-. "


def _tokens(name: str) -> list[str]:
    """name split after each separator, keeping it: "a_b.c" -> ["a_", "b.", "c"]."""
    return re.findall(r"[^_\-. ]*[_\-. ]+|[^_\-. ]+$", name)


def _clip(text: str, max_bytes: int) -> str:
    """text cut to at most max_bytes of UTF-8 without splitting a character."""
    data = text.encode("utf-8")
    if len(data) <= max_bytes:
        return text
    return data[:max_bytes].decode("utf-8", errors="ignore")


def result_name(source_name: str, target_name: str, max_bytes: int = MAX_RESULT_NAME_BYTES) -> str:
    """A short name for the result of morphing source_name into target_name.

    Names that share whole leading or trailing words (split at _ - . and
    spaces) keep what they share and end in "_morph":
    monkey_to_player_source + monkey_to_player_target -> monkey_to_player_morph,
    Cube.001 + Cube.002 -> Cube_morph, source_arm + target_arm -> arm_morph.
    Otherwise it is <source>_to_<target>, each side clipped so that the
    whole stays within max_bytes (UTF-8, so it fits Blender's name field with
    the helper's suffix); only ASCII is added to the given names.
    """
    a, b = _tokens(source_name), _tokens(target_name)
    prefix = []
    for x, y in zip(a, b):
        if x.rstrip(_SEPARATORS) != y.rstrip(_SEPARATORS):
            break
        prefix.append(x)
    rest_a, rest_b = a[len(prefix):], b[len(prefix):]
    suffix = []
    for x, y in zip(reversed(rest_a), reversed(rest_b)):
        if x.rstrip(_SEPARATORS) != y.rstrip(_SEPARATORS):
            break
        suffix.insert(0, x)
    common = "".join(prefix) + "".join(suffix)
    common = common.strip(_SEPARATORS)
    # A shared word that is only a digit run or a single character ("1_a",
    # "1_b") says nothing about the pair.
    if len(common) >= 2 and not common.isdigit():
        stem = re.sub(r"[_\-. ]+", "_", common)
        return _clip(stem, max_bytes - len(RESULT_SUFFIX) - 1).rstrip(_SEPARATORS) + "_" + RESULT_SUFFIX
    half = (max_bytes - len("_to_")) // 2
    left = _clip(source_name, max(half, max_bytes - len("_to_") - len(target_name.encode("utf-8"))))
    right = _clip(target_name, max_bytes - len("_to_") - len(left.encode("utf-8")))
    return f"{left}_to_{right}"
