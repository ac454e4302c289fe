#include "catch.h"

#include <cmath>
#include <limits>

#include "stickmorph/exact_predicates.h"

using namespace stickmorph;

TEST_CASE("orientation is exact on near-collinear points", "[exact_predicates]") {
  CHECK(orientation({0, 0}, {1, 0}, {0, 1}) == 1);
  CHECK(orientation({0, 0}, {0, 1}, {1, 0}) == -1);
  // Exactly collinear points that floating-point determinants get wrong.
  CHECK(orientation({0.5, 0.5}, {12, 12}, {24, 24}) == 0);
  const double above = std::nextafter(24.0, 25.0);
  CHECK(orientation({0.5, 0.5}, {12, 12}, {24, above}) == 1);
  CHECK(orientation({0.5, 0.5}, {12, 12}, {above, 24}) == -1);
  // 0.1 + 0.2 != 0.3 in doubles: these three are not collinear.
  CHECK(orientation({0, 0}, {0.1, 0.1}, {0.3, 0.1 + 0.2}) != 0);
}

TEST_CASE("compare_xy orders lexicographically", "[exact_predicates]") {
  CHECK(compare_xy({0, 1}, {1, 0}) == -1);
  CHECK(compare_xy({1, 0}, {1, 1}) == -1);
  CHECK(compare_xy({1, 1}, {1, 1}) == 0);
  CHECK(compare_xy({0.0, 0.0}, {-0.0, 0.0}) == 0);
}

TEST_CASE("compare_direction_ccw sorts a full turn from angle 0", "[exact_predicates]") {
  const Vec2 o{1, 1};
  // Directions at 0, 45, 90, ..., 315 degrees, in order.
  const std::vector<Vec2> around = {{2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}, {0, 0}, {1, 0}, {2, 0}};
  for (std::size_t i = 0; i < around.size(); ++i) {
    CHECK(compare_direction_ccw(o, around[i], around[i]) == 0);
    for (std::size_t j = i + 1; j < around.size(); ++j) {
      CHECK(compare_direction_ccw(o, around[i], around[j]) == -1);
      CHECK(compare_direction_ccw(o, around[j], around[i]) == 1);
    }
  }
  // Same direction at different distances.
  CHECK(compare_direction_ccw(o, {3, 3}, {2, 2}) == 0);
  // Just below the positive x axis comes last.
  CHECK(compare_direction_ccw(o, {2, std::nextafter(1.0, 0.0)}, {0, 0}) == 1);
}

TEST_CASE("on_segment is exact", "[exact_predicates]") {
  CHECK(on_segment({1, 1}, {0, 0}, {2, 2}));
  CHECK(on_segment({0, 0}, {0, 0}, {2, 2}));
  CHECK_FALSE(on_segment({3, 3}, {0, 0}, {2, 2}));
  CHECK_FALSE(on_segment({1, std::nextafter(1.0, 2.0)}, {0, 0}, {2, 2}));
}

TEST_CASE("segment_contact classifies every way two segments meet", "[exact_predicates]") {
  CHECK(segment_contact({0, 0}, {2, 2}, {0, 2}, {2, 0}) == SegmentContact::Crossing);
  CHECK(segment_contact({0, 0}, {1, 0}, {0, 1}, {1, 1}) == SegmentContact::Disjoint);
  CHECK(segment_contact({0, 0}, {2, 0}, {1, 0}, {1, 1}) == SegmentContact::Touching);
  CHECK(segment_contact({0, 0}, {2, 0}, {2, 0}, {3, 1}) == SegmentContact::Touching);
  CHECK(segment_contact({0, 0}, {2, 0}, {1, 0}, {3, 0}) == SegmentContact::Overlapping);
  CHECK(segment_contact({0, 0}, {2, 0}, {2, 0}, {3, 0}) == SegmentContact::Touching);
  CHECK(segment_contact({0, 0}, {1, 0}, {2, 0}, {3, 0}) == SegmentContact::Disjoint);
  CHECK(segment_contact({0, 0}, {4, 0}, {3, 0}, {1, 0}) == SegmentContact::Overlapping);
  // A vertical collinear pair (lexicographic order uses y).
  CHECK(segment_contact({0, 0}, {0, 2}, {0, 1}, {0, 3}) == SegmentContact::Overlapping);
  // Lines cross, segments stop short.
  CHECK(segment_contact({0, 0}, {1, 1}, {3, 0}, {2, 1}) == SegmentContact::Disjoint);
}

TEST_CASE("signed_area_sign is exact", "[exact_predicates]") {
  CHECK(signed_area_sign({{0, 0}, {1, 0}, {1, 1}, {0, 1}}) == 1);
  CHECK(signed_area_sign({{0, 0}, {0, 1}, {1, 1}, {1, 0}}) == -1);
  CHECK(signed_area_sign({{0, 0}, {1, 0}, {2, 0}, {1, 0}}) == 0);
  // A sliver whose area is far below double rounding of the large terms.
  const double big = 1e15;
  CHECK(signed_area_sign({{big, big}, {big + 2, big}, {big + 1, std::nextafter(big, 2 * big)}}) == 1);
}
