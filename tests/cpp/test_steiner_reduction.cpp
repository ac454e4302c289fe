// internal::remove_redundant_steiner (paper, section 4.2): a Steiner vertex
// goes when its star can be re-triangulated positively in both polygons.
#include "catch.h"

#include <algorithm>

#include "stickmorph/internal/steiner_reduction.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

// The square (-1,-1)..(1,1) with corner 0 pushed in to (0.3, 0.3), past
// the diagonal 1-3: reflex at corner 0, so 0-2 is its only diagonal.
const std::vector<Vec2> kDartReflexAt0 = {{0.3, 0.3}, {1, -1}, {1, 1}, {-1, 1}};
// The same with corner 1 pushed in to (-0.3, 0.3), past the diagonal 0-2:
// 1-3 is its only diagonal.
const std::vector<Vec2> kDartReflexAt1 = {{-1, -1}, {-0.3, 0.3}, {1, 1}, {-1, 1}};

// Four corners and one Steiner vertex (node 4) joined to all of them.
CompatibleMesh fan(const std::vector<Vec2>& source, const Vec2& source_steiner, const std::vector<Vec2>& target,
                   const Vec2& target_steiner) {
  CompatibleMesh mesh;
  mesh.corners = 4;
  mesh.source = source;
  mesh.source.push_back(source_steiner);
  mesh.target = target;
  mesh.target.push_back(target_steiner);
  mesh.triangles = {{4, 0, 1}, {4, 1, 2}, {4, 2, 3}, {4, 3, 0}};
  mesh.alive.assign(4, 1);
  return mesh;
}

PolygonPair pair_of(const std::vector<Vec2>& source, const std::vector<Vec2>& target) {
  return {{0, 1, 2, 3}, source, target};
}

}  // namespace

TEST_CASE("reduction removes the Steiner vertex of a fan both darts can do without", "[steiner_reduction]") {
  // Both polygons are the dart with its reflex corner at 0; the vertex at
  // (0.7, 0.5) is in the kernel of its star in both.
  CompatibleMesh mesh = fan(kDartReflexAt0, {0.7, 0.5}, kDartReflexAt0, {0.7, 0.5});
  CHECK(remove_redundant_steiner(pair_of(kDartReflexAt0, kDartReflexAt0), mesh) == 1);
  CHECK(mesh.source == kDartReflexAt0);
  CHECK(mesh.target == kDartReflexAt0);
  // The link 0, 1, 2, 3 re-triangulated by the only diagonal, 0-2.
  const std::vector<Triangle> expected{{0, 2, 3}, {0, 1, 2}};
  CHECK(mesh.triangles == expected);
  CHECK(mesh.alive == std::vector<char>{1, 1});
}

TEST_CASE("reduction keeps a Steiner vertex when the polygons need different diagonals", "[steiner_reduction]") {
  // Source: only 0-2; target: only 1-3. No triangulation of the link is
  // positive in both, so the vertex is needed (section 4's quadrilateral).
  CompatibleMesh mesh = fan(kDartReflexAt0, {0.7, 0.5}, kDartReflexAt1, {-0.5, 0.7});
  const CompatibleMesh before = mesh;
  CHECK(remove_redundant_steiner(pair_of(kDartReflexAt0, kDartReflexAt1), mesh) == 0);
  CHECK(mesh.source == before.source);
  CHECK(mesh.target == before.target);
  CHECK(mesh.triangles == before.triangles);
}

TEST_CASE("reduction never doubles an edge through a repeated corner", "[steiner_reduction]") {
  // A square whose corners 0 and 2 are the same figure vertex (as in a
  // polygon round a dangling edge): the diagonal 0-2 would be a loop and
  // 1-3 is fine, so the vertex goes with 1-3.
  const std::vector<Vec2> square = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  CompatibleMesh mesh = fan(square, {0.1, 0.2}, square, {0.1, 0.2});
  PolygonPair pair{{0, 1, 0, 3}, {}, {}};
  CHECK(remove_redundant_steiner(pair, mesh) == 1);
  for (const Triangle& t : mesh.triangles) {
    CHECK(std::count(t.begin(), t.end(), 1) == 1);
    CHECK(std::count(t.begin(), t.end(), 3) == 1);
  }
}

TEST_CASE("reduction refuses new triangles thinner than kMinNewAngle", "[steiner_reduction]") {
  // A triangle with a Steiner vertex inside: removing it leaves the
  // triangle itself, kept only if its smallest angle is at least
  // kMinNewAngle (1e-6) in both polygons.
  auto three_fan = [](const Vec2& apex, const Vec2& steiner) {
    CompatibleMesh mesh;
    mesh.corners = 3;
    mesh.source = {{0, 0}, {2, 0}, apex, steiner};
    mesh.target = mesh.source;
    mesh.triangles = {{3, 0, 1}, {3, 1, 2}, {3, 2, 0}};
    mesh.alive.assign(3, 1);
    return mesh;
  };
  const PolygonPair pair{{0, 1, 2}, {}, {}};
  // Apex 1e-7 above the base: angles of about 1e-7 at both base corners.
  CompatibleMesh thin = three_fan({1, 1e-7}, {1, 3e-8});
  CHECK(remove_redundant_steiner(pair, thin) == 0);
  CHECK(thin.triangles.size() == 3);
  // Apex at height 1: the vertex goes and the triangle is what is left.
  CompatibleMesh fat = three_fan({1, 1}, {1, 0.3});
  CHECK(remove_redundant_steiner(pair, fat) == 1);
  CHECK(fat.triangles == std::vector<Triangle>{{0, 1, 2}});
  CHECK(fat.source.size() == 3);
}
