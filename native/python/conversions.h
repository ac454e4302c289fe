// Conversions between Python objects and engine types, shared by the binding
// groups of the `stickmorph` module (module.cpp).
//
// Everything here converts or checks the form of an argument (shape, dtype,
// type); what the values mean (geometry, limits, option combinations) is
// the engine's to decide, so that the module and the CLI agree.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/local_timing.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::python {

namespace py = pybind11;
namespace sm = stickmorph;

/// The Python names of the engine's enums ('crossing_edges', 'mirror_image').
const char* defect_name(sm::FigureDefect defect);
const char* incompatibility_name(sm::Incompatibility kind);
const char* drawing_defect_name(sm::DrawingDefect defect);

/// Engine text as a Python str; bytes that are not UTF-8 become \x escapes.
py::str to_str(const std::string& text);

py::list to_list(const std::vector<int>& values);

template <typename Int>
py::array_t<std::int64_t> to_int64_array(const std::vector<Int>& values) {
  py::array_t<std::int64_t> array(static_cast<py::ssize_t>(values.size()));
  auto out = array.mutable_unchecked<1>();
  for (std::size_t i = 0; i < values.size(); ++i) out(static_cast<py::ssize_t>(i)) = values[i];
  return array;
}

/// An (n, 2) real array-like as positions; `name` names it in messages.
std::vector<sm::Vec2> to_vertices(py::handle object, const std::string& name);

/// An (n, 2) integer array-like as index pairs, not checked against any
/// vertex count; `name` names it in messages ("edges": "edge i").
std::vector<std::array<std::int64_t, 2>> to_edges(py::handle object, const std::string& name);

/// #P by 2 vertex pairs (source, target) for correspond=; None gives none.
std::vector<sm::VertexPin> to_pins(const py::object& object);

/// A solver's time argument t in [0, 1]: any real number (int, float, NumPy
/// scalar); booleans, strings and arrays of several values are refused.
double to_time(const py::object& object);

/// delay= (#V real numbers) and overlap= (one number) as a local timing
/// (local_timing.h), or none when both are None.
/// @throws InvalidArgumentError: one without the other, a wrong shape or
///         type, or LocalTiming's range check naming the entry.
std::optional<sm::LocalTiming> to_local_timing(const py::object& delay, const py::object& overlap);

/// Where each matched vertex is on one drawing: "vertex", "edge" and
/// "fraction", #m arrays each (MatchedPlace).
py::dict places_dict(const std::vector<sm::MatchedPlace>& places);

/// The matching as morph()'s and correspond()'s "correspondence" dict.
py::dict correspondence_dict(const sm::FigureCorrespondence& correspondence);

/// How the matching was found, as stats["correspondence"].
py::dict matching_stats_dict(const sm::FigureCorrespondence& correspondence);

/// A polygon's corner sequence, each index checked against vertex_count.
std::vector<int> to_corners(py::handle object, std::size_t vertex_count);

/// One figure, converted and validated (the validation without the GIL).
sm::StickFigure make_figure(py::handle vertices, py::handle edges, const std::string& vertices_name,
                            const std::string& edges_name);

/// One figure of several (a pair's source, a sequence's key k), validated;
/// a defect's message starts with "<role>: " and the error carries the role.
sm::StickFigure make_named_figure(py::handle vertices, py::handle edges, const std::string& vertices_name,
                                  const std::string& edges_name, const std::string& role);

/// The source and target figures of a pair, validated source first; a
/// defect says which figure it is in.
std::pair<sm::StickFigure, sm::StickFigure> make_figure_pair(const py::object& source_vertices,
                                                             const py::object& target_vertices,
                                                             const py::object& edges,
                                                             const py::object& target_edges,
                                                             const std::string& source_name,
                                                             const std::string& target_name);

/// Refuses non-finite and too large polygon coordinates as make_stick_figure
/// does; `role` is "source" or "target".
void check_polygon_coordinates(const std::vector<sm::Vec2>& positions, const std::string& role);

py::array_t<double> to_point_array(const std::vector<sm::Vec2>& points);
py::array_t<std::int64_t> to_edge_array(const std::vector<sm::Edge>& edges);
py::array_t<std::int64_t> to_triangle_array(const std::vector<std::array<int, 3>>& triangles);

/// An integer argument of any size (beyond long long it saturates; the
/// message should then quote py::str(object)). Booleans and floats refused.
long long to_count(const py::object& object, const std::string& name);

/// The name of a choice such as steiner=, refusing non-str with the
/// argument's name.
std::string to_name(const py::object& object, const std::string& name);

/// True or False (or a NumPy bool) only.
bool to_flag(const py::object& object, const std::string& name);

/// The FigureTriangulation as the dict documented on triangulate_figures.
py::dict triangulation_dict(const sm::FigureTriangulation& triangulation,
                            const sm::FigureTriangulationStats& stats);

/// `doc` with {min_frames}, {max_frames}, {default_frames},
/// {min_enclosure_sides}, ... (the keys of stickmorph.limits) replaced by the
/// engine's values, so that docstrings quote the limits it enforces. The
/// text lives as long as the process, as pybind11 needs for docstrings.
const char* with_limits(const char* doc);

/// The engine's limits by name: stickmorph.limits and with_limits.
std::vector<std::pair<std::string, double>> engine_limits();

/// Frames of n positions each as one (N, n, 2) float64 array.
py::array_t<double> frames_array(const std::vector<std::vector<sm::Vec2>>& frames, std::size_t n);

}  // namespace stickmorph::python
