// Figures one at a time and pairs of them: validation, file reading,
// rotation systems, Algorithm 1's decomposition and compatibility.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <climits>
#include <cstdint>
#include <string>
#include <vector>

#include "bindings.h"
#include "conversions.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/figure_parts.h"

namespace stickmorph::python {

namespace {

// A graph's edge list (no positions: figure_parts, check_pins), each index
// from 0 to vertex_count - 1; `name` names the list in messages.
std::vector<sm::Edge> graph_edges(long long vertex_count, const py::object& edges, const std::string& name) {
  const std::vector<std::array<std::int64_t, 2>> indices = to_edges(edges, name);
  const std::string row = name == "edges" ? std::string("edge ") : name + ": edge ";
  std::vector<sm::Edge> result;
  result.reserve(indices.size());
  for (std::size_t i = 0; i < indices.size(); ++i) {
    for (const std::int64_t v : indices[i])
      if (v < 0 || v >= vertex_count)
        throw sm::InvalidArgumentError(row + std::to_string(i) + " names vertex " + std::to_string(v) +
                                       ", but there are " + std::to_string(vertex_count) + " vertices");
    result.push_back({int(indices[i][0]), int(indices[i][1])});
  }
  return result;
}

long long checked_vertex_count(long long vertex_count, const std::string& name) {
  if (vertex_count < 0 || vertex_count > INT_MAX)
    throw sm::InvalidArgumentError(name + " must be from 0 to " + std::to_string(INT_MAX) + ", got " +
                                   std::to_string(vertex_count));
  return vertex_count;
}

// Vertex degrees of a graph, for the pin rule.
std::vector<int> degrees(long long vertex_count, const std::vector<sm::Edge>& edges) {
  std::vector<int> degree(std::size_t(vertex_count), 0);
  for (const sm::Edge& e : edges) {
    ++degree[std::size_t(e[0])];
    ++degree[std::size_t(e[1])];
  }
  return degree;
}

const char* pin_defect_name(sm::PinDefect defect) {
  switch (defect) {
    case sm::PinDefect::None: return "none";
    case sm::PinDefect::MissingSourceVertex: return "missing_source_vertex";
    case sm::PinDefect::MissingTargetVertex: return "missing_target_vertex";
    case sm::PinDefect::SourcePinnedTwice: return "source_pinned_twice";
    case sm::PinDefect::TargetPinnedTwice: return "target_pinned_twice";
    case sm::PinDefect::KindsDiffer: return "kinds_differ";
  }
  return "none";
}

}  // namespace

void bind_figures(py::module_& m) {
  py::class_<sm::CompatibilityReport>(m, "CompatibilityReport",
                                      "The answer of check_compatibility. True iff compatible.")
      .def_property_readonly("compatible", &sm::CompatibilityReport::compatible,
                             "True iff the two figures are compatible.")
      .def_property_readonly(
          "kind",
          [](const sm::CompatibilityReport& r) { return incompatibility_name(r.kind); },
          "Why not: 'none', 'vertex_count_differs', 'edge_set_differs', 'mirror_image', "
          "'rotation_differs', 'exterior_differs' or 'nesting_differs' (a part lies in another face of another part).")
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
  InvalidFigureError: the figure is not a straight-line plane graph (it may have
    several parts, FORMAT.md "Parts");
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
  FileError: the file cannot be read (an OSError with errno and filename:
    FigureFileNotFoundError is a FileNotFoundError, and so on).
  JsonError: malformed JSON or a field of the wrong shape.
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
        const auto figures = make_figure_pair(source_vertices, target_vertices, edges, target_edges,
                                              "source_vertices", "target_vertices");
        py::gil_scoped_release release;
        return sm::check_compatibility(figures.first, figures.second);
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
    starts with "source: " or "target: ", and its role attribute says
    which).
  InvalidArgumentError: an array of the wrong shape or type.)doc");

  m.def(
      "correspond",
      [](const py::object& source_xy, const py::object& target_xy, const py::object& edges,
         const py::object& target_edges, const py::object& pins) {
        sm::CorrespondenceOptions options;
        options.pins = to_pins(pins);
        const auto figures = make_figure_pair(source_xy, target_xy, edges, target_edges, "source_xy", "target_xy");
        sm::FigureCorrespondence c;
        {
          py::gil_scoped_release release;
          c = sm::correspond_figures(figures.first, figures.second, options);
        }
        py::dict stats = matching_stats_dict(c);
        py::dict milliseconds;
        milliseconds["correspond"] = c.milliseconds;
        stats["milliseconds"] = milliseconds;
        py::dict result;
        result["source_xy"] = to_point_array(c.source.vertices);
        result["target_xy"] = to_point_array(c.target.vertices);
        result["edges"] = to_edge_array(c.source.edges);
        result["correspondence"] = correspondence_dict(c);
        result["stats"] = stats;
        return result;
      },
      py::arg("source_xy"), py::arg("target_xy"), py::arg("edges"), py::kw_only(),
      py::arg("target_edges") = py::none(), py::arg("pins") = py::none(),
      R"doc(Matches two figures drawn separately (paper, section 6: dummy vertices).

The figures need not correspond by index: they may differ in vertex count,
numbering, edge order and in how their strokes are subdivided. Their
skeletons (the vertices of degree other than 2 and the strokes between
them) are matched as plane maps, keeping the counter-clockwise order of the
strokes around every junction and the outside; among the matchings the one
closest to a similarity wins (near ties: the smallest rotation). Strokes
are then matched by arc length: every vertex of either figure is kept, and
one with no partner gets a dummy vertex on the other figure's edge. The
result is a compatible pair on m vertices, ready for morph(),
MorphSolver or RigidMorphSolver.

Args:
  source_xy: #Vs by 2 float64 array-like, source coordinates.
  target_xy: #Vt by 2 float64 array-like, target coordinates.
  edges: #Es by 2 integer array-like, the source's edges (and the target's
    unless target_edges is given).
  target_edges: #Et by 2 integer array-like, the target's edges.
  pins: optional #P by 2 integer array-like of (source vertex, target
    vertex) pairs that must match: both junctions or ends of one degree, or
    both inside a stroke.

