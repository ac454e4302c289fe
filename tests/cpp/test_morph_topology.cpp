// internal::build_topology and the position checks of the morph's input:
// a disk bounded by the enclosure, a closed fan round every other node.
#include "catch.h"

#include "stickmorph/errors.h"
#include "stickmorph/internal/morph_topology.h"

using namespace stickmorph;
using namespace stickmorph::internal;
using stickmorph_test::Contains;

namespace {

// Figure vertices 0 and 1 inside the square enclosure 2..5, six triangles.
FigureTriangulation edge_in_square() {
  FigureTriangulation tri;
  tri.figure_vertices = 2;
  tri.enclosure_vertices = 4;
  tri.source = {{-0.5, 0}, {0.5, 0}, {-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  tri.target = {{-0.5, 0.5}, {0.5, -0.5}, {-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  tri.triangles = {{2, 3, 1}, {2, 1, 0}, {3, 4, 1}, {4, 5, 0}, {4, 0, 1}, {5, 2, 0}};
  return tri;
}

}  // namespace

TEST_CASE("build_topology: the fans round the interior nodes", "[morph_topology]") {
  const Topology topo = build_topology(edge_in_square());
  CHECK(topo.nodes == 6);
  CHECK(topo.interior_nodes == std::vector<int>{0, 1});
  CHECK(topo.unknown == std::vector<int>{0, 1, -1, -1, -1, -1});
  // Counter-clockwise, from the first neighbour of the first triangle at the node.
  CHECK(topo.ring[0] == std::vector<int>{2, 1, 4, 5});
  CHECK(topo.ring[1] == std::vector<int>{2, 3, 4, 0});
  for (int v = 2; v < 6; ++v) CHECK(topo.ring[v].empty());
}

TEST_CASE("build_topology refuses what is not a disk bounded by the enclosure", "[morph_topology]") {
  FigureTriangulation hole = edge_in_square();
  hole.triangles.erase(hole.triangles.begin() + 4);  // (4, 0, 1)
  CHECK_THROWS_WITH(build_topology(hole), Contains("borders only"));

  FigureTriangulation doubled = edge_in_square();
  doubled.triangles.push_back({2, 3, 1});
  CHECK_THROWS_WITH(build_topology(doubled), Contains("they overlap"));

  FigureTriangulation outside = edge_in_square();
  outside.triangles.push_back({3, 2, 4});  // on the far side of the enclosure side 2-3
  CHECK_THROWS_WITH(build_topology(outside), Contains("outside the enclosure side"));

  FigureTriangulation short_positions = edge_in_square();
  short_positions.target.pop_back();
  CHECK_THROWS_AS(build_topology(short_positions), InvalidArgumentError);
}

TEST_CASE("first_non_positive and require_enclosure check positions exactly", "[morph_topology]") {
  const FigureTriangulation tri = edge_in_square();
  CHECK(first_non_positive(tri, tri.source) == -1);
  CHECK(first_non_positive(tri, tri.target) == -1);
  std::vector<Vec2> crossed = tri.source;
  crossed[1] = {-1, 0};  // node 1 moved past node 0: triangle 1 flips
  CHECK(first_non_positive(tri, crossed) == 1);
  CHECK_THROWS_WITH(require_positive(tri, crossed, "target"),
                    Contains("triangle 1 (2, 1, 0) is not counter-clockwise in the target"));
  CHECK_NOTHROW(require_enclosure(tri));
  FigureTriangulation moved = tri;
  moved.target[4] = {2, 2.5};
  CHECK_THROWS_WITH(require_enclosure(moved), Contains("node 4 (enclosure vertex 2) moves"));
  FigureTriangulation concave = tri;
  concave.source[4] = concave.target[4] = {0, -1.5};  // a reflex corner
  CHECK_THROWS_WITH(require_enclosure(concave), Contains("not strictly convex"));
}
