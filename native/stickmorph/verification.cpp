#include "stickmorph/verification.h"

#include <cmath>
#include <map>
#include <set>

#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/disk_topology.h"
#include "stickmorph/internal/triangle_adjacency.h"
#include "stickmorph/internal/geometry.h"

namespace stickmorph {
namespace {

using internal::angle_at;  // unsigned, in [0, pi]; a few ulps: the differences are exact or correctly rounded
using internal::kPi;
using internal::DiskDefect;
using internal::TriangleAdjacency;

// Interior angle of the polygon at corner k, in (0, 2*pi]: the
// counter-clockwise sweep from the outgoing edge to the incoming edge.
double corner_angle(const CornerPolygon& polygon, int k) {
  const int n = polygon.size();
  const int prev = polygon.corners[(k + n - 1) % n];
  const int next = polygon.corners[(k + 1) % n];
  if (prev == next) return 2 * kPi;  // tip of a dangling edge
  const Vec2& v = polygon.at(k);
  const Vec2& p = polygon.positions[prev];
  const Vec2& q = polygon.positions[next];
  const int turn = orientation(v, q, p);
  if (turn == 0) return kPi;
  const double between = angle_at(v, q, p);
  return turn > 0 ? between : 2 * kPi - between;
}

struct Checker {
  const PolygonPair& pair;
  const CompatibleTriangulation& tri;
  const std::string& label;
  int corners;
  int nodes;

  Vec2 position(int node, bool target) const {
    if (node < corners) return target ? pair.target_positions[pair.corners[node]]
                                      : pair.source_positions[pair.corners[node]];
    return target ? tri.target_steiner[node - corners] : tri.source_steiner[node - corners];
  }

  std::string node_text(int node) const {
    if (node < corners)
      return "corner " + std::to_string(node) + " (vertex " + std::to_string(pair.corners[node]) + ")";
    return "Steiner vertex " + std::to_string(node - corners);
  }

  std::string triangle_text(int t) const {
    const auto& tr = tri.triangles[t];
    return "triangle " + std::to_string(t) + " (" + node_text(tr[0]) + ", " + node_text(tr[1]) +
           ", " + node_text(tr[2]) + ")";
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw VerificationError(label + ": compatible triangulation is invalid: " + what);
  }

  // A key that identifies corners of the same vertex: simplicial means no
  // two edges share the same pair of keys.
  long key(int node) const { return node < corners ? pair.corners[node] : -1 - long(node); }

  void run() const {
    if (int(tri.target_steiner.size()) != int(tri.source_steiner.size()))
      fail("the source has " + std::to_string(tri.source_steiner.size()) +
           " Steiner vertices and the target " + std::to_string(tri.target_steiner.size()));
    if (tri.corner_count != corners)
      fail("it has " + std::to_string(tri.corner_count) + " corners, the polygon " +
           std::to_string(corners));
    for (int side = 0; side < 2; ++side)
      for (const Vec2& p : side ? tri.target_steiner : tri.source_steiner)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1])) fail("a Steiner vertex is not finite");

    // 1. Every triangle positive in both polygons (exact).
    for (std::size_t t = 0; t < tri.triangles.size(); ++t) {
      const auto& tr = tri.triangles[t];
      for (int node : tr)
        if (node < 0 || node >= nodes) fail("triangle " + std::to_string(t) + " names node " + std::to_string(node) + ", which does not exist");
      for (int side = 0; side < 2; ++side) {
        const int o = orientation(position(tr[0], side), position(tr[1], side), position(tr[2], side));
        if (o <= 0)
          fail(triangle_text(int(t)) + " is " + (o == 0 ? "degenerate" : "inverted") + " in the " +
               (side ? "target" : "source"));
      }
    }

