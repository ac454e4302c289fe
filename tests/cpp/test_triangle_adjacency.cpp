// internal::TriangleAdjacency: stars and the triangle left of each side.
#include "catch.h"

#include "stickmorph/internal/triangle_adjacency.h"

using namespace stickmorph::internal;

namespace {

// The square 0..3 with centre 4, four triangles.
const std::vector<Triangle> kFan = {{4, 0, 1}, {4, 1, 2}, {4, 2, 3}, {4, 3, 0}};

}  // namespace

TEST_CASE("TriangleAdjacency: stars in triangle order", "[triangle_adjacency]") {
  const TriangleAdjacency adjacency(5, kFan);
  CHECK(adjacency.nodes() == 5);
  CHECK(adjacency.around(4) == std::vector<int>{0, 1, 2, 3});
  CHECK(adjacency.around(0) == std::vector<int>{0, 3});
  CHECK(adjacency.around(2) == std::vector<int>{1, 2});
  CHECK(adjacency.repeated_side().first == -1);
}

TEST_CASE("TriangleAdjacency: the triangle left of a directed side", "[triangle_adjacency]") {
  const TriangleAdjacency adjacency(5, kFan);
  CHECK(adjacency.left_of(0, 1) == 0);
  CHECK(adjacency.slot_of(0, 1) == 1);  // (4, 0, 1): from corner 1 to corner 2
  CHECK(adjacency.left_of(1, 0) == -1);  // outside the square
  CHECK(adjacency.left_of(4, 2) == 2);
  CHECK(adjacency.left_of(2, 4) == 1);
  CHECK(adjacency.left_of(0, 2) == -1);  // not an edge
}

TEST_CASE("TriangleAdjacency: dead triangles are left out, repeated sides reported", "[triangle_adjacency]") {
  const std::vector<char> alive{1, 0, 1, 1};
  const TriangleAdjacency without_second(5, kFan, alive);
  CHECK(without_second.around(4) == std::vector<int>{0, 2, 3});
  CHECK(without_second.left_of(1, 2) == -1);

  std::vector<Triangle> overlapping = kFan;
  overlapping.push_back({4, 1, 3});  // side 4 -> 1 again
  const TriangleAdjacency adjacency(5, overlapping);
  const auto& repeated = adjacency.repeated_side();
  CHECK(repeated.a == 4);
  CHECK(repeated.b == 1);
  CHECK(repeated.first == 1);
  CHECK(repeated.second == 4);
  CHECK(adjacency.left_of(4, 1) == 1);  // the first keeps the side
}
