// fit_similarity and SimilarityMotion (issue 12; Surazhsky & Gotsman 2001,
// section 6's rotated enclosure, generalised): the best-fit rotation, uniform
// scale and translation of a morph, taken out before the compatible morph and
// interpolated back in.
#include "catch.h"

#include <cmath>
#include <vector>

#include "figures.h"
#include "motion_helpers.h"
#include "stickmorph/errors.h"
#include "stickmorph/similarity_motion.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180;

// An irregular figure away from the origin: a letter-like polyline with a
// junction, so that neither its centroid nor its fit is special.
const std::vector<Vec2> kPoints = {{1, 2}, {3, 2.5}, {4, 5}, {2.5, 6}, {0.5, 4.5}, {6, 1}, {5.5, -1}};

// x -> c + s R(angle) x, the similarity the tests know.
std::vector<Vec2> similar(const std::vector<Vec2>& points, double angle, double scale, const Vec2& shift) {
  std::vector<Vec2> out;
  const double c = scale * std::cos(angle), s = scale * std::sin(angle);
  for (const Vec2& p : points) out.push_back({c * p[0] - s * p[1] + shift[0], s * p[0] + c * p[1] + shift[1]});
  return out;
}




}  // namespace

TEST_CASE("fit_similarity recovers a known similarity", "[similarity_motion]") {
  const double angle = 0.7, scale = 1.3;
  const Vec2 shift{2, -3};
  const std::vector<Vec2> target = similar(kPoints, angle, scale, shift);
  const SimilarityMotion m = fit_similarity(kPoints, target);

  CHECK(m.angle == Approx(angle).margin(1e-12));
  CHECK(m.scale == Approx(scale).margin(1e-12));
  const Vec2 c0 = mean(kPoints), c1 = mean(target);
  CHECK(m.source_center[0] == Approx(c0[0]).margin(1e-12));
  CHECK(m.source_center[1] == Approx(c0[1]).margin(1e-12));
  CHECK(m.target_center[0] == Approx(c1[0]).margin(1e-12));
  CHECK(m.target_center[1] == Approx(c1[1]).margin(1e-12));
  // The translation: the source centroid's image is the target centroid.
  const std::vector<Vec2> image_of_center = similar({c0}, angle, scale, shift);
  CHECK(m.target_center[0] == Approx(image_of_center[0][0]).margin(1e-12));
  CHECK(m.target_center[1] == Approx(image_of_center[0][1]).margin(1e-12));
  CHECK_FALSE(m.is_identity());

  // The whole motion at t = 1 is the similarity.
  check_close(m.apply(1.0, kPoints), target, 1e-12);
}

TEST_CASE("SimilarityMotion::apply at 0 is the identity, bit for bit, and unapply inverts it", "[similarity_motion]") {
  const SimilarityMotion m = fit_similarity(kPoints, similar(kPoints, -2.1, 0.4, {-7, 11}));
  CHECK(m.apply(0.0, kPoints) == kPoints);
  for (const Vec2& p : kPoints) {
    CHECK(m.apply(0.0, p) == p);
    CHECK(m.unapply(0.0, p) == p);
  }
  for (double t : {0.1, 0.25, 0.5, 0.9, 1.0}) {
    for (const Vec2& p : kPoints) {
      const Vec2 there = m.apply(t, p);
      const Vec2 back = m.unapply(t, there);
      CHECK(back[0] == Approx(p[0]).margin(1e-12));
      CHECK(back[1] == Approx(p[1]).margin(1e-12));
      // and the other way round
      const Vec2 forth = m.apply(t, m.unapply(t, p));
      CHECK(forth[0] == Approx(p[0]).margin(1e-12));
      CHECK(forth[1] == Approx(p[1]).margin(1e-12));
    }
    // The vector version is the point version.
    const std::vector<Vec2> all = m.apply(t, kPoints);
    for (std::size_t v = 0; v < kPoints.size(); ++v) CHECK(all[v] == m.apply(t, kPoints[v]));
  }
}

