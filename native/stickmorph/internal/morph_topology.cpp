// The morph's view of a triangulation's combinatorics; see morph_topology.h.
#include "stickmorph/internal/morph_topology.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/disk_topology.h"
#include "stickmorph/internal/triangle_adjacency.h"

namespace stickmorph::internal {

std::string node_text(const FigureTriangulation& tri, int node) {
  const int n = tri.figure_vertices, k = tri.enclosure_vertices;
  std::string text = "node " + std::to_string(node);
  if (node < n) return text + " (figure vertex " + std::to_string(node) + ")";
  if (node < n + k) return text + " (enclosure vertex " + std::to_string(node - n) + ")";
  return text + " (Steiner vertex " + std::to_string(node - n - k) + ")";
}

std::string triangle_text(const FigureTriangulation& tri, int t) {
  const auto& tr = tri.triangles[t];
  return "triangle " + std::to_string(t) + " (" + std::to_string(tr[0]) + ", " + std::to_string(tr[1]) + ", " +
         std::to_string(tr[2]) + ")";
}

[[noreturn]] void malformed(const std::string& what) {
  throw InvalidArgumentError("invalid triangulation for the morph: " + what);
}

bool is_enclosure(const FigureTriangulation& tri, int node) {
  return node >= tri.figure_vertices && node < tri.figure_vertices + tri.enclosure_vertices;
}

Topology build_topology(const FigureTriangulation& tri) {
  const int n = tri.figure_vertices, k = tri.enclosure_vertices, s = tri.steiner_vertices;
  if (n < 1 || k < 3 || s < 0)
    malformed("it needs at least 1 figure vertex and 3 enclosure vertices, got n = " + std::to_string(n) +
              ", k = " + std::to_string(k) + ", s = " + std::to_string(s));
  const int N = tri.node_count();
  if (int(tri.source.size()) != N || int(tri.target.size()) != N)
    malformed("it has " + std::to_string(N) + " nodes but " + std::to_string(tri.source.size()) +
              " source and " + std::to_string(tri.target.size()) + " target positions");
  for (int side = 0; side < 2; ++side)
    for (int v = 0; v < N; ++v) {
      const Vec2& p = side ? tri.target[v] : tri.source[v];
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || std::abs(p[0]) > kMaxNodeMagnitude ||
          std::abs(p[1]) > kMaxNodeMagnitude)
        malformed(node_text(tri, v) + " has a non-finite or too large position in the " +
                  (side ? "target" : "source"));
    }

  for (int t = 0; t < int(tri.triangles.size()); ++t) {
    const auto& tr = tri.triangles[t];
    for (int c = 0; c < 3; ++c)
      if (tr[c] < 0 || tr[c] >= N) malformed(triangle_text(tri, t) + " refers to a node out of range");
    if (tr[0] == tr[1] || tr[1] == tr[2] || tr[2] == tr[0]) malformed(triangle_text(tri, t) + " repeats a node");
  }

  // The boundary is the enclosure, counter-clockwise (disk_topology.h).
  std::vector<int> enclosure(k);
  for (int i = 0; i < k; ++i) enclosure[i] = n + i;
  const TriangleAdjacency adjacency(N, tri.triangles);
  Topology topo;
  topo.nodes = N;
  const DiskDefect defect = find_disk_defect(adjacency, tri.triangles, enclosure, &topo.ring);
  const std::string a = std::to_string(defect.a), b = std::to_string(defect.b);
  switch (defect.kind) {
    case DiskDefect::Kind::None: break;
    case DiskDefect::Kind::RepeatedSide:
      // Two triangles on the same side of an edge overlap.
      malformed("the side " + a + "->" + b + " belongs to " + triangle_text(tri, defect.triangle) + " and " +
                triangle_text(tri, defect.other_triangle) + " (they overlap)");
    case DiskDefect::Kind::BoundarySideMissing:
      malformed("the enclosure side " + a + "->" + b + " is not a side of any triangle");
    case DiskDefect::Kind::OutsideBoundary:
      malformed("a triangle lies outside the enclosure side " + a + "-" + b);
    case DiskDefect::Kind::SideBordersNothing:
      malformed("the edge " + a + "-" + b + " borders only " + triangle_text(tri, defect.triangle) +
                " but is not an enclosure side (a hole or a second boundary)");
    case DiskDefect::Kind::NodeInNoTriangle: malformed(node_text(tri, defect.a) + " is in no triangle");
    case DiskDefect::Kind::BoundaryFanBroken:
      malformed("the triangles around " + node_text(tri, defect.a) + " do not form one fan (the disk is pinched there)");
    case DiskDefect::Kind::InteriorFanGap:
      malformed("the triangles around " + node_text(tri, defect.a) + " leave a gap");
    case DiskDefect::Kind::InteriorFanNotClosed:
      malformed("the triangles around " + node_text(tri, defect.a) + " do not close into one fan");
  }
  topo.unknown.assign(N, -1);
  for (int v = 0; v < N; ++v)
    if (!is_enclosure(tri, v)) {
      topo.unknown[v] = int(topo.interior_nodes.size());
      topo.interior_nodes.push_back(v);
    }
  return topo;
}

int first_non_positive(const FigureTriangulation& tri, const std::vector<Vec2>& positions) {
  for (int t = 0; t < int(tri.triangles.size()); ++t) {
    const auto& tr = tri.triangles[t];
    if (orientation(positions[tr[0]], positions[tr[1]], positions[tr[2]]) <= 0) return t;
  }
  return -1;
}

void require_positive(const FigureTriangulation& tri, const std::vector<Vec2>& positions, const char* which) {
  const int t = first_non_positive(tri, positions);
  if (t >= 0) malformed(triangle_text(tri, t) + " is not counter-clockwise in the " + which);
}

void require_enclosure(const FigureTriangulation& tri) {
  const int n = tri.figure_vertices, k = tri.enclosure_vertices;
  for (int i = 0; i < k; ++i)
    if (tri.source[n + i] != tri.target[n + i])
      malformed(node_text(tri, n + i) + " moves: the enclosure must be the same in source and target");
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      if (j == i || j == (i + 1) % k) continue;
      if (orientation(tri.source[n + i], tri.source[n + (i + 1) % k], tri.source[n + j]) <= 0)
        malformed("the enclosure is not strictly convex and counter-clockwise: " + node_text(tri, n + j) +
                  " is not strictly left of the side " + std::to_string(n + i) + "-" +
                  std::to_string(n + (i + 1) % k));
    }
}

}  // namespace stickmorph::internal
