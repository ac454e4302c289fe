// Adjacency of a list of triangles; see triangle_adjacency.h.
#include "stickmorph/internal/triangle_adjacency.h"

namespace stickmorph::internal {

std::vector<std::vector<int>> TriangleAdjacency::stars_of(int nodes, const std::vector<Triangle>& triangles,
                                                          const std::vector<char>& alive) {
  std::vector<std::vector<int>> around(nodes);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (alive.empty() || alive[t])
      for (int v : triangles[t]) around[v].push_back(int(t));
  return around;
}

TriangleAdjacency::TriangleAdjacency(int nodes, const std::vector<Triangle>& triangles, const std::vector<char>& alive)
    : around_(stars_of(nodes, triangles, alive)) {
  side_.reserve(triangles.size() * 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!alive.empty() && !alive[t]) continue;
    const Triangle& tr = triangles[t];
    for (int j = 0; j < 3; ++j) {
      const auto [it, fresh] = side_.emplace(key(tr[j], tr[(j + 1) % 3]), int(3 * t) + j);
      if (!fresh && repeated_.first < 0) repeated_ = {tr[j], tr[(j + 1) % 3], it->second / 3, int(t)};
    }
  }
}

}  // namespace stickmorph::internal
