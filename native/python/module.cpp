// The `stickmorph` Python module: a thin shell over the C++ engine.
//
// Everything this file does is conversion: NumPy arrays and Python objects in,
// engine calls, NumPy arrays and Python objects out, and engine exceptions onto
// Python exception classes. Validation, geometry and compatibility decisions
// all live in the engine, so the module, the CLI and the C++ tests agree.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "stickmorph/argument_limits.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/morph.h"
#include "stickmorph/stick_figure.h"

namespace py = pybind11;
namespace sm = stickmorph;

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

// Engine text as a Python str. Messages can carry bytes that are not UTF-8
// (a file name, a name field read from a file); showing them as \x escapes
// keeps the exception intact where a strict decode would replace it with a
// UnicodeDecodeError.
py::str to_str(const std::string& text) {
  PyObject* object = PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()),
                                          "backslashreplace");
  if (object == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(object);
}

// Not named set_error: pybind11 2.12+ has pybind11::set_error(handle, const char*),
// and argument-dependent lookup on py::handle makes an unqualified call ambiguous.
void raise_with_message(py::handle type, const char* message) {
  PyErr_SetObject(type.ptr(), to_str(message).ptr());
}

py::list to_list(const std::vector<int>& values) {
  py::list list;
  for (int v : values) list.append(v);
  return list;
}

template <typename Int>
py::array_t<std::int64_t> to_int64_array(const std::vector<Int>& values) {
  py::array_t<std::int64_t> array(static_cast<py::ssize_t>(values.size()));
  auto out = array.mutable_unchecked<1>();
  for (std::size_t i = 0; i < values.size(); ++i) out(static_cast<py::ssize_t>(i)) = values[i];
  return array;
}

// The Python-side repr of a shape tuple, e.g. "(5, 3)" or "(2,)", so that
// messages read exactly like NumPy's own.
std::string shape_text(const py::array& array) {
  return py::str(array.attr("shape")).cast<std::string>();
}

std::string dtype_text(const py::array& array) {
  return py::str(array.dtype()).cast<std::string>();
}

py::array as_array(py::handle object, const std::string& name) {
  try {
    return py::module_::import("numpy").attr("asarray")(object).cast<py::array>();
  } catch (py::error_already_set& e) {
    // Ragged nested lists and similar: NumPy's own explanation is the most
    // precise one available.
    throw sm::InvalidArgumentError(name + " cannot be converted to an array: " +
                                   py::str(e.value()).cast<std::string>());
  }
}

// An (n, 2) array, or an empty one-dimensional array (what `[]` becomes).
bool has_pair_shape(const py::array& array) {
  if (array.ndim() == 2) return array.shape(1) == 2;
  return array.ndim() == 1 && array.shape(0) == 0;
}

std::vector<sm::Vec2> to_vertices(py::handle object, const std::string& name) {
  const py::array array = as_array(object, name);
  if (!has_pair_shape(array))
    throw sm::InvalidArgumentError(name + " must have shape (#V, 2), got " + shape_text(array));
  // Booleans, strings, objects and complex numbers convert to float64 only
  // by accident or not at all; coordinates are real numbers.
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f')
    throw sm::InvalidArgumentError(name + " must hold real numbers, got dtype " + dtype_text(array));
  const auto values =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!values) throw py::error_already_set();
  const py::ssize_t n = array.ndim() == 2 ? array.shape(0) : 0;
  const double* data = values.data();
  std::vector<sm::Vec2> vertices(static_cast<std::size_t>(n));
  for (py::ssize_t i = 0; i < n; ++i) vertices[i] = {data[2 * i], data[2 * i + 1]};
  return vertices;
}

