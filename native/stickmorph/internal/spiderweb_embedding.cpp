// Embedding the spiderweb in both polygons (paper, section 4.1); see
// spiderweb_embedding.h.
#include "stickmorph/internal/spiderweb_embedding.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/compatible_mesh.h"
#include "stickmorph/internal/geometry.h"
#include "stickmorph/internal/rounding_repair.h"

namespace stickmorph::internal {
namespace {

// ---------------------------------------------------------------------------
// Embedding one polygon's copy of the spiderweb.

struct Embedding {
  std::vector<Vec2> position;  // #nodes
  std::vector<int> extra_of;   // #nodes: corner whose redundant level this is, or -1
};

class SpiderwebEmbedder {
 public:
  SpiderwebEmbedder(const CornerPolygon& polygon, const PolygonTriangulation& pt, const Spiderweb& web)
      : polygon_(polygon), pt_(pt), web_(web) {
    const int n = web.corners;
    base_.assign(web.node_count, {0, 0});
    placed_.assign(web.node_count, 0);
    extra_of_.assign(web.node_count, -1);
    for (int k = 0; k < n; ++k) {
      base_[k] = polygon.at(k);
      placed_[k] = 1;
    }
    // The central vertex at the centroid of the center face.
    const Triangle& c = pt.triangles[pt.center];
    base_[web.center] = {(polygon.at(c[0])[0] + polygon.at(c[1])[0] + polygon.at(c[2])[0]) / 3,
                         (polygon.at(c[0])[1] + polygon.at(c[1])[1] + polygon.at(c[2])[1]) / 3};
    placed_[web.center] = 1;
    for (int k = 0; k < n; ++k)
      for (int l = pt.milestone[k] + 1; l <= web.level[k]; ++l) extra_of_[web.path[k][l]] = k;
    place_crossings();
    cluster_radius_.assign(n, 0.0);
  }

  // Chooses the shape of each corner's cluster: the corner and its
  // redundant path vertices, joined by short segments. In the limit of a
  // small cluster, a triangle made of one cluster segment and a third node X
  // is positive iff X lies on the correct side of that segment's direction,
  // so each such triangle bounds the segment's direction to a half-turn.
  // Every segment gets its own direction, in the middle of the widest arc
  // inside the corner's wedge that satisfies its triangles: at a strongly
  // reflex corner no single straight ray separates the two strips' nodes,
  // but a path bending round the corner does.
  void choose_directions(const std::vector<Triangle>& triangles) {
    const int n = web_.corners;
    constraints_.assign(n, {});
    for (int k = 0; k < n; ++k) constraints_[k].resize(std::max(0, web_.level[k] - pt_.milestone[k]));
    for (const Triangle& t : triangles)
      for (int j = 0; j < 3; ++j) {
        const int u = t[j], v = t[(j + 1) % 3], x = t[(j + 2) % 3];
        const int ku = cluster(u), kv = cluster(v);
        if (ku < 0 || ku != kv || cluster(x) == ku) continue;
        const int ou = order(u), ov = order(v);
        if (std::abs(ou - ov) != 1) continue;
        // orient(u, v, x) ~ (o_v - o_u) * cross(direction, x - c) must be > 0.
        constraints_[ku][std::min(ou, ov)].push_back({x, ov > ou ? 1.0 : -1.0});
      }
    segment_direction_.assign(n, {});
    segment_feasible_.assign(n, {});
    for (int k = 0; k < n; ++k) {
      const int segments = web_.level[k] - pt_.milestone[k];
      if (segments <= 0) continue;
      cluster_radius_[k] = 0.45 * clearance(k);
      for (int j = 0; j < segments; ++j) {
        std::vector<std::pair<Vec2, double>> limit;
        for (const auto& [x, sign] : constraints_[k][j]) {
          const Vec2 xp = proxy(x);
          limit.push_back({{xp[0] - base_[k][0], xp[1] - base_[k][1]}, sign});
        }
        const Vec2* fallback = j > 0 ? &segment_direction_[k][j - 1] : nullptr;
        bool feasible = false;
        segment_direction_[k].push_back(best_direction(k, limit, fallback, &feasible));
        segment_feasible_[k].push_back(feasible);
      }
    }
  }

  // The corner whose cluster holds `node`, or -1 (see cluster()).
  int cluster_of(int node) const { return cluster(node); }

