#include "catch.h"

#include <set>

#include "figures.h"
#include "polygons.h"
#include "stickmorph/polygon_triangulation.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

CornerPolygon corner_polygon(const std::vector<Vec2>& points) {
  CornerPolygon p;
  for (int i = 0; i < int(points.size()); ++i) p.corners.push_back(i);
  p.positions = points;
  return p;
}

// Every triangle is counter-clockwise and every polygon edge is a side of
// exactly one triangle, with the triangle on its left.
void check_triangulation(const CornerPolygon& p, const std::vector<std::array<int, 3>>& tris) {
  REQUIRE(int(tris.size()) == p.size() - 2);
  std::set<std::pair<int, int>> sides;
  for (const auto& t : tris) {
    CHECK(orientation(p.at(t[0]), p.at(t[1]), p.at(t[2])) > 0);
    for (int j = 0; j < 3; ++j) CHECK(sides.emplace(t[j], t[(j + 1) % 3]).second);
  }
  for (int k = 0; k < p.size(); ++k) CHECK(sides.count({k, (k + 1) % p.size()}) == 1);
}

}  // namespace

TEST_CASE("triangulate_polygon covers simple polygons", "[triangulate_polygon]") {
  std::mt19937 rng(3);
  for (int round = 0; round < 40; ++round) {
    const CornerPolygon p = corner_polygon(round % 2 ? two_opt_polygon(rng, 5 + round) : star_polygon(rng, 5 + round, 0.5));
    check_triangulation(p, triangulate_polygon(p));
  }
  const CornerPolygon spiral = corner_polygon(spiral_polygon(40, 1.5));
  check_triangulation(spiral, triangulate_polygon(spiral));
}

TEST_CASE("triangulate_polygon handles repeated corners", "[triangulate_polygon]") {
  // A square whose face holds a Y-shaped tree hanging from corner 0: the
  // walk visits vertex 0 twice and the junction three times, and has two
  // 2*pi tips.
  const StickFigure f = figure({{0, 0}, {6, 0}, {6, 6}, {0, 6}, {2, 2}, {4, 2}, {2, 4}},
                               {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {4, 5}, {4, 6}});
  const PolygonPair pair = face_pair(f, f);
  const CornerPolygon p = pair.source();
  REQUIRE(p.size() == 10);
  const auto tris = triangulate_polygon(p);
  check_triangulation(p, tris);
  // Each corner has its own wedge: the tips are corners of several triangles.
  std::vector<int> count(p.size(), 0);
  for (const auto& t : tris)
    for (int c : t) ++count[c];
  for (int k = 0; k < p.size(); ++k) CHECK(count[k] >= 1);
}

TEST_CASE("triangulate_polygon rejects what is not a counter-clockwise weakly simple polygon", "[triangulate_polygon]") {
  std::vector<Vec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<Vec2> clockwise(square.rbegin(), square.rend());
  CHECK_THROWS_AS(triangulate_polygon(corner_polygon(clockwise)), InvalidFigureError);
  CHECK_THROWS_WITH(triangulate_polygon(corner_polygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}})),
                    Contains("cross") && Contains("corner 0"));
  CHECK_THROWS_AS(triangulate_polygon(corner_polygon({{0, 0}, {1, 0}})), InvalidFigureError);
}

TEST_CASE("dual_tree_depths finds the center by peeling leaves", "[dual_tree_depths]") {
  std::mt19937 rng(11);
  for (int round = 0; round < 30; ++round) {
    const CornerPolygon p = corner_polygon(two_opt_polygon(rng, 6 + round));
    const auto tris = triangulate_polygon(p);
    for (int choice = 0; choice < 2; ++choice) {
      const PolygonTriangulation pt = dual_tree_depths(p, tris, choice);
      REQUIRE((pt.center_faces.size() == 1 || pt.center_faces.size() == 2));
      CHECK(pt.depth[pt.center] == 0);
      const int t_count = int(tris.size());
      int height = 0;
      for (int t = 0; t < t_count; ++t) {
        height = std::max(height, pt.depth[t]);
        if (t != pt.center) CHECK(pt.depth[t] == pt.depth[pt.parent[t]] + 1);
      }
      // The center of a tree minimises the height: (diameter + 1) / 2 at most.
      CHECK(2 * height <= t_count);
      for (int k = 0; k < p.size(); ++k) {
        int least = t_count;
        for (int t = 0; t < t_count; ++t)
          for (int c : tris[t])
            if (c == k) least = std::min(least, pt.depth[t]);
        CHECK(pt.milestone[k] == least);
        CHECK(pt.depth[pt.shallowest[k]] == least);
      }
    }
  }
}
