// Random compatible stick-figure pairs for property tests at scale, and the
// whole-pipeline check run on each (tests/cpp/test_random_pairs.cpp in CI,
// stickmorph_random_pairs for long runs).
//
// A pair is identified by (seed, kind): generate_pair(seed, kind) always
// returns the same pair (for the same standard library: the distributions of
// <random> are implementation-defined, libstdc++ here).
//
// Compatibility holds by construction, not by luck:
//  - polylines and polygons: any two simple polylines with the same vertex
//    count are compatible (every vertex has degree at most 2, one face), and
//    so are any two simple counter-clockwise polygons, so source and target
//    are drawn independently;
//  - trees, sparse figures, figures with dangling edges: both figures are
//    embeddings of one triangulation (the greedy triangulation of random
//    points), the target a Tutte embedding (Tutte 1963, Floater 1997:
//    positive random weights, the hull mapped in order onto a random
//    ellipse, which is strictly convex) rotated by an angle in [0, 2*pi).
//    Both embed the same rotation system with the same outer face, so the
//    same edge subset thinned from both is again a compatible pair;
//  - near-degenerate kinds take one of the above and move a vertex next to a
//    non-incident edge, or replace edges by almost collinear chains, in both
//    figures; each move is kept only if exact checks accept it.
// Every draw is still checked with the library (is_valid and
// check_compatibility, exact). A draw that fails (rounding in a Tutte
// solve or in the placement can make a valid embedding invalid) is redrawn
// from the same random stream, so the result stays a function of (seed,
// kind); the redraws are counted and bounded by kMaxRedraws.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "figures.h"
#include "polygons.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/json.h"
#include "stickmorph/morph.h"
#include "stickmorph/morph_stick_figures.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::test {

enum class PairKind {
  Polyline,       ///< two independent self-avoiding random walks
  Polygon,        ///< two independent simple polygons (star-shaped or 2-opt)
  Tree,           ///< a random spanning tree of a triangulation, Tutte target
  Sparse,         ///< a triangulation thinned to 45-100% of its edges: many faces
  Dangling,       ///< spanning tree plus a few edges: faces joined by cut vertices, dangling edges
  NearTouching,   ///< a base pair with a vertex moved next to a non-incident edge
  NearCollinear,  ///< a base pair with edges replaced by almost collinear chains
};

constexpr std::array<PairKind, 7> kAllPairKinds = {PairKind::Polyline, PairKind::Polygon,     PairKind::Tree,
                                                   PairKind::Sparse,   PairKind::Dangling,    PairKind::NearTouching,
                                                   PairKind::NearCollinear};

inline const char* pair_kind_name(PairKind kind) {
  switch (kind) {
    case PairKind::Polyline: return "polyline";
    case PairKind::Polygon: return "polygon";
    case PairKind::Tree: return "tree";
    case PairKind::Sparse: return "sparse";
    case PairKind::Dangling: return "dangling";
    case PairKind::NearTouching: return "near_touching";
    case PairKind::NearCollinear: return "near_collinear";
  }
  return "?";
}

inline std::optional<PairKind> parse_pair_kind(const std::string& name) {
  for (PairKind kind : kAllPairKinds)
    if (name == pair_kind_name(kind)) return kind;
  return std::nullopt;
}

/// Where a pair is placed: both figures are multiplied by `scale` and moved
/// by `offset_in_sizes` times their (scaled) size, in one random direction.
/// The class is seed % kPlacementCount, so consecutive seeds cover all.
///
/// Range tested and why: sizes from 1e-5 to 3e7 (scale 1e-6 to 1e6 of
/// figures about 28 across) and offsets up to 1e6 figure sizes. A double
/// resolves about 2.2e-16 of a coordinate's magnitude, so at 1e6 sizes from
/// the origin the figure itself is resolved to about 2e-10 of its size: that
/// still leaves near-degenerate gaps (kept at least kMinGapUlps ulps) and the
/// Steiner vertices of the triangulation room to be represented. At 1e7 sizes
/// the resolution is 2e-9 of the size, finer detail of the figures is
/// rounded away and the pair would test rounding, not the morph.
struct Placement {
  double scale;
  double offset_in_sizes;
  const char* name;
};
constexpr int kPlacementCount = 6;
inline Placement placement_of(std::uint64_t seed) {
  static const Placement placements[kPlacementCount] = {
      {1.0, 0.0, "unit"},
      {1e-6, 0.0, "scale 1e-6"},
      {1e6, 0.0, "scale 1e6"},
      {1.0, 1e6, "offset 1e6 sizes"},
      {1e-6, 1e5, "scale 1e-6, offset 1e5 sizes"},
      {1e6, 1e4, "scale 1e6, offset 1e4 sizes"},
  };
  return placements[seed % kPlacementCount];
}