// Reads `count` integer indices, in C order, from an integer array or from a
// float array whose values are all exact integers (never rounded or
// truncated). `element(i)` names flat element i in messages, e.g. "edge 3" or
// "corner 5"; `name` names the argument when its dtype is wrong.
template <typename Element>
std::vector<std::int64_t> to_int64_indices(const py::array& array, py::ssize_t count,
                                           const std::string& name, const Element& element) {
  std::vector<std::int64_t> indices(static_cast<std::size_t>(count));
  const auto not_int64 = [&](py::ssize_t i, const std::string& value) {
    return sm::InvalidArgumentError(element(i) + ": index " + value +
                                    " does not fit in a 64-bit signed integer");
  };

  const char kind = array.dtype().kind();
  if (kind == 'i' || (kind == 'u' && array.dtype().itemsize() < 8)) {
    // Every such value is an int64 already.
    const auto values =
        py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
    if (!values) throw py::error_already_set();
    const std::int64_t* data = values.data();
    for (py::ssize_t i = 0; i < count; ++i) indices[i] = data[i];
  } else if (kind == 'u') {
    // uint64 above INT64_MAX would wrap to a negative index: refuse instead.
    const auto values =
        py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(array);
    if (!values) throw py::error_already_set();
    const std::uint64_t* data = values.data();
    for (py::ssize_t i = 0; i < count; ++i) {
      const std::uint64_t v = data[i];
      if (v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        throw not_int64(i, std::to_string(v));
      indices[i] = static_cast<std::int64_t>(v);
    }
  } else if (kind == 'f' && array.dtype().itemsize() <= 8) {
    // Float arrays are common (np.loadtxt, JSON through Python): accept them
    // when every value is exactly an integer, never round or truncate. Long
    // double is excluded because converting it to double could itself round
    // a non-integer onto an integer.
    const auto values =
        py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
    if (!values) throw py::error_already_set();
    const double* data = values.data();
    // 2^63 is exactly representable; every integral double in [-2^63, 2^63)
    // converts to int64 without loss.
    constexpr double kTwo63 = 9223372036854775808.0;
    for (py::ssize_t i = 0; i < count; ++i) {
      const double v = data[i];
      // Python's repr: the shortest text that reads back as the same value.
      const auto text = [v] { return py::repr(py::float_(v)).cast<std::string>(); };
      if (!std::isfinite(v) || v != std::floor(v))
        throw sm::InvalidArgumentError(element(i) + ": index " + text() + " is not an integer");
      if (v < -kTwo63 || v >= kTwo63) throw not_int64(i, text());
      indices[i] = static_cast<std::int64_t>(v);
    }
  } else {
    throw sm::InvalidArgumentError(name + " must hold integer vertex indices, got dtype " +
                                   dtype_text(array));
  }
  return indices;
}

std::vector<std::array<std::int64_t, 2>> to_edges(py::handle object, const std::string& name) {
  const py::array array = as_array(object, name);
  if (!has_pair_shape(array))
    throw sm::InvalidArgumentError(name + " must have shape (#E, 2), got " + shape_text(array));
  const py::ssize_t n = array.ndim() == 2 ? array.shape(0) : 0;
  // Messages about one row name it the way the engine names edges; a second
  // edge list (check_compatibility's target_edges) is told apart by a prefix.
  const std::string row_prefix = name == "edges" ? std::string("edge ") : name + ": edge ";
  const std::vector<std::int64_t> values = to_int64_indices(
      array, 2 * n, name, [&](py::ssize_t i) { return row_prefix + std::to_string(i / 2); });
  std::vector<std::array<std::int64_t, 2>> edges(static_cast<std::size_t>(n));
  for (py::ssize_t i = 0; i < n; ++i) edges[i] = {values[2 * i], values[2 * i + 1]};
  return edges;
}

// A polygon's corner sequence: a one-dimensional array of vertex indices,
// each checked against the number of vertices here, because the engine
// indexes positions by them without checking.
std::vector<int> to_corners(py::handle object, std::size_t vertex_count) {
  const py::array array = as_array(object, "corners");
  if (array.ndim() != 1)
    throw sm::InvalidArgumentError("corners must have shape (#C,), got " + shape_text(array));
  const std::vector<std::int64_t> values = to_int64_indices(
      array, array.shape(0), "corners",
      [](py::ssize_t k) { return "corner " + std::to_string(k); });
  std::vector<int> corners(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (values[k] < 0 || static_cast<std::uint64_t>(values[k]) >= vertex_count)
      throw sm::InvalidArgumentError("corner " + std::to_string(k) + ": vertex index " +
                                     std::to_string(values[k]) + " is out of range for " +
                                     std::to_string(vertex_count) + " vertices");
    corners[k] = static_cast<int>(values[k]);
  }
  return corners;
}

// Converts and validates one figure. Validation (exact predicates over all
// nearby edge pairs) takes noticeable time on large figures, so it runs
// without the GIL; the conversions before it need the GIL.
sm::StickFigure make_figure(py::handle vertices, py::handle edges, const std::string& vertices_name,
                            const std::string& edges_name) {
  std::vector<sm::Vec2> positions = to_vertices(vertices, vertices_name);
  const std::vector<std::array<std::int64_t, 2>> indices = to_edges(edges, edges_name);
  py::gil_scoped_release release;
  return sm::make_stick_figure(std::move(positions), indices);
}

// check_compatibility validates two figures from one call, so a defect is
// ambiguous unless the message says which figure it is in; the CLI likewise
// prefixes the file name. Defect and indices are kept.
sm::StickFigure make_named_figure(py::handle vertices, py::handle edges,
                                  const std::string& vertices_name, const std::string& edges_name,
                                  const std::string& figure) {
  try {
    return make_figure(vertices, edges, vertices_name, edges_name);
  } catch (const sm::InvalidFigureError& e) {
    throw sm::InvalidFigureError(e.defect(), figure + ": " + e.what(), e.vertices(), e.edges());
  }
}

// The engine's polygon routines take positions as given; like
// make_stick_figure, refuse coordinates its floating-point work cannot handle,
// with the same defects and wording. `role` is "source" or "target", as in
// the engine's messages about a polygon pair.
void check_polygon_coordinates(const std::vector<sm::Vec2>& positions, const std::string& role) {
  const char* axis[2] = {"x", "y"};
  const std::string prefix = "polygon in the " + role + ": vertex ";
  for (std::size_t v = 0; v < positions.size(); ++v)
    for (int c = 0; c < 2; ++c) {
      const double value = positions[v][c];
      if (!std::isfinite(value))
        throw sm::InvalidFigureError(sm::FigureDefect::NonFiniteCoordinate,
                                     prefix + std::to_string(v) + " has a non-finite coordinate (" +
                                         axis[c] + " = " + sm::format_double(value) + ")",
                                     {static_cast<int>(v)});
      if (std::abs(value) > sm::kMaxCoordinateMagnitude)
        throw sm::InvalidFigureError(sm::FigureDefect::CoordinateTooLarge,
                                     prefix + std::to_string(v) + " has coordinate " + axis[c] +
                                         " = " + sm::format_double(value) +
                                         ", beyond the supported magnitude " +
                                         sm::format_double(sm::kMaxCoordinateMagnitude),
                                     {static_cast<int>(v)});
    }
}

py::array_t<double> to_point_array(const std::vector<sm::Vec2>& points) {
  const auto n = static_cast<py::ssize_t>(points.size());
  py::array_t<double> array({n, py::ssize_t{2}});
  auto out = array.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    out(i, 0) = points[i][0];
    out(i, 1) = points[i][1];
  }
  return array;
}