    // 2. A triangulated disk bounded by the polygon (disk_topology.h): the
    // polygon's edges each with a triangle on the inside only, every other
    // side shared by two triangles, one fan round every node.
    std::vector<int> boundary(corners);
    for (int k = 0; k < corners; ++k) boundary[k] = k;
    const TriangleAdjacency adjacency(nodes, tri.triangles);
    const DiskDefect defect = find_disk_defect(adjacency, tri.triangles, boundary);
    switch (defect.kind) {
      case DiskDefect::Kind::None: break;
      case DiskDefect::Kind::RepeatedSide:
        fail("the side from " + node_text(defect.a) + " to " + node_text(defect.b) +
             " is used by two triangles on the same side");
      case DiskDefect::Kind::BoundarySideMissing:
        fail("the polygon edge from " + node_text(defect.a) + " to " + node_text(defect.b) + " is not a triangle side");
      case DiskDefect::Kind::OutsideBoundary:
        fail("the polygon edge from " + node_text(defect.a) + " to " + node_text(defect.b) +
             " has triangles on both sides");
      case DiskDefect::Kind::SideBordersNothing:
        fail("the side from " + node_text(defect.a) + " to " + node_text(defect.b) + " of " +
             triangle_text(defect.triangle) + " borders nothing");
      case DiskDefect::Kind::NodeInNoTriangle: fail(node_text(defect.a) + " is in no triangle");
      case DiskDefect::Kind::BoundaryFanBroken:
      case DiskDefect::Kind::InteriorFanGap:
      case DiskDefect::Kind::InteriorFanNotClosed:
        fail("the triangles around " + node_text(defect.a) + " do not form one fan");
    }
    std::set<std::pair<int, int>> boundary_sides;
    for (int k = 0; k < corners; ++k) boundary_sides.emplace(k, (k + 1) % corners);
    std::set<std::pair<int, int>> undirected;
    for (const auto& tr : tri.triangles)
      for (int j = 0; j < 3; ++j)
        undirected.emplace(std::min(tr[j], tr[(j + 1) % 3]), std::max(tr[j], tr[(j + 1) % 3]));
    const long euler = long(nodes) - long(undirected.size()) + long(tri.triangles.size());
    if (euler != 1) fail("it is not a disk (Euler characteristic " + std::to_string(euler) + ")");

    // 3. Angle sums: one full turn around each Steiner vertex, the polygon's
    // angle at each corner. The alternatives differ by whole turns.
    for (int side = 0; side < 2; ++side) {
      std::vector<double> sum(nodes, 0.0);
      for (const auto& tr : tri.triangles)
        for (int j = 0; j < 3; ++j)
          sum[tr[j]] += angle_at(position(tr[j], side), position(tr[(j + 1) % 3], side),
                                 position(tr[(j + 2) % 3], side));
      const CornerPolygon polygon = side ? pair.target() : pair.source();
      for (int node = 0; node < nodes; ++node) {
        const double expected = node < corners ? corner_angle(polygon, node) : 2 * kPi;
        if (std::abs(sum[node] - expected) > kPi)
          fail("the triangles around " + node_text(node) + " turn " +
               format_double(sum[node] / (2 * kPi)) + " times instead of " +
               format_double(expected / (2 * kPi)) + " in the " + (side ? "target" : "source") +
               ": they overlap");
      }
    }

    // 4. Simplicial once repeated corners are identified with their vertex.
    // A figure edge walked on both sides is one edge with a triangle on
    // each side, so boundary sides may pair up; nothing else may.
    std::map<std::pair<long, long>, std::pair<int, int>> by_key;
    for (const auto& [a, b] : undirected) {
      const long ka = key(a), kb = key(b);
      if (ka == kb) fail("the side from " + node_text(a) + " to " + node_text(b) + " joins a vertex to itself");
      const std::pair<long, long> k{std::min(ka, kb), std::max(ka, kb)};
      auto [it, inserted] = by_key.emplace(k, std::make_pair(a, b));
      if (!inserted) {
        const auto [c, d] = it->second;
        const bool both_boundary = (boundary_sides.count({a, b}) || boundary_sides.count({b, a})) &&
                                   (boundary_sides.count({c, d}) || boundary_sides.count({d, c}));
        if (!both_boundary)
          fail("the sides " + node_text(a) + " - " + node_text(b) + " and " + node_text(c) + " - " +
               node_text(d) + " join the same two vertices (a doubled edge)");
      }
    }
  }
};

}  // namespace

void verify_compatible_triangulation(const PolygonPair& pair, const CompatibleTriangulation& tri,
                                     const std::string& label) {
  const int corners = int(pair.corners.size());
  Checker{pair, tri, label, corners, corners + int(tri.source_steiner.size())}.run();
}

bool is_valid(const PolygonPair& pair, const CompatibleTriangulation& tri) {
  try {
    verify_compatible_triangulation(pair, tri);
    return true;
  } catch (const VerificationError&) {
    return false;
  }
}

}  // namespace stickmorph