  // Positions with the cluster of corner k at scale[k] times its full size.
  //
  // Where the small-cluster limit leaves a segment no direction (at the tip
  // of a dangling edge both neighbouring corners are the same vertex, so
  // their clusters have the same limit but sit on opposite sides of the
  // tip's path), the segment is aimed using the other clusters' actual
  // positions at this scale. For a straight segment from p along d,
  // cross(d, x - p - s d) = cross(d, x - p), so its sign does not depend on
  // how far along the segment the vertices are.
  Embedding place(const std::vector<double>& scale) const {
    Embedding e;
    e.position = base_;
    e.extra_of = extra_of_;
    for (int pass = 0; pass < 2; ++pass)
      for (int k = 0; k < web_.corners; ++k) {
        const int m = pt_.milestone[k], top = web_.level[k];
        if (top <= m) continue;
        bool refine = false;
        for (char f : segment_feasible_[k]) refine = refine || !f;
        if (pass == 1 && !refine) continue;
        const double step = cluster_radius_[k] * scale[k] / double(top - m + 1);
        Vec2 p = base_[k];
        Vec2 previous{0, 0};
        for (int l = top; l > m; --l) {
          const int j = top - l;
          Vec2 d = segment_direction_[k][j];
          if (pass == 1 && !segment_feasible_[k][j]) {
            std::vector<std::pair<Vec2, double>> actual;
            for (const auto& [x, sign] : constraints_[k][j])
              actual.push_back({{e.position[x][0] - p[0], e.position[x][1] - p[1]}, sign});
            d = best_direction(k, actual, j > 0 ? &previous : &d, nullptr);
          }
          previous = d;
          p = {p[0] + step * d[0], p[1] + step * d[1]};
          e.position[web_.path[k][l]] = p;
        }
      }
    return e;
  }

 private:
  // Each non-root face's parent side is crossed by the paths of the corners
  // strictly between its two ends on the face's side, in polygon order; the
  // crossings are spread evenly so that paths never cross (section 4.1's
  // shrinking, done along the dual tree).
  void place_crossings() {
    const int n = web_.corners;
    for (std::size_t g = 0; g < pt_.triangles.size(); ++g) {
      if (int(g) == pt_.center) continue;
      int j = 0;
      while (pt_.neighbour[g][j] != pt_.parent[g]) ++j;
      // Side opposite slot j runs a -> b with g on its left; the sub-polygon
      // on g's side continues along the boundary from b round to a.
      const int a = pt_.triangles[g][(j + 1) % 3];
      const int b = pt_.triangles[g][(j + 2) % 3];
      const int between = ((a - b - 1) % n + n) % n;
      const int l = pt_.depth[g];
      for (int t = 1; t <= between; ++t) {
        const int k = (b + t) % n;
        const double s = double(t) / double(between + 1);
        const Vec2 pa = polygon_.at(a), pb = polygon_.at(b);
        const int node = web_.path[k][l];
        base_[node] = {pb[0] + s * (pa[0] - pb[0]), pb[1] + s * (pa[1] - pb[1])};
        placed_[node] = 1;
      }
    }
    for (int node = 0; node < web_.node_count; ++node)
      if (!placed_[node] && extra_of_[node] < 0)
        throw InternalError("spiderweb node " + std::to_string(node) + " was not placed");
  }

  // The corner whose cluster (the corner and its redundant levels) holds
  // `node`, or -1.
  int cluster(int node) const {
    if (node < web_.corners) return web_.level[node] > pt_.milestone[node] ? node : -1;
    return extra_of_[node];
  }

  // Where a node sits in the small-cluster limit.
  Vec2 proxy(int node) const {
    const int k = node < web_.corners ? -1 : extra_of_[node];
    return k >= 0 ? base_[k] : base_[node];
  }

  // Position of a node along its cluster's path: the corner is 0, its
  // outermost redundant vertex 1, deeper levels further.
  int order(int node) const {
    if (node < web_.corners) return 0;
    const int k = extra_of_[node];
    int l = 0;
    while (web_.path[k][l] != node) ++l;
    return web_.level[k] - l + 1;
  }

  // Distance from corner k to the nearest placed node that is not at the
  // same vertex and not in its cluster. The candidates are swept in order of
  // x outwards from the corner, stopping once the x gap alone exceeds the
  // best distance: a scan of every node for every corner is quadratic and
  // dominated large spiderwebs (10^5 nodes times 10^3 corners).
  double clearance(int k) {
    if (clearance_order_.empty()) {
      for (int node = 0; node < web_.node_count; ++node)
        if (node < web_.corners || extra_of_[node] < 0) clearance_order_.push_back(node);
      std::sort(clearance_order_.begin(), clearance_order_.end(),
                [&](int a, int b) { return base_[a][0] < base_[b][0]; });
    }
    double best = std::numeric_limits<double>::infinity();
    const Vec2 c = base_[k];
    auto consider = [&](int node) {
      if (node < web_.corners && polygon_.corners[node] == polygon_.corners[k]) return;
      best = std::min(best, std::hypot(base_[node][0] - c[0], base_[node][1] - c[1]));
    };
    const auto start = std::lower_bound(clearance_order_.begin(), clearance_order_.end(), c[0],
                                        [&](int node, double x) { return base_[node][0] < x; });
    for (auto it = start; it != clearance_order_.end() && base_[*it][0] - c[0] < best; ++it) consider(*it);
    for (auto it = start; it != clearance_order_.begin() && c[0] - base_[*(it - 1)][0] < best; --it) consider(*(it - 1));
    return std::isfinite(best) ? best : 1.0;
  }

