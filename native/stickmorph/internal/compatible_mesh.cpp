// The working form of a compatible triangulation; see compatible_mesh.h.
#include "stickmorph/internal/compatible_mesh.h"

#include <algorithm>
#include <map>

#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/geometry.h"
#include "stickmorph/internal/triangle_adjacency.h"

namespace stickmorph::internal {

bool positive(const std::vector<Vec2>& pos, const Triangle& t) {
  return orientation(pos[t[0]], pos[t[1]], pos[t[2]]) > 0;
}

std::vector<std::vector<int>> triangles_around(const CompatibleMesh& mesh) {
  return TriangleAdjacency::stars_of(int(mesh.source.size()), mesh.triangles, mesh.alive);
}

// Link of an interior node: its neighbours in counter-clockwise order.
std::vector<int> link_of(const CompatibleMesh& mesh, const std::vector<int>& star, int v) {
  std::map<int, int> next;
  for (int t : star) {
    const Triangle& tr = mesh.triangles[t];
    int j = 0;
    while (tr[j] != v) ++j;
    next[tr[(j + 1) % 3]] = tr[(j + 2) % 3];
  }
  std::vector<int> link;
  if (next.size() != star.size()) return link;
  int start = next.begin()->first, cur = start;
  do {
    link.push_back(cur);
    auto it = next.find(cur);
    if (it == next.end()) return {};
    cur = it->second;
  } while (cur != start && link.size() <= star.size());
  if (cur != start || link.size() != star.size()) return {};
  return link;
}

// Identity of a node once corners are merged with their vertex.
long node_key(const PolygonPair& pair, int corners, int node) {
  return node < corners ? pair.corners[node] : -1 - long(node);
}

std::pair<long, long> edge_key(const PolygonPair& pair, int corners, int a, int b) {
  const long ka = node_key(pair, corners, a), kb = node_key(pair, corners, b);
  return {std::min(ka, kb), std::max(ka, kb)};
}

double mesh_min_angle(const CompatibleMesh& mesh) {
  double m = kPi;
  for (const Triangle& t : mesh.triangles)
    m = std::min({m, triangle_min_angle(mesh.source[t[0]], mesh.source[t[1]], mesh.source[t[2]]),
                  triangle_min_angle(mesh.target[t[0]], mesh.target[t[1]], mesh.target[t[2]])});
  return m;
}

}  // namespace stickmorph::internal
