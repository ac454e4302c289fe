// Floating-point geometry helpers shared by the engine: pi and the angle
// between two directions.
//
// Angles never decide validity in stickmorph (the exact predicates of
// exact_predicates.h do); they measure quality (the smallest angle that the
// paper's section 4.2 maximises and section 5 reports), choose directions
// for the spiderweb's redundant levels (section 4.1) and sum corner angles
// to count windings (section 3, the polygon decomposition). One formula for
// all of them keeps those measurements consistent with each other.
#pragma once

#include <algorithm>
#include <cmath>

#include "stickmorph/stick_figure.h"

namespace stickmorph::internal {

constexpr double kPi = 3.14159265358979323846;

/// Unsigned angle in [0, pi] between the directions (ux, uy) and (vx, vy).
/// atan2 of the cross and dot products rather than acos of the normalised
/// dot product: acos loses all accuracy near 0 and pi, exactly where thin
/// triangles and flat corners are measured.
inline double angle_between(double ux, double uy, double vx, double vy) {
  return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
}

/// The angle at a of the triangle (a, b, c).
inline double angle_at(const Vec2& a, const Vec2& b, const Vec2& c) {
  return angle_between(b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]);
}

/// The smallest of the three angles of triangle (a, b, c):
/// min(angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)), bit for bit.
///
/// It measures every candidate triangle of the section 4.2 re-triangulation
/// and of smoothing, and its three atan2 were a seventh of a 10^3-vertex
/// polygon's triangulation (perf), so the corner of the smallest angle is
/// found first and only its atan2 taken. Each angle is atan2(y, x) of its
/// (|cross|, dot), a direction in the closed upper half-plane, where the
/// angle of (x1, y1) is below that of (x2, y2) exactly when
/// x1 y2 - y1 x2 > 0. That product is trusted only when it exceeds 1e-12
/// of (|x1| + |y1|)(|x2| + |y2|): far above its own rounding (a few ulps of
/// that bound), so the angles of those very inputs differ by more than
/// 1e-12 radians, which no atan2 rounding (an ulp, below 4e-16) reverses.
/// Any closer call (a near tie, as in the isosceles triangles of regular
/// figures) or an input off the normal range takes all three atan2 as
/// before, so the value is always the one the three-atan2 formula gives.
inline double triangle_min_angle(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2* corner[3] = {&a, &b, &c};
  double y[3], x[3];
  for (int i = 0; i < 3; ++i) {
    const Vec2& o = *corner[i];
    const Vec2& p = *corner[(i + 1) % 3];
    const Vec2& q = *corner[(i + 2) % 3];
    const double ux = p[0] - o[0], uy = p[1] - o[1], vx = q[0] - o[0], vy = q[1] - o[1];
    y[i] = std::abs(ux * vy - uy * vx);  // as angle_between
    x[i] = ux * vx + uy * vy;
  }
  int smallest = 0;
  for (int i = 1; i < 3; ++i) {
    const double order = x[i] * y[smallest] - y[i] * x[smallest];  // > 0: angle i is smaller
    const double bound = (std::abs(x[i]) + y[i]) * (std::abs(x[smallest]) + y[smallest]);
    if (!(std::abs(order) > 1e-12 * bound) || !(bound >= 1e-200) || !(bound <= 1e200))
      return std::min({std::atan2(y[0], x[0]), std::atan2(y[1], x[1]), std::atan2(y[2], x[2])});
    if (order > 0) smallest = i;
  }
  return std::atan2(y[smallest], x[smallest]);
}

}  // namespace stickmorph::internal
