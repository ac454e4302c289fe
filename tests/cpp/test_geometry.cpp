// internal::angle_between, angle_at, triangle_min_angle and kPi: the one
// angle formula of the engine.
#include "catch.h"

#include <cmath>

#include "stickmorph/internal/geometry.h"

using namespace stickmorph;
using namespace stickmorph::internal;

TEST_CASE("angle_between: right, straight and zero angles exactly", "[geometry]") {
  CHECK(angle_between(1, 0, 0, 1) == kPi / 2);
  CHECK(angle_between(0, 3, 2, 0) == kPi / 2);  // unsigned: clockwise pairs too
  CHECK(angle_between(1, 0, -1, 0) == kPi);
  CHECK(angle_between(2, 2, 1, 1) == 0);
  CHECK(kPi == std::acos(-1.0));
}

TEST_CASE("angle_between keeps tiny angles that acos would lose", "[geometry]") {
  // The angle between (1, 0) and (1, 1e-20) is 1e-20 to within rounding;
  // acos of the normalised dot product gives exactly 0 there.
  CHECK(angle_between(1, 0, 1, 1e-20) == Approx(1e-20).epsilon(1e-12));
  CHECK(std::acos(1 / std::hypot(1.0, 1e-20)) == 0);
}

TEST_CASE("angle_at and triangle_min_angle", "[geometry]") {
  const Vec2 a{0, 0}, b{4, 0}, c{0, 3};
  CHECK(angle_at(a, b, c) == kPi / 2);
  CHECK(angle_at(b, c, a) == Approx(std::atan2(3.0, 4.0)));
  CHECK(triangle_min_angle(a, b, c) == Approx(std::atan2(3.0, 4.0)));
  // Equilateral: pi / 3 at every corner.
  CHECK(triangle_min_angle({0, 0}, {2, 0}, {1, std::sqrt(3.0)}) == Approx(kPi / 3));
  // Orientation does not matter: angles are unsigned.
  CHECK(triangle_min_angle(a, c, b) == triangle_min_angle(a, b, c));
}
