// The binding groups of the `stickmorph` module. module.cpp's
// PYBIND11_MODULE calls them in this order: the exception classes must
// exist before any function can raise them.
#pragma once

#include <pybind11/pybind11.h>

namespace stickmorph::python {

/// Exception classes and the translator from engine exceptions (errors.cpp).
void bind_errors(pybind11::module_& m);

/// validate, load_figure, rotation_system, decompose, check_compatibility
/// and CompatibilityReport (bind_figures.cpp).
void bind_figures(pybind11::module_& m);

/// compatible_triangulation and triangulate_figures (bind_triangulation.cpp).
void bind_triangulation(pybind11::module_& m);

/// stickmorph.limits, OPTION_NAMES, the names tuples and option_rules: the
/// engine's limits and the rules of morph()'s options (bind_options.cpp).
void bind_options(pybind11::module_& m);

/// morph, MorphSolver and RigidMorphSolver (bind_morph.cpp).
void bind_morph(pybind11::module_& m);

/// stickmorph.Progress: progress and cancellation of long calls (bind_progress.cpp).
void bind_progress(pybind11::module_& m);

/// morph_key_poses, the morph through a sequence of key poses (bind_key_poses.cpp).
void bind_key_poses(pybind11::module_& m);

/// clean_drawing, clean_figure and CleanedDrawing (bind_drawings.cpp).
void bind_drawings(pybind11::module_& m);

}  // namespace stickmorph::python
