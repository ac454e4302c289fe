// internal::angle_between, angle_at, triangle_min_angle and kPi: the one
// angle formula of the engine (triangle_min_angle's one-atan2 shortcut
// checked against the three-atan2 formula).
#include "catch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

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

TEST_CASE("triangle_min_angle is the smallest of the three angle_at, bit for bit", "[geometry]") {
  // One atan2 after a trusted comparison, all three at a near tie: the same
  // value as the three-atan2 formula in every case, including the ties of
  // regular figures, thin caps and needles, and tiny or huge triangles.
  auto three = [](const Vec2& a, const Vec2& b, const Vec2& c) {
    return std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
  };
  std::vector<std::array<Vec2, 3>> cases = {
      {{{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}}},   // equilateral: three ties
      {{{0, 0}, {2, 0}, {1, 5}}},                       // isosceles: two ties
      {{{0, 0}, {1, 0}, {0.5, 1e-9}}},                  // a cap, two tiny angles nearly tied
      {{{0, 0}, {1, 0}, {0.3, 1e-12}}},                 // a cap, two tiny angles
      {{{0, 0}, {1e-9, 0}, {0.5, 3}}},                  // a needle
      {{{1e-150, 0}, {3e-150, 0}, {2e-150, 1e-150}}},   // tiny: products leave the normal range
      {{{1e150, 0}, {3e150, 0}, {2e150, 1e150}}},       // huge
      {{{0, 0}, {1, 0}, {2, 0}}},                       // flat
  };
  std::uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) / double(1ull << 53);
  };
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::pow(10.0, 8 * next() - 4);
    Vec2 a{next() * scale, next() * scale}, b{next() * scale, next() * scale}, c{next() * scale, next() * scale};
    if (i % 3 == 0) c = {0.5 * (a[0] + b[0]) + 1e-7 * scale * next(), 0.5 * (a[1] + b[1])};  // near-flat
    if (i % 5 == 0) c = {a[0] + (b[1] - a[1]), a[1] - (b[0] - a[0])};  // right isosceles
    cases.push_back({a, b, c});
  }
  for (const auto& t : cases) {
    const double fast = triangle_min_angle(t[0], t[1], t[2]);
    const double slow = three(t[0], t[1], t[2]);
    REQUIRE(std::memcmp(&fast, &slow, sizeof(double)) == 0);
  }
}
