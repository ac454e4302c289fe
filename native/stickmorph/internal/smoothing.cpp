// Smoothing of Steiner vertices (paper, section 4.2); see smoothing.h.
#include "stickmorph/internal/smoothing.h"

#include <algorithm>
#include <set>

#include "stickmorph/cancellation.h"
#include "stickmorph/internal/geometry.h"

namespace stickmorph::internal {

void smooth(CompatibleMesh& mesh, bool target, int rounds) {
  std::vector<Vec2>& pos = target ? mesh.target : mesh.source;
  const std::vector<std::vector<int>> around = triangles_around(mesh);
  auto local_min_angle = [&](int v) {
    double m = kPi;
    for (int t : around[v]) {
      const Triangle& tr = mesh.triangles[t];
      m = std::min(m, triangle_min_angle(pos[tr[0]], pos[tr[1]], pos[tr[2]]));
    }
    return m;
  };
  for (int round = 0; round < rounds; ++round) {
    poll_cancellation();  // a round is O(Steiner vertices): cancellable between rounds
    for (int v = mesh.corners; v < int(pos.size()); ++v) {
      std::set<int> neighbours;
      for (int t : around[v])
        for (int u : mesh.triangles[t])
          if (u != v) neighbours.insert(u);
      if (neighbours.empty()) continue;
      Vec2 mean{0, 0};
      for (int u : neighbours) mean[0] += pos[u][0], mean[1] += pos[u][1];
      mean[0] /= double(neighbours.size());
      mean[1] /= double(neighbours.size());
      const Vec2 old = pos[v];
      const double before = local_min_angle(v);
      for (double step : {1.0, 0.5, 0.25}) {
        pos[v] = {old[0] + step * (mean[0] - old[0]), old[1] + step * (mean[1] - old[1])};
        bool ok = true;
        for (int t : around[v]) ok = ok && positive(pos, mesh.triangles[t]);
        if (ok && local_min_angle(v) >= before) break;
        pos[v] = old;
      }
    }
  }
}

}  // namespace stickmorph::internal
