// The module's exception classes and the translation of engine exceptions
// onto them (bindings.h).
#include <pybind11/eval.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <string>
#include <utility>
#include <vector>

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
    case sm::FigureDefect::TooFewCorners: return "too_few_corners";
    case sm::FigureDefect::CoincidentCorners: return "coincident_corners";
    case sm::FigureDefect::ClockwiseCorners: return "clockwise_corners";
    case sm::FigureDefect::ClosedWedge: return "closed_wedge";
    case sm::FigureDefect::SelfOverlappingPolygon: return "self_overlapping_polygon";
  }
  // Only reachable if the enum grows without this table: say so rather than
  // hand Python a wrong name.
  throw sm::InternalError("stickmorph module: unknown FigureDefect value " +
                          std::to_string(static_cast<int>(defect)));
}

const char* drawing_defect_name(sm::DrawingDefect defect) {
  switch (defect) {
    case sm::DrawingDefect::NoStrokes: return "no_strokes";
    case sm::DrawingDefect::TooFewPoints: return "too_few_points";
    case sm::DrawingDefect::CollapsedStroke: return "collapsed_stroke";
    case sm::DrawingDefect::NonFiniteCoordinate: return "non_finite_coordinate";
    case sm::DrawingDefect::CoordinateTooLarge: return "coordinate_too_large";
    case sm::DrawingDefect::IndexOutOfRange: return "index_out_of_range";
    case sm::DrawingDefect::Retrace: return "retrace";
    case sm::DrawingDefect::Overlap: return "overlap";
    case sm::DrawingDefect::Unresolved: return "unresolved";
  }
  throw sm::InternalError("stickmorph module: unknown DrawingDefect value " +
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
    case sm::Incompatibility::NestingDiffers: return "nesting_differs";
    case sm::Incompatibility::TopologyDiffers: return "topology_differs";
    case sm::Incompatibility::PinsUnsatisfiable: return "pins_unsatisfiable";
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
py::handle g_invalid_drawing_error;
py::handle g_incompatible_figures_error;
py::handle g_verification_error;
py::handle g_numeric_range_error;
py::handle g_internal_error;
py::handle g_cancelled_error;
py::handle g_file_error;
// errno -> the FileError subclass that also derives from the matching
// built-in OSError subclass (FileNotFoundError, ...); other errno values
// raise FileError itself.
std::vector<std::pair<int, py::handle>> g_file_errors;

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

// FileError is both an OSError and a StickMorphError: Python code expects a
// missing file to be an OSError (FileNotFoundError), and code that catches
// StickMorphError for every stickmorph failure keeps working. Defined in
// Python because it needs a __str__: OSError's would rewrite the engine's
// message as "[Errno 2] ...: 'path'" once errno and filename are set.
void bind_file_errors(py::module_& m) {
  py::dict scope;
  scope["StickMorphError"] = g_stickmorph_error;
  scope["__builtins__"] = py::module_::import("builtins");
  py::exec(R"python(
class FileError(OSError, StickMorphError):
    """A figure file that cannot be read at all: missing, a directory, no
permission, or over the size limit. An OSError (errno, strerror and filename
set) and a StickMorphError; the message is the engine's. Subclasses also derive
from the matching built-in: FigureFileNotFoundError (FileNotFoundError),
FigureFileIsADirectoryError (IsADirectoryError), FigureFilePermissionError
(PermissionError), FigureFileNotADirectoryError (NotADirectoryError)."""
    __module__ = "stickmorph"

    def __str__(self):
        return str(self.args[0]) if self.args else ""


class FigureFileNotFoundError(FileError, FileNotFoundError):
    """A figure file that does not exist."""
    __module__ = "stickmorph"


class FigureFileIsADirectoryError(FileError, IsADirectoryError):
    """A figure path that names a directory."""
    __module__ = "stickmorph"


class FigureFilePermissionError(FileError, PermissionError):
    """A figure file that may not be read."""
    __module__ = "stickmorph"


class FigureFileNotADirectoryError(FileError, NotADirectoryError):
    """A figure path through something that is not a directory."""
    __module__ = "stickmorph"
)python",
           scope);
  const auto add = [&](const char* name) {
    py::object type = scope[name];
    m.add_object(name, type);
    return type.release();  // owned for the interpreter's lifetime, as the other classes
  };
  g_file_error = add("FileError");
  g_file_errors = {{ENOENT, add("FigureFileNotFoundError")},
                   {EISDIR, add("FigureFileIsADirectoryError")},
                   {EACCES, add("FigureFilePermissionError")},
                   {ENOTDIR, add("FigureFileNotADirectoryError")}};
  // EPERM reads as a permission problem too.
  g_file_errors.emplace_back(EPERM, g_file_errors[2].second);
}

// `message` without `prefix` when it starts with it, else all of it. The
// engine's exceptions carry a role or a reason only inside their message
// (errors.h has no field for the rest), so the split happens here, once, and
// Python callers (the add-on puts object names in place of the role) read
// attributes instead of parsing the text.
std::string without_prefix(const std::string& message, const std::string& prefix) {
  if (!prefix.empty() && message.compare(0, prefix.size(), prefix) == 0) return message.substr(prefix.size());
  return message;
}

// The prefix every IncompatibleFiguresError's message puts before the
// report's reason (compatibility.cpp, figure_triangulation.cpp).
constexpr const char* kIncompatiblePrefix = "incompatible figures: ";

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
    py::object role = e.role().empty() ? py::object(py::none()) : py::object(to_str(e.role()));
    instance.attr("role") = role;
    // make_named_figure writes "<role>: <defect>"; other messages that
    // name a role ("polygon in the source: ...") do not start with it and
    // stay whole.
    instance.attr("detail") = to_str(without_prefix(e.what(), e.role().empty() ? "" : e.role() + ": "));
    PyErr_SetObject(g_invalid_figure_error.ptr(), instance.ptr());
  } catch (const sm::InvalidDrawingError& e) {
    const py::object type = py::reinterpret_borrow<py::object>(g_invalid_drawing_error);
    py::object instance = type(to_str(e.what()));
    instance.attr("defect") = drawing_defect_name(e.defect());
    const auto index = [](int value) { return value < 0 ? py::object(py::none()) : py::object(py::int_(value)); };
    instance.attr("stroke") = index(e.stroke());
    instance.attr("point") = index(e.point());
    instance.attr("other_stroke") = index(e.other_stroke());
    PyErr_SetObject(g_invalid_drawing_error.ptr(), instance.ptr());
  } catch (const sm::FileError& e) {
    // An OSError like the ones open() raises: errno, strerror and filename
    // set, so `except FileNotFoundError` and `e.filename` work; the message
    // stays the engine's (FileError.__str__), the same text the CLI prints.
    py::handle type = g_file_error;
    for (const auto& [number, subclass] : g_file_errors)
      if (number == e.error_number()) type = subclass;
    py::object instance = py::reinterpret_borrow<py::object>(type)(to_str(e.what()));
    instance.attr("errno") = e.error_number();
    instance.attr("strerror") = to_str(std::strerror(e.error_number()));
    instance.attr("filename") = py::module_::import("os").attr("fsdecode")(py::bytes(e.path()));
    PyErr_SetObject(type.ptr(), instance.ptr());
  } catch (const sm::JsonError& e) {
    raise_with_message(g_json_error, e.what());
  } catch (const sm::InvalidArgumentError& e) {
    raise_with_message(g_invalid_argument_error, e.what());
  } catch (const sm::IncompatibleFiguresError& e) {
    const py::object type = py::reinterpret_borrow<py::object>(g_incompatible_figures_error);
    py::object instance = type(to_str(e.what()));
    instance.attr("kind") = incompatibility_name(e.kind());
    instance.attr("vertices") = to_list(e.vertices());
    instance.attr("reason") = to_str(without_prefix(e.what(), kIncompatiblePrefix));
    PyErr_SetObject(g_incompatible_figures_error.ptr(), instance.ptr());
  } catch (const sm::VerificationError& e) {
    raise_with_message(g_verification_error, e.what());
  } catch (const sm::NumericRangeError& e) {
    raise_with_message(g_numeric_range_error, e.what());
  } catch (const sm::InternalError& e) {
    raise_with_message(g_internal_error, e.what());
  } catch (const sm::CancelledError& e) {
    raise_with_message(g_cancelled_error, e.what());
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
      "  defect    what is wrong, e.g. 'crossing_edges', 'vertex_on_edge'\n"
      "  vertices  list of the vertex indices named in the message\n"
      "  edges     list of the edge indices named in the message\n"
      "  role      'source' or 'target' when the figure is one of a pair, else None\n"
      "  detail    the message without its leading 'source: ' or 'target: ' (the whole\n"
      "            message when it has none), to name the figure in the caller's words");
  for (const char* attribute : {"defect", "vertices", "edges", "role", "detail"})
    py::setattr(g_invalid_figure_error, attribute, py::none());
  g_invalid_drawing_error = new_exception(
      m, "InvalidDrawingError", g_stickmorph_error,
      "A drawing that clean_drawing or clean_figure cannot make into a stick figure.\n\n"
      "Attributes (set on instances raised by stickmorph; None on the class):\n"
      "  defect        what is wrong: 'no_strokes', 'too_few_points', 'collapsed_stroke',\n"
      "                'non_finite_coordinate', 'coordinate_too_large', 'index_out_of_range',\n"
      "                'retrace', 'overlap' or 'unresolved'\n"
      "  stroke        the stroke (a figure's edge) named, or None\n"
      "  point         the point's index within that stroke (a figure's vertex), or None\n"
      "  other_stroke  the second stroke of an overlap, or None");
  for (const char* attribute : {"defect", "stroke", "point", "other_stroke"})
    py::setattr(g_invalid_drawing_error, attribute, py::none());
  g_invalid_argument_error = new_exception(
      m, "InvalidArgumentError", g_stickmorph_error,
      "An argument of the wrong shape or type, independently of geometry.");
  g_incompatible_figures_error = new_exception(
      m, "IncompatibleFiguresError", g_stickmorph_error,
      "Two figures that an operation needs to be compatible are not.\n\n"
      "Attributes (set on instances raised by stickmorph; None on the class):\n"
      "  kind      why not, as CompatibilityReport.kind, e.g. 'mirror_image'\n"
      "  vertices  list of the vertex indices named in the message\n"
      "  reason    as CompatibilityReport.reason: the message without its leading\n"
      "            'incompatible figures: '");
  for (const char* attribute : {"kind", "vertices", "reason"})
    py::setattr(g_incompatible_figures_error, attribute, py::none());
  g_verification_error = new_exception(
      m, "VerificationError", g_stickmorph_error,
      "A result failed exact verification and could not be repaired, so none is returned; the "
      "message names the face and the triangle.");
  g_numeric_range_error = new_exception(
      m, "NumericRangeError", g_stickmorph_error,
      "A pair whose coordinates the engine's floating-point stages cannot carry (for example\n"
      "source and target sizes further apart than the method resolves); the message names the\n"
      "ratio or magnitude and the supported limit.");
  // Not a StickMorphError: it is never the caller's fault, so code catching
  // ValueError for bad input must not swallow it.
  g_internal_error = new_exception(
      m, "InternalError", PyExc_RuntimeError,
      "An internal consistency check of stickmorph failed: a bug, never the caller's fault.");
  // Neither a StickMorphError nor a RuntimeError: the caller asked for it,
  // so code that reports bad input or bugs must not catch it as either.
  g_cancelled_error = new_exception(
      m, "CancelledError", PyExc_Exception,
      "The call was cancelled through its stickmorph.Progress (Progress.cancel()); it stopped at the\n"
      "engine's next check and returned nothing. The message names the stage it stopped in.");

  bind_file_errors(m);
  py::register_local_exception_translator(translate_exception);
}

}  // namespace stickmorph::python
