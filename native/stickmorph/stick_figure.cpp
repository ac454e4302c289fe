#include "stickmorph/stick_figure.h"

#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numeric>
#include <tuple>

#include "stickmorph/exact_predicates.h"

namespace stickmorph {
namespace {

std::string vertex_text(int v) { return "vertex " + std::to_string(v); }

std::string point_text(const Vec2& p) {
  return "(" + format_double(p[0]) + ", " + format_double(p[1]) + ")";
}

void check_coordinates(const std::vector<Vec2>& vertices) {
  if (vertices.empty())
    throw InvalidFigureError(FigureDefect::NoVertices, "the figure has no vertices");
  const char* axis[2] = {"x", "y"};
  for (std::size_t v = 0; v < vertices.size(); ++v)
    for (int c = 0; c < 2; ++c)
      if (!std::isfinite(vertices[v][c]))
        throw InvalidFigureError(FigureDefect::NonFiniteCoordinate,
                                 vertex_text(int(v)) + " has a non-finite coordinate (" +
                                     axis[c] + " = " + format_double(vertices[v][c]) + ")",
                                 {int(v)});
  for (std::size_t v = 0; v < vertices.size(); ++v)
    for (int c = 0; c < 2; ++c)
      if (std::abs(vertices[v][c]) > kMaxCoordinateMagnitude)
        throw InvalidFigureError(FigureDefect::CoordinateTooLarge,
                                 vertex_text(int(v)) + " has coordinate " + axis[c] + " = " +
                                     format_double(vertices[v][c]) +
                                     ", beyond the supported magnitude " +
                                     format_double(kMaxCoordinateMagnitude),
                                 {int(v)});
}

std::vector<Edge> checked_edges(std::size_t vertex_count,
                                const std::vector<std::array<std::int64_t, 2>>& raw) {
  const auto n = static_cast<std::int64_t>(vertex_count);
  std::vector<Edge> edges;
  edges.reserve(raw.size());
  for (std::size_t e = 0; e < raw.size(); ++e) {
    for (std::int64_t index : raw[e])
      if (index < 0 || index >= n)
        throw InvalidFigureError(
            FigureDefect::EdgeIndexOutOfRange,
            "edge " + std::to_string(e) + " refers to vertex " + std::to_string(index) +
                ", which is out of range (the figure has " + std::to_string(n) +
                (n == 1 ? " vertex, index 0)" : " vertices, 0 to " + std::to_string(n - 1) + ")"),
            {}, {int(e)});
    edges.push_back({int(raw[e][0]), int(raw[e][1])});
  }
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (edges[e][0] == edges[e][1])
      throw InvalidFigureError(FigureDefect::SelfLoop,
                               "edge " + std::to_string(e) + " is a self-loop at vertex " +
                                   std::to_string(edges[e][0]),
                               {edges[e][0]}, {int(e)});
  return edges;
}

void check_duplicate_edges(const std::vector<Edge>& edges) {
  // Sort (min, max, index) so that equal undirected edges are adjacent and
  // the pair reported is the one with the smallest indices.
  std::vector<std::tuple<int, int, int>> keys;
  keys.reserve(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e)
    keys.emplace_back(std::min(edges[e][0], edges[e][1]), std::max(edges[e][0], edges[e][1]), int(e));
  std::sort(keys.begin(), keys.end());
  std::vector<std::pair<int, int>> duplicates;
  for (std::size_t k = 1; k < keys.size(); ++k)
    if (std::get<0>(keys[k]) == std::get<0>(keys[k - 1]) &&
        std::get<1>(keys[k]) == std::get<1>(keys[k - 1]))
      duplicates.emplace_back(std::get<2>(keys[k - 1]), std::get<2>(keys[k]));
  if (duplicates.empty()) return;
  const auto [first, second] = *std::min_element(duplicates.begin(), duplicates.end());
  const int a = std::min(edges[first][0], edges[first][1]);
  const int b = std::max(edges[first][0], edges[first][1]);
  throw InvalidFigureError(FigureDefect::DuplicateEdge,
                           "edges " + std::to_string(first) + " and " + std::to_string(second) +
                               " both join vertices " + std::to_string(a) + " and " +
                               std::to_string(b),
                           {a, b}, {first, second});
}

void check_coincident_vertices(const std::vector<Vec2>& vertices) {
  std::vector<int> order(vertices.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return compare_xy(vertices[a], vertices[b]) < 0;
  });
  std::vector<std::pair<int, int>> coincident;
  for (std::size_t k = 1; k < order.size(); ++k)
    if (compare_xy(vertices[order[k - 1]], vertices[order[k]]) == 0)
      coincident.emplace_back(std::min(order[k - 1], order[k]), std::max(order[k - 1], order[k]));
  if (coincident.empty()) return;
  const auto [a, b] = *std::min_element(coincident.begin(), coincident.end());
  throw InvalidFigureError(FigureDefect::CoincidentVertices,
                           "vertices " + std::to_string(a) + " and " + std::to_string(b) +
                               " coincide at " + point_text(vertices[a]),
                           {a, b});
}

// A geometric defect between two edges, or an edge and an isolated vertex.
struct ContactDefect {
  FigureDefect defect;
  int edge_a;    // smaller edge index
  int edge_b;    // other edge, or -1
  int vertex;    // vertex lying on edge_a, or -1
  bool operator<(const ContactDefect& o) const {
    return std::tie(defect, edge_a, edge_b, vertex) < std::tie(o.defect, o.edge_a, o.edge_b, o.vertex);
  }
};

// Which endpoint of edge `other` lies on edge `host` (exactly), or -1.
int endpoint_on_edge(const std::vector<Vec2>& vertices, const Edge& host, const Edge& other) {
  for (int v : other)
    if (v != host[0] && v != host[1] && on_segment(vertices[v], vertices[host[0]], vertices[host[1]]))
      return v;
  return -1;
}

// Classifies how two edges meet. Incident edges may only share their common
// endpoint; non-incident edges may not meet at all.
void classify_edge_pair(const std::vector<Vec2>& V, const std::vector<Edge>& edges, int e, int f,
                        std::vector<ContactDefect>& found) {
  if (e > f) std::swap(e, f);
  const Edge& a = edges[e];
  const Edge& b = edges[f];
  const bool incident = a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
  switch (segment_contact(V[a[0]], V[a[1]], V[b[0]], V[b[1]])) {
    case SegmentContact::Disjoint:
      return;
    case SegmentContact::Crossing:
      found.push_back({FigureDefect::CrossingEdges, e, f, -1});
      return;
    case SegmentContact::Overlapping:
      found.push_back({FigureDefect::OverlappingEdges, e, f, -1});
      return;
    case SegmentContact::Touching: {
      if (incident) return;  // they touch at their shared vertex
      // Distinct vertices never coincide (checked before), so the contact is
      // an endpoint of one edge in the interior of the other.
      int v = endpoint_on_edge(V, a, b);
      if (v >= 0) {
        found.push_back({FigureDefect::VertexOnEdge, e, -1, v});
      } else {
        v = endpoint_on_edge(V, b, a);
        found.push_back({FigureDefect::VertexOnEdge, f, -1, v});
      }
      return;
    }
  }
}

struct StopSearch {};

void check_contacts(const std::vector<Vec2>& V, const std::vector<Edge>& edges) {
  // Candidate pairs come from overlapping bounding boxes (CGAL's box
  // intersection, closed boxes so that touching counts); each candidate is
  // then classified with exact predicates. Boxes of doubles are exact.
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, int>;
  std::vector<int> degree(V.size(), 0);
  for (const Edge& e : edges) ++degree[e[0]], ++degree[e[1]];

  std::vector<Box> boxes;
  boxes.reserve(edges.size() + V.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Vec2& p = V[edges[e][0]];
    const Vec2& q = V[edges[e][1]];
    double lo[2] = {std::min(p[0], q[0]), std::min(p[1], q[1])};
    double hi[2] = {std::max(p[0], q[0]), std::max(p[1], q[1])};
    boxes.emplace_back(lo, hi, int(e));
  }
  // An isolated vertex (a part of its own, a dot)
  // is still checked against the edges, so that "vertex on edge" is reported
  // as such. Its info is -(v + 1).
  if (V.size() > 1)
    for (std::size_t v = 0; v < V.size(); ++v)
      if (degree[v] == 0) {
        double lo[2] = {V[v][0], V[v][1]};
        double hi[2] = {V[v][0], V[v][1]};
        boxes.emplace_back(lo, hi, -int(v) - 1);
      }

  // Enough defects to report the first by kind; a hostile input with
  // quadratically many crossings must not take quadratic time to reject.
  constexpr std::size_t kEnough = 1024;
  std::vector<ContactDefect> found;
  auto callback = [&](const Box& x, const Box& y) {
    int i = x.info(), j = y.info();
    if (i < 0 && j < 0) return;  // two isolated vertices: coincidence checked before
    if (i < 0 || j < 0) {
      const int e = std::max(i, j);
      const int v = -std::min(i, j) - 1;
      if (on_segment(V[v], V[edges[e][0]], V[edges[e][1]]))
        found.push_back({FigureDefect::VertexOnEdge, e, -1, v});
    } else {
      classify_edge_pair(V, edges, i, j, found);
    }
    if (found.size() >= kEnough) throw StopSearch{};
  };
  try {
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), callback);
  } catch (const StopSearch&) {
  }
  if (found.empty()) return;

  const ContactDefect d = *std::min_element(found.begin(), found.end());
  const std::string ea = "edge " + describe_edge_of(edges, d.edge_a);
  switch (d.defect) {
    case FigureDefect::CrossingEdges:
      throw InvalidFigureError(d.defect,
                               "edges " + describe_edge_of(edges, d.edge_a) + " and " +
                                   describe_edge_of(edges, d.edge_b) + " cross",
                               {}, {d.edge_a, d.edge_b});
    case FigureDefect::OverlappingEdges:
      throw InvalidFigureError(d.defect,
                               "edges " + describe_edge_of(edges, d.edge_a) + " and " +
                                   describe_edge_of(edges, d.edge_b) +
                                   " overlap: they are collinear and share a segment",
                               {}, {d.edge_a, d.edge_b});
    default:
      throw InvalidFigureError(FigureDefect::VertexOnEdge,
                               vertex_text(d.vertex) + " " + point_text(V[d.vertex]) +
                                   " lies on " + ea + ", which is not incident to it",
                               {d.vertex}, {d.edge_a});
  }
}

