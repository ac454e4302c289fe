// internal::RigidSteinerPlacement (rigid_steiner_placement.h): the guide
// frame's Steiner vertices placed as rigidly as possible.
#include "catch.h"

#include <cmath>
#include <vector>

#include "stickmorph/figure_triangulation.h"
#include "stickmorph/internal/rigid_steiner_placement.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec2 turned(const Vec2& p, double angle) {
  return {std::cos(angle) * p[0] - std::sin(angle) * p[1], std::sin(angle) * p[0] + std::cos(angle) * p[1]};
}

// One Steiner vertex (node 7, off centre) in a ring of seven nodes: the
// figure's polyline 0-1-2 and four enclosure nodes 3-6, counter-clockwise;
// the target is the source turned by `angle`.
FigureTriangulation wheel(double angle) {
  FigureTriangulation tri;
  tri.figure_vertices = 3;
  tri.enclosure_vertices = 4;
  tri.steiner_vertices = 1;
  for (int i = 0; i < 7; ++i) {
    const double a = 2 * kPi * i / 7;
    tri.source.push_back({(2 + 0.3 * i) * std::cos(a), (2 + 0.3 * i) * std::sin(a)});
  }
  tri.source.push_back({0.4, -0.3});
  for (const Vec2& p : tri.source) tri.target.push_back(turned(p, angle));
  for (int i = 0; i < 7; ++i) tri.triangles.push_back({7, i, (i + 1) % 7});
  return tri;
}

const std::vector<Edge> kEdges = {{0, 1}, {1, 2}};

}  // namespace

TEST_CASE("RigidSteinerPlacement: a figure that only turns carries its Steiner vertex along exactly",
          "[rigid_steiner_placement]") {
  const double angle = 100 * kPi / 180;
  const FigureTriangulation tri = wheel(angle);
  const RigidSteinerPlacement placement(tri, kEdges, {angle, angle});
  for (double u : {0.0, 0.25, 0.5, 1.0}) {
    std::vector<Vec2> p;
    for (const Vec2& x : tri.source) p.push_back(turned(x, u * angle));
    const Vec2 expected = p[7];
    p[7] = {100, 100};
    REQUIRE(placement.place(u, p));
    CHECK(p[7][0] == Approx(expected[0]).margin(1e-12));
    CHECK(p[7][1] == Approx(expected[1]).margin(1e-12));
  }
}

TEST_CASE("RigidSteinerPlacement: triangles turn the way the guide turns the figure's edges, whole turns included",
          "[rigid_steiner_placement]") {
  // Turned by 170 degrees: the guide may turn the figure +170 or -190 (a
  // chosen direction); the triangles follow either, while their principal
  // angle is +170.
  const double angle = 170 * kPi / 180;
  const FigureTriangulation tri = wheel(angle);
  for (double turn : {angle, angle - 2 * kPi, angle + 2 * kPi}) {
    const RigidSteinerPlacement placement(tri, kEdges, {turn, turn});
    std::vector<Vec2> p;
    for (const Vec2& x : tri.source) p.push_back(turned(x, 0.5 * turn));
    const Vec2 expected = p[7];
    REQUIRE(placement.place(0.5, p));
    CHECK(p[7][0] == Approx(expected[0]).margin(1e-12));
    CHECK(p[7][1] == Approx(expected[1]).margin(1e-12));
  }
}

TEST_CASE("RigidSteinerPlacement: without Steiner vertices nothing moves", "[rigid_steiner_placement]") {
  FigureTriangulation tri;
  tri.figure_vertices = 1;
  tri.enclosure_vertices = 3;
  tri.source = {{0, 0}, {2, -1}, {0, 2}, {-2, -1}};
  tri.target = tri.source;
  tri.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}};
  const RigidSteinerPlacement placement(tri, {}, {});
  std::vector<Vec2> p = tri.source;
  REQUIRE(placement.place(0.5, p));
  CHECK(p == tri.source);
}
