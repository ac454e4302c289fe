// Rounding repair of an embedding; see rounding_repair.h.
#include "stickmorph/internal/rounding_repair.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/triangle_adjacency.h"

namespace stickmorph::internal {

std::optional<Vec2> star_kernel_middle(const std::vector<Vec2>& pos, const std::vector<Triangle>& star, int v,
                                       const Vec2& origin) {
  auto local = [&](int node) { return Vec2{pos[node][0] - origin[0], pos[node][1] - origin[1]}; };
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const Triangle& t : star)
    for (int node : t)
      if (node != v)
        for (int c = 0; c < 2; ++c) lo[c] = std::min(lo[c], local(node)[c]), hi[c] = std::max(hi[c], local(node)[c]);
  std::vector<Vec2> kernel = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
  for (const Triangle& t : star) {
    int j = 0;
    while (t[j] != v) ++j;
    const Vec2 a = local(t[(j + 1) % 3]), b = local(t[(j + 2) % 3]);
    auto side = [&](const Vec2& p) { return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]); };
    std::vector<Vec2> clipped;
    for (std::size_t i = 0; i < kernel.size(); ++i) {
      const Vec2 p = kernel[i], q = kernel[(i + 1) % kernel.size()];
      const double sp = side(p), sq = side(q);
      if (sp > 0) clipped.push_back(p);
      if ((sp > 0) != (sq > 0) && sp != sq) {
        const double u = sp / (sp - sq);
        clipped.push_back({p[0] + u * (q[0] - p[0]), p[1] + u * (q[1] - p[1])});
      }
    }
    kernel = std::move(clipped);
    if (kernel.size() < 3) return std::nullopt;
  }
  Vec2 middle{0, 0};
  for (const Vec2& p : kernel) middle = {middle[0] + p[0], middle[1] + p[1]};
  return Vec2{middle[0] / double(kernel.size()), middle[1] / double(kernel.size())};
}

bool untangle(std::vector<Vec2>& pos, const std::vector<Triangle>& triangles, int corners) {
  auto is_positive = [&](const Triangle& t) { return orientation(pos[t[0]], pos[t[1]], pos[t[2]]) > 0; };
  // The usual case, every attempt of every spiderweb: nothing to repair, so
  // no stars to build (10^5 nodes in large exterior faces).
  if (std::all_of(triangles.begin(), triangles.end(), is_positive)) return true;
  const std::vector<std::vector<int>> star_of = TriangleAdjacency::stars_of(int(pos.size()), triangles);
  auto step = [](double x, int ulps) {
    for (; ulps > 0; --ulps) x = std::nextafter(x, std::numeric_limits<double>::infinity());
    for (; ulps < 0; ++ulps) x = std::nextafter(x, -std::numeric_limits<double>::infinity());
    return x;
  };
  auto try_move = [&](int v) {
    std::vector<Triangle> star;
    for (int i : star_of[v]) star.push_back(triangles[i]);
    const Vec2 origin = pos[v];
    const std::optional<Vec2> middle = star_kernel_middle(pos, star, v, origin);
    if (!middle) return false;
    const Vec2 centre{origin[0] + (*middle)[0], origin[1] + (*middle)[1]};
    for (int radius = 0; radius <= 3; ++radius)
      for (int dx = -radius; dx <= radius; ++dx)
        for (int dy = -radius; dy <= radius; ++dy) {
          if (std::max(std::abs(dx), std::abs(dy)) != radius) continue;
          pos[v] = {step(centre[0], dx), step(centre[1], dy)};
          bool ok = true;
          for (const Triangle& t : star) ok = ok && is_positive(t);
          if (ok) return true;
        }
    pos[v] = origin;
    return false;
  };
  for (int pass = 0; pass < 8; ++pass) {
    bool moved = false, all_positive = true;
    for (const Triangle& bad : triangles) {
      if (is_positive(bad)) continue;
      all_positive = false;
      for (int v : bad)
        if (v >= corners && try_move(v)) {  // polygon corners are fixed
          moved = true;
          break;
        }
    }
    if (all_positive) return true;
    if (!moved) return false;
  }
  for (const Triangle& t : triangles)
    if (!is_positive(t)) return false;
  return true;
}

}  // namespace stickmorph::internal
