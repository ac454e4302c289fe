#include "catch.h"

#include "polygons.h"
#include "stickmorph/verification.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

// A square whose source and target differ, with one Steiner vertex joined to
// every corner.
struct Fixture {
  PolygonPair pair = polygon_pair({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{0, 0}, {3, 0}, {3, 1}, {0, 1}});
  CompatibleTriangulation tri;
  Fixture() {
    tri.corner_count = 4;
    tri.source_steiner = {{1, 1}};
    tri.target_steiner = {{1.5, 0.5}};
    tri.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  }
};

}  // namespace

TEST_CASE("a valid compatible triangulation passes", "[verify_compatible_triangulation]") {
  Fixture f;
  CHECK_NOTHROW(verify_compatible_triangulation(f.pair, f.tri));
  CHECK(is_valid(f.pair, f.tri));
  // Without the Steiner vertex: one diagonal.
  CompatibleTriangulation plain;
  plain.corner_count = 4;
  plain.triangles = {{0, 1, 2}, {0, 2, 3}};
  CHECK(is_valid(f.pair, plain));
}

TEST_CASE("an inverted or degenerate triangle is named", "[verify_compatible_triangulation]") {
  Fixture f;
  f.tri.target_steiner = {{4, 0.5}};  // outside the target rectangle
  CHECK_THROWS_WITH(verify_compatible_triangulation(f.pair, f.tri, "face 7"),
                    Contains("face 7") && Contains("inverted in the target") && Contains("Steiner vertex 0"));
  f.tri.target_steiner = {{3, 0.5}};  // on the target's right edge
  CHECK_THROWS_WITH(verify_compatible_triangulation(f.pair, f.tri), Contains("degenerate in the target"));
}

TEST_CASE("holes, overlaps and loose vertices are caught", "[verify_compatible_triangulation]") {
  Fixture f;
  SECTION("a missing triangle leaves a polygon edge uncovered") {
    f.tri.triangles.pop_back();
    CHECK_THROWS_WITH(verify_compatible_triangulation(f.pair, f.tri), Contains("is not a triangle side"));
  }
  SECTION("a triangle used twice") {
    f.tri.triangles.push_back(f.tri.triangles[0]);
    CHECK_THROWS_WITH(verify_compatible_triangulation(f.pair, f.tri), Contains("used by two triangles"));
  }
  SECTION("an unused Steiner vertex") {
    f.tri.source_steiner.push_back({0.5, 0.5});
    f.tri.target_steiner.push_back({0.5, 0.5});
    CHECK_THROWS_WITH(verify_compatible_triangulation(f.pair, f.tri), Contains("is in no triangle"));
  }
  SECTION("mismatched Steiner counts") {
    f.tri.target_steiner.push_back({0.5, 0.5});
    CHECK_THROWS_WITH(verify_compatible_triangulation(f.pair, f.tri), Contains("Steiner vertices"));
  }
  SECTION("a node that does not exist") {
    f.tri.triangles[0][2] = 9;
    CHECK_THROWS_WITH(verify_compatible_triangulation(f.pair, f.tri), Contains("does not exist"));
  }
  SECTION("triangles on the outer side of a polygon edge") {
    // Both diagonals' triangles: the square is covered twice.
    CompatibleTriangulation twice;
    twice.corner_count = 4;
    twice.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {1, 2, 3}};
    CHECK_FALSE(is_valid(f.pair, twice));
  }
}