Returns:
  dict with
    "source_xy"      (m, 2) float64 ndarray: the matched figure on the source
                     drawing; rows 0..#Vs-1 are source_xy itself, then come
                     the dummies on source edges, in target-vertex order
    "target_xy"      (m, 2) float64 ndarray: the same vertices on the target
    "edges"          (#E, 2) int64 ndarray: the matched figure's edges
    "correspondence" dict of (m,) ndarrays, as morph()'s: "source",
                     "target", "source_edge", "source_fraction",
                     "target_edge", "target_fraction"
    "stats"          dict: "matched_vertices", "source_dummies",
                     "target_dummies", "skeleton_nodes", "skeleton_chains",
                     "candidates" (matchings compared), "residual" (of the
                     similarity fit, 0 perfect), "rotation_degrees" and
                     "milliseconds" ({"correspond": float})

Raises:
  InvalidFigureError: the source or the target is invalid.
  InvalidArgumentError: a pin names a missing vertex, pins one twice or
    joins vertices of different kinds; an array of the wrong shape.
  IncompatibleFiguresError: the figures cannot be matched; kind
    "topology_differs" (loops, ends, junction degrees or their arrangement
    differ, or the number of parts; the message says which), "mirror_image",
    "exterior_differs", "nesting_differs" (the matched parts nest otherwise)
    or "pins_unsatisfiable".)doc");

  // The engine's figure_parts (figure_parts.h) for callers that number
  // parts as the engine's messages do ("part 1"): the Blender add-on's
  // report, which used to repeat the union-find in Python.
  m.def(
      "figure_parts",
      [](long long vertex_count, const py::object& edges) {
        checked_vertex_count(vertex_count, "vertex_count");
        // Only the vertex count and the edges matter to the parts: no figure
        // (no positions) is made.
        const sm::FigureParts parts = sm::figure_parts(int(vertex_count), graph_edges(vertex_count, edges, "edges"));
        py::list result;
        for (const std::vector<int>& part : parts.vertices) result.append(to_list(part));
        return result;
      },
      py::arg("vertex_count"), py::arg("edges"),
      R"doc(The parts (connected components) of a figure, numbered as the engine's messages number them.

Only the vertex count and the edges matter: the figure is not validated
(no positions are given), so this answers for any graph on the vertices.

Args:
  vertex_count: int, the number of vertices (0 or more).
  edges: #E by 2 integer array-like of vertex indices, each from 0 to
    vertex_count - 1 ([] for none).

Returns:
  list of parts, each a list of its vertex indices in ascending order, the
  parts in order of their smallest vertex ("part 0" holds vertex 0). A
  vertex on no edge (a dot) is a part of its own.

Raises:
  InvalidArgumentError: a negative vertex_count, an edge naming a vertex
    outside 0..vertex_count-1, or an array of the wrong shape or type.)doc");

  // The engine's edge-set comparison (section 2.1's first test), for callers
  // that word their own message before any figure exists: the add-on.
  m.def(
      "edge_set_difference",
      [](const py::object& source_edges, const py::object& target_edges) {
        auto as_edges = [](const py::object& edges, const std::string& name) {
          std::vector<sm::Edge> result;
          const std::vector<std::array<std::int64_t, 2>> indices = to_edges(edges, name);
          for (std::size_t i = 0; i < indices.size(); ++i) {
            for (const std::int64_t v : indices[i])
              if (v < 0 || v > INT_MAX)
                throw sm::InvalidArgumentError(name + ": edge " + std::to_string(i) + " names vertex " +
                                               std::to_string(v) + ", not a vertex index");
            result.push_back({int(indices[i][0]), int(indices[i][1])});
          }
          return result;
        };
        const sm::EdgeSetDifference difference =
            sm::edge_set_difference(as_edges(source_edges, "source_edges"), as_edges(target_edges, "target_edges"));
        return py::make_tuple(to_edge_array(difference.only_in_source), to_edge_array(difference.only_in_target));
      },
      py::arg("source_edges"), py::arg("target_edges"),
      R"doc(The undirected edges that only one of two edge lists has.

Compatible figures (paper, section 2.1) have the same edges, whatever their
order and direction: this is check_compatibility's first test, without the
figures.

Args:
  source_edges, target_edges: #E by 2 integer array-like of vertex indices
    (0 or more).

Returns:
  (only_in_source, only_in_target): two #A by 2 int64 arrays of edges (i, j)
  with i < j, sorted; both empty iff the lists hold the same edges.

Raises:
  InvalidArgumentError: a negative index, or an array of the wrong shape or
    type.)doc");

  // The engine's pin rule (figure_correspondence.h's check_vertex_pins), for
  // callers that name pins their own way: the add-on's pin groups.
  m.def(
      "check_pins",
      [](long long source_vertex_count, const py::object& source_edges, long long target_vertex_count,
         const py::object& target_edges, const py::object& pins) -> py::object {
        checked_vertex_count(source_vertex_count, "source_vertex_count");
        checked_vertex_count(target_vertex_count, "target_vertex_count");
        const std::vector<int> source_degree =
            degrees(source_vertex_count, graph_edges(source_vertex_count, source_edges, "source_edges"));
        const std::vector<int> target_degree =
            degrees(target_vertex_count, graph_edges(target_vertex_count, target_edges, "target_edges"));
        const sm::PinCheck check = sm::check_vertex_pins(source_degree, target_degree, to_pins(pins));
        if (check.ok()) return py::none();
        py::dict problem;
        problem["pin"] = check.pin;
        problem["defect"] = pin_defect_name(check.defect);
        problem["source_degree"] = check.source_degree;
        problem["target_degree"] = check.target_degree;
        problem["reason"] = check.reason;
        return std::move(problem);
      },
      py::arg("source_vertex_count"), py::arg("source_edges"), py::arg("target_vertex_count"),
      py::arg("target_edges"), py::arg("pins"),
      R"doc(The first pin that correspond (and morph with correspond='auto') would refuse, or None.

The rule: each pin names a vertex of each figure, no vertex is pinned
twice, and a pin joins two ends, two junctions of the same degree or two
vertices inside strokes. Only the vertex counts and the edges matter.

Args:
  source_vertex_count, target_vertex_count: int, the figures' vertex counts.
  source_edges, target_edges: #E by 2 integer array-like of vertex indices.
  pins: #P by 2 integer array-like of (source vertex, target vertex).

Returns:
  None, or a dict: "pin" (its index in pins), "defect"
  ('missing_source_vertex', 'missing_target_vertex', 'source_pinned_twice',
  'target_pinned_twice' or 'kinds_differ'), "source_degree" and
  "target_degree" (for 'kinds_differ'), "reason" (as correspond's error
  says it).

Raises:
  InvalidArgumentError: a negative vertex count, an edge naming a vertex
    outside its figure, or an array of the wrong shape or type.)doc");
}

}  // namespace stickmorph::python
