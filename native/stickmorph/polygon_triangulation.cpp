#include "stickmorph/polygon_triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <map>
#include <queue>
#include <set>

#include "stickmorph/cancellation.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/triangle_adjacency.h"

namespace stickmorph {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
// Per face: the polygon corner at each of its three slots (-1 if outside).
using FaceInfo = std::array<int, 3>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// No constraint may cross another in a valid polygon, so CGAL never has to
// construct an intersection point: exact predicates suffice.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;
using VertexHandle = Cdt::Vertex_handle;
using FaceHandle = Cdt::Face_handle;

[[noreturn]] void reject(FigureDefect defect, const std::string& what, std::vector<int> vertices) {
  throw InvalidFigureError(defect, "polygon is not weakly simple: " + what, std::move(vertices));
}

// Names two polygon edges that meet where they should not (brute force: this
// only runs to explain a rejection).
std::string find_bad_contact(const CornerPolygon& polygon, std::vector<int>& vertices) {
  const int n = polygon.size();
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const int a = polygon.corners[i], b = polygon.corners[(i + 1) % n];
      const int c = polygon.corners[j], d = polygon.corners[(j + 1) % n];
      if ((a == c && b == d) || (a == d && b == c)) continue;  // one edge walked twice
      const SegmentContact contact = segment_contact(polygon.positions[a], polygon.positions[b],
                                                     polygon.positions[c], polygon.positions[d]);
      const bool shared = a == c || a == d || b == c || b == d;
      if (contact == SegmentContact::Crossing || contact == SegmentContact::Overlapping ||
          (contact == SegmentContact::Touching && !shared)) {
        vertices = {a, b, c, d};
        return "its edges from corner " + std::to_string(i) + " (" + std::to_string(a) + "-" +
               std::to_string(b) + ") and from corner " + std::to_string(j) + " (" + std::to_string(c) +
               "-" + std::to_string(d) + ") " +
               (contact == SegmentContact::Crossing ? "cross" : contact == SegmentContact::Overlapping ? "overlap" : "touch");
      }
    }
  return "two of its edges cross";
}

// The face to the left of the directed edge a -> b, which must be an edge.
std::pair<FaceHandle, int> face_left_of(const Cdt& cdt, VertexHandle a, VertexHandle b) {
  FaceHandle f;
  int i;
  if (!cdt.is_edge(a, b, f, i)) return {FaceHandle(), -1};
  // Edge (f, i) runs vertex(ccw(i)) -> vertex(cw(i)) with f on its left.
  if (f->vertex(Cdt::ccw(i)) == a) return {f, i};
  FaceHandle g = f->neighbor(i);
  return {g, g->index(f)};
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_polygon(const CornerPolygon& polygon) {
  const int n = polygon.size();
  if (n < 3) reject(FigureDefect::TooFewCorners, "it has " + std::to_string(n) + " corners", {});

  Cdt cdt;
  std::map<int, VertexHandle> handle;  // vertex id -> CDT vertex
  // The constrained Delaunay triangulation of a 2 * 10^5-corner exterior
  // face (a 10^5-vertex polyline) takes tens of seconds: cancellable
  // (cancellation.h) vertex by vertex and constraint by constraint.
  for (int id : polygon.corners)
    if (!handle.count(id)) {
      poll_cancellation();
      const Vec2& p = polygon.positions[id];
      const std::size_t before = cdt.number_of_vertices();
      VertexHandle v = cdt.insert(Kernel::Point_2(p[0], p[1]));
      if (cdt.number_of_vertices() == before)
        reject(FigureDefect::CoincidentCorners,
               "vertices " + std::to_string(v->info()) + " and " + std::to_string(id) + " coincide",
               {v->info(), id});
      v->info() = id;
      handle[id] = v;
    }
  try {
    // An edge walked on both sides (a dangling edge, a bridge) is one
    // constraint: inserting it twice would count as an overlap.
    std::set<std::pair<int, int>> inserted;
    for (int k = 0; k < n; ++k) {
      poll_cancellation();
      const int a = polygon.corners[k], b = polygon.corners[(k + 1) % n];
      if (a == b) reject(FigureDefect::CoincidentCorners, "corner " + std::to_string(k) + " repeats its successor", {a});
      if (inserted.emplace(std::min(a, b), std::max(a, b)).second) cdt.insert_constraint(handle[a], handle[b]);
    }
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    std::vector<int> vertices;
    const std::string what = find_bad_contact(polygon, vertices);
    reject(FigureDefect::CrossingEdges, what, vertices);
  }
  // A polygon edge passing through another vertex is split by CGAL into two
  // constraints; detect it as a missing edge.
  for (int k = 0; k < n; ++k) {
    const int a = polygon.corners[k], b = polygon.corners[(k + 1) % n];
    if (face_left_of(cdt, handle[a], handle[b]).second < 0)
      reject(FigureDefect::VertexOnEdge, "its edge from corner " + std::to_string(k) + " (vertex " + std::to_string(a) +
                 ") to vertex " + std::to_string(b) + " passes through another vertex",
             {a, b});
  }

  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = {-1, -1, -1};

  // Assign corners: rotate counter-clockwise around each corner's vertex from
  // its outgoing edge to its incoming edge; every face swept lies in this
  // corner's wedge. Sweeping stops at the first constrained edge.
  for (int k = 0; k < n; ++k) {
    VertexHandle v = handle[polygon.corners[k]];
    VertexHandle next = handle[polygon.corners[(k + 1) % n]];
    VertexHandle prev = handle[polygon.corners[(k + n - 1) % n]];
    auto [f, i] = face_left_of(cdt, v, next);
    for (int guard = 0;; ++guard) {
      if (cdt.is_infinite(f) || guard > int(cdt.number_of_faces()) + 2)
        reject(FigureDefect::ClockwiseCorners,
               "corner " + std::to_string(k) + " (vertex " + std::to_string(polygon.corners[k]) +
                   ") opens onto the outside: the corners are not in counter-clockwise order",
               {polygon.corners[k]});
      const int j = f->index(v);
      if (f->info()[j] >= 0)
        reject(FigureDefect::ClosedWedge, "corners " + std::to_string(f->info()[j]) + " and " + std::to_string(k) +
                   " claim the same wedge at vertex " + std::to_string(polygon.corners[k]),
               {polygon.corners[k]});
      f->info()[j] = k;
      // The edge from v to vertex(cw(j)) is opposite ccw(j).
      const int side = Cdt::ccw(j);
      if (cdt.is_constrained({f, side})) {
        if (f->vertex(Cdt::cw(j)) != prev)
          reject(FigureDefect::ClosedWedge, "the wedge at corner " + std::to_string(k) + " (vertex " +
                     std::to_string(polygon.corners[k]) + ") is closed by another edge",
                 {polygon.corners[k]});
        break;
      }
      f = f->neighbor(side);
    }
    (void)i;
  }

  std::vector<std::array<int, 3>> triangles;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const FaceInfo& c = f->info();
    const int assigned = (c[0] >= 0) + (c[1] >= 0) + (c[2] >= 0);
    if (assigned == 3) triangles.push_back(c);
    else if (assigned != 0)
      reject(FigureDefect::SelfOverlappingPolygon, "a triangle touches the region at only some of its corners", {});
  }
  if (int(triangles.size()) != n - 2)
    reject(FigureDefect::SelfOverlappingPolygon, "its interior triangulates into " + std::to_string(triangles.size()) +
               " triangles instead of " + std::to_string(n - 2) +
               " (it overlaps itself or runs clockwise)",
           {});
  return triangles;
}

