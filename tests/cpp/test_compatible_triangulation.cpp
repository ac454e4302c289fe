#include "catch.h"

#include "figures.h"
#include "polygons.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/verification.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

const SteinerMethod kMethods[] = {SteinerMethod::Aronov, SteinerMethod::Sg2001, SteinerMethod::Improved};

// Runs one method, checks the result exactly and its statistics, and returns
// the number of Steiner vertices.
int triangulate_checked(const PolygonPair& pair, SteinerMethod method) {
  CompatibleTriangulationOptions options;
  options.method = method;
  CompatibleTriangulationStats stats;
  const CompatibleTriangulation tri = compatible_triangulation(pair, options, &stats);
  INFO("method " << steiner_method_name(method) << ", " << pair.corners.size() << " corners");
  CHECK_NOTHROW(verify_compatible_triangulation(pair, tri));
  CHECK(stats.steiner_vertices == tri.steiner_count());
  CHECK(stats.spiderweb_steiner_vertices >= stats.steiner_vertices);
  CHECK(stats.min_angle_before_smoothing > 0);
  CHECK(stats.min_angle_after_smoothing >= stats.min_angle_before_smoothing);
  CHECK(min_angle(pair, tri) == Approx(stats.min_angle_after_smoothing));
  return tri.steiner_count();
}

std::array<int, 3> all_methods(const PolygonPair& pair) {
  return {triangulate_checked(pair, SteinerMethod::Aronov), triangulate_checked(pair, SteinerMethod::Sg2001),
          triangulate_checked(pair, SteinerMethod::Improved)};
}

}  // namespace

TEST_CASE("method names", "[compatible_triangulation]") {
  for (SteinerMethod m : kMethods) CHECK(parse_steiner_method(steiner_method_name(m)) == m);
  CHECK_THROWS_AS(parse_steiner_method("delaunay"), InvalidArgumentError);
  CHECK_THROWS_WITH(parse_steiner_method("delaunay"), Contains("aronov, sg2001 or improved"));
}

TEST_CASE("hand-made polygon pairs", "[compatible_triangulation]") {
  std::mt19937 rng(5);
  SECTION("a triangle needs nothing once redundancy is removed") {
    const auto counts = all_methods(polygon_pair({{0, 0}, {1, 0}, {0, 1}}, {{0, 0}, {5, 1}, {2, 3}}));
    CHECK(counts[2] == 0);
  }
  SECTION("convex to convex") { all_methods(polygon_pair(regular(9), counter_clockwise(star_polygon(rng, 9, 0.1)))); }
  SECTION("star-shaped to star-shaped") { all_methods(polygon_pair(star_polygon(rng, 24, 0.7), star_polygon(rng, 24, 0.7))); }
  SECTION("spiral to comb") { all_methods(polygon_pair(spiral_polygon(40, 1.75), comb_polygon(10, 3))); }
  SECTION("comb to spiral, and comb rotated by 90 and 180 degrees") {
    all_methods(polygon_pair(comb_polygon(8, 2), spiral_polygon(32, 1.25)));
    const auto comb = comb_polygon(6, 2);
    all_methods(polygon_pair(comb, rotated(comb, kTestPi / 2)));
    all_methods(polygon_pair(comb, rotated(comb, kTestPi)));
  }
  SECTION("a random polygon rotated by 180 degrees") {
    const auto p = two_opt_polygon(rng, 20);
    all_methods(polygon_pair(p, rotated(p, kTestPi)));
  }
}

TEST_CASE("faces with repeated corners and 2*pi angles", "[compatible_triangulation]") {
  SECTION("a Y-shaped tree hanging into a square") {
    const RawEdges edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {4, 5}, {4, 6}};
    const StickFigure s = figure({{0, 0}, {6, 0}, {6, 6}, {0, 6}, {2, 2}, {4, 2}, {2, 4}}, edges);
    const StickFigure t = figure({{0, 0}, {8, 1}, {7, 7}, {-1, 5}, {3, 2.5}, {6, 3}, {3, 5}}, edges);
    REQUIRE(check_compatibility(s, t).compatible());
    all_methods(face_pair(s, t));
  }
  SECTION("a triangle hanging from a square corner by one edge (cut vertices)") {
    const RawEdges edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {4, 5}, {5, 6}, {6, 4}};
    const StickFigure s = figure({{0, 0}, {6, 0}, {6, 6}, {0, 6}, {2, 2}, {4, 2}, {3, 4}}, edges);
    const StickFigure t = figure({{0, 0}, {8, 1}, {7, 7}, {-1, 5}, {3, 2.5}, {5, 3}, {4, 4.5}}, edges);
    REQUIRE(check_compatibility(s, t).compatible());
    for (int face = 0; face < 2; ++face) all_methods(face_pair(s, t, face));
  }
  SECTION("a spike whose tip turns round between source and target") {
    const RawEdges edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {1, 4}};
    const StickFigure s = figure({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 3}}, edges);
    const StickFigure t = figure({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {3.5, 3.5}}, edges);
    REQUIRE(check_compatibility(s, t).compatible());
    all_methods(face_pair(s, t));
  }
}

TEST_CASE("identical polygons need no Steiner vertex with the improved method", "[compatible_triangulation]") {
  std::mt19937 rng(17);
  for (int round = 0; round < 10; ++round) {
    const auto p = two_opt_polygon(rng, 8 + 4 * round);
    const PolygonPair pair = polygon_pair(p, p);
    CHECK(triangulate_checked(pair, SteinerMethod::Improved) == 0);
    CHECK(triangulate_checked(pair, SteinerMethod::Sg2001) > 0);
  }
}

TEST_CASE("a 38-corner pair like Figure 7: improved < sg2001 < aronov", "[compatible_triangulation]") {
  std::mt19937 rng(38);
  const PolygonPair pair = polygon_pair(two_opt_polygon(rng, 38), two_opt_polygon(rng, 38));
  const auto counts = all_methods(pair);
  CHECK(counts[2] < counts[1]);
  CHECK(counts[1] < counts[0]);
}

TEST_CASE("500 random polygon pairs with all three methods", "[compatible_triangulation][property]") {
  std::mt19937 rng(2001);
  long totals[3] = {0, 0, 0};
  for (int round = 0; round < 500; ++round) {
    const int n = 4 + round % 37;
    const PolygonPair pair = round % 3 == 0   ? polygon_pair(star_polygon(rng, n, 0.6), two_opt_polygon(rng, n))
                             : round % 3 == 1 ? polygon_pair(two_opt_polygon(rng, n), two_opt_polygon(rng, n))
                                              : polygon_pair(star_polygon(rng, n, 0.8), star_polygon(rng, n, 0.8));
    const auto counts = all_methods(pair);
    for (int m = 0; m < 3; ++m) totals[m] += counts[m];
  }
  CHECK(totals[2] < totals[1]);
  CHECK(totals[1] < totals[0]);
}
