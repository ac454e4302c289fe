// internal::embed_in_both (paper, section 4.1): the spiderweb embedded in
// both polygons, every triangle positive in both (exact).
#include "catch.h"

#include <algorithm>
#include <cmath>

#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/spiderweb_embedding.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

std::array<PolygonTriangulation, 2> dual_trees(const PolygonPair& pair) {
  return {dual_tree_depths(pair.source(), triangulate_polygon(pair.source()), 0),
          dual_tree_depths(pair.target(), triangulate_polygon(pair.target()), 0)};
}

std::vector<int> common_levels(const std::array<PolygonTriangulation, 2>& pts) {
  std::vector<int> level(pts[0].milestone.size());
  for (std::size_t k = 0; k < level.size(); ++k) level[k] = std::max(pts[0].milestone[k], pts[1].milestone[k]);
  return level;
}

void check_embedding(const PolygonPair& pair, const Spiderweb& web, const Placement& placement) {
  REQUIRE(placement.ok);
  CHECK(placement.failure.empty());
  REQUIRE(int(placement.source.size()) == web.node_count);
  REQUIRE(int(placement.target.size()) == web.node_count);
  // The fixed triangles and one split of each cell.
  CHECK(placement.triangles.size() == web.fixed.size() + 2 * web.quads.size());
  CHECK(std::equal(web.fixed.begin(), web.fixed.end(), placement.triangles.begin()));
  for (const Triangle& t : placement.triangles) {
    CHECK(orientation(placement.source[t[0]], placement.source[t[1]], placement.source[t[2]]) > 0);
    CHECK(orientation(placement.target[t[0]], placement.target[t[1]], placement.target[t[2]]) > 0);
  }
  for (int k = 0; k < web.corners; ++k) {
    CHECK(placement.source[k] == pair.source().at(k));
    CHECK(placement.target[k] == pair.target().at(k));
  }
}

}  // namespace

TEST_CASE("embedding of a triangle's spiderweb: the central vertex at each centroid", "[spiderweb_embedding]") {
  const PolygonPair pair{{0, 1, 2}, {{0, 0}, {3, 0}, {0, 3}}, {{0, 0}, {6, 0}, {3, 3}}};
  const auto pts = dual_trees(pair);
  const Spiderweb web = build_spiderweb(common_levels(pts), pair.corners);
  REQUIRE(web.node_count == 4);
  const Placement placement = embed_in_both(pair, pts, web);
  check_embedding(pair, web, placement);
  CHECK(placement.source[3] == Vec2{1, 1});
  CHECK(placement.target[3] == Vec2{3, 1});
}

TEST_CASE("embedding of two rhombi with different diagonals: redundant levels near corners",
          "[spiderweb_embedding]") {
  // Each rhombus's own triangulation puts one corner at depth 1; the other
  // polygon does not need that level (section 4.1's redundant vertices).
  const PolygonPair pair{{0, 1, 2, 3},
                         {{-3, 0}, {0, -1}, {3, 0}, {0, 1}},
                         {{-1, 0}, {0, -3}, {1, 0}, {0, 3}}};
  const auto pts = dual_trees(pair);
  const std::vector<int> level = common_levels(pts);
  int total = 0;
  for (int l : level) total += l;
  CHECK(total == 2);
  const Spiderweb web = build_spiderweb(level, pair.corners);
  CHECK(web.node_count == 4 + 1 + 2);
  const Placement placement = embed_in_both(pair, pts, web);
  check_embedding(pair, web, placement);
  // A level that a polygon does not need sits near its corner: within 0.45
  // times the distance to the nearest other node (at most 3 here), so
  // closer than 1 + a little; 1 is enough for these rhombi.
  for (int k = 0; k < 4; ++k)
    for (int side = 0; side < 2; ++side) {
      const PolygonTriangulation& pt = pts[side];
      for (int l = pt.milestone[k] + 1; l <= level[k]; ++l) {
        const Vec2 p = (side ? placement.target : placement.source)[web.path[k][l]];
        const Vec2 c = (side ? pair.target() : pair.source()).at(k);
        CHECK(std::hypot(p[0] - c[0], p[1] - c[1]) < 1.0);
      }
    }
}
