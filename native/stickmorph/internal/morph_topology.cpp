// The morph's view of a triangulation's combinatorics; see morph_topology.h.
#include "stickmorph/internal/morph_topology.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"

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
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || std::abs(p[0]) > kMaxCoordinateMagnitude ||
          std::abs(p[1]) > kMaxCoordinateMagnitude)
        malformed(node_text(tri, v) + " has a non-finite or too large position in the " +
                  (side ? "target" : "source"));
    }

  // Every directed side of a triangle once: two triangles on the same side
  // of an edge would overlap.
  std::unordered_map<std::int64_t, int> side_of;
  side_of.reserve(tri.triangles.size() * 3);
  auto key = [N](int a, int b) { return std::int64_t(a) * N + b; };
  for (int t = 0; t < int(tri.triangles.size()); ++t) {
    const auto& tr = tri.triangles[t];
    for (int c = 0; c < 3; ++c)
      if (tr[c] < 0 || tr[c] >= N) malformed(triangle_text(tri, t) + " refers to a node out of range");
    if (tr[0] == tr[1] || tr[1] == tr[2] || tr[2] == tr[0]) malformed(triangle_text(tri, t) + " repeats a node");
    for (int c = 0; c < 3; ++c) {
      const auto [it, fresh] = side_of.emplace(key(tr[c], tr[(c + 1) % 3]), t);
      if (!fresh)
        malformed("the side " + std::to_string(tr[c]) + "->" + std::to_string(tr[(c + 1) % 3]) + " belongs to " +
                  triangle_text(tri, it->second) + " and " + triangle_text(tri, t) + " (they overlap)");
    }
  }
  // The boundary is the enclosure, counter-clockwise: each enclosure side
  // has a triangle on its left and none on its right; every other side has
  // triangles on both.
  for (int i = 0; i < k; ++i) {
    const int a = n + i, b = n + (i + 1) % k;
    if (!side_of.count(key(a, b)))
      malformed("the enclosure side " + std::to_string(a) + "->" + std::to_string(b) +
                " is not a side of any triangle");
    if (side_of.count(key(b, a)))
      malformed("a triangle lies outside the enclosure side " + std::to_string(a) + "-" + std::to_string(b));
  }
  for (const auto& [edge_key, t] : side_of) {
    const int a = int(edge_key / N), b = int(edge_key % N);
    const bool enclosure_side = is_enclosure(tri, a) && is_enclosure(tri, b) && (b - n) == (a - n + 1) % k;
    if (!enclosure_side && !side_of.count(key(b, a)))
      malformed("the edge " + std::to_string(a) + "-" + std::to_string(b) + " borders only " +
                triangle_text(tri, t) + " but is not an enclosure side (a hole or a second boundary)");
  }

  // Fans: at node v, triangle (v, b, c) leads from neighbour b to c
  // counter-clockwise.
  std::vector<std::vector<std::pair<int, int>>> turns(N);
  for (const auto& tr : tri.triangles)
    for (int c = 0; c < 3; ++c) turns[tr[c]].emplace_back(tr[(c + 1) % 3], tr[(c + 2) % 3]);

  Topology topo;
  topo.nodes = N;
  topo.ring.assign(N, {});
  topo.unknown.assign(N, -1);
  for (int v = 0; v < N; ++v) {
    if (turns[v].empty()) malformed(node_text(tri, v) + " is in no triangle");
    std::unordered_map<int, int> next;
    for (const auto& [b, c] : turns[v]) next.emplace(b, c);
    if (is_enclosure(tri, v)) {
      // An open fan from the next enclosure vertex to the previous one.
      const int i = v - n;
      int at = n + (i + 1) % k;
      const int last = n + (i + k - 1) % k;
      std::size_t steps = 0;
      while (at != last && steps <= turns[v].size()) {
        auto it = next.find(at);
        if (it == next.end()) break;
        at = it->second;
        ++steps;
      }
      if (at != last || steps != turns[v].size())
        malformed("the triangles around " + node_text(tri, v) + " do not form one fan (the disk is pinched there)");
      continue;
    }
    std::vector<int> ring{turns[v].front().first};
    for (std::size_t step = 0; step < turns[v].size(); ++step) {
      auto it = next.find(ring.back());
      if (it == next.end()) malformed("the triangles around " + node_text(tri, v) + " leave a gap");
      ring.push_back(it->second);
    }
    // turns[v].size() steps must close the cycle exactly then, not before.
    ring.pop_back();
    const bool closed = next.at(ring.back()) == ring.front();
    std::vector<int> sorted = ring;
    std::sort(sorted.begin(), sorted.end());
    if (!closed || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      malformed("the triangles around " + node_text(tri, v) + " do not close into one fan");
    topo.unknown[v] = int(topo.interior_nodes.size());
    topo.interior_nodes.push_back(v);
    topo.ring[v] = std::move(ring);
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
