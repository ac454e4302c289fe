// The global similarity of a morph, factored out before the compatible
// morph and interpolated back in afterwards.
//
// Surazhsky & Gotsman 2001, section 6 ("rotated enclosure"): a figure that
// turns as a whole morphs badly inside one fixed enclosure, since the
// convex-combination morph of [8] cannot rotate it; the paper suggests
// rotating the enclosure with the figure. Generalised here (issue 12): the
// best-fit rotation, uniform scale and translation from source to target
// (Procrustes on the figure's vertices) are taken out, the compatible
// triangulation and its morph are built between the source and the target
// mapped back by that similarity (the "normalised target"), and frame t is
// the normalised frame moved by the similarity interpolated to t: the
// rotation the short way by default (or in a chosen direction, plus whole
// turns), the scale geometrically, the centroid on a straight line.
//
// Why validity survives: a similarity x -> c + s R (x - c0) with s > 0 and R
// a rotation preserves orientation and maps a simple polygon to a simple
// polygon, so it maps a triangulation with every triangle positive and a
// simple boundary to another one, and a plane stick figure to a plane stick
// figure with the same rotation system. (The frames are still verified
// exactly after the similarity is applied: floating-point rounding of the
// map could in principle flip a nearly flat triangle.) A pure similarity
// pair then morphs rigidly: the normalised target is the source itself.
#pragma once

#include <string>
#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// Which way the factored-out rotation turns.
enum class RotationDirection {
  Short,             ///< the smaller angle, in (-180°, 180°]
  CounterClockwise,  ///< in [0°, 360°)
  Clockwise,         ///< in (-360°, 0°]
};

/// "short", "ccw", "cw" -> direction.
/// @throws InvalidArgumentError naming the accepted names.
RotationDirection parse_rotation_direction(const std::string& name);
std::string rotation_direction_name(RotationDirection direction);

/// Whole extra turns a morph may add to its rotation, either sign.
constexpr int kMaxExtraTurns = 100;

/// x(t) = c(t) + s^t R(t angle) (x - source_center) for a point x of the
/// normalised morph, c(t) = (1 - t) source_center + t target_center.
struct SimilarityMotion {
  Vec2 source_center{0, 0};  ///< the source vertices' centroid
  Vec2 target_center{0, 0};  ///< the target vertices' centroid
  double angle = 0;          ///< the whole rotation at t = 1, radians, counter-clockwise positive
  double scale = 1;          ///< target RMS radius over source RMS radius, > 0

  bool is_identity() const;
  /// The point x of the normalised morph moved to time t.
  Vec2 apply(double t, const Vec2& x) const;
  /// The inverse of apply(t, .).
  Vec2 unapply(double t, const Vec2& y) const;
  /// apply and unapply to every point.
  std::vector<Vec2> apply(double t, const std::vector<Vec2>& points) const;
  std::vector<Vec2> unapply(double t, const std::vector<Vec2>& points) const;
};

/// The similarity between two equally long vertex lists (#V by 2, vertex i
/// corresponding to vertex i): translation of the centroid, the
/// least-squares (Procrustes) rotation angle of the centred points, taken in
/// `direction` and with `extra_turns` whole turns added (counter-clockwise
/// positive), and the ratio of RMS radii as the scale (1 if either radius is
/// 0, as for a single point).
/// @throws InvalidArgumentError for lists of different lengths, empty lists
///         or |extra_turns| > kMaxExtraTurns.
SimilarityMotion fit_similarity(const std::vector<Vec2>& source, const std::vector<Vec2>& target,
                                RotationDirection direction = RotationDirection::Short, int extra_turns = 0);

}  // namespace stickmorph
