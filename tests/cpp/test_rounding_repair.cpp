// internal::star_kernel_middle and internal::untangle: moving a rounded
// Steiner vertex back into the kernel of its star (keeps section 4.1's
// embedding valid in floating point).
#include "catch.h"

#include "stickmorph/internal/rounding_repair.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

const std::vector<Triangle> kSquareFan = {{4, 0, 1}, {4, 1, 2}, {4, 2, 3}, {4, 3, 0}};

std::vector<Vec2> square_with(const Vec2& steiner) { return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, steiner}; }

}  // namespace

TEST_CASE("kernel of a convex star is the link polygon, its middle the link's centroid", "[rounding_repair]") {
  const std::vector<Vec2> pos = square_with({0.25, 0.5});
  // Relative to the origin given: the square's centre (0, 0) minus origin.
  const std::optional<Vec2> middle = star_kernel_middle(pos, kSquareFan, 4, pos[4]);
  REQUIRE(middle);
  CHECK((*middle)[0] == -0.25);
  CHECK((*middle)[1] == -0.5);
}

TEST_CASE("kernel of an impossible star is empty", "[rounding_repair]") {
  // The link is the square traversed clockwise: every triangle of the star
  // asks for the outside of one side, and no point is outside all four.
  const std::vector<Triangle> clockwise = {{4, 1, 0}, {4, 2, 1}, {4, 3, 2}, {4, 0, 3}};
  CHECK_FALSE(star_kernel_middle(square_with({0, 0}), clockwise, 4, {0, 0}));
}

TEST_CASE("untangle moves an inverted Steiner vertex to its kernel's middle", "[rounding_repair]") {
  // (1.5, 0) is beyond the side 1-2: triangle (4, 1, 2) is inverted.
  std::vector<Vec2> pos = square_with({1.5, 0});
  CHECK(untangle(pos, kSquareFan, 4));
  CHECK(pos[4] == Vec2{0, 0});
  for (int k = 0; k < 4; ++k) CHECK(pos[k] == square_with({0, 0})[k]);  // corners are fixed
}

TEST_CASE("untangle leaves a valid embedding untouched", "[rounding_repair]") {
  std::vector<Vec2> pos = square_with({0.9, -0.8});
  CHECK(untangle(pos, kSquareFan, 4));
  CHECK(pos[4] == Vec2{0.9, -0.8});
}

TEST_CASE("untangle cannot move corners", "[rounding_repair]") {
  // A clockwise triangle of corners only: nothing may move, so it fails.
  std::vector<Vec2> pos = {{0, 0}, {1, 0}, {0, 1}};
  CHECK_FALSE(untangle(pos, {{0, 2, 1}}, 3));
  CHECK(pos == std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}});
}
