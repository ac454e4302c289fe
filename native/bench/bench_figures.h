// Deterministic compatible pairs of stick figures for the benchmarks.
//
// Six families, each at any size n (the vertex count comes out close to the
// requested one; the benchmark reports the actual count):
//  - polyline:      a sine-shaped open path, target another sine wave;
//  - spiral:        the same path, target wound into a spiral (adversarial:
//                   one long thin exterior face that changes completely);
//  - polygon:       a star-shaped polygon with seeded random radii, target
//                   another such polygon turned by 135 degrees;
//  - tree:          a spine with alternating two-edge branches, target twisted;
//  - triangulation: a k by k grid cut by one diagonal per cell, target twisted;
//  - thinned:       a Delaunay triangulation of a seeded jittered lattice, thinned
//                   to a random spanning tree plus a third of the other edges
//                   (faces of every size, dangling trees), target twisted;
//  - rings:         figures of several parts (issue 14): a grid of cells, each
//                   a ring round a smaller ring round a dot; in the target
//                   every inner ring turned by 120 degrees in its ring, then
//                   the whole twisted (the bridges between the parts must
//                   bend).
//
// Compatible by construction: polylines and simple polygons with the same
// vertex order are always compatible; the other targets are the source under
// a smooth twist of the plane, a homeomorphism, so only the straightening of
// edges can break the figure. The generator checks the result exactly and
// halves the twist until it is compatible, so every pair it returns is.
// Everything is seeded: std::mt19937 with fixed seeds, whose raw output the
// standard fixes, turned into numbers by plain arithmetic rather than the
// standard distributions (their algorithms differ between libraries), so
// the corpus is the same on every machine.
#pragma once

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::bench {

constexpr double kPi = 3.14159265358979323846;

using RawEdges = std::vector<std::array<std::int64_t, 2>>;

/// A pair before validation: the benchmark times make_stick_figure itself.
struct RawPair {
  std::vector<Vec2> source;
  std::vector<Vec2> target;
  RawEdges edges;
  double twist = 0;  ///< twist strength that made the target (0: not twisted)
};

inline const std::vector<std::string>& family_names() {
  static const std::vector<std::string> names = {"polyline", "spiral",        "polygon",
                                                  "tree",     "triangulation", "thinned", "rings"};
  return names;
}

/// A double in [0, 1) from the generator's raw 32-bit output. (The standard
/// distributions are implementation-defined, the engine's output is not.)
inline double unit(std::mt19937& rng) { return double(rng()) / 4294967296.0; }

/// A twist about the points' centre by up to `strength` radians at the
/// outermost point, and a shift by 0.3 of the reach: smooth, so edges that
/// are short next to the twist's variation keep their arrangement.
inline std::vector<Vec2> twisted(const std::vector<Vec2>& p, double strength) {
  double cx = 0, cy = 0, reach = 0;
  for (const Vec2& q : p) cx += q[0] / double(p.size()), cy += q[1] / double(p.size());
  for (const Vec2& q : p) reach = std::max(reach, std::hypot(q[0] - cx, q[1] - cy));
  std::vector<Vec2> out;
  for (const Vec2& q : p) {
    const double dx = q[0] - cx, dy = q[1] - cy;
    const double a = strength * std::hypot(dx, dy) / reach;
    out.push_back({cx + std::cos(a) * dx - std::sin(a) * dy + 0.3 * reach, cy + std::sin(a) * dx + std::cos(a) * dy});
  }
  return out;
}

inline bool is_compatible_pair(const std::vector<Vec2>& source, const std::vector<Vec2>& target,
                               const RawEdges& edges) {
  try {
    return check_compatibility(make_stick_figure(source, edges), make_stick_figure(target, edges)).compatible();
  } catch (const InvalidFigureError&) {
    return false;
  }
}

/// The source twisted by `strength`, halved until the pair is compatible.
/// Throws if even a tiny twist is not (the source itself is then invalid).
inline RawPair twisted_pair(std::vector<Vec2> source, RawEdges edges, double strength) {
  for (int attempt = 0; attempt < 12; ++attempt, strength *= 0.5) {
    std::vector<Vec2> target = twisted(source, strength);
    if (is_compatible_pair(source, target, edges)) return {std::move(source), std::move(target), std::move(edges), strength};
  }
  throw std::runtime_error("bench_figures: no twist below " + std::to_string(strength * 2) +
                           " keeps the figure compatible");
}

/// A sine wave, target another sine wave: the benign case, one exterior
/// face that stays roughly the same.
inline RawPair polyline_pair(int n) {
  RawPair pair;
  for (int i = 0; i < n; ++i) {
    pair.source.push_back({double(i), 3 * std::sin(i * 0.3)});
    pair.target.push_back({double(i) * 0.8, 4 * std::cos(i * 0.17) + 0.01 * i});
    if (i) pair.edges.push_back({i - 1, i});
  }
  return pair;
}

/// A sine wave wound up into a spiral: point i at angle sqrt(i + 1) on
/// the Archimedean spiral r = angle, so consecutive points are about 0.5
/// apart and successive turns 2 pi apart; the path never meets itself.
inline RawPair spiral_pair(int n) {
  RawPair pair;
  for (int i = 0; i < n; ++i) {
    pair.source.push_back({0.5 * i, 3 * std::sin(i * 0.3)});
    const double angle = std::sqrt(double(i + 1));
    pair.target.push_back({angle * std::cos(angle), angle * std::sin(angle)});
    if (i) pair.edges.push_back({i - 1, i});
  }
  return pair;
}

/// Star-shaped about the origin (angles strictly increasing, radii positive),
/// hence simple and counter-clockwise.
inline std::vector<Vec2> star_polygon(int n, std::uint32_t seed, double turn) {
  std::mt19937 rng(seed);
  std::vector<Vec2> corners;
  for (int i = 0; i < n; ++i) {
    const double radius = 0.5 + 0.5 * unit(rng);
    const double angle = turn + 2 * kPi * i / n;
    corners.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  return corners;
}

inline RawPair polygon_pair(int n) {
  RawPair pair;
  pair.source = star_polygon(n, 1001, 0);
  pair.target = star_polygon(n, 2002, 0.75 * kPi);
  for (int i = 0; i < n; ++i) pair.edges.push_back({i, (i + 1) % n});
  return pair;
}

inline RawPair tree_pair(int n) {
  std::vector<Vec2> p;
  RawEdges e;
  const int spine = std::max(2, n / 3);
  for (int i = 0; i < spine; ++i) {
    p.push_back({double(i), 0});
    if (i) e.push_back({i - 1, i});
  }
  for (int i = 0; int(p.size()) + 2 <= n && i < spine; ++i) {
    const double side = i % 2 ? 1 : -1;
    const std::int64_t a = std::int64_t(p.size());
    p.push_back({i + 0.3, side * 1.0});
    p.push_back({i + 0.1, side * 2.0});
    e.push_back({i, a});
    e.push_back({a, a + 1});
  }
  return twisted_pair(std::move(p), std::move(e), 1.5);
}

inline RawPair triangulation_pair(int n) {
  const int k = std::max(2, int(std::lround(std::sqrt(double(n)))));
  std::vector<Vec2> p;
  RawEdges e;
  auto id = [k](int i, int j) { return std::int64_t(i) * k + j; };
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) p.push_back({double(j), double(i)});
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      if (j + 1 < k) e.push_back({id(i, j), id(i, j + 1)});
      if (i + 1 < k) e.push_back({id(i, j), id(i + 1, j)});
      if (i + 1 < k && j + 1 < k) e.push_back({id(i, j), id(i + 1, j + 1)});
    }
  return twisted_pair(std::move(p), std::move(e), 3.0);
}

