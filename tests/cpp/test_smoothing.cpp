// internal::smooth (paper, section 4.2): Laplacian smoothing of one
// polygon's Steiner vertices, keeping positivity and the smallest angle.
#include "catch.h"

#include "stickmorph/internal/smoothing.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

// The square (-1,-1)..(1,1) with one Steiner vertex joined to its corners.
CompatibleMesh square_fan(const Vec2& source_steiner, const Vec2& target_steiner) {
  CompatibleMesh mesh;
  mesh.corners = 4;
  mesh.source = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, source_steiner};
  mesh.target = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, target_steiner};
  mesh.triangles = {{4, 0, 1}, {4, 1, 2}, {4, 2, 3}, {4, 3, 0}};
  mesh.alive.assign(4, 1);
  return mesh;
}

}  // namespace

TEST_CASE("smoothing moves a Steiner vertex to the mean of its neighbours", "[smoothing]") {
  CompatibleMesh mesh = square_fan({0.5, 0.2}, {0.5, 0.2});
  smooth(mesh, false, 1);
  // The full step lands on (0, 0): all four triangles positive and the
  // smallest angle there (45 degrees) larger than before.
  CHECK(mesh.source[4] == Vec2{0, 0});
  // Only the source moves; corners never do.
  CHECK(mesh.target[4] == Vec2{0.5, 0.2});
  for (int k = 0; k < 4; ++k) CHECK(mesh.source[k] == mesh.target[k]);
  CHECK(mesh_min_angle(mesh) < 0.7);  // the target keeps its thinner angles

  smooth(mesh, true, 1);
  CHECK(mesh.target[4] == Vec2{0, 0});
  CHECK(mesh_min_angle(mesh) == Approx(0.25 * 3.14159265358979323846));
}

TEST_CASE("smoothing with zero rounds changes nothing", "[smoothing]") {
  CompatibleMesh mesh = square_fan({0.5, 0.2}, {-0.3, 0.1});
  smooth(mesh, false, 0);
  smooth(mesh, true, 0);
  CHECK(mesh.source[4] == Vec2{0.5, 0.2});
  CHECK(mesh.target[4] == Vec2{-0.3, 0.1});
}

TEST_CASE("smoothing refuses a move that would invert a triangle", "[smoothing]") {
  // A deep dart: corner 0 pushed in to (0.9, 0.9), so the kernel of the
  // vertex's star is a small region near (0.95, 0.95). The mean of the
  // corners, (0.475, 0.475), and the half and quarter steps towards it from
  // (0.95, 0.93) are all below the line from corner 3 to corner 0, which
  // would invert triangle (4, 3, 0): the vertex stays.
  CompatibleMesh mesh = square_fan({0.95, 0.93}, {0.95, 0.93});
  mesh.source[0] = mesh.target[0] = {0.9, 0.9};
  for (const Triangle& t : mesh.triangles) REQUIRE(positive(mesh.source, t));
  smooth(mesh, false, 3);
  CHECK(mesh.source[4] == Vec2{0.95, 0.93});
}
