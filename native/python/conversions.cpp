// Conversions between Python objects and engine types (conversions.h).
#include "conversions.h"

#include "stickmorph/similarity_motion.h"

#include <climits>
#include <cmath>
#include <deque>
#include <limits>

#include "stickmorph/argument_limits.h"
#include "stickmorph/errors.h"
#include "stickmorph/json.h"

namespace stickmorph::python {

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

py::list to_list(const std::vector<int>& values) {
  py::list list;
  for (int v : values) list.append(v);
  return list;
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

std::vector<sm::VertexPin> to_pins(const py::object& object) {
  if (object.is_none()) return {};
  const py::array array = as_array(object, "pins");
  if (!has_pair_shape(array))
    throw sm::InvalidArgumentError("pins must have shape (#P, 2), pairs (source vertex, target vertex), got " +
                                   shape_text(array));
  const py::ssize_t n = array.ndim() == 2 ? array.shape(0) : 0;
  const std::vector<std::int64_t> values =
      to_int64_indices(array, 2 * n, "pins", [&](py::ssize_t i) { return "pins: pin " + std::to_string(i / 2); });
  std::vector<sm::VertexPin> pins;
  for (py::ssize_t i = 0; i < n; ++i) {
    for (const std::int64_t v : {values[2 * i], values[2 * i + 1]})
      if (v < INT_MIN || v > INT_MAX)
        throw sm::InvalidArgumentError("pins: pin " + std::to_string(i) + " names vertex " + std::to_string(v) +
                                       ", beyond any figure's vertices");
    pins.push_back({int(values[2 * i]), int(values[2 * i + 1])});
  }
  return pins;
}

namespace {

py::array_t<std::int64_t> place_array(const std::vector<sm::MatchedPlace>& places, int sm::MatchedPlace::*field) {
  std::vector<std::int64_t> values;
  for (const sm::MatchedPlace& place : places) values.push_back(place.*field);
  return to_int64_array(values);
}

py::array_t<double> fraction_array(const std::vector<sm::MatchedPlace>& places) {
  py::array_t<double> array(static_cast<py::ssize_t>(places.size()));
  auto out = array.mutable_unchecked<1>();
  for (std::size_t i = 0; i < places.size(); ++i) out(static_cast<py::ssize_t>(i)) = places[i].fraction;
  return array;
}

int dummies(const std::vector<sm::MatchedPlace>& places) {
  int count = 0;
  for (const sm::MatchedPlace& place : places) count += place.vertex < 0;
  return count;
}

}  // namespace

// A time argument: any real number (int, float, NumPy scalar); booleans are
// refused like frames=True, a time of True is a mistake. The range check is
// here, not only in the engine, so that the message quotes the value.
double to_time(const py::object& object) {
  if (PyBool_Check(object.ptr()) || !(PyFloat_Check(object.ptr()) || PyIndex_Check(object.ptr()) ||
                                      py::hasattr(object, "__float__")) ||
      py::isinstance<py::str>(object))
    throw sm::InvalidArgumentError("t must be a number in [0, 1], got " +
                                   py::str(py::type::of(object).attr("__name__")).cast<std::string>());
  double t = 0;
  try {
    t = py::float_(object).cast<double>();
  } catch (py::error_already_set&) {
    // An array of several values has __float__ but refuses it (TypeError).
    throw sm::InvalidArgumentError("t must be one number in [0, 1], got " +
                                   py::str(py::type::of(object).attr("__name__")).cast<std::string>() +
                                   (py::hasattr(object, "shape") ? " of shape " + py::str(object.attr("shape")).cast<std::string>()
                                                                  : std::string()));
  }
  if (!(t >= 0 && t <= 1))
    throw sm::InvalidArgumentError("t must be in [0, 1], got " + py::repr(py::float_(t)).cast<std::string>());
  return t;
}

std::optional<sm::LocalTiming> to_local_timing(const py::object& delay, const py::object& overlap) {
  if (delay.is_none() && overlap.is_none()) return std::nullopt;
  if (overlap.is_none())
    throw sm::InvalidArgumentError("delay needs overlap (a number in [0, 1): how far weight-1 parts lag)");
  if (delay.is_none())
    throw sm::InvalidArgumentError("overlap needs delay (one weight in [0, 1] per source vertex)");
  const py::array array = as_array(delay, "delay");
  if (array.ndim() != 1) throw sm::InvalidArgumentError("delay must have shape (#V,), got " + shape_text(array));
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f')
    throw sm::InvalidArgumentError("delay must hold real numbers, got dtype " + dtype_text(array));
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!values) throw py::error_already_set();
  std::vector<double> weights(values.data(), values.data() + array.shape(0));
  if (PyBool_Check(overlap.ptr()) || py::isinstance<py::str>(overlap) ||
      !(PyFloat_Check(overlap.ptr()) || PyIndex_Check(overlap.ptr()) || py::hasattr(overlap, "__float__")))
    throw sm::InvalidArgumentError("overlap must be a number in [0, 1), got " +
                                   py::str(py::type::of(overlap).attr("__name__")).cast<std::string>());
  double d = 0;
  try {
    d = py::float_(overlap).cast<double>();
  } catch (py::error_already_set&) {
    throw sm::InvalidArgumentError("overlap must be one number in [0, 1), got " +
                                   py::str(py::type::of(overlap).attr("__name__")).cast<std::string>());
  }
  return sm::LocalTiming(std::move(weights), d);
}

py::dict places_dict(const std::vector<sm::MatchedPlace>& places) {
  py::dict dict;
  dict["vertex"] = place_array(places, &sm::MatchedPlace::vertex);
  dict["edge"] = place_array(places, &sm::MatchedPlace::edge);
  dict["fraction"] = fraction_array(places);
  return dict;
}

py::dict correspondence_dict(const sm::FigureCorrespondence& c) {
  py::dict dict;
  dict["source"] = place_array(c.source_places, &sm::MatchedPlace::vertex);
  dict["target"] = place_array(c.target_places, &sm::MatchedPlace::vertex);
  dict["source_edge"] = place_array(c.source_places, &sm::MatchedPlace::edge);
  dict["source_fraction"] = fraction_array(c.source_places);
  dict["target_edge"] = place_array(c.target_places, &sm::MatchedPlace::edge);
  dict["target_fraction"] = fraction_array(c.target_places);
  return dict;
}

py::dict matching_stats_dict(const sm::FigureCorrespondence& c) {
  py::dict dict;
  dict["matched_vertices"] = c.source.vertices.size();
  dict["source_dummies"] = dummies(c.source_places);
  dict["target_dummies"] = dummies(c.target_places);
  dict["skeleton_nodes"] = c.skeleton_nodes;
  dict["skeleton_chains"] = c.skeleton_chains;
  dict["candidates"] = c.candidates;
  dict["residual"] = c.residual;
  dict["rotation_degrees"] = c.rotation_degrees;
  return dict;
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
    // The role travels as an attribute, and the message without the prefix
    // as `detail` (errors.cpp); the prefix stays in the message for the
    // readers of str(e), who have no attributes (logs, the CLI's users).
    throw sm::InvalidFigureError(e.defect(), figure + ": " + e.what(), e.vertices(), e.edges(), figure);
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
                                     {static_cast<int>(v)}, {}, role);
      if (std::abs(value) > sm::kMaxCoordinateMagnitude)
        throw sm::InvalidFigureError(sm::FigureDefect::CoordinateTooLarge,
                                     prefix + std::to_string(v) + " has coordinate " + axis[c] +
                                         " = " + sm::format_double(value) +
                                         ", beyond the supported magnitude " +
                                         sm::format_double(sm::kMaxCoordinateMagnitude),
                                     {static_cast<int>(v)}, {}, role);
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

// #E by 2 vertex indices as an int64 array.
py::array_t<std::int64_t> to_edge_array(const std::vector<sm::Edge>& edges) {
  py::array_t<std::int64_t> out({static_cast<py::ssize_t>(edges.size()), py::ssize_t{2}});
  auto w = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (py::ssize_t j = 0; j < 2; ++j) w(static_cast<py::ssize_t>(i), j) = edges[i][static_cast<std::size_t>(j)];
  return out;
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
  statistics["parts"] = stats.parts;
  statistics["bridges"] = stats.bridges;
  statistics["bridge_bends"] = stats.bridge_bends;
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

std::vector<std::pair<std::string, double>> engine_limits() {
  return {{"min_frames", sm::kMinMorphFrames},
          {"max_frames", sm::kMaxMorphFrames},
          {"default_frames", sm::kDefaultMorphFrames},
          {"min_enclosure_sides", sm::kMinEnclosureSides},
          {"max_enclosure_sides", sm::kMaxEnclosureSides},
          {"default_enclosure_sides", sm::kDefaultEnclosureSides},
          {"min_smoothing_rounds", sm::kMinSmoothingRounds},
          {"max_smoothing_rounds", sm::kMaxSmoothingRounds},
          {"default_smoothing_rounds", sm::kDefaultSmoothingRounds},
          {"max_turns", sm::kMaxExtraTurns},
          {"max_coordinate_magnitude", sm::kMaxCoordinateMagnitude}};
}

const char* with_limits(const char* doc) {
  // A deque: growing it never moves the strings already handed out.
  static std::deque<std::string> texts;
  std::string text = doc;
  for (const auto& [name, value] : engine_limits()) {
    const std::string key = "{" + name + "}";
    const bool whole = value == std::floor(value) && std::abs(value) < 1e15;
    const std::string shown = whole ? std::to_string(static_cast<long long>(value)) : sm::format_double(value);
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + shown.size()))
      text.replace(at, key.size(), shown);
  }
  if (text.find("{min_") != std::string::npos || text.find("{max_") != std::string::npos ||
      text.find("{default_") != std::string::npos)
    throw sm::InternalError("stickmorph module: a docstring names an unknown limit: " + text.substr(0, 60));
  texts.push_back(std::move(text));
  return texts.back().c_str();
}

py::array_t<double> frames_array(const std::vector<std::vector<sm::Vec2>>& frames, std::size_t n) {
  const auto count = static_cast<py::ssize_t>(frames.size());
  py::array_t<double> array({count, static_cast<py::ssize_t>(n), py::ssize_t{2}});
  double* out = array.mutable_data();
  {
    py::gil_scoped_release release;
    for (const std::vector<sm::Vec2>& frame : frames) {
      // The engine promises n positions per frame; a shorter one would be
      // read past its end.
      if (frame.size() != n)
        throw sm::InternalError("stickmorph module: a morph frame holds " + std::to_string(frame.size()) +
                                " positions, not the figure's " + std::to_string(n) + " vertices");
      for (std::size_t v = 0; v < n; ++v) {
        *out++ = frame[v][0];
        *out++ = frame[v][1];
      }
    }
  }
  return array;
}

}  // namespace stickmorph::python