  Vec2 best_direction(int k, const std::vector<std::pair<Vec2, double>>& constraints, const Vec2* fallback,
                      bool* feasible) const {
    const int n = web_.corners;
    const Vec2 c = base_[k];
    const Vec2 next = polygon_.at((k + 1) % n), prev = polygon_.at((k + n - 1) % n);
    const double start = std::atan2(next[1] - c[1], next[0] - c[0]);
    double wedge = std::atan2(prev[1] - c[1], prev[0] - c[0]) - start;
    if (polygon_.corners[(k + 1) % n] == polygon_.corners[(k + n - 1) % n]) wedge = 2 * kPi;
    while (wedge <= 0) wedge += 2 * kPi;
    while (wedge > 2 * kPi) wedge -= 2 * kPi;
    // Work with angles phi measured counter-clockwise from the outgoing
    // edge, so the wedge is (0, wedge). Each constraint keeps an open
    // half-turn of directions; intersect them as interval lists.
    using Interval = std::pair<double, double>;
    std::vector<Interval> arcs{{0.0, wedge}};
    auto normalise = [](double a) {
      a = std::fmod(a, 2 * kPi);
      return a < 0 ? a + 2 * kPi : a;
    };
    for (const auto& [x, sign] : constraints) {
      // sign * cross(d, x) > 0  <=>  sign * sin(alpha - phi) > 0.
      const double alpha = normalise(std::atan2(x[1], x[0]) - start);
      const double lo = sign > 0 ? normalise(alpha - kPi) : alpha;
      std::vector<Interval> arc;  // (lo, lo + pi) cut at 2*pi
      if (lo + kPi <= 2 * kPi) {
        arc.push_back({lo, lo + kPi});
      } else {
        arc.push_back({lo, 2 * kPi});
        arc.push_back({0.0, lo + kPi - 2 * kPi});
      }
      std::vector<Interval> next;
      for (const Interval& f : arcs)
        for (const Interval& a : arc) {
          const double l = std::max(f.first, a.first), h = std::min(f.second, a.second);
          if (l < h) next.push_back({l, h});
        }
      arcs = std::move(next);
    }
    double best_lo = 0, best_hi = -1;
    for (const Interval& f : arcs)
      if (f.second - f.first > best_hi - best_lo) best_lo = f.first, best_hi = f.second;
    const int best_length = best_hi > best_lo ? 1 : 0;
    if (feasible) *feasible = best_length > 0;
    double phi;
    if (best_length > 0) {
      phi = start + 0.5 * (best_lo + best_hi);
    } else if (fallback) {
      // No direction satisfies all: keep the previous segment's direction;
      // verification reports the failure if it persists.
      return *fallback;
    } else {
      const Vec2 target = base_[web_.path[k][pt_.milestone[k]]];
      phi = std::atan2(target[1] - c[1], target[0] - c[0]);
    }
    return {std::cos(phi), std::sin(phi)};
  }

