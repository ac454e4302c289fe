// internal::piecewise_mesh: the Improved method's recursion, cutting along
// shared diagonals before any spiderweb.
#include "catch.h"

#include <algorithm>

#include "stickmorph/internal/piecewise_triangulation.h"
#include "stickmorph/polygon_triangulation.h"
#include "stickmorph/verification.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

CompatibleMesh piecewise(const PolygonPair& pair, int& spiderweb_steiner) {
  CompatibleTriangulationOptions options;
  return piecewise_mesh(pair, triangulate_polygon(pair.source()), triangulate_polygon(pair.target()), options,
                        spiderweb_steiner);
}

CompatibleTriangulation as_result(const CompatibleMesh& mesh) {
  CompatibleTriangulation result;
  result.corner_count = mesh.corners;
  result.source_steiner.assign(mesh.source.begin() + mesh.corners, mesh.source.end());
  result.target_steiner.assign(mesh.target.begin() + mesh.corners, mesh.target.end());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (mesh.alive[t]) result.triangles.push_back(mesh.triangles[t]);
  return result;
}

}  // namespace

TEST_CASE("piecewise_mesh of two rhombi: one shared diagonal, no Steiner vertex", "[piecewise_triangulation]") {
  const PolygonPair rhombi{{0, 1, 2, 3},
                           {{-3, 0}, {0, -1}, {3, 0}, {0, 1}},
                           {{-1, 0}, {0, -3}, {1, 0}, {0, 3}}};
  int spiderweb_steiner = 0;
  const CompatibleMesh mesh = piecewise(rhombi, spiderweb_steiner);
  CHECK(spiderweb_steiner == 0);  // no spiderweb was built
  CHECK(mesh.source.size() == 4);
  std::vector<Triangle> triangles = mesh.triangles;
  std::sort(triangles.begin(), triangles.end());
  CHECK(triangles == std::vector<Triangle>{{0, 1, 3}, {1, 2, 3}});  // cut along the source's diagonal 1-3
  CHECK_NOTHROW(verify_compatible_triangulation(rhombi, as_result(mesh)));
}

TEST_CASE("piecewise_mesh of identical hexagons: every diagonal shared", "[piecewise_triangulation]") {
  const std::vector<Vec2> hexagon = {{0, 0}, {2, 0}, {3, 1}, {2, 2}, {0, 2}, {-1, 1}};
  const PolygonPair pair{{0, 1, 2, 3, 4, 5}, hexagon, hexagon};
  int spiderweb_steiner = 0;
  const CompatibleMesh mesh = piecewise(pair, spiderweb_steiner);
  CHECK(spiderweb_steiner == 0);
  CHECK(mesh.source.size() == 6);
  CHECK(mesh.triangles.size() == 4);
  CHECK_NOTHROW(verify_compatible_triangulation(pair, as_result(mesh)));
}

TEST_CASE("piecewise_mesh of two darts: no shared diagonal, a spiderweb is needed", "[piecewise_triangulation]") {
  // Reflex at corner 0 in the source (only diagonal 0-2), at corner 1 in
  // the target (only 1-3): no triangulation without Steiner vertices is
  // compatible, so at least one must remain.
  const PolygonPair darts{{0, 1, 2, 3},
                          {{0.3, 0.3}, {1, -1}, {1, 1}, {-1, 1}},
                          {{-1, -1}, {-0.3, 0.3}, {1, 1}, {-1, 1}}};
  int spiderweb_steiner = 0;
  const CompatibleMesh mesh = piecewise(darts, spiderweb_steiner);
  CHECK(spiderweb_steiner == 3);  // the center and one level at two corners
  CHECK(mesh.source.size() >= 5);
  CHECK(mesh.source.size() <= 7);
  CHECK_NOTHROW(verify_compatible_triangulation(darts, as_result(mesh)));
}
