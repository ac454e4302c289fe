#include "stickmorph/compatible_triangulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "stickmorph/exact_predicates.h"
#include "stickmorph/verification.h"

namespace stickmorph {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Smallest angle (radians) of a triangle that the construction creates from
// existing vertices (redundancy removal, shared diagonals). Exact arithmetic
// would accept thinner ones whose positivity is only rounding; the morph's
// convex weights need tan of half-angles that stay finite.
constexpr double kMinNewAngle = 1e-6;

double angle_at(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double ux = b[0] - a[0], uy = b[1] - a[1];
  const double vx = c[0] - a[0], vy = c[1] - a[1];
  return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
}

double triangle_min_angle(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
}

using Triangle = std::array<int, 3>;

// ---------------------------------------------------------------------------
// Spiderweb connectivity (section 4.1): given the common depth of every
// corner, the radial paths and the ladders between neighbouring paths.

struct Spiderweb {
  int corners = 0;
  int center = -1;                        // node of the central vertex
  std::vector<int> level;                 // #C: common depth of each corner
  std::vector<std::vector<int>> path;     // path[k][l]: node at level l (0 = center)
  int node_count = 0;
  std::vector<Triangle> fixed;            // triangles with no choice
  // A ladder cell or top cell: two ways to split it, each two triangles.
  struct Quad {
    std::array<std::array<Triangle, 2>, 2> option;
    std::array<std::array<int, 2>, 2> diagonal;  // the edge each option adds
  };
  void add_quad(int a, int b, int c, int d) {
    // Cell a -> b -> c -> d (counter-clockwise), split by a-c or by b-d.
    Quad q;
    q.option[0] = {Triangle{a, b, c}, Triangle{a, c, d}};
    q.option[1] = {Triangle{a, b, d}, Triangle{b, c, d}};
    q.diagonal[0] = {a, c};
    q.diagonal[1] = {b, d};
    quads.push_back(q);
  }
  std::vector<Quad> quads;