/// Closest approach of a moved vertex to a non-incident edge, in ulps of the
/// largest coordinate. Closer than this, the morph's floating-point frames
/// (solved in double, refined in long double) cannot resolve the gap, and
/// the engine rightly refuses the frame instead of returning it.
constexpr double kMinGapUlps = 4096;

/// A draw that fails its validity or compatibility check is redrawn at most
/// this many times; more is a generator bug and throws GeneratorError.
constexpr int kMaxRedraws = 40;

class GeneratorError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RandomPair {
  std::uint64_t seed = 0;
  PairKind kind = PairKind::Polyline;
  StickFigure source, target;
  int redraws = 0;          ///< draws discarded before this one
  std::string description;  ///< "seed 12 kind tree (unit, base ...)"
};

namespace random_pairs_detail {

using Rng = std::mt19937;

inline double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
inline int uniform_int(Rng& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

inline double figure_size(const std::vector<Vec2>& pts) {
  double lo[2] = {pts[0][0], pts[0][1]}, hi[2] = {pts[0][0], pts[0][1]};
  for (const Vec2& p : pts)
    for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

inline double max_magnitude(const std::vector<Vec2>& pts) {
  double m = 0;
  for (const Vec2& p : pts) m = std::max({m, std::abs(p[0]), std::abs(p[1])});
  return m;
}

/// The figure if make_stick_figure accepts it, else nothing.
inline std::optional<StickFigure> try_figure(std::vector<Vec2> pts, const std::vector<Edge>& edges) {
  StickFigure f;
  f.vertices = std::move(pts);
  f.edges = edges;
  if (!is_valid(f)) return std::nullopt;
  return f;
}

/// Strict convex hull, counter-clockwise (Andrew's monotone chain with exact
/// orientation tests; points on a hull edge are left out).
inline std::vector<int> convex_hull(const std::vector<Vec2>& pts) {
  std::vector<int> order(pts.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return compare_xy(pts[a], pts[b]) < 0; });
  std::vector<int> hull(2 * order.size());
  std::size_t k = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = k;
    for (int v : order) {
      while (k >= start + 2 && orientation(pts[hull[k - 2]], pts[hull[k - 1]], pts[v]) <= 0) --k;
      hull[k++] = v;
    }
    --k;  // the last point starts the other chain
    std::reverse(order.begin(), order.end());
  }
  hull.resize(k);
  return hull;
}

/// A Tutte embedding of the triangulation (pts, edges) whose hull is
/// `hull`: hull vertices on a random ellipse in the same cyclic order
/// (strictly convex), every other vertex the weighted average of its
/// neighbours with random positive weights. By Tutte's and Floater's
/// theorems it is a plane embedding with the same rotation system; the
/// caller checks that rounding kept it so.
inline std::vector<Vec2> tutte_embedding(int n, const std::vector<Edge>& edges, const std::vector<int>& hull,
                                         Rng& rng) {
  std::vector<Vec2> out(n, Vec2{0, 0});
  std::vector<int> boundary_index(n, -1);
  for (std::size_t i = 0; i < hull.size(); ++i) boundary_index[hull[i]] = int(i);
  // Random angular gaps, normalised to a full turn: uneven boundaries.
  std::vector<double> gaps(hull.size());
  double total = 0;
  for (double& g : gaps) total += (g = uniform(rng, 0.2, 1.0));
  const double a = uniform(rng, 6, 14), b = a * uniform(rng, 0.3, 1.0), tilt = uniform(rng, 0, 2 * kTestPi);
  double angle = uniform(rng, 0, 2 * kTestPi);
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const double x = a * std::cos(angle), y = b * std::sin(angle);
    out[hull[i]] = {std::cos(tilt) * x - std::sin(tilt) * y, std::sin(tilt) * x + std::cos(tilt) * y};
    angle += 2 * kTestPi * gaps[i] / total;
  }
  std::vector<int> interior_index(n, -1);
  int m = 0;
  for (int v = 0; v < n; ++v)
    if (boundary_index[v] < 0) interior_index[v] = m++;
  if (m == 0) return out;
  // Random weights in [0.05, 1]; a random exponent spreads them further.
  const double spread = uniform(rng, 0.5, 3.0);
  Eigen::MatrixXd lhs = Eigen::MatrixXd::Zero(m, m);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m, 2);
  auto couple = [&](int v, int w, double weight) {
    const int i = interior_index[v];
    if (i < 0) return;
    lhs(i, i) += weight;
    if (interior_index[w] >= 0) lhs(i, interior_index[w]) -= weight;
    else rhs(i, 0) += weight * out[w][0], rhs(i, 1) += weight * out[w][1];
  };
  for (const Edge& e : edges) {
    couple(e[0], e[1], std::pow(uniform(rng, 0.05, 1.0), spread));
    couple(e[1], e[0], std::pow(uniform(rng, 0.05, 1.0), spread));
  }
  const Eigen::MatrixXd x = lhs.partialPivLu().solve(rhs);
  for (int v = 0; v < n; ++v)
    if (interior_index[v] >= 0) out[v] = {x(interior_index[v], 0), x(interior_index[v], 1)};
  return out;
}

