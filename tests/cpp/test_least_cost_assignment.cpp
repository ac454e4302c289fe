// internal::least_cost_assignment (least_cost_assignment.h): the Hungarian
// method that pairs the parts of two figures.
#include "catch.h"

#include "stickmorph/internal/least_cost_assignment.h"

using namespace stickmorph::internal;

TEST_CASE("least_cost_assignment finds the assignment of least total cost", "[least_cost_assignment]") {
  // Greedy by row would take 1 then 0 then 2 (1 + 2 + 2 = 5) as well; the
  // second matrix needs the global optimum.
  CHECK(least_cost_assignment({{4, 1, 3}, {2, 0, 5}, {3, 2, 2}}) == std::vector<int>{1, 0, 2});
  CHECK(least_cost_assignment({{1, 2}, {1, 100}}) == std::vector<int>{1, 0});
  CHECK(least_cost_assignment({{7}}) == std::vector<int>{0});
  CHECK(least_cost_assignment({}).empty());
}

TEST_CASE("least_cost_assignment avoids a barred pairing where it can", "[least_cost_assignment]") {
  constexpr double kBarred = 1e12;
  CHECK(least_cost_assignment({{0, kBarred, kBarred}, {kBarred, kBarred, 0}, {kBarred, 0, 3}}) ==
        std::vector<int>{0, 2, 1});
}