  // Node of corner k's path at level l; level ℓ_k + 1 is the corner itself.
  int at(int k, int l) const { return l == level[k] + 1 ? k : path[k][l]; }
};

// `vertex[k]` is the vertex of corner k: where both neighbours of a corner
// are the same vertex (the tip of a dangling edge), the tip's first path
// edge must not have that vertex on both sides, or the two triangles there
// would be the same triangle twice with opposite orientations. The top cells
// next to a tip are therefore split on the side away from the tip.
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

bool positive(const std::vector<Vec2>& pos, const Triangle& t) {
  return orientation(pos[t[0]], pos[t[1]], pos[t[2]]) > 0;
}

double option_quality(const std::vector<Vec2>& ps, const std::vector<Vec2>& pt, const std::array<Triangle, 2>& option) {
  double q = kPi;
  for (const Triangle& t : option)
    q = std::min({q, triangle_min_angle(ps[t[0]], ps[t[1]], ps[t[2]]),
                  triangle_min_angle(pt[t[0]], pt[t[1]], pt[t[2]])});
  return q;
}

// Kernel of a star: where node `v` may sit so that every triangle of its
// star stays positive, the intersection of the half-planes left of each
// opposite edge. Clipped to the link's bounding box (an interior node's
// closed link bounds it anyway). Computed relative to `origin`, since far
// from the origin the absolute coordinates would swallow a thin kernel.
// Returns the kernel's vertex centroid relative to `origin`, or nothing if
// the kernel is empty in floating point.
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

// Rounding repair. The spiderweb is an embedding in exact arithmetic
// (section 4.1), but its Steiner vertices are rounded: a path crossing placed
// a small fraction along a diagonal of a sliver face (a vertex very close to
// a non-incident edge), or a central vertex in a sliver center face, can
// land on the wrong side of a nearly collinear edge. Moving such a vertex to
// the middle of its star's kernel fixes its inverted triangles without
// touching any other triangle, so each accepted move strictly reduces the
// number of inverted triangles. Where the kernel is only a few units in the
// last place wide, the representable points next to its middle are tried
// too. A move is kept only if the exact predicates accept its whole star.
// Returns true if every triangle is positive afterwards.
bool untangle(std::vector<Vec2>& pos, const std::vector<Triangle>& triangles, int corners) {
  auto is_positive = [&](const Triangle& t) { return orientation(pos[t[0]], pos[t[1]], pos[t[2]]) > 0; };
  // The usual case, every attempt of every spiderweb: nothing to repair, so
  // no stars to build (10^5 nodes in large exterior faces).
  if (std::all_of(triangles.begin(), triangles.end(), is_positive)) return true;
  std::vector<std::vector<int>> star_of(pos.size());
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int node : triangles[i]) star_of[node].push_back(int(i));
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

// Identity of a node once corners are merged with their vertex.
long node_key(const PolygonPair& pair, int corners, int node) {
  return node < corners ? pair.corners[node] : -1 - long(node);
}

std::pair<long, long> edge_key(const PolygonPair& pair, int corners, int a, int b) {
  const long ka = node_key(pair, corners, a), kb = node_key(pair, corners, b);
  return {std::min(ka, kb), std::max(ka, kb)};
}

// Result of embedding the spiderweb in both polygons with chosen splits.
struct Placement {
  std::vector<Vec2> source, target;
  std::vector<Triangle> triangles;
  bool ok = false;
  std::string failure;  // what stayed inverted at the last attempt
};

// Embeds the spiderweb in both polygons. Redundant vertices start at their
// full cluster distance and are pulled towards their corners, in the
// polygon(s) where something is still inverted, until every triangle is
// positive in both (all decided exactly).
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
  std::set<std::pair<long, long>> fixed_edges;
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
    std::set<std::pair<long, long>> used = fixed_edges;
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

// ---------------------------------------------------------------------------
// Mesh operations on the node/triangle form.

struct Mesh {
  int corners = 0;
  std::vector<Vec2> source, target;  // #nodes
  std::vector<Triangle> triangles;
  std::vector<char> alive;           // per triangle
};

std::vector<std::vector<int>> triangles_around(const Mesh& mesh) {
  std::vector<std::vector<int>> around(mesh.source.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (mesh.alive[t])
      for (int v : mesh.triangles[t]) around[v].push_back(int(t));
  return around;
}

// Link of an interior node: its neighbours in counter-clockwise order.
std::vector<int> link_of(const Mesh& mesh, const std::vector<int>& star, int v) {
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

// Section 4.2: a Steiner vertex is redundant in both polygons when its star
// can be re-triangulated without it, every new triangle positive in both.
// The best such re-triangulation (largest smallest angle over both) is found
// by dynamic programming over the link polygon; positivity of every
// triangle of a triangulated simple polygon without interior vertices makes
// it an embedding, so validity is kept exactly.
int remove_redundant_steiner(const PolygonPair& pair, Mesh& mesh) {
  const int nodes = int(mesh.source.size());
  std::vector<char> removed(nodes, 0);
  int count = 0;
  // Triangles around each node (dead ones are skipped when read) and the
  // set of edges by vertex identity, both kept up to date as stars change.
  std::vector<std::vector<int>> around = triangles_around(mesh);
  std::set<std::pair<long, long>> edges;
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
  std::vector<char> dirty(nodes, 1);
  for (bool changed = true, long_links = false; changed || !long_links;) {
    if (!changed) long_links = true;  // nothing short left: allow long links
    else if (long_links) long_links = false;  // a long one went: short ones again first
    changed = false;
    // Newest Steiner vertices first: redundant levels sit at path tops.
    for (int v = nodes - 1; v >= mesh.corners; --v) {
      if (removed[v] || !dirty[v]) continue;
      std::vector<int> star;
      for (int t : around[v])
        if (mesh.alive[t]) star.push_back(t);
      around[v] = star;
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

// Moves each Steiner vertex of one polygon towards the average of its
// neighbours. A move is kept only if every triangle around the vertex stays
// positive (the vertex then stays in the kernel of its unchanged link, so the
// embedding stays valid) and the smallest angle among those triangles does
// not shrink (so the triangulation's smallest angle never gets worse).
void smooth(Mesh& mesh, bool target, int rounds) {
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
  for (int round = 0; round < rounds; ++round)
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

double mesh_min_angle(const Mesh& mesh) {
  double m = kPi;
  for (const Triangle& t : mesh.triangles)
    m = std::min({m, triangle_min_angle(mesh.source[t[0]], mesh.source[t[1]], mesh.source[t[2]]),
                  triangle_min_angle(mesh.target[t[0]], mesh.target[t[1]], mesh.target[t[2]])});
  return m;
}

// Levels that keep the spiderweb a simplicial complex: at the tip of a
// dangling edge both neighbours are the same vertex, and if the tip's path
// were longer than both neighbouring paths, that vertex would be joined to
// the tip's outermost path vertex from both sides (section 3's warning about
// repeated vertices). Lengthening one neighbour's path prevents it.
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

}  // namespace

SteinerMethod parse_steiner_method(const std::string& name) {
  if (name == "aronov") return SteinerMethod::Aronov;
  if (name == "sg2001") return SteinerMethod::Sg2001;
  if (name == "improved") return SteinerMethod::Improved;
  throw InvalidArgumentError("unknown Steiner method '" + name + "' (choose aronov, sg2001 or improved)");
}

std::string steiner_method_name(SteinerMethod method) {
  switch (method) {
    case SteinerMethod::Aronov: return "aronov";
    case SteinerMethod::Sg2001: return "sg2001";
    case SteinerMethod::Improved: return "improved";
  }
  return "?";
}

double min_angle(const PolygonPair& pair, const CompatibleTriangulation& tri) {
  const int c = tri.corner_count;
  auto pos = [&](int node, bool target) {
    if (node < c) return target ? pair.target_positions[pair.corners[node]] : pair.source_positions[pair.corners[node]];
    return target ? tri.target_steiner[node - c] : tri.source_steiner[node - c];
  };
  double m = kPi;
  for (const Triangle& t : tri.triangles)
    for (bool target : {false, true})
      m = std::min(m, triangle_min_angle(pos(t[0], target), pos(t[1], target), pos(t[2], target)));
  return m;
}

namespace {

std::vector<std::array<int, 3>> triangulate_checked(const CornerPolygon& polygon, const std::string& label,
                                                    bool target) {
  try {
    return triangulate_polygon(polygon);
  } catch (const InvalidFigureError& e) {
    throw InvalidFigureError(e.defect(), label + " in the " + (target ? "target" : "source") + ": " + e.what(),
                             e.vertices(), e.edges(), target ? "target" : "source");
  }
}

// Section 4.1 (and for Improved, 4.2) on one polygon pair: the spiderweb
// embedded in both, with redundant vertices removed for Improved.
Mesh spiderweb_piece(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                     const std::vector<std::array<int, 3>>& target_base, const CompatibleTriangulationOptions& options,
                     int& spiderweb_steiner) {
  const int n = int(pair.corners.size());
  const CornerPolygon polygons[2] = {pair.source(), pair.target()};
  const std::vector<std::array<int, 3>>* base[2] = {&source_base, &target_base};
  // Choose each polygon's center (one of at most two) to minimise the total
  // common depth: the paper's maximum of the two milestones per corner.
  std::array<PolygonTriangulation, 2> pts;
  std::vector<int> level;
  long best_total = std::numeric_limits<long>::max();
  for (int cs = 0; cs < 2; ++cs)
    for (int ct = 0; ct < 2; ++ct) {
      std::array<PolygonTriangulation, 2> candidate = {dual_tree_depths(polygons[0], *base[0], cs),
                                                       dual_tree_depths(polygons[1], *base[1], ct)};
      if ((cs && candidate[0].center_faces.size() < 2) || (ct && candidate[1].center_faces.size() < 2)) continue;
      std::vector<int> common(n);
      for (int k = 0; k < n; ++k) common[k] = std::max(candidate[0].milestone[k], candidate[1].milestone[k]);
      long total = 0;
      for (int l : common) total += l;
      if (total < best_total) best_total = total, pts = candidate, level = common;
    }

  if (options.method == SteinerMethod::Aronov) {
    // Universal spiderweb: complete layers, ceil((n-5)/2) of them as in
    // Aronov, Seidel & Souvaine, or more if a polygon's own dual-tree paths
    // need them.
    int layers = n > 4 ? (n - 5 + 1) / 2 : 0;
    for (int l : level) layers = std::max(layers, l);
    std::fill(level.begin(), level.end(), layers);
  }
  enforce_tip_levels(pair, level);

  const Spiderweb web = build_spiderweb(level, pair.corners);
  const Placement placement = embed_in_both(pair, pts, web);
  if (!placement.ok)
    throw VerificationError(options.label + ": no valid embedding of the spiderweb was found in both polygons (" +
                            std::to_string(n) + " corners, method " + steiner_method_name(options.method) +
                            "): " + placement.failure);
  Mesh mesh;
  mesh.corners = n;
  mesh.source = placement.source;
  mesh.target = placement.target;
  mesh.triangles = placement.triangles;
  mesh.alive.assign(mesh.triangles.size(), 1);
  spiderweb_steiner += int(mesh.source.size()) - n;
  if (options.method == SteinerMethod::Improved) remove_redundant_steiner(pair, mesh);
  return mesh;
}

// Beyond the paper: the diagonals of the source's triangulation that are
// also diagonals of the target (inside it, meeting its boundary only at
// their ends). Whether two diagonals cross depends only on the cyclic order
// of their ends, which both polygons share, so any set of them cuts both
// polygons into the same pieces; the spiderweb is then needed only where
// the polygons differ, which keeps its quadratic size local.
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
      if (std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) < min_new_angle) return false;
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
  std::vector<char> ok(candidates.size(), 0);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto [a, b] = candidates[i];
    ok[i] = target.corners[a] != target.corners[b] && enters(a, b) && enters(b, a);
    diagonals.push_back({target.at(a), target.at(b)});
  }
  for (int k = 0; k < n; ++k) edges.push_back({target.at(k), target.at((k + 1) % n)});
  // ... and meets no edge of the target except at its own ends.
  for (const auto& [i, e] : overlapping_boxes(diagonals, edges)) {
    if (!ok[i]) continue;
    const auto [a, b] = candidates[i];
    const int va = pair.corners[a], vb = pair.corners[b];
    const int ea = pair.corners[e], eb = pair.corners[(e + 1) % n];
    const SegmentContact contact = segment_contact(diagonals[i][0], diagonals[i][1], edges[e][0], edges[e][1]);
    if (contact == SegmentContact::Disjoint) continue;
    const bool shares_end = ea == va || ea == vb || eb == va || eb == vb;
    if (contact == SegmentContact::Touching && shares_end) continue;
    ok[i] = 0;
  }
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (ok[i]) common.insert(candidates[i]);
  return common;
}

// The pieces of the polygon cut along `cuts` (diagonals of `triangles`), each
// as its corners in counter-clockwise order.
std::vector<std::vector<int>> pieces_of(const std::vector<std::array<int, 3>>& triangles,
                                        const std::set<std::pair<int, int>>& cuts) {
  std::map<std::pair<int, int>, int> owner;  // directed side -> triangle
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int j = 0; j < 3; ++j) owner[{triangles[t][j], triangles[t][(j + 1) % 3]}] = int(t);
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
        auto it = owner.find({b, a});
        if (it != owner.end() && component[it->second] < 0) {
          component[it->second] = count;
          stack.push_back(it->second);
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
      auto twin = owner.find({b, a});
      if (twin == owner.end() || component[twin->second] != component[t]) next[component[t]][a] = b;
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

// Smallest altitude, in units of the spacing of doubles at its coordinates,
// of the triangles of `base` next to a cut, in either polygon: how much room
// rounding has before one of them flattens.
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

Mesh improved_mesh(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                   const std::vector<std::array<int, 3>>& target_base, const CompatibleTriangulationOptions& options,
                   int& spiderweb_steiner) {
  const int n = int(pair.corners.size());
  Mesh mesh;
  mesh.corners = n;
  for (int k = 0; k < n; ++k) {
    mesh.source.push_back(pair.source_positions[pair.corners[k]]);
    mesh.target.push_back(pair.target_positions[pair.corners[k]]);
  }
  if (n == 3) {  // a triangle in both (both counter-clockwise): nothing to add
    mesh.triangles.push_back({0, 1, 2});
    mesh.alive.assign(1, 1);
    return mesh;
  }
  // Candidates come from the source's triangulation; if none of them is a
  // diagonal of the target too, the target's are tried in the source (the
  // two Delaunay triangulations can differ only by a sliver's diagonal, as
  // in a quadrilateral whose source copy has a corner flat to 1e-7 rad).
  auto find_cuts = [&](double min_new_angle, const std::vector<std::array<int, 3>>*& base) {
    std::set<std::pair<int, int>> found = common_diagonals(pair, source_base, min_new_angle);
    base = &source_base;
    if (found.empty()) {
      const PolygonPair swapped{pair.corners, pair.target_positions, pair.source_positions};
      found = common_diagonals(swapped, target_base, min_new_angle);
      base = &target_base;
    }
    return found;
  };
  const std::vector<std::array<int, 3>>* cut_base = nullptr;
  std::set<std::pair<int, int>> cuts = find_cuts(kMinNewAngle, cut_base);
  if (cuts.empty()) {
    try {
      return spiderweb_piece(pair, source_base, target_base, options, spiderweb_steiner);
    } catch (const VerificationError&) {
      // The spiderweb needs room for its Steiner vertices. In a needle (a
      // far corner facing a few nearly collinear ones) every diagonal makes
      // an angle below kMinNewAngle and the center face can be thinner than
      // the spacing of doubles, so no Steiner vertex fits. A diagonal that
      // the exact predicates accept in both polygons is still valid: take
      // it, thin as it is, rather than fail.
      // Of the two candidate sets, the one whose cut-off triangles stand
      // highest above their sides in units of the spacing of doubles there
      // (what every morph frame must resolve) is taken.
      const PolygonPair swapped{pair.corners, pair.target_positions, pair.source_positions};
      std::set<std::pair<int, int>> from_source = common_diagonals(pair, source_base, 0.0);
      std::set<std::pair<int, int>> from_target = common_diagonals(swapped, target_base, 0.0);
      const double source_room = cut_room(pair, source_base, from_source);
      const double target_room = cut_room(pair, target_base, from_target);
      if (from_source.empty() && from_target.empty()) throw;
      if (!from_source.empty() && (from_target.empty() || source_room >= target_room)) {
        cuts = std::move(from_source);
        cut_base = &source_base;
      } else {
        cuts = std::move(from_target);
        cut_base = &target_base;
      }
    }
  }
  for (const std::vector<int>& cycle : pieces_of(*cut_base, cuts)) {
    PolygonPair sub;
    for (int k : cycle) sub.corners.push_back(pair.corners[k]);
    sub.source_positions = pair.source_positions;
    sub.target_positions = pair.target_positions;
    const int m = int(cycle.size());
    Mesh piece;
    if (m == 3) {
      piece.corners = 3;
      piece.triangles.push_back({0, 1, 2});
    } else {
      piece = improved_mesh(sub, triangulate_checked(sub.source(), options.label, false),
                            triangulate_checked(sub.target(), options.label, true), options, spiderweb_steiner);
    }
    // Corners of the piece are corners of the pair; its Steiner vertices are new.
    const int offset = int(mesh.source.size());
    for (std::size_t v = piece.corners; v < piece.source.size(); ++v) {
      mesh.source.push_back(piece.source[v]);
      mesh.target.push_back(piece.target[v]);
    }
    for (std::size_t t = 0; t < piece.triangles.size(); ++t) {
      if (!piece.alive.empty() && !piece.alive[t]) continue;
      Triangle global;
      for (int j = 0; j < 3; ++j) {
        const int v = piece.triangles[t][j];
        global[j] = v < m ? cycle[v] : offset + (v - m);
      }
      mesh.triangles.push_back(global);
    }
  }
  mesh.alive.assign(mesh.triangles.size(), 1);
  return mesh;
}

}  // namespace

CompatibleTriangulation compatible_triangulation(const PolygonPair& pair,
                                                 const CompatibleTriangulationOptions& options,
                                                 CompatibleTriangulationStats* stats) {
  const int n = int(pair.corners.size());
  const std::vector<std::array<int, 3>> source_base = triangulate_checked(pair.source(), options.label, false);
  const std::vector<std::array<int, 3>> target_base = triangulate_checked(pair.target(), options.label, true);

  CompatibleTriangulationStats local;
  Mesh mesh = options.method == SteinerMethod::Improved
                  ? improved_mesh(pair, source_base, target_base, options, local.spiderweb_steiner_vertices)
                  : spiderweb_piece(pair, source_base, target_base, options, local.spiderweb_steiner_vertices);
  local.min_angle_before_smoothing = mesh_min_angle(mesh);
  smooth(mesh, false, options.smoothing_rounds);
  smooth(mesh, true, options.smoothing_rounds);
  local.min_angle_after_smoothing = mesh_min_angle(mesh);

  CompatibleTriangulation result;
  result.corner_count = n;
  result.source_steiner.assign(mesh.source.begin() + n, mesh.source.end());
  result.target_steiner.assign(mesh.target.begin() + n, mesh.target.end());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (mesh.alive.empty() || mesh.alive[t]) result.triangles.push_back(mesh.triangles[t]);
  verify_compatible_triangulation(pair, result, options.label);
  local.steiner_vertices = result.steiner_count();
  if (stats) *stats = local;
  return result;
}

}  // namespace stickmorph