inline std::vector<Vec2> rotated(const std::vector<Vec2>& pts, double angle, double dx, double dy) {
  std::vector<Vec2> out;
  const double c = std::cos(angle), s = std::sin(angle);
  for (const Vec2& p : pts) out.push_back({c * p[0] - s * p[1] + dx, s * p[0] + c * p[1] + dy});
  return out;
}

/// Spanning tree (random, Kruskal on shuffled edges) plus each other edge
/// with probability `extra`.
inline std::vector<Edge> spanning_tree_plus(std::vector<Edge> edges, int n, double extra, Rng& rng) {
  std::shuffle(edges.begin(), edges.end(), rng);
  std::vector<int> parent(n);
  for (int v = 0; v < n; ++v) parent[v] = v;
  auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::bernoulli_distribution keep_extra(extra);
  std::vector<Edge> kept;
  for (const Edge& e : edges) {
    const int a = root(e[0]), b = root(e[1]);
    if (a != b) parent[a] = b, kept.push_back(e);
    else if (keep_extra(rng)) kept.push_back(e);
  }
  return kept;
}

using Draw = std::optional<std::pair<StickFigure, StickFigure>>;

/// Both figures embed one triangulation; see the file comment.
inline Draw draw_triangulation_family(PairKind kind, Rng& rng, std::string& note) {
  const int n = uniform_int(rng, 8, 100);
  std::vector<Vec2> pts(n);
  // Half of the draws cluster the points (Gaussian blobs) for uneven faces.
  const bool clustered = uniform(rng, 0, 1) < 0.5;
  std::vector<Vec2> centres = {{uniform(rng, -6, 6), uniform(rng, -6, 6)}, {uniform(rng, -6, 6), uniform(rng, -6, 6)}};
  std::normal_distribution<double> blob(0.0, 2.5);
  for (Vec2& p : pts) {
    if (clustered) {
      const Vec2& c = centres[uniform_int(rng, 0, 1)];
      p = {c[0] + blob(rng), c[1] + blob(rng)};
    } else {
      p = {uniform(rng, -10, 10), uniform(rng, -10, 10)};
    }
  }
  const std::vector<Edge> triangulation = greedy_triangulation(pts);
  const std::vector<int> hull = convex_hull(pts);
  std::set<std::pair<int, int>> edge_set;
  for (const Edge& e : triangulation) edge_set.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  // The Tutte boundary must be the triangulation's outer cycle: every strict
  // hull edge present (a point exactly on a hull edge would break this).
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const int a = hull[i], b = hull[(i + 1) % hull.size()];
    if (!edge_set.count({std::min(a, b), std::max(a, b)})) return std::nullopt;
  }
  const bool source_is_tutte = uniform(rng, 0, 1) < 0.5;
  std::vector<Vec2> source_pts = source_is_tutte ? tutte_embedding(n, triangulation, hull, rng) : pts;
  std::vector<Vec2> target_pts = tutte_embedding(n, triangulation, hull, rng);
  const double turn = uniform(rng, 0, 2 * kTestPi);
  target_pts = rotated(target_pts, turn, uniform(rng, -15, 15), uniform(rng, -15, 15));
  std::vector<Edge> edges;
  double keep = 0;
  if (kind == PairKind::Tree) {
    edges = spanning_tree_plus(triangulation, n, 0.0, rng);
  } else if (kind == PairKind::Dangling) {
    keep = uniform(rng, 0.03, 0.2);
    edges = spanning_tree_plus(triangulation, n, keep, rng);
  } else {
    keep = uniform(rng, 0.45, 1.0);
    edges = triangulation;
    thin_keeping_connected(edges, n, keep, rng);
  }
  note = std::to_string(n) + " vertices, " + std::to_string(edges.size()) + " edges, " +
         (source_is_tutte ? "Tutte source" : "point-set source") + ", target turned " +
         format_double(turn) + " rad";
  auto s = try_figure(std::move(source_pts), edges);
  auto t = try_figure(std::move(target_pts), edges);
  if (!s || !t) return std::nullopt;
  return std::make_pair(std::move(*s), std::move(*t));
}