void check_figure(const std::vector<Vec2>& vertices, const std::vector<Edge>& edges) {
  check_duplicate_edges(edges);
  check_coincident_vertices(vertices);
  // No connectivity check: a figure may have several parts (issue 14),
  // every pair of which is checked above like edges of one part.
  check_contacts(vertices, edges);
}

}  // namespace

std::string describe_edge_of(const std::vector<Edge>& edges, int edge) {
  return std::to_string(edge) + " (" + std::to_string(edges[edge][0]) + "-" +
         std::to_string(edges[edge][1]) + ")";
}

StickFigure make_stick_figure(std::vector<Vec2> vertices,
                              const std::vector<std::array<std::int64_t, 2>>& edges,
                              std::string name) {
  check_coordinates(vertices);
  std::vector<Edge> checked = checked_edges(vertices.size(), edges);
  check_figure(vertices, checked);
  return StickFigure{std::move(vertices), std::move(checked), std::move(name)};
}

void validate(const StickFigure& figure) {
  check_coordinates(figure.vertices);
  std::vector<std::array<std::int64_t, 2>> raw;
  raw.reserve(figure.edges.size());
  for (const Edge& e : figure.edges) raw.push_back({e[0], e[1]});
  check_figure(figure.vertices, checked_edges(figure.vertices.size(), raw));
}

bool is_valid(const StickFigure& figure) {
  try {
    validate(figure);
    return true;
  } catch (const InvalidFigureError&) {
    return false;
  }
}

int find_edge(const StickFigure& figure, int a, int b) {
  for (std::size_t e = 0; e < figure.edges.size(); ++e) {
    const Edge& edge = figure.edges[e];
    if ((edge[0] == a && edge[1] == b) || (edge[0] == b && edge[1] == a)) return int(e);
  }
  return -1;
}

std::string describe_edge(const StickFigure& figure, int edge) {
  return describe_edge_of(figure.edges, edge);
}

std::string format_double(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace stickmorph
