// Cutting a polygon pair along shared diagonals; see shared_diagonals.h.
#include "stickmorph/internal/shared_diagonals.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "stickmorph/cancellation.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/geometry.h"
#include "stickmorph/internal/triangle_adjacency.h"

namespace stickmorph::internal {

std::set<std::pair<int, int>> common_diagonals(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                                              double min_new_angle) {
  const int n = int(pair.corners.size());
  const CornerPolygon target = pair.target();
  std::vector<std::pair<int, int>> candidates;
  std::set<std::pair<int, int>> seen;
  for (const auto& t : source_base)
    for (int j = 0; j < 3; ++j) {
      const int a = t[j], b = t[(j + 1) % 3];
      if ((a + 1) % n == b || (b + 1) % n == a) continue;  // a polygon edge
      if (seen.emplace(std::min(a, b), std::max(a, b)).second) candidates.push_back({std::min(a, b), std::max(a, b)});
    }
  std::set<std::pair<int, int>> common;
  if (candidates.empty()) return common;
  // In the target: leaves each end into that corner's wedge, clear of the
  // corner's edges by kMinNewAngle in both polygons (a diagonal along a
  // nearly straight run of edges would cut off a triangle that is flat in
  // all but rounding) ...
  const CornerPolygon source = pair.source();
  auto clear_of_edges = [&](const CornerPolygon& polygon, int from, int to) {
    const Vec2& v = polygon.at(from);
    const Vec2& q = polygon.at(to);
    for (int neighbour : {(from + 1) % n, (from + n - 1) % n}) {
      const Vec2& e = polygon.at(neighbour);
      const double ux = e[0] - v[0], uy = e[1] - v[1], wx = q[0] - v[0], wy = q[1] - v[1];
      if (angle_between(ux, uy, wx, wy) < min_new_angle) return false;
    }
    return true;
  };
  auto enters = [&](int from, int to) {
    const int prev = pair.corners[(from + n - 1) % n], next = pair.corners[(from + 1) % n];
    return strictly_inside_corner(target.at(from), target.positions[next], target.positions[prev], prev == next,
                                  target.at(to)) &&
           clear_of_edges(target, from, to) && clear_of_edges(source, from, to);
  };
  std::vector<Segment> diagonals, edges;
  std::vector<int> diagonal_candidate;  // diagonals[k] is candidates[diagonal_candidate[k]]
  std::vector<char> ok(candidates.size(), 0);
  // Exact tests on every candidate and every overlapping pair: seconds on
  // a 10^5-vertex figure's exterior face, so cancellable (cancellation.h).
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    poll_cancellation();
    const auto [a, b] = candidates[i];
    ok[i] = target.corners[a] != target.corners[b] && enters(a, b) && enters(b, a);
    // Only those still in the running are boxed: the others cannot be saved.
    if (ok[i]) {
      diagonals.push_back({target.at(a), target.at(b)});
      diagonal_candidate.push_back(int(i));
    }
  }
  for (int k = 0; k < n; ++k) edges.push_back({target.at(k), target.at((k + 1) % n)});
  // ... and meets no edge of the target except at its own ends. The pairs
  // are visited, not collected (for_each_overlapping_box says why); one
  // blocking edge decides, so a diagonal already out skips its exact tests.
  // Order does not matter: a diagonal is out iff some edge blocks it.
  for_each_overlapping_box(diagonals, edges, [&](int k, int e) {
    const int i = diagonal_candidate[std::size_t(k)];
    if (!ok[i]) return;
    poll_cancellation();
    const auto [a, b] = candidates[i];
    const int va = pair.corners[a], vb = pair.corners[b];
    const int ea = pair.corners[e], eb = pair.corners[(e + 1) % n];
    const SegmentContact contact = segment_contact(diagonals[k][0], diagonals[k][1], edges[e][0], edges[e][1]);
    if (contact == SegmentContact::Disjoint) return;
    const bool shares_end = ea == va || ea == vb || eb == va || eb == vb;
    if (contact == SegmentContact::Touching && shares_end) return;
    ok[i] = 0;
  });
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (ok[i]) common.insert(candidates[i]);
  return common;
}

std::vector<std::vector<int>> pieces_of(const std::vector<std::array<int, 3>>& triangles,
                                        const std::set<std::pair<int, int>>& cuts) {
  int corners = 0;
  for (const auto& t : triangles) corners = std::max({corners, t[0] + 1, t[1] + 1, t[2] + 1});
  const TriangleAdjacency adjacency(corners, triangles);
  auto is_cut = [&](int a, int b) { return cuts.count({std::min(a, b), std::max(a, b)}) > 0; };
  // Components of triangles joined across uncut diagonals.
  std::vector<int> component(triangles.size(), -1);
  int count = 0;
  for (std::size_t start = 0; start < triangles.size(); ++start) {
    if (component[start] >= 0) continue;
    std::vector<int> stack{int(start)};
    component[start] = count;
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int j = 0; j < 3; ++j) {
        const int a = triangles[t][j], b = triangles[t][(j + 1) % 3];
        if (is_cut(a, b)) continue;
        const int across = adjacency.left_of(b, a);
        if (across >= 0 && component[across] < 0) {
          component[across] = count;
          stack.push_back(across);
        }
      }
    }
    ++count;
  }
  // Each component's boundary: sides without a twin in the same component.
  std::vector<std::map<int, int>> next(count);  // corner -> next corner along the boundary
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int j = 0; j < 3; ++j) {
      const int a = triangles[t][j], b = triangles[t][(j + 1) % 3];
      const int twin = adjacency.left_of(b, a);
      if (twin < 0 || component[twin] != component[t]) next[component[t]][a] = b;
    }
  std::vector<std::vector<int>> pieces;
  for (int c = 0; c < count; ++c) {
    std::vector<int> cycle;
    int corner = std::min_element(next[c].begin(), next[c].end())->first;
    do {
      cycle.push_back(corner);
      corner = next[c].at(corner);
    } while (corner != cycle.front() && cycle.size() <= next[c].size());
    if (cycle.size() != next[c].size())
      throw InternalError("compatible triangulation: a piece's boundary is not one cycle");
    pieces.push_back(std::move(cycle));
  }
  return pieces;
}

double cut_room(const PolygonPair& pair, const std::vector<std::array<int, 3>>& base,
                const std::set<std::pair<int, int>>& cuts) {
  double room = std::numeric_limits<double>::infinity();
  for (const auto& t : base) {
    bool next_to_cut = false;
    for (int j = 0; j < 3; ++j)
      next_to_cut = next_to_cut || cuts.count({std::min(t[j], t[(j + 1) % 3]), std::max(t[j], t[(j + 1) % 3])});
    if (!next_to_cut) continue;
    for (const CornerPolygon& polygon : {pair.source(), pair.target()}) {
      const Vec2 a = polygon.at(t[0]), b = polygon.at(t[1]), c = polygon.at(t[2]);
      const double cross = std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
      const double longest = std::max({std::hypot(b[0] - a[0], b[1] - a[1]), std::hypot(c[0] - b[0], c[1] - b[1]),
                                       std::hypot(a[0] - c[0], a[1] - c[1])});
      double magnitude = 0;
      for (const Vec2& p : {a, b, c}) magnitude = std::max({magnitude, std::abs(p[0]), std::abs(p[1])});
      const double spacing = std::max(magnitude, std::numeric_limits<double>::min()) * std::numeric_limits<double>::epsilon();
      room = std::min(room, cross / std::max(longest, std::numeric_limits<double>::min()) / spacing);
    }
  }
  return room;
}

}  // namespace stickmorph::internal
