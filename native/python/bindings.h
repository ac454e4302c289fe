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

/// morph, and the limits and option names it checks (bind_morph.cpp).
void bind_morph(pybind11::module_& m);

}  // namespace stickmorph::python