PolygonTriangulation dual_tree_depths(const CornerPolygon& polygon,
                                      std::vector<std::array<int, 3>> triangles, int center_choice) {
  PolygonTriangulation pt;
  const int n = polygon.size();
  const int t_count = int(triangles.size());
  pt.triangles = std::move(triangles);
  pt.neighbour.assign(t_count, {-1, -1, -1});

  // Two triangles are adjacent when they share a side as corner pairs: side
  // (a -> b) in one is (b -> a) in the other. Polygon edges join consecutive
  // corners and are never shared.
  const internal::TriangleAdjacency adjacency(polygon.size(), pt.triangles);
  for (int t = 0; t < t_count; ++t)
    for (int j = 0; j < 3; ++j) {
      const int a = pt.triangles[t][(j + 1) % 3], b = pt.triangles[t][(j + 2) % 3];
      pt.neighbour[t][j] = adjacency.left_of(b, a);
    }

  // Center: remove all leaves at once until one face (or two adjacent
  // faces) remain.
  std::vector<int> degree(t_count, 0);
  for (int t = 0; t < t_count; ++t)
    for (int j = 0; j < 3; ++j) degree[t] += pt.neighbour[t][j] >= 0;
  std::vector<int> removed(t_count, 0);
  std::vector<int> layer;
  for (int t = 0; t < t_count; ++t)
    if (degree[t] <= 1) layer.push_back(t);
  int remaining = t_count;
  std::vector<int> last = layer;
  while (remaining > int(layer.size())) {
    std::vector<int> next_layer;
    for (int t : layer) {
      removed[t] = 1;
      --remaining;
    }
    for (int t : layer)
      for (int j = 0; j < 3; ++j) {
        const int u = pt.neighbour[t][j];
        if (u >= 0 && !removed[u] && --degree[u] == 1) next_layer.push_back(u);
      }
    layer = next_layer;
  }
  // `layer` holds the last one or two faces.
  std::sort(layer.begin(), layer.end());
  pt.center_faces = layer;
  pt.center = layer[std::min<int>(center_choice, int(layer.size()) - 1)];

  pt.parent.assign(t_count, -1);
  pt.depth.assign(t_count, -1);
  std::queue<int> queue;
  queue.push(pt.center);
  pt.depth[pt.center] = 0;
  while (!queue.empty()) {
    const int t = queue.front();
    queue.pop();
    for (int j = 0; j < 3; ++j) {
      const int u = pt.neighbour[t][j];
      if (u >= 0 && pt.depth[u] < 0) {
        pt.depth[u] = pt.depth[t] + 1;
        pt.parent[u] = t;
        queue.push(u);
      }
    }
  }
  pt.milestone.assign(n, -1);
  pt.shallowest.assign(n, -1);
  for (int t = 0; t < t_count; ++t)
    for (int c : pt.triangles[t])
      if (pt.milestone[c] < 0 || pt.depth[t] < pt.milestone[c]) {
        pt.milestone[c] = pt.depth[t];
        pt.shallowest[c] = t;
      }
  return pt;
}

}  // namespace stickmorph
