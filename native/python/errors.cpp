// The module's exception classes and the translation of engine exceptions
// onto them (bindings.h).
#include <exception>
#include <string>

#include "bindings.h"
#include "conversions.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"

namespace stickmorph::python {

const char* defect_name(sm::FigureDefect defect) {
  switch (defect) {
    case sm::FigureDefect::NoVertices: return "no_vertices";
    case sm::FigureDefect::NonFiniteCoordinate: return "non_finite_coordinate";
    case sm::FigureDefect::CoordinateTooLarge: return "coordinate_too_large";
    case sm::FigureDefect::EdgeIndexOutOfRange: return "edge_index_out_of_range";
    case sm::FigureDefect::SelfLoop: return "self_loop";
    case sm::FigureDefect::DuplicateEdge: return "duplicate_edge";
    case sm::FigureDefect::CoincidentVertices: return "coincident_vertices";
    case sm::FigureDefect::CrossingEdges: return "crossing_edges";
    case sm::FigureDefect::OverlappingEdges: return "overlapping_edges";
    case sm::FigureDefect::VertexOnEdge: return "vertex_on_edge";
    case sm::FigureDefect::Disconnected: return "disconnected";
  }
  // Only reachable if the enum grows without this table: say so rather than
  // hand Python a wrong name.
  throw sm::InternalError("stickmorph module: unknown FigureDefect value " +
                          std::to_string(static_cast<int>(defect)));
}

const char* incompatibility_name(sm::Incompatibility kind) {
  switch (kind) {
    case sm::Incompatibility::None: return "none";
    case sm::Incompatibility::VertexCountDiffers: return "vertex_count_differs";
    case sm::Incompatibility::EdgeSetDiffers: return "edge_set_differs";
    case sm::Incompatibility::MirrorImage: return "mirror_image";
    case sm::Incompatibility::RotationDiffers: return "rotation_differs";
    case sm::Incompatibility::ExteriorDiffers: return "exterior_differs";
  }
  throw sm::InternalError("stickmorph module: unknown Incompatibility value " +
                          std::to_string(static_cast<int>(kind)));
}


namespace {

// The Python exception classes. They are created once when the module is
// imported and owned by the module object; the handles deliberately hold a
// reference that is never released, because the translator may run at any
// time while the interpreter lives and static py::object destructors would run
// after the interpreter is gone.
py::handle g_stickmorph_error;
py::handle g_json_error;
py::handle g_invalid_figure_error;
py::handle g_invalid_argument_error;
py::handle g_incompatible_figures_error;
py::handle g_verification_error;
py::handle g_internal_error;

py::handle new_exception(py::module_& m, const char* name, py::handle base, const char* doc) {
  const std::string qualified = std::string("stickmorph.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base.ptr(), nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.add_object(name, py::handle(type));
  return py::handle(type);
}

// Not named set_error: pybind11 2.12+ has pybind11::set_error(handle, const char*),
// and argument-dependent lookup on py::handle makes an unqualified call ambiguous.
void raise_with_message(py::handle type, const char* message) {
  PyErr_SetObject(type.ptr(), to_str(message).ptr());
}

void translate_exception(std::exception_ptr pointer) {
  try {
    if (pointer) std::rethrow_exception(pointer);
  } catch (const sm::InvalidFigureError& e) {
    // Build the instance here so that the attributes travel with it; a class
    // alone (PyErr_SetString) would carry only the message.
    const py::object type = py::reinterpret_borrow<py::object>(g_invalid_figure_error);
    py::object instance = type(to_str(e.what()));
    instance.attr("defect") = defect_name(e.defect());
    instance.attr("vertices") = to_list(e.vertices());
    instance.attr("edges") = to_list(e.edges());
    PyErr_SetObject(g_invalid_figure_error.ptr(), instance.ptr());
  } catch (const sm::JsonError& e) {
    raise_with_message(g_json_error, e.what());
  } catch (const sm::InvalidArgumentError& e) {
    raise_with_message(g_invalid_argument_error, e.what());
  } catch (const sm::IncompatibleFiguresError& e) {
    raise_with_message(g_incompatible_figures_error, e.what());
  } catch (const sm::VerificationError& e) {
    raise_with_message(g_verification_error, e.what());
  } catch (const sm::InternalError& e) {
    raise_with_message(g_internal_error, e.what());
  } catch (const sm::Error& e) {
    raise_with_message(g_stickmorph_error, e.what());
  }
}

}  // namespace

void bind_errors(py::module_& m) {
  g_stickmorph_error = new_exception(
      m, "StickMorphError", PyExc_ValueError,
      "Base of the errors stickmorph reports about its input (a ValueError).");
  g_json_error = new_exception(
      m, "JsonError", g_stickmorph_error,
      "A figure file that is not valid JSON or has the wrong shape; the message names line and "
      "column.");
  g_invalid_figure_error = new_exception(
      m, "InvalidFigureError", g_stickmorph_error,
      "A figure that is not a connected straight-line plane graph.\n\n"
      "Attributes (set on instances raised by stickmorph; None on the class):\n"
      "  defect    what is wrong, e.g. 'crossing_edges', 'disconnected'\n"
      "  vertices  list of the vertex indices named in the message\n"
      "  edges     list of the edge indices named in the message");
  for (const char* attribute : {"defect", "vertices", "edges"})
    py::setattr(g_invalid_figure_error, attribute, py::none());
  g_invalid_argument_error = new_exception(
      m, "InvalidArgumentError", g_stickmorph_error,
      "An argument of the wrong shape or type, independently of geometry.");
  g_incompatible_figures_error = new_exception(
      m, "IncompatibleFiguresError", g_stickmorph_error,
      "Two figures that an operation needs to be compatible are not.");
  g_verification_error = new_exception(
      m, "VerificationError", g_stickmorph_error,
      "A result failed exact verification and could not be repaired, so none is returned; the "
      "message names the face and the triangle.");
  // Not a StickMorphError: it is never the caller's fault, so code catching
  // ValueError for bad input must not swallow it.
  g_internal_error = new_exception(
      m, "InternalError", PyExc_RuntimeError,
      "An internal consistency check of stickmorph failed: a bug, never the caller's fault.");

  py::register_local_exception_translator(translate_exception);
}

}  // namespace stickmorph::python
