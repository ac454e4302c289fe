// Figure builders shared by the Catch2 tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::test {

using RawEdges = std::vector<std::array<std::int64_t, 2>>;

inline StickFigure figure(std::vector<Vec2> vertices, RawEdges edges) {
  return make_stick_figure(std::move(vertices), edges);
}

/// Closed polygon through the points in the given order.
inline StickFigure polygon(std::vector<Vec2> corners) {
  RawEdges edges;
  const std::int64_t n = std::int64_t(corners.size());
  for (std::int64_t i = 0; i < n; ++i) edges.push_back({i, (i + 1) % n});
  return figure(std::move(corners), edges);
}

/// Open polyline through the points in order.
inline StickFigure polyline(std::vector<Vec2> points) {
  RawEdges edges;
  for (std::int64_t i = 0; i + 1 < std::int64_t(points.size()); ++i) edges.push_back({i, i + 1});
  return figure(std::move(points), edges);
}

/// Regular n-gon of radius r, counter-clockwise.
inline std::vector<Vec2> regular(int n, double r = 1.0, double phase = 0.0) {
  std::vector<Vec2> pts;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * 3.14159265358979323846 * i / n;
    pts.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return pts;
}

/// A k by k grid of points triangulated by one diagonal per cell:
/// 2*(k-1)^2 triangles.
inline StickFigure grid_triangulation(int k) {
  std::vector<Vec2> pts;
  RawEdges edges;
  auto id = [k](int i, int j) { return std::int64_t(i * k + j); };
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) pts.push_back({double(j), double(i)});
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      if (j + 1 < k) edges.push_back({id(i, j), id(i, j + 1)});
      if (i + 1 < k) edges.push_back({id(i, j), id(i + 1, j)});
      if (i + 1 < k && j + 1 < k) edges.push_back({id(i, j), id(i + 1, j + 1)});
    }
  return figure(std::move(pts), edges);
}

/// The greedy triangulation of `pts`: every pair of points as a candidate
/// segment, shortest first, kept when it meets no kept segment except at a
/// shared endpoint and passes through no other point. The result is a
/// maximal plane graph on the points, i.e. a triangulation of their convex
/// hull when no three hull points are collinear. Decided by exact predicates.
inline std::vector<Edge> greedy_triangulation(const std::vector<Vec2>& pts) {
  const int n = int(pts.size());
  struct Candidate { double length; int a, b; };
  std::vector<Candidate> candidates;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      candidates.push_back({std::hypot(pts[a][0] - pts[b][0], pts[a][1] - pts[b][1]), a, b});
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& x, const Candidate& y) { return x.length < y.length; });
  std::vector<Edge> kept;
  for (const Candidate& c : candidates) {
    bool ok = true;
    for (const Edge& e : kept) {
      const bool incident = e[0] == c.a || e[0] == c.b || e[1] == c.a || e[1] == c.b;
      const SegmentContact contact = segment_contact(pts[c.a], pts[c.b], pts[e[0]], pts[e[1]]);
      if (contact == SegmentContact::Disjoint || (incident && contact == SegmentContact::Touching))
        continue;
      ok = false;
      break;
    }
    for (int v = 0; ok && v < n; ++v)
      if (v != c.a && v != c.b && on_segment(pts[v], pts[c.a], pts[c.b])) ok = false;
    if (ok) kept.push_back({c.a, c.b});
  }
  return kept;
}

/// Thins `edges` (a connected graph on vertices 0..n-1): in random order,
/// drops each edge with probability 1 - keep_fraction if the graph stays
/// connected without it. The edge list comes out shuffled.
template <class Rng>
void thin_keeping_connected(std::vector<Edge>& edges, int n, double keep_fraction, Rng& rng) {
  std::shuffle(edges.begin(), edges.end(), rng);
  std::bernoulli_distribution drop(1.0 - keep_fraction);
  auto connected_without = [&](std::size_t skip) {
    std::vector<std::vector<int>> adj(n);
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (i != skip) adj[edges[i][0]].push_back(edges[i][1]), adj[edges[i][1]].push_back(edges[i][0]);
    std::vector<int> seen(n, 0), stack{0};
    seen[0] = 1;
    int count = 1;
    while (!stack.empty()) {
      int v = stack.back();
      stack.pop_back();
      for (int w : adj[v])
        if (!seen[w]) seen[w] = 1, ++count, stack.push_back(w);
    }
    return count == n;
  };
  for (std::size_t i = 0; i < edges.size();) {
    if (drop(rng) && connected_without(i)) edges.erase(edges.begin() + long(i));
    else ++i;
  }
}

inline RawEdges raw_edges(const std::vector<Edge>& edges) {
  RawEdges raw;
  for (const Edge& e : edges) raw.push_back({e[0], e[1]});
  return raw;
}

/// A random connected plane graph: the greedy triangulation of random points
/// thinned by removing random edges while it stays connected. Produces faces
/// with dangling edges, cut vertices and tree parts.
inline StickFigure random_plane_graph(std::mt19937& rng, int n, double keep_fraction) {
  std::uniform_real_distribution<double> coord(-10.0, 10.0);
  std::vector<Vec2> pts(n);
  for (Vec2& p : pts) p = {coord(rng), coord(rng)};
  std::vector<Edge> kept = greedy_triangulation(pts);
  thin_keeping_connected(kept, n, keep_fraction, rng);
  return figure(std::move(pts), raw_edges(kept));
}

