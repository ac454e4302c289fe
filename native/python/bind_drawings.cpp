// clean_drawing, clean_figure and CleanedDrawing: a drawing's strokes
// cleaned into a stick figure (drawing_cleaning.h, issue 32).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "conversions.h"
#include "stickmorph/drawing_cleaning.h"
#include "stickmorph/errors.h"

namespace stickmorph::python {
namespace {

// The cleaning and the drawing's strokes (to split point_vertex per stroke).
struct PyCleanedDrawing {
  sm::CleanedDrawing cleaned;
  std::vector<std::vector<int>> stroke_points;
};

std::optional<double> to_tolerance(const py::object& tolerance) {
  if (tolerance.is_none()) return std::nullopt;
  if (py::isinstance<py::bool_>(tolerance) || !(py::isinstance<py::float_>(tolerance) || py::isinstance<py::int_>(tolerance)))
    throw sm::InvalidArgumentError("tolerance must be a number or None, got " +
                                   py::str(py::type::of(tolerance).attr("__name__")).cast<std::string>());
  return tolerance.cast<double>();
}

py::object index_or_none(int value) { return value < 0 ? py::object(py::none()) : py::object(py::int_(value)); }

PyCleanedDrawing clean(const sm::Drawing& drawing, std::optional<double> tolerance) {
  sm::DrawingCleaningOptions options;
  options.tolerance = tolerance;
  PyCleanedDrawing result;
  {
    py::gil_scoped_release release;
    result.cleaned = sm::clean_drawing(drawing, options);
    // The check beside the algorithm, as the CLI runs it (linear).
    sm::validate_cleaning(result.cleaned, drawing);
  }
  result.stroke_points = drawing.strokes;
  return result;
}

}  // namespace

void bind_drawings(py::module_& m) {
  py::class_<PyCleanedDrawing>(m, "CleanedDrawing",
                               R"doc(A drawing cleaned into a stick figure (clean_drawing, clean_figure).

Attributes:
  vertices         #V by 2 float64 array: the valid figure's vertices, in the order of the
                   first input point that became each; vertices made by crossings last.
  edges            #E by 2 int64 array.
  stroke_vertices  list, per input stroke, of its vertex indices in order (int64 arrays),
                   junctions included; a cyclic stroke does not repeat its first vertex.
  point_vertex     list, per input stroke, of the vertex each of its points became.
  cyclic           list of bool, per stroke.
  tolerance        the tolerance used.
  junctions_made, ends_snapped, points_merged: the counts.
  changes          list of dicts {"kind": "merge"|"snap"|"crossing"|"touch", "stroke",
                   "point", "other_stroke" (int or None), "at": (x, y), "distance"}:
                   every point not where it was drawn is named by a merge or snap.)doc")
      .def_property_readonly("vertices", [](const PyCleanedDrawing& c) { return to_point_array(c.cleaned.figure.vertices); })
      .def_property_readonly("edges", [](const PyCleanedDrawing& c) { return to_edge_array(c.cleaned.figure.edges); })
      .def_property_readonly("stroke_vertices",
                             [](const PyCleanedDrawing& c) {
                               py::list out;
                               for (const auto& path : c.cleaned.stroke_vertices) out.append(to_int64_array(path));
                               return out;
                             })
      .def_property_readonly("point_vertex",
                             [](const PyCleanedDrawing& c) {
                               py::list out;
                               for (const auto& stroke : c.stroke_points) {
                                 std::vector<int> vertices;
                                 for (int p : stroke) vertices.push_back(c.cleaned.point_vertex[std::size_t(p)]);
                                 out.append(to_int64_array(vertices));
                               }
                               return out;
                             })
      .def_property_readonly("cyclic",
                             [](const PyCleanedDrawing& c) {
                               py::list out;
                               for (bool flag : c.cleaned.cyclic) out.append(py::bool_(flag));
                               return out;
                             })
      .def_property_readonly("tolerance", [](const PyCleanedDrawing& c) { return c.cleaned.tolerance; })
      .def_property_readonly("junctions_made", [](const PyCleanedDrawing& c) { return c.cleaned.junctions_made; })
      .def_property_readonly("ends_snapped", [](const PyCleanedDrawing& c) { return c.cleaned.ends_snapped; })
      .def_property_readonly("points_merged", [](const PyCleanedDrawing& c) { return c.cleaned.points_merged; })
      .def_property_readonly("changes",
                             [](const PyCleanedDrawing& c) {
                               py::list out;
                               for (const sm::DrawingChange& change : c.cleaned.changes) {
                                 py::dict entry;
                                 entry["kind"] = sm::drawing_change_name(change.kind);
                                 entry["stroke"] = index_or_none(change.stroke);
                                 entry["point"] = index_or_none(change.point);
                                 entry["other_stroke"] = index_or_none(change.other_stroke);
                                 entry["at"] = py::make_tuple(change.at[0], change.at[1]);
                                 entry["distance"] = change.distance;
                                 out.append(entry);
                               }
                               return out;
                             })
      .def("summary", [](const PyCleanedDrawing& c) { return c.cleaned.summary(); },
           "\"2 junctions made, 1 end snapped, 3 points merged\", or \"no changes\".")
      .def("__repr__", [](const PyCleanedDrawing& c) {
        return "CleanedDrawing(vertices=" + std::to_string(c.cleaned.figure.vertices.size()) +
               ", edges=" + std::to_string(c.cleaned.figure.edges.size()) + ", " + c.cleaned.summary() + ")";
      });

  m.def(
      "clean_drawing",
      [](const py::object& strokes, const py::object& cyclic, const py::object& tolerance) {
        if (!py::isinstance<py::sequence>(strokes) || py::isinstance<py::str>(strokes))
          throw sm::InvalidArgumentError("strokes must be a list of #P by 2 arrays, got " +
                                         py::str(py::type::of(strokes).attr("__name__")).cast<std::string>());
        std::vector<std::vector<sm::Vec2>> points;
        const py::sequence list = py::reinterpret_borrow<py::sequence>(strokes);
        for (std::size_t i = 0; i < list.size(); ++i) {
          const py::object stroke = list[i];
          if (py::isinstance<py::sequence>(stroke) && !py::isinstance<py::str>(stroke) && py::len(stroke) == 0) {
            points.emplace_back();  // clean_drawing names the empty stroke
            continue;
          }
          points.push_back(to_vertices(stroke, "strokes[" + std::to_string(i) + "]"));
        }
        std::vector<bool> closed;
        if (!cyclic.is_none()) {
          if (!py::isinstance<py::sequence>(cyclic) || py::isinstance<py::str>(cyclic))
            throw sm::InvalidArgumentError("cyclic must be a list of bool, one per stroke");
          const py::sequence flags = py::reinterpret_borrow<py::sequence>(cyclic);
          for (std::size_t i = 0; i < flags.size(); ++i)
            closed.push_back(to_flag(flags[i], "cyclic[" + std::to_string(i) + "]"));
          if (closed.size() != points.size())
            throw sm::InvalidArgumentError("cyclic has " + std::to_string(closed.size()) + " entries for " +
                                           std::to_string(points.size()) + " strokes");
        }
        const std::optional<double> limit = to_tolerance(tolerance);
        return clean(sm::drawing_from_strokes(points, std::move(closed)), limit);
      },
      py::arg("strokes"), py::arg("cyclic") = py::none(), py::arg("tolerance") = py::none(),
      R"doc(Cleans a drawing (strokes that cross and touch) into a stick figure.

Crossings and touchings become shared vertices, a free stroke end within
`tolerance` of a stroke snaps onto it, points within tolerance / 100 merge
(exact duplicates always). Nothing changes silently: every change is in
the result's `changes`.

Args:
  strokes: list of #P_i by 2 float64 array-likes, each a stroke's points in order.
  cyclic: list of bool, one per stroke (default all False): a closing edge last to first.
  tolerance: absolute distance, or None for 1% of the bounding-box diagonal; 0 snaps
    nothing and merges only exact duplicates.

Returns:
  CleanedDrawing.

Raises:
  InvalidDrawingError: no strokes, a stroke of fewer than two points or collapsing to one,
    a coordinate not finite or too large, strokes overlapping along a length, a stroke
    retracing itself; its `stroke`, `point`, `other_stroke` and `defect` say where and what.
  InvalidArgumentError: an array of the wrong shape, a bad tolerance.)doc");

  m.def(
      "clean_figure",
      [](const py::object& vertices, const py::object& edges, const py::object& tolerance) {
        std::vector<sm::Vec2> positions = to_vertices(vertices, "vertices");
        const std::vector<std::array<std::int64_t, 2>> indices = to_edges(edges, "edges");
        const std::optional<double> limit = to_tolerance(tolerance);
        return clean(sm::drawing_from_figure(std::move(positions), indices), limit);
      },
      py::arg("vertices"), py::arg("edges"), py::arg("tolerance") = py::none(),
      R"doc(Cleans a figure whose edges may cross or touch (a mesh) into a stick figure.

As clean_drawing with stroke i = edge i and point = vertex: the figure's vertex order
is kept, crossing vertices come last, and `point_vertex[i]` holds edge i's two vertices'.

Args:
  vertices: #V by 2 float64 array-like.
  edges: #E by 2 integer array-like.
  tolerance: as clean_drawing.

Returns:
  CleanedDrawing.

Raises:
  InvalidDrawingError, InvalidArgumentError: as clean_drawing (an edge naming a vertex
    that does not exist is InvalidDrawingError with defect "index_out_of_range").)doc");
}

}  // namespace stickmorph::python
