// The global similarity of a morph; see similarity_motion.h.
#include "stickmorph/similarity_motion.h"

#include <cmath>

#include "stickmorph/errors.h"
#include "stickmorph/internal/geometry.h"

namespace stickmorph {
namespace {

using internal::kPi;

Vec2 centroid(const std::vector<Vec2>& points) {
  long double x = 0, y = 0;
  for (const Vec2& p : points) {
    x += p[0];
    y += p[1];
  }
  return {double(x / points.size()), double(y / points.size())};
}

double rms_radius(const std::vector<Vec2>& points, const Vec2& center) {
  long double sum = 0;
  for (const Vec2& p : points) {
    const long double dx = p[0] - center[0], dy = p[1] - center[1];
    sum += dx * dx + dy * dy;
  }
  return std::sqrt(double(sum / points.size()));
}

}  // namespace

RotationDirection parse_rotation_direction(const std::string& name) {
  if (name == "short") return RotationDirection::Short;
  if (name == "ccw") return RotationDirection::CounterClockwise;
  if (name == "cw") return RotationDirection::Clockwise;
  throw InvalidArgumentError("unknown rotation direction '" + name + "' (choose short, ccw or cw)");
}

std::string rotation_direction_name(RotationDirection direction) {
  switch (direction) {
    case RotationDirection::Short: return "short";
    case RotationDirection::CounterClockwise: return "ccw";
    case RotationDirection::Clockwise: return "cw";
  }
  throw InternalError("rotation_direction_name: unknown RotationDirection");
}

bool SimilarityMotion::is_identity() const {
  return angle == 0 && scale == 1 && source_center == target_center;
}

namespace {

// x -> center + (c, -s; s, c) (x - origin): the similarity at one time,
// its power and trigonometry evaluated once for all points.
struct SimilarityAt {
  double c, s;
  Vec2 origin, center;
  Vec2 operator()(const Vec2& x) const {
    const double dx = x[0] - origin[0], dy = x[1] - origin[1];
    return {center[0] + c * dx - s * dy, center[1] + s * dx + c * dy};
  }
};

SimilarityAt forward_at(const SimilarityMotion& m, double t) {
  const double a = t * m.angle;
  const double k = std::pow(m.scale, t);  // geometric: the same ratio in every equal time step
  return {k * std::cos(a), k * std::sin(a), m.source_center,
          {(1 - t) * m.source_center[0] + t * m.target_center[0],
           (1 - t) * m.source_center[1] + t * m.target_center[1]}};
}

SimilarityAt inverse_at(const SimilarityMotion& m, double t) {
  const double a = -t * m.angle;
  const double k = std::pow(m.scale, -t);
  return {k * std::cos(a), k * std::sin(a),
          {(1 - t) * m.source_center[0] + t * m.target_center[0],
           (1 - t) * m.source_center[1] + t * m.target_center[1]},
          m.source_center};
}

}  // namespace

Vec2 SimilarityMotion::apply(double t, const Vec2& x) const {
  if (t == 0) return x;
  return forward_at(*this, t)(x);
}

Vec2 SimilarityMotion::unapply(double t, const Vec2& y) const {
  if (t == 0) return y;
  return inverse_at(*this, t)(y);
}

std::vector<Vec2> SimilarityMotion::apply(double t, const std::vector<Vec2>& points) const {
  if (t == 0) return points;
  const SimilarityAt map = forward_at(*this, t);
  std::vector<Vec2> out;
  out.reserve(points.size());
  for (const Vec2& p : points) out.push_back(map(p));
  return out;
}

std::vector<Vec2> SimilarityMotion::unapply(double t, const std::vector<Vec2>& points) const {
  if (t == 0) return points;
  const SimilarityAt map = inverse_at(*this, t);
  std::vector<Vec2> out;
  out.reserve(points.size());
  for (const Vec2& p : points) out.push_back(map(p));
  return out;
}

SimilarityMotion fit_similarity(const std::vector<Vec2>& source, const std::vector<Vec2>& target,
                                RotationDirection direction, int extra_turns) {
  if (source.size() != target.size())
    throw InvalidArgumentError("fit_similarity: the source has " + std::to_string(source.size()) +
                               " points and the target " + std::to_string(target.size()));
  if (source.empty()) throw InvalidArgumentError("fit_similarity: no points");
  if (extra_turns < -kMaxExtraTurns || extra_turns > kMaxExtraTurns)
    throw InvalidArgumentError("extra turns must be in [" + std::to_string(-kMaxExtraTurns) + ", " +
                               std::to_string(kMaxExtraTurns) + "], got " + std::to_string(extra_turns));
  SimilarityMotion motion;
  motion.source_center = centroid(source);
  motion.target_center = centroid(target);
  // The least-squares rotation of the centred points: the angle of
  // sum(a x b, a . b) (a uniform scale does not change it).
  long double cross = 0, dot = 0;
  for (std::size_t i = 0; i < source.size(); ++i) {
    const long double ax = source[i][0] - motion.source_center[0], ay = source[i][1] - motion.source_center[1];
    const long double bx = target[i][0] - motion.target_center[0], by = target[i][1] - motion.target_center[1];
    cross += ax * by - ay * bx;
    dot += ax * bx + ay * by;
  }
  double angle = (cross == 0 && dot == 0) ? 0.0 : std::atan2(double(cross), double(dot));  // (-pi, pi]
  if (direction == RotationDirection::CounterClockwise && angle < 0) angle += 2 * kPi;
  if (direction == RotationDirection::Clockwise && angle > 0) angle -= 2 * kPi;
  motion.angle = angle + 2 * kPi * extra_turns;
  const double r0 = rms_radius(source, motion.source_center);
  const double r1 = rms_radius(target, motion.target_center);
  motion.scale = (r0 > 0 && r1 > 0 && std::isfinite(r1 / r0) && r1 / r0 > 0) ? r1 / r0 : 1.0;
  return motion;
}

}  // namespace stickmorph