/// A self-avoiding random walk of n vertices: each step turns by a normal
/// random angle and is kept only if it meets the walk so far nowhere but at
/// its start (exact); a walk that gets stuck fails the draw.
inline std::optional<std::vector<Vec2>> random_walk(int n, Rng& rng) {
  const double turn_sigma = uniform(rng, 0.1, 1.5);
  std::normal_distribution<double> turn(0.0, turn_sigma);
  std::vector<Vec2> pts = {{0, 0}};
  double heading = uniform(rng, 0, 2 * kTestPi);
  while (int(pts.size()) < n) {
    bool placed = false;
    for (int attempt = 0; attempt < 30 && !placed; ++attempt) {
      const double h = heading + turn(rng) * (1 + attempt / 5.0);
      const double step = uniform(rng, 0.3, 2.0);
      const Vec2& last = pts.back();
      const Vec2 next = {last[0] + step * std::cos(h), last[1] + step * std::sin(h)};
      bool ok = true;
      for (std::size_t i = 0; ok && i + 1 < pts.size(); ++i) {
        const SegmentContact contact = segment_contact(pts[i], pts[i + 1], last, next);
        ok = contact == SegmentContact::Disjoint || (i + 2 == pts.size() && contact == SegmentContact::Touching);
      }
      if (ok) pts.push_back(next), heading = h, placed = true;
    }
    if (!placed) return std::nullopt;
  }
  return pts;
}

inline std::vector<Edge> path_edges(int n, bool closed) {
  std::vector<Edge> edges;
  for (int i = 0; i + 1 < n; ++i) edges.push_back({i, i + 1});
  if (closed) edges.push_back({n - 1, 0});
  return edges;
}

inline Draw draw_polyline_pair(Rng& rng, std::string& note) {
  const int n = uniform_int(rng, 3, 100);
  auto s = random_walk(n, rng);
  auto t = random_walk(n, rng);
  if (!s || !t) return std::nullopt;
  note = std::to_string(n) + " vertices";
  auto fs = try_figure(std::move(*s), path_edges(n, false));
  auto ft = try_figure(std::move(*t), path_edges(n, false));
  if (!fs || !ft) return std::nullopt;
  return std::make_pair(std::move(*fs), std::move(*ft));
}

