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

/// The smallest of the three angles of triangle (a, b, c).
inline double triangle_min_angle(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
}

}  // namespace stickmorph::internal
