// internal::spiderweb_mesh and internal::triangulate_checked (paper,
// sections 4.1-4.2): one polygon pair triangulated by a spiderweb.
#include "catch.h"

#include "stickmorph/errors.h"
#include "stickmorph/internal/spiderweb_triangulation.h"
#include "stickmorph/polygon_triangulation.h"
#include "stickmorph/verification.h"

using namespace stickmorph;
using namespace stickmorph::internal;
using stickmorph_test::Contains;

namespace {

const PolygonPair kRhombi{{0, 1, 2, 3},
                          {{-3, 0}, {0, -1}, {3, 0}, {0, 1}},
                          {{-1, 0}, {0, -3}, {1, 0}, {0, 3}}};

CompatibleMesh mesh_by(const PolygonPair& pair, SteinerMethod method, int& spiderweb_steiner) {
  CompatibleTriangulationOptions options;
  options.method = method;
  return spiderweb_mesh(pair, triangulate_polygon(pair.source()), triangulate_polygon(pair.target()), options,
                        spiderweb_steiner);
}

// The public form, for the exact verifier.
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

TEST_CASE("spiderweb_mesh Sg2001 of two rhombi: the center and one level at two corners", "[spiderweb_triangulation]") {
  int spiderweb_steiner = 0;
  const CompatibleMesh mesh = mesh_by(kRhombi, SteinerMethod::Sg2001, spiderweb_steiner);
  // Each polygon's triangulation puts one corner at depth 1, a different one
  // in each whichever center is taken: depths sum to 2, plus the center.
  CHECK(spiderweb_steiner == 3);
  CHECK(mesh.source.size() == 7);
  CHECK(as_result(mesh).triangles.size() == 2 * 7 - 4 - 2);  // a triangulated disk
  CHECK_NOTHROW(verify_compatible_triangulation(kRhombi, as_result(mesh)));
}

TEST_CASE("spiderweb_mesh Aronov of two rhombi: one complete layer", "[spiderweb_triangulation]") {
  int spiderweb_steiner = 0;
  const CompatibleMesh mesh = mesh_by(kRhombi, SteinerMethod::Aronov, spiderweb_steiner);
  // ceil((4 - 5) / 2) = 0 layers, raised to the deepest milestone, 1: a
  // path vertex at every corner, plus the center.
  CHECK(spiderweb_steiner == 5);
  CHECK(mesh.source.size() == 9);
  CHECK(as_result(mesh).triangles.size() == 2 * 9 - 4 - 2);
  CHECK_NOTHROW(verify_compatible_triangulation(kRhombi, as_result(mesh)));
}

TEST_CASE("spiderweb_mesh Improved removes redundant vertices from the Sg2001 web", "[spiderweb_triangulation]") {
  int spiderweb_steiner = 0;
  const CompatibleMesh mesh = mesh_by(kRhombi, SteinerMethod::Improved, spiderweb_steiner);
  CHECK(spiderweb_steiner == 3);  // counted before removal
  CHECK(mesh.source.size() < 7);
  CHECK_NOTHROW(verify_compatible_triangulation(kRhombi, as_result(mesh)));
  // The spiderweb count accumulates over calls (one per piece).
  mesh_by(kRhombi, SteinerMethod::Sg2001, spiderweb_steiner);
  CHECK(spiderweb_steiner == 6);
}

TEST_CASE("triangulate_checked names the face and the side of a bad polygon", "[spiderweb_triangulation]") {
  const CornerPolygon clockwise{{0, 1, 2}, {{0, 0}, {0, 1}, {1, 0}}};
  CHECK_THROWS_WITH(triangulate_checked(clockwise, "face 3", true), Contains("face 3 in the target"));
  CHECK_THROWS_AS(triangulate_checked(clockwise, "face 3", false), InvalidFigureError);
  CHECK(triangulate_checked(CornerPolygon{{0, 1, 2}, {{0, 0}, {1, 0}, {0, 1}}}, "face 3", false).size() == 1);
}