TEST_CASE("SimilarityMotion interpolates: rotation at constant speed, scale geometric, centroid on a line",
          "[similarity_motion]") {
  const double angle = 1.2, scale = 4.0;
  const std::vector<Vec2> target = similar(kPoints, angle, scale, {3, 1});
  const SimilarityMotion m = fit_similarity(kPoints, target);
  REQUIRE(m.scale == Approx(4.0).margin(1e-12));
  const double r0 = rms_radius(kPoints);
  for (double t : {0.25, 0.5, 0.75}) {
    const std::vector<Vec2> frame = m.apply(t, kPoints);
    // Geometric: s^t, so at t = 0.5 the radius is sqrt(4) = 2 times the source's, not 2.5.
    CHECK(rms_radius(frame) == Approx(std::pow(scale, t) * r0).epsilon(1e-12));
    const Vec2 c = mean(frame);
    CHECK(c[0] == Approx((1 - t) * m.source_center[0] + t * m.target_center[0]).margin(1e-12));
    CHECK(c[1] == Approx((1 - t) * m.source_center[1] + t * m.target_center[1]).margin(1e-12));
    // The frame is the source turned by t * angle: the fit of the frame says so.
    const SimilarityMotion part = fit_similarity(kPoints, frame);
    CHECK(part.angle == Approx(t * angle).margin(1e-12));
    CHECK(part.scale == Approx(std::pow(scale, t)).epsilon(1e-12));
  }
  CHECK(rms_radius(m.apply(0.5, kPoints)) == Approx(2 * r0).epsilon(1e-12));
}

TEST_CASE("fit_similarity turns in the direction asked, with whole turns added", "[similarity_motion]") {
  // The target is the source turned by -100 degrees (and scaled, moved).
  const std::vector<Vec2> minus100 = similar(kPoints, -100 * kDegree, 0.8, {1, 1});
  CHECK(fit_similarity(kPoints, minus100).angle == Approx(-100 * kDegree).margin(1e-12));
  CHECK(fit_similarity(kPoints, minus100, RotationDirection::Short).angle == Approx(-100 * kDegree).margin(1e-12));
  CHECK(fit_similarity(kPoints, minus100, RotationDirection::CounterClockwise).angle ==
        Approx(260 * kDegree).margin(1e-12));
  CHECK(fit_similarity(kPoints, minus100, RotationDirection::Clockwise).angle == Approx(-100 * kDegree).margin(1e-12));
  CHECK(fit_similarity(kPoints, minus100, RotationDirection::Short, 2).angle == Approx(620 * kDegree).margin(1e-12));
  CHECK(fit_similarity(kPoints, minus100, RotationDirection::CounterClockwise, 2).angle ==
        Approx(980 * kDegree).margin(1e-12));
  CHECK(fit_similarity(kPoints, minus100, RotationDirection::CounterClockwise, -1).angle ==
        Approx(-100 * kDegree).margin(1e-12));
  CHECK(fit_similarity(kPoints, minus100, RotationDirection::Clockwise, -3).angle ==
        Approx(-1180 * kDegree).margin(1e-12));

  // +100 degrees: short and ccw keep it, cw goes the long way.
  const std::vector<Vec2> plus100 = similar(kPoints, 100 * kDegree, 1.0, {0, 0});
  CHECK(fit_similarity(kPoints, plus100).angle == Approx(100 * kDegree).margin(1e-12));
  CHECK(fit_similarity(kPoints, plus100, RotationDirection::CounterClockwise).angle ==
        Approx(100 * kDegree).margin(1e-12));
  CHECK(fit_similarity(kPoints, plus100, RotationDirection::Clockwise).angle == Approx(-260 * kDegree).margin(1e-12));

  // Whatever the direction and turns, the motion ends on the target.
  for (RotationDirection d :
       {RotationDirection::Short, RotationDirection::CounterClockwise, RotationDirection::Clockwise})
    for (int turns : {-2, 0, 1})
      check_close(fit_similarity(kPoints, minus100, d, turns).apply(1.0, kPoints), minus100, 1e-11);
}

TEST_CASE("fit_similarity's ranges at the edges: a half turn, no turn", "[similarity_motion]") {
  // The exact half turn (negation) is +180 degrees: short is (-180, 180].
  std::vector<Vec2> negated;
  for (const Vec2& p : kPoints) negated.push_back({-p[0], -p[1]});
  CHECK(fit_similarity(kPoints, negated).angle == kPi);
  CHECK(fit_similarity(kPoints, negated, RotationDirection::CounterClockwise).angle == kPi);
  CHECK(fit_similarity(kPoints, negated, RotationDirection::Clockwise).angle == -kPi);
  // No rotation: 0 in every direction (ccw is [0, 360), cw (-360, 0]).
  const std::vector<Vec2> shifted = similar(kPoints, 0, 2, {5, 0});
  for (RotationDirection d :
       {RotationDirection::Short, RotationDirection::CounterClockwise, RotationDirection::Clockwise})
    CHECK(fit_similarity(kPoints, shifted, d).angle == 0);
  CHECK(fit_similarity(kPoints, shifted, RotationDirection::Short, -1).angle == -2 * kPi);
}

