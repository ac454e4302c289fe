// Spiderweb connectivity (paper, section 4.1); see spiderweb.h.
#include "stickmorph/internal/spiderweb.h"

#include <algorithm>

namespace stickmorph::internal {

Spiderweb build_spiderweb(const std::vector<int>& level, const std::vector<int>& vertex) {
  Spiderweb web;
  const int n = int(level.size());
  web.corners = n;
  web.level = level;
  web.center = n;
  web.node_count = n + 1;
  web.path.resize(n);
  for (int k = 0; k < n; ++k) {
    web.path[k].push_back(web.center);
    for (int l = 1; l <= level[k]; ++l) web.path[k].push_back(web.node_count++);
  }
  // The strip between the paths of corners k and k+1 is bounded by
  // c_k -> c_k+1 -> path k+1 inwards -> center -> path k outwards.
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    const int a = level[k], b = level[k1];
    const int r = std::min(a, b);
    if (r >= 1) web.fixed.push_back({web.at(k1, 1), web.center, web.at(k, 1)});
    for (int l = 1; l < r; ++l) {
      const int p1 = web.at(k1, l + 1), p0 = web.at(k1, l), q0 = web.at(k, l), q1 = web.at(k, l + 1);
      web.add_quad(p1, p0, q0, q1);
    }
    const int ck = k, ck1 = k1;
    if (a == b) {
      if (r == 0) {
        web.fixed.push_back({ck, ck1, web.center});
      } else {
        const int p = web.at(k1, r), q = web.at(k, r);
        const bool k_is_tip = vertex[(k + n - 1) % n] == vertex[k1];
        const bool k1_is_tip = vertex[k] == vertex[(k1 + 1) % n];
        if (k_is_tip) {
          web.fixed.push_back({ck, ck1, p});
          web.fixed.push_back({ck, p, q});
        } else if (k1_is_tip) {
          web.fixed.push_back({ck, ck1, q});
          web.fixed.push_back({ck1, p, q});
        } else {
          web.add_quad(ck, ck1, p, q);
        }
      }
    } else if (a < b) {
      // Corner k is the end of the shorter path: it fans over path k+1.
      web.fixed.push_back({ck, ck1, web.at(k1, b)});
      for (int l = b; l > r; --l) web.fixed.push_back({ck, web.at(k1, l), web.at(k1, l - 1)});
      if (r >= 1) web.fixed.push_back({ck, web.at(k1, r), web.at(k, r)});
    } else {
      if (r >= 1) web.fixed.push_back({ck1, web.at(k1, r), web.at(k, r)});
      for (int l = r; l < a; ++l) web.fixed.push_back({ck1, web.at(k, l), web.at(k, l + 1)});
      web.fixed.push_back({ck1, web.at(k, a), ck});
    }
  }
  return web;
}

void enforce_tip_levels(const PolygonPair& pair, std::vector<int>& level) {
  const int n = int(level.size());
  for (bool changed = true; changed;) {
    changed = false;
    for (int k = 0; k < n; ++k) {
      const int prev = (k + n - 1) % n, next = (k + 1) % n;
      if (pair.corners[prev] != pair.corners[next]) continue;
      if (level[k] > level[prev] && level[k] > level[next]) {
        level[next] = level[k];
        changed = true;
      }
    }
  }
}

}  // namespace stickmorph::internal