/// `f` rotated by `angle`, scaled and moved.
inline StickFigure moved(const StickFigure& f, double angle, double scale, double dx, double dy) {
  StickFigure g = f;
  const double c = std::cos(angle) * scale, s = std::sin(angle) * scale;
  for (Vec2& p : g.vertices) p = {c * p[0] - s * p[1] + dx, s * p[0] + c * p[1] + dy};
  return g;
}

/// A random compatible pair for round `round` of a property test: a thinned
/// triangulation (faces of every size, trees, dangling edges) and a rotated,
/// scaled copy with every vertex pushed a little; nothing if the pushed copy
/// is no longer a valid figure compatible with the source.
inline std::optional<std::pair<StickFigure, StickFigure>> random_compatible_pair(std::mt19937& rng, int round,
                                                                                 int smallest, int spread) {
  std::normal_distribution<double> jitter(0.0, 0.3);
  StickFigure s = random_plane_graph(rng, smallest + round % spread, 0.25 + 0.02 * (round % 30));
  StickFigure t = moved(s, 0.8 * round, 0.5 + 0.1 * (round % 7), round % 5, -(round % 3));
  for (Vec2& p : t.vertices) p = {p[0] + jitter(rng), p[1] + jitter(rng)};
  if (!is_valid(t) || !check_compatibility(s, t).compatible()) return std::nullopt;
  return std::make_pair(std::move(s), std::move(t));
}

}  // namespace stickmorph::test

namespace stickmorph::test {

/// A stick man posed by forward kinematics: 11 vertices, a tree of 10 edges.
/// Vertex 0 is the pelvis at `root`; edge i joins kStickManParent[i] to
/// vertex i + 1 (1 chest, 2 head, 3-4 left arm, 5-6 right arm, 7-8 left leg,
/// 9-10 right leg) with length lengths[i], turned by bends[i] radians from
/// the direction of edge kStickManReference[i] (the spine's from `heading`).
inline constexpr std::array<int, 10> kStickManParent = {0, 1, 1, 3, 1, 5, 0, 7, 0, 9};
inline constexpr std::array<int, 10> kStickManReference = {-1, 0, 0, 2, 0, 4, 0, 6, 0, 8};

inline StickFigure stick_man(const Vec2& root, double heading, const std::array<double, 10>& lengths,
                             const std::array<double, 10>& bends) {
  std::vector<Vec2> pts(11);
  pts[0] = root;
  std::array<double, 10> direction{};
  RawEdges edges;
  for (int i = 0; i < 10; ++i) {
    direction[i] = (kStickManReference[i] < 0 ? heading : direction[kStickManReference[i]]) + bends[i];
    const Vec2& from = pts[kStickManParent[i]];
    pts[i + 1] = {from[0] + lengths[i] * std::cos(direction[i]), from[1] + lengths[i] * std::sin(direction[i])};
    edges.push_back({kStickManParent[i], i + 1});
  }
  return figure(std::move(pts), edges);
}

/// The stick man standing: spine up, arms hanging out, legs apart.
inline StickFigure stick_man_standing() {
  constexpr double d = 3.14159265358979323846 / 180;
  return stick_man({0, 0}, 90 * d, {3, 0.8, 1.2, 1.2, 1.2, 1.2, 1.5, 1.5, 1.5, 1.5},
                   {0, 0, 120 * d, -30 * d, -120 * d, 30 * d, 160 * d, 10 * d, -160 * d, -10 * d});
}

/// The same stick man walking, leaning, waving, with longer limbs, turned
/// by about 30 degrees and moved: every joint angle and length changed.
inline StickFigure stick_man_walking() {
  constexpr double d = 3.14159265358979323846 / 180;
  return stick_man({2, -1}, 120 * d, {3.3, 0.9, 1.0, 1.4, 1.3, 1.1, 1.8, 1.6, 1.4, 1.7},
                   {0, -15 * d, 80 * d, -60 * d, -140 * d, 55 * d, 140 * d, 35 * d, -150 * d, -35 * d});
}

/// The stick man in pose `k` of a walk: every joint bent from the standing
/// pose by its own sine of the pose's phase, the whole figure leaning more
/// and moving on with each pose.
inline std::vector<Vec2> stick_man_walk_pose(int k) {
  constexpr double d = 3.14159265358979323846 / 180;
  const double phase = 0.9 * k;
  const std::array<double, 10> rest = {0, 0, 120, -30, -120, 30, 160, 10, -160, -10};
  std::array<double, 10> bends{};
  for (int i = 0; i < 10; ++i) bends[i] = (rest[i] + 20 * std::sin(phase + 0.7 * i)) * d;
  return stick_man({1.5 * k, 0.3 * std::sin(phase)}, (90 + 10 * k) * d,
                   {3, 0.8, 1.2, 1.2, 1.2, 1.2, 1.5, 1.5, 1.5, 1.5}, bends)
      .vertices;
}

/// Poses 0 .. keys - 1 of that walk.
inline std::vector<std::vector<Vec2>> stick_man_walk(int keys) {
  std::vector<std::vector<Vec2>> poses;
  for (int k = 0; k < keys; ++k) poses.push_back(stick_man_walk_pose(k));
  return poses;
}

}  // namespace stickmorph::test
