#include "catch.h"

#include <cmath>

#include "figures.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/morph.h"

using namespace stickmorph;
using namespace stickmorph::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec2 on_circle(double cx, double cy, double r, double degrees) {
  const double a = degrees * kPi / 180;
  return {cx + r * std::cos(a), cy + r * std::sin(a)};
}

// The paper's Figure 8(c)/(d) pair in spirit: an S and a U, 12 vertices each.
// The S runs counter-clockwise around its upper bowl from the right, then
// clockwise around its lower bowl.
StickFigure letter_s() {
  std::vector<Vec2> p;
  for (int k = 0; k <= 6; ++k) p.push_back(on_circle(2, 3, 1, 45.0 * k));
  for (int k = 1; k <= 5; ++k) p.push_back(on_circle(2, 1, 1, 90 - 45.0 * k));
  return polyline(p);
}

// The U runs down its left side, round the bottom, up its right side.
StickFigure letter_u() {
  std::vector<Vec2> p = {{1, 4}, {1, 10.0 / 3}, {1, 8.0 / 3}, {1, 2}};
  for (int k = 1; k <= 5; ++k) p.push_back(on_circle(2, 2, 1, 180 + 30.0 * k));
  for (double y : {2.0, 3.0, 4.0}) p.push_back({3, y});
  return polyline(p);
}

}  // namespace

TEST_CASE("the linear morph from S to U self-intersects in the middle", "[linear_morph]") {
  const StickFigure s = letter_s(), u = letter_u();
  REQUIRE(s.vertices.size() == 12);
  REQUIRE(u.vertices.size() == 12);
  REQUIRE(is_frame_valid(s, u.vertices));  // polylines in the same order are compatible
  std::vector<int> invalid{-1};            // cleared by the call
  const MorphResult r = linear_morph(s, u, 51, &invalid);
  REQUIRE(r.frames.size() == 51);
  REQUIRE(r.times.size() == 51);
  CHECK(r.frames.front() == s.vertices);
  CHECK(r.frames.back() == u.vertices);
  CHECK(r.times.back() == 1.0);
  CHECK_FALSE(invalid.empty());
  CHECK(std::is_sorted(invalid.begin(), invalid.end()));
  CHECK(invalid.front() > 0);
  CHECK(invalid.back() < 50);
  // The listed frames are exactly the invalid ones.
  for (int f = 0; f < 51; ++f) {
    const bool listed = std::find(invalid.begin(), invalid.end(), f) != invalid.end();
    CHECK(listed == !is_frame_valid(s, r.frames[f]));
  }
}

TEST_CASE("Figure 8(c): the barycentric morph of the same S and U stays valid", "[linear_morph][morph_triangulation]") {
  const StickFigure s = letter_s(), u = letter_u();
  const FigureTriangulation tri = triangulate_figures(s, u);
  MorphOptions options;
  options.frames = 51;
  options.verify = false;  // checked here, independently
  const MorphResult r = morph_triangulation(tri, s, options);
  const int n = tri.figure_vertices;
  for (int f = 0; f < 51; ++f) {
    INFO("frame " << f);
    for (const auto& t : tri.triangles)
      REQUIRE(orientation(r.frames[f][t[0]], r.frames[f][t[1]], r.frames[f][t[2]]) > 0);
    REQUIRE(is_frame_valid(s, {r.frames[f].begin(), r.frames[f].begin() + n}));
  }
  CHECK(std::vector<Vec2>(r.frames.back().begin(), r.frames.back().begin() + n) == u.vertices);
}

TEST_CASE("the linear morph interpolates straight lines", "[linear_morph]") {
  const StickFigure s = letter_s(), u = letter_u();
  const MorphResult r = linear_morph(s, u, 5);
  for (int f = 0; f < 5; ++f) {
    const double t = f / 4.0;
    CHECK(r.times[f] == t);
    for (int v = 0; v < 12; ++v) {
      CHECK(r.frames[f][v][0] == Approx((1 - t) * s.vertices[v][0] + t * u.vertices[v][0]).epsilon(1e-15));
      CHECK(r.frames[f][v][1] == Approx((1 - t) * s.vertices[v][1] + t * u.vertices[v][1]).epsilon(1e-15));
    }
  }
}

TEST_CASE("the linear morph of a figure to itself or a moved copy is valid throughout", "[linear_morph]") {
  const StickFigure s = letter_s();
  std::vector<int> invalid{3};
  linear_morph(s, s, 20, &invalid);
  CHECK(invalid.empty());
  // Translation and uniform scaling keep every intermediate shape similar.
  StickFigure moved = s;
  for (Vec2& p : moved.vertices) p = {3 * p[0] + 10, 3 * p[1] - 4};
  linear_morph(s, moved, 20, &invalid);
  CHECK(invalid.empty());
}

TEST_CASE("linear morph arguments", "[linear_morph]") {
  const StickFigure s = letter_s();
  CHECK_THROWS_AS(linear_morph(s, s, 1, nullptr), InvalidArgumentError);
  CHECK_THROWS_AS(linear_morph(s, polyline({{0, 0}, {1, 0}}), 10, nullptr), InvalidArgumentError);
  const MorphResult two = linear_morph(s, letter_u(), 2, nullptr);
  CHECK(two.times == std::vector<double>{0.0, 1.0});
}
