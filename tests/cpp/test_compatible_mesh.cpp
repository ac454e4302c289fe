// internal::CompatibleMesh operations: stars, links, edge identity by
// figure vertex, smallest angle.
#include "catch.h"

#include <cmath>

#include "stickmorph/internal/compatible_mesh.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

CompatibleMesh square_fan() {
  CompatibleMesh mesh;
  mesh.corners = 4;
  mesh.source = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, 0}};
  mesh.target = mesh.source;
  mesh.triangles = {{4, 0, 1}, {1, 2, 4}, {4, 2, 3}, {0, 4, 3}};
  mesh.alive.assign(4, 1);
  return mesh;
}

}  // namespace

TEST_CASE("triangles_around lists the live triangles of each node", "[compatible_mesh]") {
  CompatibleMesh mesh = square_fan();
  mesh.alive[2] = 0;
  const auto around = triangles_around(mesh);
  REQUIRE(around.size() == 5);
  CHECK(around[4] == std::vector<int>{0, 1, 3});
  CHECK(around[0] == std::vector<int>{0, 3});
  CHECK(around[3] == std::vector<int>{3});
}

TEST_CASE("link_of is the closed fan's neighbours counter-clockwise", "[compatible_mesh]") {
  const CompatibleMesh mesh = square_fan();
  // Whatever the order of the triangles and of each one's corners, the
  // link starts at the smallest neighbour and turns counter-clockwise.
  CHECK(link_of(mesh, {3, 1, 0, 2}, 4) == std::vector<int>{0, 1, 2, 3});
  // With a triangle missing the fan is open: no link.
  CHECK(link_of(mesh, {0, 1, 2}, 4).empty());
}

TEST_CASE("edge_key identifies corners at the same figure vertex", "[compatible_mesh]") {
  // Corners 0 and 2 are figure vertex 7 (a polygon round a dangling edge).
  const PolygonPair pair{{7, 8, 7, 9}, {}, {}};
  CHECK(node_key(pair, 4, 0) == node_key(pair, 4, 2));
  CHECK(edge_key(pair, 4, 1, 0) == edge_key(pair, 4, 2, 1));
  CHECK(edge_key(pair, 4, 0, 3) == std::pair<long, long>{7, 9});
  // Steiner vertices are their own: distinct from each other and from any vertex.
  CHECK(node_key(pair, 4, 4) != node_key(pair, 4, 5));
  CHECK(node_key(pair, 4, 4) < 0);
  CHECK(edge_key(pair, 4, 4, 0) == edge_key(pair, 4, 0, 4));
}

TEST_CASE("mesh_min_angle is the smallest angle over both polygons", "[compatible_mesh]") {
  CompatibleMesh mesh = square_fan();
  CHECK(mesh_min_angle(mesh) == Approx(0.25 * 3.14159265358979323846));  // right isosceles triangles
  // The target's centre moved to (0, 0.5): in triangle (4, 2, 3) the angles
  // at corners 2 and 3 are atan(0.5 / 1), the smallest of all.
  mesh.target[4] = {0, 0.5};
  CHECK(mesh_min_angle(mesh) == Approx(std::atan2(1.0, 2.0)));
  CHECK(positive(mesh.target, mesh.triangles[0]));
}
