"""The check of a rigid morph's stats["rigid"] (docs/FORMAT.md), shared by the CLI's and the
module's tests: the fitted similarity is recomputed here (Procrustes on the vertices)."""
import math

import numpy as np
import pytest

RIGID_STATS = {"rotation", "turns", "easing", "similarity_factored", "similarity", "guide_frames",
               "refinement_steiner_vertices"}


def check_rigid_section(stats, source_vertices, target_vertices, frames, rotation="short", turns=0,
                        easing="none"):
    """Checks stats["rigid"] and the counters a rigid morph reports; returns stats["rigid"]."""
    rigid = stats["rigid"]
    assert set(rigid) == RIGID_STATS
    assert (rigid["rotation"], rigid["turns"], rigid["easing"]) == (rotation, turns, easing)
    assert type(rigid["turns"]) is int and type(rigid["similarity_factored"]) is bool
    similarity = rigid["similarity"]
    assert set(similarity) == {"angle_degrees", "scale", "source_center", "target_center"}
    assert type(similarity["angle_degrees"]) is float and math.isfinite(similarity["angle_degrees"])
    assert type(similarity["scale"]) is float and similarity["scale"] > 0
    source, target = np.asarray(source_vertices, float), np.asarray(target_vertices, float)
    for center, points in ((similarity["source_center"], source), (similarity["target_center"], target)):
        assert len(center) == 2 and all(type(c) is float for c in center)
        np.testing.assert_allclose(center, points.mean(axis=0), rtol=0, atol=1e-12 * (1 + np.abs(points).max()))
    a, b = source - source.mean(axis=0), target - target.mean(axis=0)
    if np.abs(a).max() > 0 and np.abs(b).max() > 0:
        assert similarity["scale"] == pytest.approx(np.sqrt((b ** 2).sum() / (a ** 2).sum()), rel=1e-9)
        fitted = math.degrees(math.atan2((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]).sum(), (a * b).sum()))
        # The rotation taken: the short way in (-180, 180], counter-clockwise in [0, 360) or
        # clockwise in (-360, 0], plus the whole turns.
        low = {"short": -180, "ccw": 0, "cw": -360}[rotation] + 360 * turns
        angle = similarity["angle_degrees"]
        assert low - 1e-9 <= angle <= low + 360 + 1e-9, (angle, rotation, turns)
        assert math.remainder(angle - fitted, 360) == pytest.approx(0, abs=1e-7)
    guide = rigid["guide_frames"]
    assert set(guide) == {"exact", "blended", "barycentric"}
    assert all(type(v) is int and v >= 0 for v in guide.values())
    # Every interior frame is made one way or another.
    assert sum(guide.values()) == frames - 2
    refinement = rigid["refinement_steiner_vertices"]
    assert type(refinement) is int and 0 <= refinement <= stats["steiner_vertices"]
    # The rigid morph's factorizations are those of its own systems (set-up included); its set-up
    # time is reported as "factorize", part of the morph's.
    milliseconds = stats["milliseconds"]
    assert type(stats["factorizations"]) is int and stats["factorizations"] >= 0
    assert 0 <= milliseconds["factorize"] <= milliseconds["morph"]
    return rigid
