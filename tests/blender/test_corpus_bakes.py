"""Bakes of figure pairs the suite does not ship (opt-in, a long mode).

    STICKMORPH_CORPUS_DIR=out/motion_corpus bash scripts/blender_tests.sh -k corpus

runs, for every NAME.source.json / NAME.target.json pair in that folder (for
example the corpus `bench/motion_corpus.py` writes), the checks of
test_bake.test_bake_matches_engine_in_world_space: the source and target are
placed with different tilted world matrices, baked through the operator, and
every frame must equal the engine's morph in world space, be a stick figure
compatible with the source, and the ends must be the source and the target.
Without the variable the test is skipped (it is a measurement over a corpus,
not part of the regular suite).
"""

import glob
import json
import os

import numpy as np
import pytest

from conftest import (evaluated_world, make_mesh_object, select, source_matrix, target_matrix,
                      world_coords)
from test_bake import bake, expected_frames, figure_size

CORPUS = os.environ.get("STICKMORPH_CORPUS_DIR", "")
STEMS = sorted(path[:-len(".source.json")]
               for path in glob.glob(os.path.join(CORPUS, "*.source.json"))) if CORPUS else []


def load(path):
    with open(path) as file:
        figure = json.load(file)
    return figure["vertices"], figure["edges"]


@pytest.mark.skipif(not STEMS, reason="set STICKMORPH_CORPUS_DIR to a folder of figure pairs")
@pytest.mark.parametrize("stem", STEMS or ["(no corpus)"], ids=os.path.basename)
def test_corpus_pair_bakes_to_the_engine_morph(scene, addon, stem):
    source_xy, edges = load(stem + ".source.json")
    target_xy, target_edges = load(stem + ".target.json")
    assert {tuple(sorted(e)) for e in edges} == {tuple(sorted(e)) for e in target_edges}
    source = make_mesh_object("Source", source_xy, edges, source_matrix())
    target = make_mesh_object("Target", target_xy, edges, target_matrix())
    select(source, target)
    frame_count = 12
    result = bake(frame_count=frame_count, frame_start=1)

    expected, _, src_xy, mesh_edges, _ = expected_frames(addon, source, target, frame_count)
    tolerance = 1e-5 * figure_size(source, target)
    engine = addon.core.load_engine()
    fitted = addon.core.fit_plane(world_coords(source), world_coords(target), "AUTO")
    for k in range(frame_count):
        got = evaluated_world(result, 1 + k)
        error = np.abs(got - expected[k]).max()
        assert error <= tolerance, f"frame {k}: off the engine's morph by {error}"
        d = got - fitted.origin
        xy = np.stack([d @ fitted.u, d @ fitted.v], axis=1)
        assert engine.check_compatibility(src_xy, xy, mesh_edges), f"frame {k} is not valid"
    assert np.abs(evaluated_world(result, 1) - world_coords(source)).max() <= tolerance
    assert np.abs(evaluated_world(result, frame_count) - world_coords(target)).max() <= tolerance
