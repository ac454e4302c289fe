"""The add-on's geometry and engine glue, free of bpy: one name space over
the modules that hold it, split by concept.

- native.py: the native module (load_engine, engine_limits);
- plane.py: the common plane, projection and the way back (fit_plane, ...);
- correspondence.py: edge sets, parts, pins and the by-index-or-matched
  choice (choose_correspondence, read_pins, ...);
- timing.py: easing and which engine frame each output frame shows, local
  timing (delay_weights, local_times);
- messages.py: user messages for the engine's exceptions;
- morph.py: prepare_pair, compute_morph and their results;
- naming.py: the result object's name;
- drawings.py: Grease Pencil drawings and curves as figures (issue 32):
  cleaned by the engine (prepare_drawings), and a morph back into strokes
  (output_strokes).

Everything here works on NumPy arrays and plain Python values, so it can be
imported and tested outside Blender. The Blender side (operators.py,
baking.py) reads meshes into arrays, calls `prepare_pair` and `compute_morph`,
and writes the arrays back. Callers use `core.X`; the modules above import
each other directly, never through this one.

World space and the plane
-------------------------
The engine morphs 2D figures. Both meshes are read in world space and
projected onto one plane with an orthonormal basis (u, v) and normal n, u x v
= n, so that 2D orientation is the orientation seen looking down -n. The
projection is the same for both figures, so a mirror image in 3D stays a
mirror image in 2D (and is refused by the engine).

Each vertex also keeps its height h = n . (p - origin) in its own figure. The
way back to world space at eased time s is

    p(s) = origin + x u + y v + ((1 - s) h_source + s h_target) n

so frame 0 is the source's world vertices and the last frame the target's
(up to floating-point roundoff), including the offset between two figures
that lie in parallel planes, e.g. side by side at different depths. s is the
engine frame's time for BARYCENTRIC and LINEAR (easing picks frames, see
ease_sample_indices), and the eased time ease(k / (N - 1)) for RIGID, whose
frames may be spaced along the motion after the easing: the
height then moves in step with the figure.
"""

# The settings and the error type live in common.py, which imports without
# numpy; they are part of core's interface too.
from .common import (BakeSettings, StickMorphError, is_drawing_type, is_pin_group, next_pin_name,  # noqa: F401
                     pin_names)
from .native import load_engine, engine_limits, option_methods  # noqa: F401
from .plane import PLANES, Plane, fit_plane, project, unproject, planarity_deviation  # noqa: F401
from .correspondence import (  # noqa: F401
    CORRESPONDENCES, Pin, Matching, compare_edge_sets, figure_parts, parts_summary,
    choose_correspondence, read_pins, check_pins, matched_heights, correspondence_summary,
)
from .timing import (  # noqa: F401
    EASINGS, RIGID_EASINGS, EASE_OVERSAMPLING, ease, engine_frame_count, ease_sample_indices, frame_list,
    delay_weights, local_times,
)
from .messages import match_error_message, NESTING_DIFFERS, nesting_message, engine_error_message  # noqa: F401
from .morph import (  # noqa: F401
    MOTIONS, ROTATIONS, Fallback, IndexReport, PreparedPair, MorphResult, prepare_pair, prepare_projected,
    compute_morph, morph_pair,
    motion_summary, local_timing_summary,
    triangulation_world, tube_radius,
)
from .naming import MAX_RESULT_NAME_BYTES, RESULT_SUFFIX, result_name  # noqa: F401
from .drawings import (  # noqa: F401
    OUTPUTS, DrawingChoice, Stroke, Drawing, MeshFigure, CleanedSide, DrawingPair, OutputStroke, output_kind,
    prepare_drawings, cleaning_summary, figure_chains, source_strokes, output_strokes,
)