  const CornerPolygon& polygon_;
  const PolygonTriangulation& pt_;
  const Spiderweb& web_;
  std::vector<Vec2> base_;
  std::vector<int> placed_;
  std::vector<int> extra_of_;
  std::vector<double> cluster_radius_;
  std::vector<int> clearance_order_;  // corners and placed Steiner nodes, by x (see clearance)
  std::vector<std::vector<Vec2>> segment_direction_;  // per corner, outermost segment first
  std::vector<std::vector<char>> segment_feasible_;   // false: aimed at actual positions
  // constraints_[k][j]: (third node, required sign) for segment j of corner k.
  std::vector<std::vector<std::vector<std::pair<int, double>>>> constraints_;
};

double option_quality(const std::vector<Vec2>& ps, const std::vector<Vec2>& pt, const std::array<Triangle, 2>& option) {
  double q = kPi;
  for (const Triangle& t : option)
    q = std::min({q, triangle_min_angle(ps[t[0]], ps[t[1]], ps[t[2]]),
                  triangle_min_angle(pt[t[0]], pt[t[1]], pt[t[2]])});
  return q;
}

}  // namespace

Placement embed_in_both(const PolygonPair& pair, const std::array<PolygonTriangulation, 2>& pts,
                        const Spiderweb& web) {
  const CornerPolygon polygons[2] = {pair.source(), pair.target()};
  std::vector<Triangle> all = web.fixed;
  for (const auto& q : web.quads)
    for (const auto& opt : q.option)
      for (const Triangle& t : opt) all.push_back(t);
  SpiderwebEmbedder embedder[2] = {{polygons[0], pts[0], web}, {polygons[1], pts[1], web}};
  for (auto& e : embedder) e.choose_directions(all);

  // Edges fixed by the triangles without choice, by vertex identity: a split
  // must not double one of them (repeated corners).
  EdgeKeySet fixed_edges;
  for (const Triangle& t : web.fixed)
    for (int j = 0; j < 3; ++j) fixed_edges.insert(edge_key(pair, web.corners, t[j], t[(j + 1) % 3]));

  // Each cluster shrinks only while a triangle or cell it belongs to is
  // inverted, so clusters that are fine keep their size (and their
  // triangles their shape).
  std::vector<double> scale[2] = {std::vector<double>(web.corners, 1.0), std::vector<double>(web.corners, 1.0)};
  Placement best;
  for (int attempt = 0; attempt < 80; ++attempt) {
    const Embedding e[2] = {embedder[0].place(scale[0]), embedder[1].place(scale[1])};
    auto node_text = [&](int v) {
      if (v < web.corners) return "corner " + std::to_string(v);
      if (v == web.center) return std::string("the central vertex");
      for (int k = 0; k < web.corners; ++k)
        for (int l = 1; l <= web.level[k]; ++l)
          if (web.path[k][l] == v) return "level " + std::to_string(l) + " of corner " + std::to_string(k) + "'s path";
      return std::to_string(v);
    };
    // Each cell takes the split that is positive in both polygons with the
    // larger smallest angle, never doubling an edge; a cell with neither is
    // split by its first diagonal and left to the repair below.
    std::vector<Triangle> triangles = web.fixed;
    EdgeKeySet used = fixed_edges;
    for (const auto& q : web.quads) {
      int chosen = -1;
      double quality = -1;
      for (int o = 0; o < 2; ++o) {
        const auto& opt = q.option[o];
        if (used.count(edge_key(pair, web.corners, q.diagonal[o][0], q.diagonal[o][1]))) continue;
        bool valid = true;
        for (const Triangle& t : opt) valid = valid && positive(e[0].position, t) && positive(e[1].position, t);
        if (!valid) continue;
        const double qv = option_quality(e[0].position, e[1].position, opt);
        if (qv > quality) quality = qv, chosen = o;
      }
      if (chosen < 0) chosen = used.count(edge_key(pair, web.corners, q.diagonal[0][0], q.diagonal[0][1])) ? 1 : 0;
      for (const Triangle& t : q.option[chosen]) {
        triangles.push_back(t);
        for (int j = 0; j < 3; ++j) used.insert(edge_key(pair, web.corners, t[j], t[(j + 1) % 3]));
      }
    }
    // Rounding first (see untangle), then what is left is blamed on the
    // clusters involved, which shrink for the next attempt.
    std::vector<Vec2> repaired[2] = {e[0].position, e[1].position};
    std::vector<char> shrink[2] = {std::vector<char>(web.corners, 0), std::vector<char>(web.corners, 0)};
    std::string failure;
    bool any_bad = false;
    for (int s = 0; s < 2; ++s) {
      if (untangle(repaired[s], triangles, web.corners)) continue;
      for (const Triangle& t : triangles) {
        if (positive(repaired[s], t)) continue;
        any_bad = true;
        if (failure.empty())
          failure = "triangle (" + node_text(t[0]) + ", " + node_text(t[1]) + ", " + node_text(t[2]) +
                    ") is inverted in the " + (s ? "target" : "source");
        for (int v : t) {
          const int k = embedder[s].cluster_of(v);
          if (k >= 0) shrink[s][k] = 1;
        }
      }
    }
    if (!any_bad) {
      best.source = std::move(repaired[0]);
      best.target = std::move(repaired[1]);
      best.triangles = std::move(triangles);
      best.ok = true;
      return best;
    }
    best.failure = failure;
    bool shrunk = false;
    for (int s = 0; s < 2; ++s)
      for (int k = 0; k < web.corners; ++k)
        if (shrink[s][k]) scale[s][k] *= 0.5, shrunk = true;
    if (!shrunk) break;  // only fixed vertices are involved: shrinking cannot help
  }
  return best;
}

}  // namespace stickmorph::internal