inline RawPair thinned_pair(int n) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
  std::mt19937 rng(3003 + std::uint32_t(n));
  // A triangular lattice of unit spacing, each point moved by up to 0.12:
  // random, but with the Delaunay angles of a slightly perturbed
  // equilateral mesh. Uniform random points have nearly flat triangles and
  // nearly parallel edges, which any shear (the twist) flips.
  const int columns = std::max(2, int(std::lround(std::sqrt(double(n)))));
  std::vector<Vec2> points;
  std::vector<std::pair<Kernel::Point_2, int>> located;
  for (int i = 0; i < n; ++i) {
    const int row = i / columns, column = i % columns;
    const double jitter_angle = 2 * kPi * unit(rng), jitter = 0.12 * unit(rng);
    points.push_back({column + 0.5 * (row % 2) + jitter * std::cos(jitter_angle),
                      row * std::sqrt(3.0) / 2 + jitter * std::sin(jitter_angle)});
    located.push_back({Kernel::Point_2(points[i][0], points[i][1]), i});
  }
  Delaunay delaunay(located.begin(), located.end());
  std::vector<std::array<int, 2>> all;
  for (auto edge = delaunay.finite_edges_begin(); edge != delaunay.finite_edges_end(); ++edge) {
    const int a = edge->first->vertex(Delaunay::cw(edge->second))->info();
    const int b = edge->first->vertex(Delaunay::ccw(edge->second))->info();
    // Lattice neighbours are at most 1.24 apart. Longer edges span the
    // ragged hull, nearly through the points along it, and the twist would
    // push those points across them.
    if (std::hypot(points[a][0] - points[b][0], points[a][1] - points[b][1]) > 1.5) continue;
    all.push_back({std::min(a, b), std::max(a, b)});
  }
  // CGAL's edge order depends on its internals; sort before shuffling so the
  // corpus depends only on the seed.
  std::sort(all.begin(), all.end());
  for (std::size_t i = all.size(); i > 1; --i) std::swap(all[i - 1], all[rng() % i]);
  // Kruskal in shuffled order: a random spanning tree keeps the figure
  // connected; a third of the remaining edges add faces.
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  RawEdges edges;
  for (const auto& [a, b] : all) {
    const int ra = root(a), rb = root(b);
    if (ra != rb) {
      parent[ra] = rb;
      edges.push_back({a, b});
    } else if (rng() % 3 == 0) {
      edges.push_back({a, b});
    }
  }
  return twisted_pair(std::move(points), std::move(edges), 3.0);
}

