// internal::build_spiderweb and internal::enforce_tip_levels (paper, section
// 4.1): the spiderweb's connectivity for a given depth sequence.
#include "catch.h"

#include <algorithm>
#include <set>

#include "stickmorph/internal/spiderweb.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

// Every triangle of the web, fixed ones first, then both splits' first option.
std::vector<Triangle> first_split(const Spiderweb& web) {
  std::vector<Triangle> all = web.fixed;
  for (const auto& q : web.quads)
    for (const Triangle& t : q.option[0]) all.push_back(t);
  return all;
}

std::vector<int> iota(int n) {
  std::vector<int> v(n);
  for (int i = 0; i < n; ++i) v[i] = i;
  return v;
}

// A triangulated disk with V nodes and b boundary edges has 2V - b - 2
// triangles (Euler); the spiderweb's boundary is the polygon's n sides.
int disk_triangles(int nodes, int boundary) { return 2 * nodes - boundary - 2; }

}  // namespace

TEST_CASE("spiderweb of a triangle is the fan around the central vertex", "[spiderweb]") {
  const Spiderweb web = build_spiderweb({0, 0, 0}, iota(3));
  CHECK(web.corners == 3);
  CHECK(web.center == 3);
  CHECK(web.node_count == 4);
  CHECK(web.quads.empty());
  const std::vector<Triangle> expected{{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  CHECK(web.fixed == expected);
}

TEST_CASE("spiderweb with one complete layer: four ladders' top cells are quads", "[spiderweb]") {
  const Spiderweb web = build_spiderweb({1, 1, 1, 1}, iota(4));
  // 4 corners, the center, one path vertex per corner.
  CHECK(web.node_count == 9);
  for (int k = 0; k < 4; ++k) {
    REQUIRE(web.path[k].size() == 2);
    CHECK(web.path[k][0] == web.center);
    CHECK(web.path[k][1] == 5 + k);
    CHECK(web.at(k, 2) == k);  // level ℓ_k + 1 is the corner
  }
  // One central triangle per strip, one top cell (corner, corner, two path vertices) per strip.
  CHECK(web.fixed.size() == 4);
  CHECK(web.quads.size() == 4);
  CHECK(int(first_split(web).size()) == disk_triangles(9, 4));
  CHECK(web.quads[0].diagonal[0] == std::array<int, 2>{0, 6});
  CHECK(web.quads[0].diagonal[1] == std::array<int, 2>{1, 5});
}

TEST_CASE("spiderweb with mixed depths: shorter paths fan over longer ones", "[spiderweb]") {
  // Depths 2, 1, 0, 1: V = 4 corners + center + 4 path vertices = 9, and
  // no strip has two equal depths above 0 or a ladder, so no choice.
  const Spiderweb web = build_spiderweb({2, 1, 0, 1}, iota(4));
  CHECK(web.node_count == 9);
  CHECK(web.quads.empty());
  CHECK(int(web.fixed.size()) == disk_triangles(9, 4));  // 12
  // Corner 2 has depth 0: its path is the center alone, and the strip to
  // corner 3 fans from corner 2 over corner 3's path.
  CHECK(web.path[2] == std::vector<int>{web.center});
  CHECK(std::count(web.fixed.begin(), web.fixed.end(), Triangle{2, 3, web.path[3][1]}) == 1);
  CHECK(std::count(web.fixed.begin(), web.fixed.end(), Triangle{2, web.path[3][1], web.center}) == 1);
}

TEST_CASE("spiderweb ladders: two equal deep paths make a ladder of quads", "[spiderweb]") {
  // Depths 3 everywhere in a triangle: per strip 1 central triangle, 2
  // ladder cells and 1 top cell.
  const Spiderweb web = build_spiderweb({3, 3, 3}, iota(3));
  CHECK(web.node_count == 3 + 1 + 9);
  CHECK(web.fixed.size() == 3);
  CHECK(web.quads.size() == 9);
  CHECK(int(first_split(web).size()) == disk_triangles(13, 3));
}

TEST_CASE("spiderweb at the tip of a dangling edge splits away from the tip", "[spiderweb]") {
  // Corners 0..3 at vertices 0, 1, 0, 2: the polygon round two dangling
  // edges from vertex 0, with tips at corners 1 and 3 (both neighbours of
  // each are vertex 0). Every strip is next to a tip, so no cell is left
  // to choose: per strip the central triangle and the top cell's two.
  const Spiderweb web = build_spiderweb({1, 1, 1, 1}, {0, 1, 0, 2});
  CHECK(web.node_count == 9);
  CHECK(web.quads.empty());
  CHECK(int(web.fixed.size()) == disk_triangles(9, 4));  // 12
  // A tip's first path edge (the tip to its level-1 vertex) must not be in
  // a triangle with corner 0 or corner 2 (vertex 0 on both sides would be
  // the same triangle twice, with opposite orientations).
  for (int tip : {1, 3}) {
    const int p = web.path[tip][1];
    int triangles_on_edge = 0;
    for (const Triangle& t : web.fixed) {
      if (!std::count(t.begin(), t.end(), tip) || !std::count(t.begin(), t.end(), p)) continue;
      ++triangles_on_edge;
      CHECK((std::count(t.begin(), t.end(), 0) + std::count(t.begin(), t.end(), 2)) == 0);
    }
    CHECK(triangles_on_edge == 2);
  }
  // Without the tips (four distinct vertices) the same depths leave four
  // top cells to choose.
  CHECK(build_spiderweb({1, 1, 1, 1}, {0, 1, 2, 3}).quads.size() == 4);
}

TEST_CASE("enforce_tip_levels lengthens a neighbour of a tip deeper than both", "[spiderweb]") {
  PolygonPair pair;
  pair.corners = {0, 1, 0, 2};
  std::vector<int> level{0, 2, 0, 0};
  enforce_tip_levels(pair, level);
  CHECK(level == std::vector<int>{0, 2, 2, 0});
  // Not a tip: nothing changes.
  pair.corners = {0, 1, 2, 3};
  level = {0, 2, 0, 0};
  enforce_tip_levels(pair, level);
  CHECK(level == std::vector<int>{0, 2, 0, 0});
}