TEST_CASE("fit_similarity of a figure to itself is the identity", "[similarity_motion]") {
  const SimilarityMotion m = fit_similarity(kPoints, kPoints);
  CHECK(m.angle == 0);
  CHECK(m.scale == 1);
  CHECK(m.source_center == m.target_center);
  CHECK(m.is_identity());
  CHECK(SimilarityMotion{}.is_identity());
  // Extra turns are a motion even though the ends agree.
  CHECK_FALSE(fit_similarity(kPoints, kPoints, RotationDirection::Short, 1).is_identity());
}

TEST_CASE("fit_similarity of degenerate input has scale 1", "[similarity_motion]") {
  SECTION("a single point: a translation") {
    const SimilarityMotion m = fit_similarity({{1, 2}}, {{5, -6}});
    CHECK(m.scale == 1);
    CHECK(m.angle == 0);
    CHECK(m.source_center == Vec2{1, 2});
    CHECK(m.target_center == Vec2{5, -6});
    const Vec2 p = m.apply(1.0, Vec2{1, 2});
    CHECK(p[0] == Approx(5).margin(1e-12));
    CHECK(p[1] == Approx(-6).margin(1e-12));
    const Vec2 half = m.apply(0.5, Vec2{1, 2});
    CHECK(half[0] == Approx(3).margin(1e-12));
    CHECK(half[1] == Approx(-2).margin(1e-12));
  }
  SECTION("points that all coincide, on either side") {
    const std::vector<Vec2> same = {{2, 2}, {2, 2}, {2, 2}};
    const std::vector<Vec2> spread = {{0, 0}, {1, 0}, {0, 3}};
    CHECK(fit_similarity(same, spread).scale == 1);
    CHECK(fit_similarity(spread, same).scale == 1);
    CHECK(fit_similarity(same, same).scale == 1);
    CHECK(std::isfinite(fit_similarity(same, spread).angle));
    CHECK(fit_similarity(same, same).angle == 0);
  }
}

TEST_CASE("fit_similarity refuses unequal or empty lists and too many turns", "[similarity_motion]") {
  const std::vector<Vec2> two = {{0, 0}, {1, 0}}, three = {{0, 0}, {1, 0}, {0, 1}};
  CHECK_THROWS_AS(fit_similarity(two, three), InvalidArgumentError);
  CHECK_THROWS_WITH(fit_similarity(two, three), Contains("the source has 2 points and the target 3"));
  CHECK_THROWS_AS(fit_similarity({}, {}), InvalidArgumentError);
  CHECK_THROWS_WITH(fit_similarity({}, {}), Contains("no points"));
  CHECK_THROWS_AS(fit_similarity(two, two, RotationDirection::Short, kMaxExtraTurns + 1), InvalidArgumentError);
  CHECK_THROWS_WITH(fit_similarity(two, two, RotationDirection::Short, kMaxExtraTurns + 1),
                    Contains("extra turns must be in [-100, 100], got 101"));
  CHECK_THROWS_AS(fit_similarity(two, two, RotationDirection::Clockwise, -kMaxExtraTurns - 1), InvalidArgumentError);
  CHECK(kMaxExtraTurns == 100);
  CHECK(fit_similarity(two, two, RotationDirection::Short, kMaxExtraTurns).angle ==
        Approx(2 * kPi * kMaxExtraTurns).epsilon(1e-15));
  CHECK(fit_similarity(two, two, RotationDirection::Short, -kMaxExtraTurns).angle ==
        Approx(-2 * kPi * kMaxExtraTurns).epsilon(1e-15));
}

TEST_CASE("parse_rotation_direction and rotation_direction_name round trip", "[similarity_motion]") {
  CHECK(parse_rotation_direction("short") == RotationDirection::Short);
  CHECK(parse_rotation_direction("ccw") == RotationDirection::CounterClockwise);
  CHECK(parse_rotation_direction("cw") == RotationDirection::Clockwise);
  for (RotationDirection d :
       {RotationDirection::Short, RotationDirection::CounterClockwise, RotationDirection::Clockwise})
    CHECK(parse_rotation_direction(rotation_direction_name(d)) == d);
  CHECK(rotation_direction_name(RotationDirection::CounterClockwise) == "ccw");
  CHECK_THROWS_AS(parse_rotation_direction("up"), InvalidArgumentError);
  CHECK_THROWS_WITH(parse_rotation_direction("up"), "unknown rotation direction 'up' (choose short, ccw or cw)");
  CHECK_THROWS_AS(parse_rotation_direction("CCW"), InvalidArgumentError);  // names are lower case
  CHECK_THROWS_AS(parse_rotation_direction(""), InvalidArgumentError);
}