/// A simple counter-clockwise polygon: star-shaped, 2-opt untangled random
/// points, or a spiral strip, scaled to about 20 across and cyclically
/// shifted so that vertex 0 is not always in the same place.
inline std::vector<Vec2> random_polygon(int n, Rng& rng, std::string& style) {
  const double pick = uniform(rng, 0, 1);
  std::vector<Vec2> p;
  if (pick < 0.45) {
    p = star_polygon(rng, n, uniform(rng, 0.05, 0.9));
    style = "star";
  } else if (pick < 0.9 || n % 2 == 1 || n < 8) {
    p = two_opt_polygon(rng, n);
    style = "2-opt";
  } else {
    p = spiral_polygon(n, uniform(rng, 0.5, 2.0));
    style = "spiral";
  }
  p = counter_clockwise(p);
  std::rotate(p.begin(), p.begin() + uniform_int(rng, 0, n - 1), p.end());
  for (Vec2& q : p) q = {10 * q[0], 10 * q[1]};
  return p;
}

inline Draw draw_polygon_pair(Rng& rng, std::string& note) {
  const int n = uniform_int(rng, 3, 60);
  std::string s_style, t_style;
  std::vector<Vec2> s = random_polygon(n, rng, s_style);
  std::vector<Vec2> t = random_polygon(n, rng, t_style);
  note = std::to_string(n) + " corners, " + s_style + " to " + t_style;
  auto fs = try_figure(std::move(s), path_edges(n, true));
  auto ft = try_figure(std::move(t), path_edges(n, true));
  if (!fs || !ft) return std::nullopt;
  return std::make_pair(std::move(*fs), std::move(*ft));
}

inline Draw draw_base(PairKind kind, Rng& rng, std::string& note) {
  switch (kind) {
    case PairKind::Polyline: return draw_polyline_pair(rng, note);
    case PairKind::Polygon: return draw_polygon_pair(rng, note);
    default: return draw_triangulation_family(kind, rng, note);
  }
}

/// Moves one vertex of `f` to `gap` (absolute) from the interior of a
/// non-incident edge, on its own side. Candidates are tried in random order,
/// each toward its nearest edge; a move is kept only if the figure stays
/// valid and compatible with `f` (exact). False if no candidate works.
inline bool pinch(StickFigure& f, double gap, Rng& rng, std::string& note) {
  const int n = int(f.vertices.size());
  std::vector<int> order(n);
  for (int v = 0; v < n; ++v) order[v] = v;
  std::shuffle(order.begin(), order.end(), rng);
  for (int tries = 0; tries < std::min(n, 16); ++tries) {
    const int v = order[tries];
    const Vec2 p = f.vertices[v];
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    Vec2 best_foot{}, best_normal{};
    for (int e = 0; e < int(f.edges.size()); ++e) {
      const Vec2& a = f.vertices[f.edges[e][0]];
      const Vec2& b = f.vertices[f.edges[e][1]];
      if (f.edges[e][0] == v || f.edges[e][1] == v) continue;
      const int side = orientation(a, b, p);
      if (side == 0) continue;
      const double dx = b[0] - a[0], dy = b[1] - a[1];
      const double len2 = dx * dx + dy * dy;
      // The foot stays inside the edge (10%-90%) so that the vertex ends up
      // near the edge's interior, not near its endpoints.
      const double t = std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2, 0.1, 0.9);
      const Vec2 foot = {a[0] + t * dx, a[1] + t * dy};
      const double distance = std::hypot(p[0] - foot[0], p[1] - foot[1]);
      if (distance < best_distance) {
        const double len = std::sqrt(len2);
        best = e, best_distance = distance, best_foot = foot;
        best_normal = {-dy / len * side, dx / len * side};
      }
    }
    if (best < 0) continue;
    StickFigure g = f;
    g.vertices[v] = {best_foot[0] + gap * best_normal[0], best_foot[1] + gap * best_normal[1]};
    if (is_valid(g) && check_compatibility(f, g).compatible()) {
      note += "vertex " + std::to_string(v) + " moved " + format_double(gap) + " from edge " +
              describe_edge(f, best) + "; ";
      f = std::move(g);
      return true;
    }
  }
  return false;
}