// An integer argument such as frames or enclosure_sides, as a Python int of
// any size (so 10**12 is reported as out of range, not as a TypeError), or
// anything with __index__ (NumPy integers). Booleans and floats are refused:
// frames=True or frames=7.5 is a mistake, not a count.
long long to_count(const py::object& object, const std::string& name) {
  if (PyBool_Check(object.ptr()) || !PyIndex_Check(object.ptr()))
    throw sm::InvalidArgumentError(name + " must be an integer, got " +
                                   py::str(py::type::of(object).attr("__name__")).cast<std::string>());
  const auto value = py::reinterpret_steal<py::object>(PyNumber_Index(object.ptr()));
  if (!value) throw py::error_already_set();
  int overflow = 0;
  const long long result = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
  if (result == -1 && PyErr_Occurred()) throw py::error_already_set();
  if (overflow > 0) return std::numeric_limits<long long>::max();
  if (overflow < 0) return std::numeric_limits<long long>::min();
  return result;
}

// The name of a choice such as steiner= or method=. Declared as a Python
// object rather than std::string so that a wrong type (None, a number) is an
// InvalidArgumentError naming the argument, not pybind11's multi-line
// TypeError listing the whole signature.
std::string to_name(const py::object& object, const std::string& name) {
  if (!py::isinstance<py::str>(object))
    throw sm::InvalidArgumentError(name + " must be a str, got " +
                                   py::str(py::type::of(object).attr("__name__")).cast<std::string>());
  return object.cast<std::string>();
}

// A yes/no argument such as verify=. Only True and False (and NumPy's
// booleans): verify="no" would be truthy, the opposite of what was meant.
bool to_flag(const py::object& object, const std::string& name) {
  if (PyBool_Check(object.ptr())) return object.ptr() == Py_True;
  const py::object numpy_bool = py::module_::import("numpy").attr("bool_");
  if (py::isinstance(object, numpy_bool)) return object.cast<bool>();
  throw sm::InvalidArgumentError(name + " must be True or False, got " +
                                 py::str(py::type::of(object).attr("__name__")).cast<std::string>());
}

// The frame count, checked before any work with the engine's own wording
// (morph_triangulation checks it too, but only after triangulating).
int to_frame_count(const py::object& object) {
  const long long frames = to_count(object, "frames");
  if (frames < 2 || frames > sm::kMaxMorphFrames)
    throw sm::InvalidArgumentError("the number of frames must be between 2 and " +
                                   std::to_string(sm::kMaxMorphFrames) + ", got " +
                                   py::str(object).cast<std::string>());
  return static_cast<int>(frames);
}

// Steiner method and enclosure, as the CLI's --steiner and --enclosure-sides.
// Checked here, not only in triangulate_figures, so that the linear morph
// (which triangulates nothing) refuses the same bad arguments.
sm::FigureTriangulationOptions to_triangulation_options(const std::string& steiner,
                                                        const py::object& enclosure_sides) {
  sm::FigureTriangulationOptions options;
  options.method = sm::parse_steiner_method(steiner);
  const long long sides = to_count(enclosure_sides, "enclosure_sides");
  if (sides < 3)
    throw sm::InvalidArgumentError("the enclosure needs at least 3 sides, got " +
                                   py::str(enclosure_sides).cast<std::string>());
  if (sides > sm::kMaxEnclosureSides)
    throw sm::InvalidArgumentError("the enclosure can have at most " + std::to_string(sm::kMaxEnclosureSides) +
                                   " sides, got " + py::str(enclosure_sides).cast<std::string>());
  options.enclosure_sides = static_cast<int>(sides);
  return options;
}

// The source and target figures of a pair, validated source first; a defect
// message starts with "source: " or "target: " (make_named_figure).
std::pair<sm::StickFigure, sm::StickFigure> make_figure_pair(const py::object& source_vertices,
                                                             const py::object& target_vertices,
                                                             const py::object& edges,
                                                             const py::object& target_edges,
                                                             const std::string& source_name,
                                                             const std::string& target_name) {
  sm::StickFigure source = make_named_figure(source_vertices, edges, source_name, "edges", "source");
  sm::StickFigure target =
      target_edges.is_none()
          ? make_named_figure(target_vertices, edges, target_name, "edges", "target")
          : make_named_figure(target_vertices, target_edges, target_name, "target_edges", "target");
  return {std::move(source), std::move(target)};
}

// #T by 3 node indices as an int64 array.
py::array_t<std::int64_t> to_triangle_array(const std::vector<std::array<int, 3>>& triangles) {
  const auto t = static_cast<py::ssize_t>(triangles.size());
  py::array_t<std::int64_t> out({t, py::ssize_t{3}});
  auto w = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < t; ++i)
    for (py::ssize_t j = 0; j < 3; ++j) w(i, j) = triangles[i][j];
  return out;
}

