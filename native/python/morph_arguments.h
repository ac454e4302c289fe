// The morph's keyword arguments (morph(), RigidMorphSolver) turned into the
// engine's MorphStickFiguresOptions. Only conversion lives here: which
// option applies to which method, ranges and names are the engine's
// (stickmorph/morph_options.h), asked in the order the module always
// reported them.
#pragma once

#include <pybind11/pybind11.h>

#include "stickmorph/morph_stick_figures.h"

namespace stickmorph::python {

/// None means "not given", so that the engine can refuse what the method
/// would ignore; everything is checked before the figures, as the CLI does.
/// @throws InvalidArgumentError as check_morph_options, or an argument of
///         the wrong type or an unknown name.
stickmorph::MorphStickFiguresOptions to_morph_options(
    const pybind11::object& frames, const pybind11::object& steiner, const pybind11::object& weights,
    const pybind11::object& enclosure_sides, const pybind11::object& method, const pybind11::object& verify,
    const pybind11::object& rotation, const pybind11::object& turns, const pybind11::object& easing,
    const pybind11::object& correspond = pybind11::none(), const pybind11::object& pins = pybind11::none(),
    const pybind11::object& frame_check = pybind11::none(), const pybind11::object& delay = pybind11::none(),
    const pybind11::object& overlap = pybind11::none());

}  // namespace stickmorph::python