/// Replaces 1 to 3 edges (the same in both figures) by chains of 2 to 6 new
/// vertices, each offset from the edge by at most `relative_offset` times
/// its length, to either side: almost collinear chains (exactly collinear
/// where the offset rounds away, which is valid too).
inline Draw subdivide_almost_collinear(const StickFigure& s, const StickFigure& t, Rng& rng, std::string& note) {
  std::vector<Vec2> sp = s.vertices, tp = t.vertices;
  std::vector<Edge> edges = s.edges;
  if (edges.empty()) return std::nullopt;
  const int chains = std::min<int>(uniform_int(rng, 1, 3), int(edges.size()));
  const double relative_offset = std::pow(10.0, -uniform(rng, 4, 12));
  note += std::to_string(chains) + " edges made almost collinear chains (offset " + format_double(relative_offset) +
          " of the length); ";
  for (int c = 0; c < chains; ++c) {
    const int e = uniform_int(rng, 0, int(edges.size()) - 1);
    const Edge old = edges[e];
    edges.erase(edges.begin() + e);
    const int k = uniform_int(rng, 2, 6);
    std::vector<double> ts(k);
    for (double& x : ts) x = uniform(rng, 0.05, 0.95);
    std::sort(ts.begin(), ts.end());
    int previous = old[0];
    for (int i = 0; i < k; ++i) {
      const int id = int(sp.size());
      for (std::vector<Vec2>* pts : {&sp, &tp}) {
        const Vec2 a = (*pts)[old[0]], b = (*pts)[old[1]];
        const double dx = b[0] - a[0], dy = b[1] - a[1];
        const double offset = relative_offset * uniform(rng, -1, 1);
        pts->push_back({a[0] + ts[i] * dx - offset * dy, a[1] + ts[i] * dy + offset * dx});
      }
      edges.push_back({previous, id});
      previous = id;
    }
    edges.push_back({previous, old[1]});
  }
  auto fs = try_figure(std::move(sp), edges);
  auto ft = try_figure(std::move(tp), edges);
  if (!fs || !ft) return std::nullopt;
  return std::make_pair(std::move(*fs), std::move(*ft));
}

inline void place(std::vector<Vec2>& pts, double scale, const Vec2& offset) {
  for (Vec2& p : pts) p = {p[0] * scale + offset[0], p[1] * scale + offset[1]};
}

/// One draw of the whole pair, or nothing if a check rejected it.
inline Draw draw_pair(std::uint64_t seed, PairKind kind, Rng& rng, std::string& note) {
  PairKind base_kind = kind;
  if (kind == PairKind::NearTouching || kind == PairKind::NearCollinear) {
    static const PairKind bases[] = {PairKind::Polyline, PairKind::Polygon, PairKind::Tree, PairKind::Sparse,
                                     PairKind::Dangling};
    base_kind = bases[uniform_int(rng, 0, 4)];
  }
  std::string base_note;
  Draw pair = draw_base(base_kind, rng, base_note);
  note = std::string(pair_kind_name(base_kind)) + " base: " + base_note + "; ";
  if (!pair) return std::nullopt;
  if (kind == PairKind::NearCollinear) {
    pair = subdivide_almost_collinear(pair->first, pair->second, rng, note);
    if (!pair) return std::nullopt;
  }
  // Placement: the same scale and offset for both figures.
  const Placement placement = placement_of(seed);
  const double size = std::max(figure_size(pair->first.vertices), figure_size(pair->second.vertices));
  const double direction = uniform(rng, 0, 2 * kTestPi);
  const double distance = placement.offset_in_sizes * size * placement.scale;
  const Vec2 offset = {distance * std::cos(direction), distance * std::sin(direction)};
  place(pair->first.vertices, placement.scale, offset);
  place(pair->second.vertices, placement.scale, offset);
  note += std::string(placement.name) + "; ";
  if (!is_valid(pair->first) || !is_valid(pair->second)) return std::nullopt;
  if (kind == PairKind::NearTouching) {
    // Gaps from 1e-3 down to 1e-9 of the figure's size, but never below
    // kMinGapUlps ulps of its largest coordinate (see there).
    for (StickFigure* f : {&pair->first, &pair->second}) {
      const double magnitude = max_magnitude(f->vertices);
      const double ulp = std::nextafter(magnitude, 2 * magnitude) - magnitude;
      const double gap =
          std::max(std::pow(10.0, -uniform(rng, 3, 9)) * figure_size(f->vertices), kMinGapUlps * ulp);
      note += f == &pair->first ? "source: " : "target: ";
      if (!pinch(*f, gap, rng, note)) return std::nullopt;
    }
  }
  if (!check_compatibility(pair->first, pair->second).compatible()) return std::nullopt;
  return pair;
}

}  // namespace random_pairs_detail