// The FigureTriangulation as the dict documented on triangulate_figures
// (FORMAT.md's triangulation object plus the triangulation's statistics).
py::dict triangulation_dict(const sm::FigureTriangulation& triangulation,
                            const sm::FigureTriangulationStats& stats) {
  const py::array_t<std::int64_t> triangles = to_triangle_array(triangulation.triangles);
  py::dict statistics;
  statistics["interior_faces"] = stats.interior_faces;
  statistics["cut_bends"] = stats.cut_bends;
  statistics["interior_steiner"] = stats.interior_steiner;
  statistics["min_angle"] = stats.min_angle;
  py::dict result;
  result["figure_vertices"] = triangulation.figure_vertices;
  result["enclosure_vertices"] = triangulation.enclosure_vertices;
  result["steiner_vertices"] = triangulation.steiner_vertices;
  result["source"] = to_point_array(triangulation.source);
  result["target"] = to_point_array(triangulation.target);
  result["triangles"] = triangles;
  result["stats"] = statistics;
  return result;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The first n positions of every frame as one (N, n, 2) float64 array: the
// barycentric morph's frames hold all triangulation nodes, the figure's
// vertices first.
py::array_t<double> figure_frames(const std::vector<std::vector<sm::Vec2>>& frames, std::size_t n) {
  const auto count = static_cast<py::ssize_t>(frames.size());
  py::array_t<double> array({count, static_cast<py::ssize_t>(n), py::ssize_t{2}});
  double* out = array.mutable_data();
  {
    py::gil_scoped_release release;
    for (const std::vector<sm::Vec2>& frame : frames) {
      if (frame.size() < n)
        throw sm::InternalError("stickmorph module: a morph frame holds " + std::to_string(frame.size()) +
                                " positions, fewer than the figure's " + std::to_string(n) + " vertices");
      for (std::size_t v = 0; v < n; ++v) {
        *out++ = frame[v][0];
        *out++ = frame[v][1];
      }
    }
  }
  return array;
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

const char* const kModuleDoc = R"doc(Morphing of stick figures (connected straight-line plane graphs).

Surazhsky & Gotsman, "Morphing Stick Figures Using Optimized Compatible
Triangulations", Pacific Graphics 2001. A figure is given as

  vertices  #V by 2 array-like of float64 coordinates
  edges     #E by 2 array-like of integer vertex indices (0-based, undirected)

Every function validates its figures first and raises InvalidFigureError
naming the offending vertex and edge indices. Exception messages are the
engine's, the same text the `stickmorph` command prints after "error: ".)doc";

}  // namespace

PYBIND11_MODULE(stickmorph, m) {
  m.doc() = kModuleDoc;
  // Keep in step with project(VERSION) in the top-level CMakeLists.txt.
  m.attr("__version__") = STICKMORPH_VERSION;  // from CMake

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

  py::class_<sm::CompatibilityReport>(m, "CompatibilityReport",
                                      "The answer of check_compatibility. True iff compatible.")
      .def_property_readonly("compatible", &sm::CompatibilityReport::compatible,
                             "True iff the two figures are compatible.")
      .def_property_readonly(
          "kind",
          [](const sm::CompatibilityReport& r) { return incompatibility_name(r.kind); },
          "Why not: 'none', 'vertex_count_differs', 'edge_set_differs', 'mirror_image', "
          "'rotation_differs' or 'exterior_differs'.")
      .def_property_readonly(
          "reason", [](const sm::CompatibilityReport& r) { return r.reason; },
          "Explanation naming vertices; empty when compatible.")
      .def_property_readonly(
          "vertices", [](const sm::CompatibilityReport& r) { return to_list(r.vertices); },
          "List of the vertex indices named in the reason.")
      .def("__bool__", &sm::CompatibilityReport::compatible)
      .def("__repr__", [](const sm::CompatibilityReport& r) {
        if (r.compatible()) return std::string("CompatibilityReport(compatible=True)");
        return "CompatibilityReport(compatible=False, kind='" +
               std::string(incompatibility_name(r.kind)) +
               "', vertices=" + py::repr(to_list(r.vertices)).cast<std::string>() +
               ", reason=" + py::repr(py::str(r.reason)).cast<std::string>() + ")";
      });

  m.def(
      "validate",
      [](const py::object& vertices, const py::object& edges) { make_figure(vertices, edges, "vertices", "edges"); },
      py::arg("vertices"), py::arg("edges"),
      R"doc(Checks that a figure is a valid stick figure.

Args:
  vertices: #V by 2 float64 array-like of coordinates.
  edges: #E by 2 integer array-like of vertex indices ([] for a single vertex).

Returns:
  None.

Raises:
  InvalidFigureError: the figure is not a connected straight-line plane graph;
    its `defect`, `vertices` and `edges` say what and where.
  InvalidArgumentError: an array of the wrong shape or type.)doc");

  m.def(
      "load_figure",
      [](const py::object& path) {
        const py::module_ os = py::module_::import("os");
        if (!py::isinstance<py::str>(path) && !py::isinstance<py::bytes>(path) &&
            !py::isinstance(path, os.attr("PathLike")))
          throw sm::InvalidArgumentError("path must be a str, bytes or os.PathLike, got " +
                                         py::str(py::type::of(path).attr("__name__")).cast<std::string>());
        // os.fsencode gives the bytes the OS uses for str (surrogate escapes
        // included), bytes and os.PathLike alike.
        py::object encoded;
        try {
          encoded = os.attr("fsencode")(path);
        } catch (py::error_already_set& e) {
          // A PathLike whose __fspath__ returns something else.
          throw sm::InvalidArgumentError("path cannot be used as a file name: " +
                                         py::str(e.value()).cast<std::string>());
        }
        const std::string file = encoded.cast<std::string>();
        // The C library stops at a NUL byte, so "a\0b" would open "a".
        if (file.find('\0') != std::string::npos)
          throw sm::InvalidArgumentError("path contains a NUL byte");
        if (file.empty()) throw sm::InvalidArgumentError("path is an empty file name");
        sm::StickFigure figure;
        {
          py::gil_scoped_release release;
          figure = sm::read_figure_file(file);
        }
        const auto n = static_cast<py::ssize_t>(figure.vertices.size());
        const auto e = static_cast<py::ssize_t>(figure.edges.size());
        py::array_t<double> vertices({n, py::ssize_t{2}});
        auto v = vertices.mutable_unchecked<2>();
        for (py::ssize_t i = 0; i < n; ++i) {
          v(i, 0) = figure.vertices[i][0];
          v(i, 1) = figure.vertices[i][1];
        }
        py::array_t<std::int64_t> edges({e, py::ssize_t{2}});
        auto w = edges.mutable_unchecked<2>();
        for (py::ssize_t i = 0; i < e; ++i) {
          w(i, 0) = figure.edges[i][0];
          w(i, 1) = figure.edges[i][1];
        }
        py::dict result;
        result["name"] = to_str(figure.name);
        result["vertices"] = vertices;
        result["edges"] = edges;
        return result;
      },
      py::arg("path"),
      R"doc(Reads and validates a stick figure file (JSON, see docs/CLI.md).

Args:
  path: str or os.PathLike.

Returns:
  dict with "name" (str), "vertices" (#V by 2 float64 ndarray) and
  "edges" (#E by 2 int64 ndarray), in file order.

Raises:
  JsonError: unreadable file, malformed JSON or a field of the wrong shape.
  InvalidFigureError: the file describes an invalid figure.)doc");

  m.def(
      "rotation_system",
      [](const py::object& vertices, const py::object& edges) {
        const sm::StickFigure figure = make_figure(vertices, edges, "vertices", "edges");
        sm::RotationSystem rotation;
        {
          py::gil_scoped_release release;
          rotation = sm::rotation_system(figure);
        }
        py::list result;
        for (const std::vector<int>& darts : rotation.outgoing_ccw) {
          std::vector<int> neighbours;
          neighbours.reserve(darts.size());
          for (int dart : darts) neighbours.push_back(sm::dart_head(figure, dart));
          result.append(to_int64_array(neighbours));
        }
        return result;
      },
      py::arg("vertices"), py::arg("edges"),
      R"doc(The cyclic order of edges around each vertex.

Args:
  vertices: #V by 2 float64 array-like of coordinates.
  edges: #E by 2 integer array-like of vertex indices.

Returns:
  list of #V int64 ndarrays; entry v holds the neighbours of vertex v in
  counter-clockwise order, starting from the first direction at or after the
  positive x axis. Decided by exact predicates.

Raises:
  InvalidFigureError, InvalidArgumentError: as validate().)doc");

  m.def(
      "decompose",
      [](const py::object& vertices, const py::object& edges) {
        const sm::StickFigure figure = make_figure(vertices, edges, "vertices", "edges");
        sm::Decomposition decomposition;
        {
          py::gil_scoped_release release;
          decomposition = sm::decompose(figure);
        }
        py::list result;
        for (const sm::CyclicSequence& sequence : decomposition.sequences) {
          py::dict entry;
          entry["vertices"] = to_int64_array(sequence.vertices);
          entry["exterior"] = sequence.exterior;
          entry["angle_sum"] = sequence.angle_sum;
          result.append(entry);
        }
        return result;
      },
      py::arg("vertices"), py::arg("edges"),
      R"doc(Decomposes a figure into cyclic sequences (paper, Algorithm 1).

Args:
  vertices: #V by 2 float64 array-like of coordinates.
  edges: #E by 2 integer array-like of vertex indices.

Returns:
  list of dicts, one per cyclic sequence in the order Algorithm 1 finds them:
    "vertices"  int64 ndarray of the n vertices along the sequence; a vertex
                repeats where the walk passes it more than once
    "exterior"  True for the one sequence bounding the unbounded region
    "angle_sum" float, sum of the n polygon angles: pi*(n-2) for an
                interior sequence, pi*(n+2) for the exterior one
  Interior sequences run counter-clockwise, the exterior one clockwise. A
  single vertex without edges gives one exterior sequence [0], angle_sum 0.

Raises:
  InvalidFigureError, InvalidArgumentError: as validate().)doc");

  m.def(
      "check_compatibility",
      [](const py::object& source_vertices, const py::object& target_vertices,
         const py::object& edges, const py::object& target_edges) {
        const sm::StickFigure source =
            make_named_figure(source_vertices, edges, "source_vertices", "edges", "source");
        const sm::StickFigure target =
            target_edges.is_none()
                ? make_named_figure(target_vertices, edges, "target_vertices", "edges", "target")
                : make_named_figure(target_vertices, target_edges, "target_vertices",
                                    "target_edges", "target");
        py::gil_scoped_release release;
        return sm::check_compatibility(source, target);
      },
      py::arg("source_vertices"), py::arg("target_vertices"), py::arg("edges"),
      py::arg("target_edges") = py::none(),
      R"doc(Decides whether two corresponding figures are compatible (paper, 2.1).

Vertex i of the source corresponds to vertex i of the target. Compatible
figures have the same cyclic sequences with the same orientation and the same
exterior sequence.

Args:
  source_vertices: #V by 2 float64 array-like, source coordinates.
  target_vertices: #V by 2 float64 array-like, target coordinates.
  edges: #E by 2 integer array-like of vertex indices of the source (and of
    the target unless target_edges is given).
  target_edges: optional #E by 2 integer array-like, the target's edge list;
    order and direction may differ from edges.

Returns:
  CompatibilityReport: truthy iff compatible; `kind`, `reason` and `vertices`
  say why not.

Raises:
  InvalidFigureError: the source or the target is invalid (the message
    starts with "source: " or "target: ").
  InvalidArgumentError: an array of the wrong shape or type.)doc");

  m.def(
      "compatible_triangulation",
      [](const py::object& source, const py::object& target, const py::object& steiner,
         const py::object& corners, const py::object& smoothing_rounds) {
        sm::CompatibleTriangulationOptions options;
        options.method = sm::parse_steiner_method(to_name(steiner, "steiner"));
        const long long rounds = to_count(smoothing_rounds, "smoothing_rounds");
        if (rounds < 0)
          throw sm::InvalidArgumentError("smoothing_rounds must be at least 0, got " +
                                         py::str(smoothing_rounds).cast<std::string>());
        if (rounds > sm::kMaxSmoothingRounds)
          throw sm::InvalidArgumentError("smoothing_rounds must be at most " +
                                         std::to_string(sm::kMaxSmoothingRounds) + ", got " +
                                         py::str(smoothing_rounds).cast<std::string>());
        options.smoothing_rounds = static_cast<int>(rounds);

        sm::PolygonPair pair;
        pair.source_positions = to_vertices(source, "source");
        pair.target_positions = to_vertices(target, "target");
        const std::size_t n = pair.source_positions.size();
        if (pair.target_positions.size() != n)
          throw sm::InvalidArgumentError("source and target must have the same number of vertices, "
                                         "got " + std::to_string(n) + " and " +
                                         std::to_string(pair.target_positions.size()));
        if (corners.is_none()) {
          pair.corners.resize(n);
          for (std::size_t k = 0; k < n; ++k) pair.corners[k] = static_cast<int>(k);
        } else {
          pair.corners = to_corners(corners, n);
        }
        check_polygon_coordinates(pair.source_positions, "source");
        check_polygon_coordinates(pair.target_positions, "target");

        sm::CompatibleTriangulation triangulation;
        sm::CompatibleTriangulationStats stats;
        {
          py::gil_scoped_release release;
          triangulation = sm::compatible_triangulation(pair, options, &stats);
        }

        const py::array_t<std::int64_t> triangles = to_triangle_array(triangulation.triangles);
        py::dict statistics;
        statistics["steiner_vertices"] = stats.steiner_vertices;
        statistics["spiderweb_steiner_vertices"] = stats.spiderweb_steiner_vertices;
        statistics["min_angle_before_smoothing"] = stats.min_angle_before_smoothing;
        statistics["min_angle_after_smoothing"] = stats.min_angle_after_smoothing;
        py::dict result;
        result["triangles"] = triangles;
        result["corners"] = to_int64_array(pair.corners);
        result["source_steiner"] = to_point_array(triangulation.source_steiner);
        result["target_steiner"] = to_point_array(triangulation.target_steiner);
        result["stats"] = statistics;
        return result;
      },
      py::arg("source"), py::arg("target"), py::arg("steiner") = "improved",
      py::arg("corners") = py::none(), py::arg("smoothing_rounds") = 10,
      R"doc(Compatibly triangulates two corresponding polygons (paper, section 4).

Both polygons share one corner sequence; corner k sits at source[corners[k]]
in the source and at target[corners[k]] in the target. The result is one
triangulation, with Steiner vertices added inside, whose triangles are
positively oriented in both polygons. It is verified with exact predicates
before it is returned.

Args:
  source: #V by 2 float64 array-like, source vertex coordinates.
  target: #V by 2 float64 array-like, target vertex coordinates (same #V).
  steiner: how Steiner vertices are placed: "aronov" (the universal
    spiderweb of Aronov, Seidel & Souvaine), "sg2001" (the reduced spiderweb
    of Surazhsky & Gotsman 2001) or "improved" (section 4.2: sg2001 without
    the vertices redundant in both polygons).
  corners: optional #C integer array-like of vertex indices, the corner
    sequence counter-clockwise in both polygons; a vertex may repeat (weakly
    simple polygons, e.g. a face with a dangling edge walked on both sides).
    Default: 0, 1, ..., #V-1, a simple polygon through every vertex in order.
  smoothing_rounds: rounds of Laplacian smoothing of the Steiner vertices in
    each polygon (0 to 1000); a move is kept only if the triangulation stays valid
    and its smallest angle does not shrink.

Returns:
  dict with
    "triangles"       #T by 3 int64 ndarray of node indices, counter-clockwise
                      in both polygons: nodes 0..#C-1 are the corners in
                      order, nodes #C..#C+#S-1 the Steiner vertices
    "corners"         #C int64 ndarray, the vertex index of each corner
    "source_steiner"  #S by 2 float64 ndarray, Steiner vertices in the source
    "target_steiner"  #S by 2 float64 ndarray, Steiner vertices in the target
    "stats"           dict: "steiner_vertices" (int, #S),
                      "spiderweb_steiner_vertices" (int, before redundancy
                      removal), "min_angle_before_smoothing" and
                      "min_angle_after_smoothing" (float, radians, smallest
                      triangle angle over both polygons)

Raises:
  InvalidFigureError: a polygon is not weakly simple and counter-clockwise,
    or has a non-finite or too large coordinate (the message says "in the
    source" or "in the target").
  InvalidArgumentError: an unknown steiner name, an array of the wrong shape
    or type, source and target of different lengths, a corner index out of
    range, or a negative smoothing_rounds.
  VerificationError: no compatible triangulation passing verification was
    found; the message names the face and the triangle.)doc");

  m.def(
      "triangulate_figures",
      [](const py::object& source, const py::object& target, const py::object& edges,
         const py::object& target_edges, const py::object& steiner, const py::object& enclosure_sides) {
        const sm::FigureTriangulationOptions options =
            to_triangulation_options(to_name(steiner, "steiner"), enclosure_sides);
        const auto figures = make_figure_pair(source, target, edges, target_edges, "source", "target");
        sm::FigureTriangulation triangulation;
        sm::FigureTriangulationStats stats;
        {
          py::gil_scoped_release release;
          triangulation = sm::triangulate_figures(figures.first, figures.second, options, &stats);
        }
        return triangulation_dict(triangulation, stats);
      },
      py::arg("source"), py::arg("target"), py::arg("edges"), py::arg("target_edges") = py::none(),
      py::arg("steiner") = "improved", py::arg("enclosure_sides") = 6,
      R"doc(Compatibly triangulates two compatible stick figures (paper, Algorithm 3, steps 1-3).

Both figures are enclosed in the same regular polygon; every interior face
pair and the annulus between figure and enclosure are compatibly
triangulated, and the pieces glued into one triangulation of the enclosure
whose triangles are counter-clockwise in both figures and which contains
every figure edge. It is verified in exact arithmetic before it is
returned. The same triangulation `stickmorph triangulate` writes.

Args:
  source: #V by 2 float64 array-like, source coordinates.
  target: #V by 2 float64 array-like, target coordinates; vertex i of the
    source corresponds to vertex i of the target.
  edges: #E by 2 integer array-like of vertex indices of the source (and of
    the target unless target_edges is given).
  target_edges: optional #E by 2 integer array-like, the target's edge list;
    order and direction may differ from edges.
  steiner: Steiner vertex placement in the faces, "improved" (default),
    "sg2001" or "aronov" (see compatible_triangulation).
  enclosure_sides: sides k of the common regular enclosure, 3 to 1000.

Returns:
  dict (FORMAT.md's triangulation object) with
    "figure_vertices"     int n (= #V)
    "enclosure_vertices"  int k
    "steiner_vertices"    int s
    "source", "target"    (n+k+s) by 2 float64 ndarrays, node positions in the
                          two figures: the n figure vertices in input order
                          (exactly the given coordinates), then the k
                          enclosure vertices counter-clockwise (the same in
                          both), then the s Steiner vertices
    "triangles"           #T by 3 int64 ndarray of node indices,
                          counter-clockwise in both
    "stats"               dict: "interior_faces" (int), "cut_bends" (int,
                          Steiner vertices on the annulus cut),
                          "interior_steiner" (int, Steiner vertices inside
                          interior faces), "min_angle" (float, radians, the
                          smallest triangle angle over both embeddings)

Raises:
  InvalidFigureError: the source or the target is invalid (the message
    starts with "source: " or "target: ").
  IncompatibleFiguresError: the figures are not compatible.
  InvalidArgumentError: an unknown steiner name, enclosure_sides below 3, or
    an array of the wrong shape or type.
  VerificationError: no triangulation passing exact verification was found.)doc");

  m.def(
      "morph",
      [](const py::object& source_xy, const py::object& target_xy, const py::object& edges,
         const py::object& frames, const py::object& steiner, const py::object& weights,
         const py::object& enclosure_sides, const py::object& method_object, const py::object& verify,
         const py::object& target_edges) {
        // Arguments first, figures second, as the CLI does.
        sm::MorphOptions options;
        options.frames = to_frame_count(frames);
        options.weights = sm::parse_weight_kind(to_name(weights, "weights"));
        options.verify = to_flag(verify, "verify");
        const std::string method = to_name(method_object, "method");
        if (method != "barycentric" && method != "linear")
          throw sm::InvalidArgumentError("unknown morph method '" + method +
                                         "' (choose barycentric or linear)");
        const sm::FigureTriangulationOptions tri_options =
            to_triangulation_options(to_name(steiner, "steiner"), enclosure_sides);
        const auto figures =
            make_figure_pair(source_xy, target_xy, edges, target_edges, "source_xy", "target_xy");
        const sm::StickFigure& source = figures.first;
        const sm::StickFigure& target = figures.second;
        const std::size_t n = source.vertices.size();

        py::dict milliseconds;
        py::dict statistics;
        py::dict result;
        if (method == "linear") {
          // The paper's Figure 8d baseline: frames that are not stick figures
          // compatible with the source are reported, not refused.
          sm::MorphResult morphed;
          std::vector<int> invalid;
          double morph_ms = 0;
          {
            py::gil_scoped_release release;
            sm::require_compatible(source, target);
            const auto start = std::chrono::steady_clock::now();
            morphed = sm::linear_morph(source, target, options.frames, &invalid);
            morph_ms = milliseconds_since(start);
          }
          result["times"] = py::array_t<double>(static_cast<py::ssize_t>(morphed.times.size()),
                                                morphed.times.data());
          result["frames"] = figure_frames(morphed.frames, n);
          result["triangulation"] = py::none();
          milliseconds["triangulate"] = 0.0;
          milliseconds["morph"] = morph_ms;
          // Interpolation counts as solving, the validity check as verifying.
          milliseconds["factorize"] = 0.0;
          milliseconds["solve"] = morphed.stats.solve_ms;
          milliseconds["verify"] = morphed.stats.verify_ms;
          statistics["steiner_vertices"] = 0;
          statistics["triangles"] = 0;
          statistics["milliseconds"] = milliseconds;
          statistics["method"] = method;
          statistics["refined_frames"] = 0;
          statistics["factorizations"] = 0;
          statistics["invalid_frames"] = to_list(invalid);
          result["stats"] = statistics;
          return result;
        }

        sm::FigureTriangulation triangulation;
        sm::FigureTriangulationStats triangulation_stats;
        sm::MorphResult morphed;
        double triangulate_ms = 0;
        double morph_ms = 0;
        {
          py::gil_scoped_release release;
          auto start = std::chrono::steady_clock::now();
          triangulation = sm::triangulate_figures(source, target, tri_options, &triangulation_stats);
          triangulate_ms = milliseconds_since(start);
          start = std::chrono::steady_clock::now();
          morphed = sm::morph_triangulation(triangulation, source, options);
          morph_ms = milliseconds_since(start);
        }
        result["times"] =
            py::array_t<double>(static_cast<py::ssize_t>(morphed.times.size()), morphed.times.data());
        result["frames"] = figure_frames(morphed.frames, n);
        result["triangulation"] = triangulation_dict(triangulation, triangulation_stats);
        milliseconds["triangulate"] = triangulate_ms;
        milliseconds["morph"] = morph_ms;
        milliseconds["factorize"] = morphed.stats.factorize_ms;
        milliseconds["solve"] = morphed.stats.solve_ms;
        milliseconds["verify"] = morphed.stats.verify_ms;
        statistics["steiner_vertices"] = triangulation.steiner_vertices;
        statistics["triangles"] = static_cast<py::ssize_t>(triangulation.triangles.size());
        statistics["milliseconds"] = milliseconds;
        statistics["method"] = method;
        statistics["steiner_method"] = sm::steiner_method_name(tri_options.method);
        statistics["enclosure_sides"] = tri_options.enclosure_sides;
        statistics["weights"] = sm::weight_kind_name(options.weights);
        statistics["verified"] = options.verify;
        statistics["refined_frames"] = morphed.stats.refined_frames;
        statistics["factorizations"] = morphed.stats.factorizations;
        result["stats"] = statistics;
        return result;
      },
      py::arg("source_xy"), py::arg("target_xy"), py::arg("edges"), py::arg("frames") = 50,
      py::arg("steiner") = "improved", py::arg("weights") = "mvc", py::arg("enclosure_sides") = 6,
      py::arg("method") = "barycentric", py::arg("verify") = true,
      py::arg("target_edges") = py::none(),
      R"doc(Morphs one stick figure into a compatible one (paper, Algorithm 3).

The barycentric method (default) compatibly triangulates both figures inside
a common convex enclosure (triangulate_figures) and morphs the triangulation
by Floater & Gotsman: convex-combination weights interpolated linearly in
time, positions solved for at every frame. Every frame is then a stick
figure compatible with the source; with verify=True this is checked exactly
for every frame (frames failing through roundoff are refined in long
double, and a frame that still fails raises VerificationError). The linear
method is the paper's Figure 8d baseline: straight-line interpolation of
the vertices, whose invalid frames are reported, not refused. The same
computation as `stickmorph morph`.

Args:
  source_xy: #V by 2 float64 array-like, source coordinates.
  target_xy: #V by 2 float64 array-like, target coordinates; vertex i of the
    source corresponds to vertex i of the target.
  edges: #E by 2 integer array-like of vertex indices of the source (and of
    the target unless target_edges is given).
  frames: N, the number of frames, 2 <= N <= 100000; frame k is at time
    k/(N-1).
  steiner: "improved" (default), "sg2001" or "aronov", as for
    triangulate_figures.
  weights: "mvc" (mean value coordinates, default), "uniform" or "floater".
  enclosure_sides: sides of the common regular enclosure, 3 to 1000.
  method: "barycentric" (default) or "linear".
  verify: check every frame exactly (barycentric only).
  target_edges: optional #E by 2 integer array-like, the target's edge list.

Returns:
  dict with
    "times"          (N,) float64 ndarray, k/(N-1): 0.0 first, 1.0 last
    "frames"         (N, #V, 2) float64 ndarray of the figure's vertices;
                     frames[0] is exactly source_xy, frames[-1] exactly
                     target_xy
    "triangulation"  the dict triangulate_figures returns, the triangulation
                     the morph used; None for method="linear"
    "stats"          dict: "steiner_vertices" (int), "triangles" (int),
                     "milliseconds" (dict of floats: "triangulate", "morph",
                     "factorize", "solve", "verify"), "refined_frames" (int,
                     frames refined in long double), "factorizations" (int,
                     frames whose warm-started iterative solve stalled or
                     failed the exact check and were solved with the direct
                     factorization), "method" (str); for
                     "barycentric" also "steiner_method", "enclosure_sides",
                     "weights" and "verified"; for "linear" also
                     "invalid_frames" (list of int, the frames that are not
                     stick figures compatible with the source). For "linear"
                     the counts, refined_frames, factorizations and the
                     triangulate and factorize times are 0, "solve" is the interpolation and "verify" the check
                     that finds the invalid frames.

Raises:
  InvalidFigureError: the source or the target is invalid (the message
    starts with "source: " or "target: ").
  IncompatibleFiguresError: the figures are not compatible.
  InvalidArgumentError: frames out of range or not an integer, an unknown
    method, weights or steiner name, enclosure_sides below 3, or an array of
    the wrong shape or type.
  VerificationError: a triangulation or a frame failed exact verification
    and could not be repaired.)doc");
}
