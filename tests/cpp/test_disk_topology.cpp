// internal::find_disk_defect: the combinatorial check that triangles form
// a disk with a given boundary, used by the compatible-triangulation
// verifier and by the morph.
#include "catch.h"

#include "stickmorph/internal/disk_topology.h"

using namespace stickmorph::internal;
using Kind = DiskDefect::Kind;

namespace {

// The square 0..3 (boundary, counter-clockwise) with centre 4.
const std::vector<Triangle> kFan = {{4, 0, 1}, {4, 1, 2}, {4, 2, 3}, {4, 3, 0}};
const std::vector<int> kSquare = {0, 1, 2, 3};

DiskDefect check(int nodes, const std::vector<Triangle>& triangles, const std::vector<int>& boundary = kSquare,
                 std::vector<std::vector<int>>* rings = nullptr) {
  return find_disk_defect(TriangleAdjacency(nodes, triangles), triangles, boundary, rings);
}

}  // namespace

TEST_CASE("find_disk_defect accepts a fan and returns the interior rings", "[disk_topology]") {
  std::vector<std::vector<int>> rings;
  const DiskDefect defect = check(5, kFan, kSquare, &rings);
  CHECK_FALSE(defect);
  REQUIRE(rings.size() == 5);
  CHECK(rings[4] == std::vector<int>{0, 1, 2, 3});
  for (int v = 0; v < 4; ++v) CHECK(rings[v].empty());
  // Two triangles, no interior node.
  CHECK_FALSE(check(4, {{0, 1, 2}, {0, 2, 3}}));
}

TEST_CASE("find_disk_defect names each kind of defect", "[disk_topology]") {
  DiskDefect d = check(5, {{4, 0, 1}, {4, 1, 2}, {4, 2, 3}, {4, 3, 0}, {4, 1, 3}});
  CHECK(d.kind == Kind::RepeatedSide);
  CHECK(d.triangle == 1);
  CHECK(d.other_triangle == 4);

  d = check(5, {{4, 0, 1}, {4, 1, 2}, {4, 2, 3}});  // the side 3 -> 0 is missing
  CHECK(d.kind == Kind::BoundarySideMissing);
  CHECK(d.a == 3);
  CHECK(d.b == 0);

  d = check(6, {{4, 0, 1}, {4, 1, 2}, {4, 2, 3}, {4, 3, 0}, {1, 0, 5}});  // a triangle outside side 0-1
  CHECK(d.kind == Kind::OutsideBoundary);
  CHECK(d.triangle == 4);

  d = check(5, {{0, 1, 2}, {0, 2, 3}, {4, 1, 2}}, kSquare);
  CHECK(d.kind == Kind::RepeatedSide);  // 1 -> 2 twice

  d = check(6, {{4, 0, 1}, {4, 1, 2}, {4, 2, 3}, {4, 3, 5}, {5, 3, 0}, {4, 5, 0}});
  CHECK_FALSE(d);  // two interior nodes, still a disk

  d = check(6, kFan);  // node 5 exists but is in no triangle
  CHECK(d.kind == Kind::NodeInNoTriangle);
  CHECK(d.a == 5);
}

TEST_CASE("find_disk_defect finds a hole and a pinched boundary node", "[disk_topology]") {
  // A hole: the square 0..3 round an inner triangle 4, 5, 6 with one ring of
  // triangles missing the inner triangle itself: its sides border nothing.
  const std::vector<int> outer = {0, 1, 2, 3};
  std::vector<Triangle> annulus = {{0, 1, 4}, {1, 5, 4}, {1, 2, 5}, {2, 6, 5}, {2, 3, 6}, {3, 0, 6}, {0, 4, 6}};
  DiskDefect d = check(7, annulus, outer);
  CHECK(d.kind == Kind::SideBordersNothing);
  annulus.push_back({4, 5, 6});
  CHECK_FALSE(check(7, annulus, outer));

}

TEST_CASE("find_disk_defect finds a sphere pinched onto the disk at a node", "[disk_topology]") {
  // A closed tetrahedron surface 4, 5, 6, 7 glued to the fan at its centre
  // 4: every side has its twin, but 4's triangles form two closed fans.
  std::vector<Triangle> at_centre = kFan;
  for (const Triangle& t : std::vector<Triangle>{{4, 5, 6}, {4, 6, 7}, {4, 7, 5}, {5, 7, 6}}) at_centre.push_back(t);
  DiskDefect d = check(8, at_centre);
  CHECK(d.kind == Kind::InteriorFanNotClosed);
  CHECK(d.a == 4);
  // The same glued at boundary node 0: its fan from 1 to 3 leaves three
  // triangles out.
  std::vector<Triangle> at_corner = kFan;
  for (const Triangle& t : std::vector<Triangle>{{0, 5, 6}, {0, 6, 7}, {0, 7, 5}, {5, 7, 6}}) at_corner.push_back(t);
  d = check(8, at_corner);
  CHECK(d.kind == Kind::BoundaryFanBroken);
  CHECK(d.a == 0);
}