/// The pair (seed, kind); see the file comment. Throws GeneratorError if
/// more than kMaxRedraws draws in a row fail their checks.
inline RandomPair generate_pair(std::uint64_t seed, PairKind kind) {
  using namespace random_pairs_detail;
  std::seed_seq seq{std::uint32_t(seed), std::uint32_t(seed >> 32), std::uint32_t(kind)};
  Rng rng(seq);
  RandomPair result;
  result.seed = seed;
  result.kind = kind;
  for (int redraws = 0; redraws <= kMaxRedraws; ++redraws) {
    std::string note;
    if (Draw pair = draw_pair(seed, kind, rng, note)) {
      result.source = std::move(pair->first);
      result.target = std::move(pair->second);
      result.redraws = redraws;
      result.description = "seed " + std::to_string(seed) + " kind " + pair_kind_name(kind) + " (" + note +
                           std::to_string(redraws) + " redraws)";
      return result;
    }
  }
  throw GeneratorError("seed " + std::to_string(seed) + " kind " + pair_kind_name(kind) + ": more than " +
                       std::to_string(kMaxRedraws) + " draws failed their validity or compatibility check");
}

/// The class name of an engine error, for reports.
inline std::string error_class(const std::exception& e) {
  if (dynamic_cast<const InvalidFigureError*>(&e)) return "InvalidFigureError";
  if (dynamic_cast<const IncompatibleFiguresError*>(&e)) return "IncompatibleFiguresError";
  if (dynamic_cast<const VerificationError*>(&e)) return "VerificationError";
  if (dynamic_cast<const InvalidArgumentError*>(&e)) return "InvalidArgumentError";
  if (dynamic_cast<const InternalError*>(&e)) return "InternalError";
  if (dynamic_cast<const JsonError*>(&e)) return "JsonError";
  if (dynamic_cast<const Error*>(&e)) return "stickmorph::Error";
  return "std::exception";
}

/// What morph_and_verify measured on a pair that passed.
struct PipelineStats {
  int steiner_vertices = 0;
  int triangles = 0;
  int frames_verified = 0;
};

/// The whole pipeline on a pair with the default options (the rigid method,
/// improved Steiner method, mean value weights), through the engine's one entry
/// morph_stick_figures with `frames` frames, then checked again
/// independently of the engine's own checks: the triangulation verified
/// again, endpoints exact, frames of the figure's n vertices only, every
/// triangle counter-clockwise (exact) in every frame of all nodes, and
/// verify_frame on the figure.
/// Returns an empty string on success, else what failed; any exception is
/// caught and reported with its class.
inline std::string morph_and_verify(const StickFigure& source, const StickFigure& target, int frames,
                                    PipelineStats* stats = nullptr) {
  try {
    MorphStickFiguresOptions options;
    options.frames = frames;
    // The triangles can only be re-checked on every node's position.
    options.keep_node_frames = true;
    const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
    if (!result.triangulation) return "the morph returned no triangulation";
    const FigureTriangulation& tri = *result.triangulation;
    verify_figure_triangulation(tri, source);
    if (int(result.frames.size()) != frames || int(result.times.size()) != frames ||
        int(result.node_frames.size()) != frames)
      return "morph returned " + std::to_string(result.frames.size()) + " frames, asked for " + std::to_string(frames);
    const std::size_t n = source.vertices.size();
    for (std::size_t v = 0; v < n; ++v) {
      if (result.frames.front()[v] != source.vertices[v]) return "frame 0 moves vertex " + std::to_string(v);
      if (result.frames.back()[v] != target.vertices[v])
        return "last frame misses the target at vertex " + std::to_string(v);
    }
    const Decomposition decomposition = decompose(source);
    for (int f = 0; f < frames; ++f) {
      const std::vector<Vec2>& all = result.node_frames[f];
      if (int(all.size()) != tri.node_count()) return "frame " + std::to_string(f) + " has the wrong node count";
      if (result.frames[f].size() != n) return "frame " + std::to_string(f) + " holds more than the figure";
      if (!std::equal(result.frames[f].begin(), result.frames[f].end(), all.begin()))
        return "frame " + std::to_string(f) + ": the figure's vertices are not the first nodes";
      for (std::size_t i = 0; i < tri.triangles.size(); ++i) {
        const auto& tr = tri.triangles[i];
        if (orientation(all[tr[0]], all[tr[1]], all[tr[2]]) <= 0)
          return frame_label(f, result.times[f]) + ": triangle " + std::to_string(i) + " (" + std::to_string(tr[0]) +
                 ", " + std::to_string(tr[1]) + ", " + std::to_string(tr[2]) + ") is not counter-clockwise";
      }
      verify_frame(source, decomposition, result.frames[f], f, result.times[f]);
    }
    if (stats) {
      stats->steiner_vertices = result.stats.steiner_vertices;
      stats->triangles = result.stats.triangles;
      stats->frames_verified = frames;
    }
    return {};
  } catch (const std::exception& e) {
    return error_class(e) + ": " + e.what();
  }
}

