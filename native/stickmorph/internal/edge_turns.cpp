// Consistent edge turns between two drawings; see edge_turns.h.
#include "stickmorph/internal/edge_turns.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "stickmorph/internal/geometry.h"

namespace stickmorph {
namespace internal {

namespace {

// The counter-clockwise angle from direction a to direction b, in [0, 2 pi).
double ccw_angle(const Vec2& a, const Vec2& b) {
  double angle = std::atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]);
  if (angle < 0) angle += 2 * kPi;
  return angle;
}

// Every edge's turn from source to target, made consistent between
// neighbours (Baxter, Barla & Anjyo 2008, "Rigid shape interpolation using
// normal equations", for rotations of adjacent elements): at every joint,
// two edges consecutive round a vertex (the same order in both figures,
// which are compatible) keep their counter-clockwise angle in (0, 360°)
// and interpolate it linearly, so turn_f - turn_e = angle1 - angle0 with
// no multiple of a full turn left to choose. That never folds two edges of
// a joint onto each other (the joint-angle metric of docs/MOTION.md is 0
// on a tree). The constraints determine the turns of a connected figure up
// to one whole number of full turns (around every face they add up to the
// same total in both figures); that number is chosen so that the mean turn
// is nearest the whole figure's rotation `whole` (with its extra turns).
std::vector<double> consistent_turns(const std::vector<Vec2>& source, const std::vector<Vec2>& target,
                                     const std::vector<Edge>& edges, const std::vector<double>& change,
                                     double whole) {
  const int n = int(source.size()), m = int(edges.size());
  // Incident edges per vertex, counter-clockwise in the source.
  std::vector<std::vector<int>> incident(n);
  for (int e = 0; e < m; ++e) {
    incident[edges[e][0]].push_back(e);
    incident[edges[e][1]].push_back(e);
  }
  auto away = [&](const std::vector<Vec2>& p, int v, int e) {
    const int u = edges[e][0] == v ? edges[e][1] : edges[e][0];
    return Vec2{p[u][0] - p[v][0], p[u][1] - p[v][1]};
  };
  // Constraint graph: (neighbour edge, offset) with turn[f] = turn[e] + offset.
  std::vector<std::vector<std::pair<int, double>>> links(m);
  for (int v = 0; v < n; ++v) {
    std::vector<int>& around = incident[v];
    if (around.size() < 2) continue;
    std::sort(around.begin(), around.end(), [&](int a, int b) {
      const Vec2 da = away(source, v, a), db = away(source, v, b);
      return std::atan2(da[1], da[0]) < std::atan2(db[1], db[0]);
    });
    for (std::size_t k = 0; k < around.size(); ++k) {
      const int e = around[k], f = around[(k + 1) % around.size()];
      const double offset = ccw_angle(away(target, v, e), away(target, v, f)) -
                            ccw_angle(away(source, v, e), away(source, v, f));
      links[e].push_back({f, offset});
      links[f].push_back({e, -offset});
    }
  }
  std::vector<double> turn(m, 0.0);
  std::vector<char> seen(m, 0);
  for (int root = 0; root < m; ++root) {
    if (seen[root]) continue;
    // One connected part: propagate from its first edge, then shift by the
    // whole number of turns that brings its mean nearest `whole`.
    std::vector<int> part{root};
    seen[root] = 1;
    turn[root] = change[root];
    for (std::size_t i = 0; i < part.size(); ++i)
      for (const auto& [f, offset] : links[part[i]])
        if (!seen[f]) {
          seen[f] = 1;
          turn[f] = turn[part[i]] + offset;
          part.push_back(f);
        }
    double mean = 0;
    for (int e : part) mean += turn[e];
    mean /= double(part.size());
    const double shift = 2 * kPi * std::round((whole - mean) / (2 * kPi));
    for (int e : part) turn[e] += shift;
  }
  return turn;
}

}  // namespace

double wrap_angle(double a) {
  a = std::fmod(a + kPi, 2 * kPi);
  if (a <= 0) a += 2 * kPi;
  return a - kPi;
}

std::vector<double> edge_turns(const std::vector<Vec2>& source, const std::vector<Vec2>& target,
                               const std::vector<Edge>& edges, double whole) {
  const std::size_t m = edges.size();
  std::vector<double> change(m);  // each edge's own change of direction, in (-pi, pi]
  for (std::size_t e = 0; e < m; ++e) {
    const Edge& edge = edges[e];
    const Vec2 d0{source[edge[1]][0] - source[edge[0]][0], source[edge[1]][1] - source[edge[0]][1]};
    const Vec2 d1{target[edge[1]][0] - target[edge[0]][0], target[edge[1]][1] - target[edge[0]][1]};
    change[e] = wrap_angle(std::atan2(d1[1], d1[0]) - std::atan2(d0[1], d0[0]));
  }
  return consistent_turns(source, target, edges, change, whole);
}

}  // namespace internal
}  // namespace stickmorph
