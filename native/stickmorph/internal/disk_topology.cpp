// The combinatorial disk check; see disk_topology.h.
#include "stickmorph/internal/disk_topology.h"

#include <algorithm>
#include <unordered_map>

namespace stickmorph::internal {

DiskDefect find_disk_defect(const TriangleAdjacency& adjacency, const std::vector<Triangle>& triangles,
                            const std::vector<int>& boundary, std::vector<std::vector<int>>* rings) {
  using Kind = DiskDefect::Kind;
  const int nodes = adjacency.nodes();
  if (adjacency.repeated_side().first >= 0) {
    const auto& r = adjacency.repeated_side();
    return {Kind::RepeatedSide, r.a, r.b, r.first, r.second};
  }
  const int k = int(boundary.size());
  std::vector<int> boundary_index(nodes, -1);
  for (int i = 0; i < k; ++i) boundary_index[boundary[i]] = i;
  for (int i = 0; i < k; ++i) {
    const int a = boundary[i], b = boundary[(i + 1) % k];
    if (adjacency.left_of(a, b) < 0) return {Kind::BoundarySideMissing, a, b};
    const int outside = adjacency.left_of(b, a);
    if (outside >= 0) return {Kind::OutsideBoundary, a, b, outside};
  }
  auto is_boundary_side = [&](int a, int b) {
    return boundary_index[a] >= 0 && boundary_index[b] >= 0 && boundary_index[b] == (boundary_index[a] + 1) % k;
  };
  for (int t = 0; t < int(triangles.size()); ++t)
    for (int j = 0; j < 3; ++j) {
      const int a = triangles[t][j], b = triangles[t][(j + 1) % 3];
      if (!is_boundary_side(a, b) && adjacency.left_of(b, a) < 0) return {Kind::SideBordersNothing, a, b, t};
    }
  // Fans: at node v, triangle (v, b, c) leads from neighbour b to c
  // counter-clockwise.
  if (rings) rings->assign(nodes, {});
  for (int v = 0; v < nodes; ++v) {
    const std::vector<int>& star = adjacency.around(v);
    if (star.empty()) return {Kind::NodeInNoTriangle, v};
    std::unordered_map<int, int> next;
    int first = -1;
    for (int t : star) {
      const Triangle& tr = triangles[t];
      const int c = int(std::find(tr.begin(), tr.end(), v) - tr.begin());
      next.emplace(tr[(c + 1) % 3], tr[(c + 2) % 3]);
      if (first < 0) first = tr[(c + 1) % 3];
    }
    if (boundary_index[v] >= 0) {
      // An open fan from the next boundary node to the previous one.
      const int i = boundary_index[v];
      int at = boundary[(i + 1) % k];
      const int last = boundary[(i + k - 1) % k];
      std::size_t steps = 0;
      while (at != last && steps <= star.size()) {
        auto it = next.find(at);
        if (it == next.end()) break;
        at = it->second;
        ++steps;
      }
      if (at != last || steps != star.size()) return {Kind::BoundaryFanBroken, v};
      continue;
    }
    std::vector<int> ring{first};
    for (std::size_t step = 0; step < star.size(); ++step) {
      auto it = next.find(ring.back());
      if (it == next.end()) return {Kind::InteriorFanGap, v};
      ring.push_back(it->second);
    }
    // star.size() steps must close the cycle exactly then, not before.
    ring.pop_back();
    const bool closed = next.at(ring.back()) == ring.front();
    std::vector<int> sorted = ring;
    std::sort(sorted.begin(), sorted.end());
    if (!closed || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      return {Kind::InteriorFanNotClosed, v};
    if (rings) (*rings)[v] = std::move(ring);
  }
  return {};
}

}  // namespace stickmorph::internal