/// Structure of a figure, to show what the generator covers.
struct FigureFeatures {
  int interior_faces = 0;
  int dangling_vertices = 0;  ///< degree 1
  int cut_vertices = 0;       ///< articulation points
};

inline FigureFeatures features_of(const StickFigure& f) {
  FigureFeatures out;
  const int n = int(f.vertices.size());
  out.interior_faces = int(f.edges.size()) - n + 1;  // Euler, connected plane graph
  std::vector<std::vector<int>> adj(n);
  for (const Edge& e : f.edges) adj[e[0]].push_back(e[1]), adj[e[1]].push_back(e[0]);
  for (int v = 0; v < n; ++v) out.dangling_vertices += adj[v].size() == 1 && n > 2;
  // Articulation points by low-link (iterative DFS; figures are small but
  // recursion depth should not depend on that).
  std::vector<int> depth(n, -1), low(n, 0), parent(n, -1), next_child(n, 0), children(n, 0);
  std::vector<bool> cut(n, false);
  std::vector<int> stack = {0};
  depth[0] = 0;
  while (!stack.empty()) {
    const int v = stack.back();
    if (next_child[v] < int(adj[v].size())) {
      const int w = adj[v][next_child[v]++];
      if (depth[w] < 0) {
        depth[w] = low[w] = depth[v] + 1, parent[w] = v, ++children[v];
        stack.push_back(w);
      } else if (w != parent[v]) {
        low[v] = std::min(low[v], depth[w]);
      }
    } else {
      stack.pop_back();
      if (parent[v] >= 0) {
        const int p = parent[v];
        low[p] = std::min(low[p], low[v]);
        if (parent[p] >= 0 && low[v] >= depth[p]) cut[p] = true;
      }
    }
  }
  if (n > 0 && children[0] > 1) cut[0] = true;
  for (int v = 0; v < n; ++v) out.cut_vertices += cut[v];
  return out;
}

/// Writes a stick figure file (../shared/FORMAT.md) that read_figure_file
/// reads back exactly (shortest round-trip decimals).
inline void write_figure_file(const std::string& path, const StickFigure& figure, const std::string& name) {
  std::ofstream out(path, std::ios::binary);
  out << figure_json(figure, name) << '\n';
  if (!out) throw std::runtime_error("cannot write " + path);
}

/// Saves a failing pair as DIR/random_<kind>_seed<seed>.source.json and
/// .target.json, the source's name field giving seed, kind and the error;
/// returns the common path prefix.
inline std::string save_regression_pair(const std::string& dir, const RandomPair& pair, const std::string& error) {
  const std::string stem = dir + "/random_" + pair_kind_name(pair.kind) + "_seed" + std::to_string(pair.seed);
  const std::string name = "random pair " + pair.description + " failed: " + error;
  write_figure_file(stem + ".source.json", pair.source, name);
  write_figure_file(stem + ".target.json", pair.target, name + " (target)");
  return stem;
}

}  // namespace stickmorph::test
