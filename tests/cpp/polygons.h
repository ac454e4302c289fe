// Polygon pair generators shared by the Catch2 tests and the benchmark.
#pragma once

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/exact_predicates.h"

namespace stickmorph::test {

constexpr double kTestPi = 3.14159265358979323846;

inline double signed_area(const std::vector<Vec2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& u = p[i];
    const Vec2& v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return a / 2;
}

/// Reorders `p` counter-clockwise if it runs clockwise.
inline std::vector<Vec2> counter_clockwise(std::vector<Vec2> p) {
  if (signed_area(p) < 0) std::reverse(p.begin(), p.end());
  return p;
}

/// Star-shaped polygon: sorted random angles, random radii in [1-j, 1+j].
/// Every angular gap stays below a half-turn, so the origin is in the
/// kernel and the polygon is simple.
inline std::vector<Vec2> star_polygon(std::mt19937& rng, int n, double jitter) {
  std::uniform_real_distribution<double> angle(0, 2 * kTestPi), radius(1 - jitter, 1 + jitter);
  std::vector<double> angles(n);
  for (bool gap_ok = false; !gap_ok;) {
    for (double& a : angles) a = angle(rng);
    std::sort(angles.begin(), angles.end());
    gap_ok = angles.front() + 2 * kTestPi - angles.back() < 0.9 * kTestPi;
    for (int i = 1; i < n; ++i) gap_ok = gap_ok && angles[i] - angles[i - 1] < 0.9 * kTestPi;
  }
  std::vector<Vec2> p;
  for (double a : angles) {
    const double r = radius(rng);
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}

/// A random simple polygon: random points joined in random order, untangled
/// by 2-opt moves (reversing the chain between two crossing edges) until no
/// edges cross. Far from star-shaped in general.
inline std::vector<Vec2> two_opt_polygon(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> coord(-1, 1);
  std::vector<Vec2> p(n);
  for (Vec2& q : p) q = {coord(rng), coord(rng)};
  for (bool crossed = true; crossed;) {
    crossed = false;
    for (int i = 0; i < n && !crossed; ++i)
      for (int j = i + 2; j < n && !crossed; ++j) {
        if (i == 0 && j == n - 1) continue;
        if (segment_contact(p[i], p[i + 1], p[j], p[(j + 1) % n]) != SegmentContact::Disjoint) {
          std::reverse(p.begin() + i + 1, p.begin() + j + 1);
          crossed = true;
        }
      }
  }
  return counter_clockwise(p);
}

/// A spiral strip with `n` corners (n even), `turns` turns.
inline std::vector<Vec2> spiral_polygon(int n, double turns) {
  const int half = n / 2;
  std::vector<Vec2> outer, inner;
  for (int i = 0; i < half; ++i) {
    const double t = double(i) / (half - 1);
    const double a = t * turns * 2 * kTestPi;
    const double r = 1 + 2 * t;
    outer.push_back({(r + 0.4) * std::cos(a), (r + 0.4) * std::sin(a)});
    inner.push_back({r * std::cos(a), r * std::sin(a)});
  }
  std::vector<Vec2> p = inner;
  for (int i = half - 1; i >= 0; --i) p.push_back(outer[i]);
  return counter_clockwise(p);
}

/// A comb with `teeth` teeth hanging down from a bar: 4*teeth corners.
inline std::vector<Vec2> comb_polygon(int teeth, double depth) {
  std::vector<Vec2> p;
  // Along the bottom from left to right (the interior above), then back
  // along the top of the bar.
  for (int i = 0; i < teeth; ++i) {
    p.push_back({2.0 * i, -depth});
    p.push_back({2.0 * i + 1, -depth});
    if (i + 1 < teeth) {
      p.push_back({2.0 * i + 1, 0});
      p.push_back({2.0 * i + 2, 0});
    }
  }
  p.push_back({2.0 * teeth - 1, 1});
  p.push_back({0, 1});
  return p;
}

inline std::vector<Vec2> rotated(std::vector<Vec2> p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (Vec2& q : p) q = {c * q[0] - s * q[1], s * q[0] + c * q[1]};
  return p;
}

/// Corner k of both polygons is vertex k.
inline PolygonPair polygon_pair(const std::vector<Vec2>& source, const std::vector<Vec2>& target) {
  PolygonPair pair;
  pair.corners.resize(source.size());
  std::iota(pair.corners.begin(), pair.corners.end(), 0);
  pair.source_positions = source;
  pair.target_positions = target;
  return pair;
}

}  // namespace stickmorph::test

#include "stickmorph/decomposition.h"

namespace stickmorph::test {

/// The polygon pair of interior sequence `index` (in Algorithm 1 order,
/// counting interior sequences only) of two compatible figures.
inline PolygonPair face_pair(const StickFigure& source, const StickFigure& target, int index = 0) {
  const Decomposition d = decompose(source);
  int seen = 0;
  for (const CyclicSequence& s : d.sequences) {
    if (s.exterior) continue;
    if (seen++ == index) {
      PolygonPair pair;
      pair.corners = s.vertices;
      pair.source_positions = source.vertices;
      pair.target_positions = target.vertices;
      return pair;
    }
  }
  throw std::logic_error("face_pair: no such interior sequence");
}

}  // namespace stickmorph::test