/// Rings in rings round dots, 25 vertices a cell: an outer ring of 16, an
/// inner ring of 8, turned by 120 degrees in the target, and a dot off the
/// centre; the target twisted, the twist halved until the pair is
/// compatible (nesting included).
inline RawPair rings_pair(int n) {
  const int side = std::max(1, int(std::lround(std::sqrt(n / 25.0))));
  RawPair pair;
  std::vector<Vec2> turned;
  auto ring = [&](double cx, double cy, double r, int count, double phase, double turn) {
    const std::int64_t first = std::int64_t(pair.source.size());
    for (int i = 0; i < count; ++i) {
      const double a = phase + 2 * kPi * i / count;
      pair.source.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
      turned.push_back({cx + r * std::cos(a + turn), cy + r * std::sin(a + turn)});
      pair.edges.push_back({first + i, first + (i + 1) % count});
    }
  };
  for (int row = 0; row < side; ++row)
    for (int column = 0; column < side; ++column) {
      const double cx = 10.0 * column, cy = 10.0 * row;
      ring(cx, cy, 4.0, 16, 0.0, 0.0);
      ring(cx, cy, 2.0, 8, 0.2, 2 * kPi / 3);
      pair.source.push_back({cx + 0.3, cy + 0.1});
      turned.push_back({cx + 0.3, cy + 0.1});
    }
  double strength = 3.0;
  for (int attempt = 0; attempt < 12; ++attempt, strength *= 0.5) {
    pair.target = twisted(turned, strength);
    if (is_compatible_pair(pair.source, pair.target, pair.edges)) {
      pair.twist = strength;
      return pair;
    }
  }
  throw std::runtime_error("bench_figures: no twist keeps the rings compatible");
}

/// The pair of `family` at about n vertices.
/// @throws std::invalid_argument for an unknown family.
inline RawPair make_pair(const std::string& family, int n) {
  if (family == "polyline") return polyline_pair(n);
  if (family == "spiral") return spiral_pair(n);
  if (family == "polygon") return polygon_pair(n);
  if (family == "tree") return tree_pair(n);
  if (family == "triangulation") return triangulation_pair(n);
  if (family == "thinned") return thinned_pair(n);
  if (family == "rings") return rings_pair(n);
  throw std::invalid_argument("unknown family '" + family + "'");
}

}  // namespace stickmorph::bench
