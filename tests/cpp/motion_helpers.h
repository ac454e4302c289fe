// Measurements of point sets and frames shared by the rigid morph's tests
// (test_similarity_motion, test_rigid_guide, test_guided_morph) and the key
// poses' (test_key_pose_guide, test_key_pose_morph): #V by 2 point lists,
// edges as vertex pairs.
#pragma once

#include <cmath>
#include <vector>

#include "catch.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::test {

constexpr double kTestPi = 3.14159265358979323846;

/// Into (-pi, pi].
inline double wrap(double a) {
  a = std::fmod(a + kTestPi, 2 * kTestPi);
  if (a <= 0) a += 2 * kTestPi;
  return a - kTestPi;
}

inline Vec2 vector_of(const std::vector<Vec2>& p, const Edge& e) {
  return {p[e[1]][0] - p[e[0]][0], p[e[1]][1] - p[e[0]][1]};
}
inline double length_of(const std::vector<Vec2>& p, const Edge& e) {
  const Vec2 d = vector_of(p, e);
  return std::hypot(d[0], d[1]);
}
inline double angle_of(const std::vector<Vec2>& p, const Edge& e) {
  const Vec2 d = vector_of(p, e);
  return std::atan2(d[1], d[0]);
}

inline Vec2 mean(const std::vector<Vec2>& points) {
  Vec2 m{0, 0};
  for (const Vec2& p : points) m = {m[0] + p[0], m[1] + p[1]};
  return {m[0] / points.size(), m[1] / points.size()};
}

/// RMS distance of the points from their centroid.
inline double rms_radius(const std::vector<Vec2>& points) {
  const Vec2 c = mean(points);
  double sum = 0;
  for (const Vec2& p : points) sum += (p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]);
  return std::sqrt(sum / points.size());
}

/// Every coordinate of a within `margin` of b's.
inline void check_close(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double margin) {
  REQUIRE(a.size() == b.size());
  for (std::size_t v = 0; v < a.size(); ++v)
    for (int c = 0; c < 2; ++c) CHECK(a[v][c] == Approx(b[v][c]).margin(margin));
}

/// The Euclidean distance between two frames of the same vertices, as one
/// vector of 2 #V coordinates.
inline double frame_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double sum = 0;
  for (std::size_t v = 0; v < a.size(); ++v)
    sum += (b[v][0] - a[v][0]) * (b[v][0] - a[v][0]) + (b[v][1] - a[v][1]) * (b[v][1] - a[v][1]);
  return std::sqrt(sum);
}

/// The length of a whole-figure vector (a velocity, a jump).
inline double frame_norm(const std::vector<Vec2>& v) {
  return frame_distance(std::vector<Vec2>(v.size(), Vec2{0, 0}), v);
}

}  // namespace stickmorph::test
