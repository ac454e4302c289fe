// Compatible triangulations: of a polygon pair (section 4) and of a figure
// pair inside a common enclosure (Algorithm 3, steps 1-3).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

#include "bindings.h"
#include "conversions.h"
#include "stickmorph/argument_limits.h"
#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_triangulation.h"

namespace stickmorph::python {

void bind_triangulation(py::module_& m) {
  m.def(
      "compatible_triangulation",
      [](const py::object& source, const py::object& target, const py::object& steiner,
         const py::object& corners, const py::object& smoothing_rounds) {
        sm::CompatibleTriangulationOptions options;
        options.method = sm::parse_steiner_method(to_name(steiner, "steiner"));
        options.smoothing_rounds = sm::check_smoothing_rounds(
            to_count(smoothing_rounds, "smoothing_rounds"), sm::OptionSpelling::Keyword, py::str(smoothing_rounds));

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
      py::arg("corners") = py::none(), py::arg("smoothing_rounds") = sm::kDefaultSmoothingRounds,
      with_limits(R"doc(Compatibly triangulates two corresponding polygons (paper, section 4).

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
    each polygon ({min_smoothing_rounds} to {max_smoothing_rounds}); a move is kept only if the triangulation stays valid
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
    found; the message names the face and the triangle.)doc"));

  m.def(
      "triangulate_figures",
      [](const py::object& source, const py::object& target, const py::object& edges,
         const py::object& target_edges, const py::object& steiner, const py::object& enclosure_sides) {
        sm::FigureTriangulationOptions options;
        options.method = sm::parse_steiner_method(to_name(steiner, "steiner"));
        options.enclosure_sides = sm::check_enclosure_sides(to_count(enclosure_sides, "enclosure_sides"),
                                                            sm::OptionSpelling::Keyword, py::str(enclosure_sides));
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
      py::arg("steiner") = "improved", py::arg("enclosure_sides") = sm::kDefaultEnclosureSides,
      with_limits(R"doc(Compatibly triangulates two compatible stick figures (paper, Algorithm 3, steps 1-3).

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
  enclosure_sides: sides k of the common regular enclosure,
    {min_enclosure_sides} to {max_enclosure_sides}.

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
                          smallest triangle angle over both embeddings),
                          "parts" (int), "bridges" (int, parts - 1) and
                          "bridge_bends" (int, Steiner vertices on the
                          bridges that join a figure of several parts)

Raises:
  InvalidFigureError: the source or the target is invalid (the message
    starts with "source: " or "target: ", and its role attribute says
    which).
  IncompatibleFiguresError: the figures are not compatible; its kind and
    vertices attributes are those of check_compatibility's report.
  InvalidArgumentError: an unknown steiner name, enclosure_sides below 3, or
    an array of the wrong shape or type.
  VerificationError: no triangulation passing exact verification was found.)doc"));

}

}  // namespace stickmorph::python
