// Removal of redundant Steiner vertices (paper, section 4.2); see
// steiner_reduction.h.
#include "stickmorph/internal/steiner_reduction.h"

#include <algorithm>

#include "stickmorph/cancellation.h"
#include "stickmorph/internal/geometry.h"

namespace stickmorph::internal {

// Section 4.2: a Steiner vertex is redundant in both polygons when its star
// can be re-triangulated without it, every new triangle positive in both.
// The best such re-triangulation (largest smallest angle over both) is found
// by dynamic programming over the link polygon; positivity of every
// triangle of a triangulated simple polygon without interior vertices makes
// it an embedding, so validity is kept exactly.
int remove_redundant_steiner(const PolygonPair& pair, CompatibleMesh& mesh, const std::vector<char>* candidates) {
  const int nodes = int(mesh.source.size());
  std::vector<char> removed(nodes, 0);
  int count = 0;
  // Triangles around each node (dead ones are skipped when read) and the
  // set of edges by vertex identity, both kept up to date as stars change.
  std::vector<std::vector<int>> around = triangles_around(mesh);
  EdgeKeySet edges;
  edges.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int j = 0; j < 3; ++j)
      edges.insert(edge_key(pair, mesh.corners, mesh.triangles[t][j], mesh.triangles[t][(j + 1) % 3]));
  // A vertex whose removal failed is tried again only after its star
  // changed: the outcome depends only on its link, the positions and the
  // edges between link vertices, and an edge between two of its link
  // vertices is erased only when one of them is removed, which changes its
  // star (added edges can only forbid more). Retrying every vertex on every
  // pass made large spiderwebs quadratic.
  //
  // The re-triangulation costs d^3 for a link of d vertices, and links grow
  // as neighbours go (the central vertex's reached 2000 in a 10^4-vertex
  // polygon): vertices with long links are tried only once no short-linked
  // vertex can go, so each is tried a few times rather than after every
  // neighbour's removal.
  constexpr int kShortLink = 32;
  // Links longer than this are not tried at all: the dynamic programme
  // takes d^3 time and d^2 memory, and on a 10^5-vertex wavy polyline (issue
  // 29's benchmark) removals merged the exterior's Steiner vertices into
  // links so long that one try had not ended after 11 minutes. Keeping such
  // a vertex is always valid (it only costs one Steiner vertex); a link of
  // 1024 costs about a second and 12 MB.
  constexpr int kLongestLink = 1024;
  std::vector<char> dirty(nodes, 1);
  if (candidates)
    for (int v = 0; v < nodes; ++v) dirty[v] = v < int(candidates->size()) && (*candidates)[v];
  for (bool changed = true, long_links = false; changed || !long_links;) {
    if (!changed) long_links = true;  // nothing short left: allow long links
    else if (long_links) long_links = false;  // a long one went: short ones again first
    changed = false;
    // Newest Steiner vertices first: redundant levels sit at path tops.
    for (int v = nodes - 1; v >= mesh.corners; --v) {
      if (removed[v] || !dirty[v]) continue;
      poll_cancellation();  // each try re-triangulates a link, up to O(d^3)
      std::vector<int> star;
      for (int t : around[v])
        if (mesh.alive[t]) star.push_back(t);
      around[v] = star;
      if (int(star.size()) > kLongestLink) {
        dirty[v] = 0;  // tried again only if its star changes (and shrinks)
        continue;
      }
      if (!long_links && int(star.size()) > kShortLink) continue;  // stays dirty
      dirty[v] = 0;
      const std::vector<int> link = link_of(mesh, star, v);
      const int d = int(link.size());
      if (d < 3) continue;
      // A new diagonal must not repeat an existing edge (a Steiner vertex's
      // edges are its own, so v's star never matches a diagonal's key).
      auto diagonal_ok = [&](int i, int j) {
        if (j - i == 1 || (i == 0 && j == d - 1)) return true;  // a side of the link
        const auto k = edge_key(pair, mesh.corners, link[i], link[j]);
        return k.first != k.second && !edges.count(k);
      };
      auto tri_quality = [&](int i, int k, int j) -> double {
        const Triangle t{link[i], link[k], link[j]};
        if (!positive(mesh.source, t) || !positive(mesh.target, t)) return -1;
        const double q = std::min(triangle_min_angle(mesh.source[t[0]], mesh.source[t[1]], mesh.source[t[2]]),
                                  triangle_min_angle(mesh.target[t[0]], mesh.target[t[1]], mesh.target[t[2]]));
        // Path vertices spread along one diagonal are collinear in truth; a
        // triangle of three of them can come out positive only through the
        // rounding of their positions. Keep the vertex rather than accept a
        // triangle that thin.
        return q > kMinNewAngle ? q : -1;
      };
      std::vector<std::vector<double>> best(d, std::vector<double>(d, -1));
      std::vector<std::vector<int>> split(d, std::vector<int>(d, -1));
      for (int i = 0; i + 1 < d; ++i) best[i][i + 1] = kPi;
      for (int len = 2; len < d; ++len)
        for (int i = 0; i + len < d; ++i) {
          const int j = i + len;
          if (!diagonal_ok(i, j)) continue;
          for (int k = i + 1; k < j; ++k) {
            if (best[i][k] < 0 || best[k][j] < 0) continue;
            // The split cannot beat the best so far whatever its triangle
            // (value <= min(best[i][k], best[k][j])): skip the triangle's
            // exact tests and angles, the bulk of the cost.
            if (std::min(best[i][k], best[k][j]) <= best[i][j]) continue;
            const double q = tri_quality(i, k, j);
            if (q < 0) continue;
            const double value = std::min({q, best[i][k], best[k][j]});
            if (value > best[i][j]) best[i][j] = value, split[i][j] = k;
          }
        }
      if (best[0][d - 1] < 0) continue;
      for (int t : star) mesh.alive[t] = 0;
      for (int u : link) edges.erase(edge_key(pair, mesh.corners, v, u));
      std::vector<std::pair<int, int>> stack{{0, d - 1}};
      while (!stack.empty()) {
        auto [i, j] = stack.back();
        stack.pop_back();
        if (j - i < 2) continue;
        const int k = split[i][j];
        const Triangle t{link[i], link[k], link[j]};
        const int id = int(mesh.triangles.size());
        mesh.triangles.push_back(t);
        mesh.alive.push_back(1);
        for (int u : t) around[u].push_back(id), dirty[u] = 1;
        for (int e = 0; e < 3; ++e) edges.insert(edge_key(pair, mesh.corners, t[e], t[(e + 1) % 3]));
        stack.push_back({i, k});
        stack.push_back({k, j});
      }
      removed[v] = 1;
      ++count;
      changed = true;
    }
  }
  // Renumber the surviving nodes.
  std::vector<int> renumber(nodes, -1);
  std::vector<Vec2> source, target;
  for (int v = 0; v < nodes; ++v)
    if (!removed[v]) {
      renumber[v] = int(source.size());
      source.push_back(mesh.source[v]);
      target.push_back(mesh.target[v]);
    }
  std::vector<Triangle> triangles;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (mesh.alive[t])
      triangles.push_back({renumber[mesh.triangles[t][0]], renumber[mesh.triangles[t][1]],
                           renumber[mesh.triangles[t][2]]});
  mesh.source = std::move(source);
  mesh.target = std::move(target);
  mesh.triangles = std::move(triangles);
  mesh.alive.assign(mesh.triangles.size(), 1);
  return count;
}

}  // namespace stickmorph::internal
