#include "catch.h"

#include <cmath>
#include <limits>

#include "figures.h"
#include "stickmorph/stick_figure.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;
using stickmorph_test::Equals;

namespace {

// Runs make_stick_figure and returns the error it must throw.
InvalidFigureError rejection(std::vector<Vec2> vertices, RawEdges edges) {
  try {
    make_stick_figure(std::move(vertices), edges);
  } catch (const InvalidFigureError& e) {
    return e;
  }
  FAIL("make_stick_figure accepted an invalid figure");
  throw std::logic_error("unreachable");
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

}  // namespace

TEST_CASE("valid figures are accepted", "[make_stick_figure]") {
  SECTION("a single vertex") {
    const StickFigure f = figure({{3, 4}}, {});
    CHECK(f.vertices.size() == 1);
    CHECK(is_valid(f));
  }
  SECTION("a single edge") { CHECK(is_valid(figure({{0, 0}, {1, 0}}, {{1, 0}}))); }
  SECTION("polygon, polyline, triangulation") {
    CHECK(is_valid(polygon(regular(7))));
    CHECK(is_valid(polyline({{0, 0}, {1, 0}, {2, 0}, {3, 0}})));  // collinear chain
    CHECK(is_valid(grid_triangulation(6)));
  }
  SECTION("edges meeting at a vertex at any angle, including straight through") {
    CHECK(is_valid(figure({{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}}, {{0, 1}, {0, 2}, {0, 3}, {0, 4}})));
  }
  SECTION("a vertex a hair away from a non-incident edge") {
    const double hair = std::nextafter(0.0, 1.0);  // the smallest positive double
    CHECK(is_valid(figure({{0, 0}, {2, 0}, {1, hair}, {1, 1}}, {{0, 1}, {2, 3}, {3, 0}})));
    CHECK_FALSE(is_valid(StickFigure{{{0, 0}, {2, 0}, {1, 0}, {1, 1}}, {{0, 1}, {2, 3}, {3, 0}}, ""}));
  }
  SECTION("random plane graphs") {
    std::mt19937 rng(7);
    for (int i = 0; i < 20; ++i) CHECK(is_valid(random_plane_graph(rng, 30, 0.5)));
  }
}

TEST_CASE("coordinates must be finite and bounded", "[make_stick_figure]") {
  auto e = rejection({}, {});
  CHECK(e.defect() == FigureDefect::NoVertices);

  e = rejection({{0, 0}, {1, kNaN}}, {{0, 1}});
  CHECK(e.defect() == FigureDefect::NonFiniteCoordinate);
  CHECK_THAT(e.what(), Equals("vertex 1 has a non-finite coordinate (y = nan)"));
  CHECK(e.vertices() == std::vector<int>{1});

  e = rejection({{-kInf, 0}, {1, 0}}, {{0, 1}});
  CHECK(e.defect() == FigureDefect::NonFiniteCoordinate);
  CHECK_THAT(e.what(), Contains("vertex 0") && Contains("x = -inf"));

  e = rejection({{0, 0}, {1, 2e100}}, {{0, 1}});
  CHECK(e.defect() == FigureDefect::CoordinateTooLarge);
  CHECK_THAT(e.what(), Contains("vertex 1") && Contains("y = 2e+100"));
  CHECK(is_valid(figure({{0, 0}, {1e100, -1e100}}, {{0, 1}})));
}

TEST_CASE("edge indices must name existing vertices", "[make_stick_figure]") {
  auto e = rejection({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {1, 3}});
  CHECK(e.defect() == FigureDefect::EdgeIndexOutOfRange);
  CHECK_THAT(e.what(), Equals("edge 1 refers to vertex 3, which is out of range (the figure has 3 vertices, 0 to 2)"));
  CHECK(e.edges() == std::vector<int>{1});

  e = rejection({{0, 0}, {1, 0}}, {{-1, 1}});
  CHECK(e.defect() == FigureDefect::EdgeIndexOutOfRange);
  CHECK_THAT(e.what(), Contains("edge 0 refers to vertex -1"));

  // Values far outside int range are reported, not truncated.
  e = rejection({{0, 0}, {1, 0}}, {{0, 1}, {0, std::int64_t(1) << 40}});
  CHECK_THAT(e.what(), Contains("edge 1 refers to vertex 1099511627776"));
}

TEST_CASE("self-loops and duplicate edges are rejected", "[make_stick_figure]") {
  auto e = rejection({{0, 0}, {1, 0}}, {{0, 1}, {1, 1}});
  CHECK(e.defect() == FigureDefect::SelfLoop);
  CHECK_THAT(e.what(), Equals("edge 1 is a self-loop at vertex 1"));

  e = rejection({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {1, 2}, {2, 0}, {2, 1}});
  CHECK(e.defect() == FigureDefect::DuplicateEdge);
  CHECK_THAT(e.what(), Equals("edges 1 and 3 both join vertices 1 and 2"));
  CHECK(e.edges() == std::vector<int>{1, 3});
}

TEST_CASE("coincident vertices are rejected", "[make_stick_figure]") {
  auto e = rejection({{0, 0}, {1, 0}, {2, 0}, {1, 0}}, {{0, 1}, {1, 2}, {2, 3}});
  CHECK(e.defect() == FigureDefect::CoincidentVertices);
  CHECK_THAT(e.what(), Equals("vertices 1 and 3 coincide at (1, 0)"));
  CHECK(e.vertices() == std::vector<int>{1, 3});
  // -0.0 and 0.0 are the same point.
  e = rejection({{0.0, 1}, {-0.0, 1}, {5, 5}}, {{0, 2}, {1, 2}});
  CHECK(e.defect() == FigureDefect::CoincidentVertices);
}

TEST_CASE("edges may meet only at shared endpoints", "[make_stick_figure]") {
  SECTION("crossing") {
    // A square with both diagonals.
    auto e = rejection({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 3}});
    CHECK(e.defect() == FigureDefect::CrossingEdges);
    CHECK_THAT(e.what(), Equals("edges 4 (0-2) and 5 (1-3) cross"));
    CHECK(e.edges() == std::vector<int>{4, 5});
  }
  SECTION("collinear overlap of non-incident edges") {
    auto e = rejection({{0, 0}, {2, 0}, {1, 0}, {3, 0}, {1, 5}}, {{0, 1}, {2, 3}, {1, 4}, {4, 2}});
    CHECK(e.defect() == FigureDefect::OverlappingEdges);
    CHECK_THAT(e.what(), Contains("edges 0 (0-1) and 1 (2-3) overlap"));
  }
  SECTION("collinear overlap of incident edges (folded back)") {
    auto e = rejection({{0, 0}, {2, 0}, {1, 0}}, {{0, 1}, {0, 2}});
    CHECK(e.defect() == FigureDefect::OverlappingEdges);
    CHECK(e.edges() == std::vector<int>{0, 1});
  }
  SECTION("a vertex on a non-incident edge") {
    auto e = rejection({{0, 0}, {2, 0}, {1, 0}, {1, 1}}, {{0, 1}, {2, 3}, {3, 0}});
    CHECK(e.defect() == FigureDefect::VertexOnEdge);
    CHECK_THAT(e.what(), Equals("vertex 2 (1, 0) lies on edge 0 (0-1), which is not incident to it"));
    CHECK(e.vertices() == std::vector<int>{2});
    CHECK(e.edges() == std::vector<int>{0});
  }
  SECTION("an isolated vertex on an edge is named as such") {
    auto e = rejection({{0, 0}, {2, 0}, {1, 0}}, {{0, 1}});
    CHECK(e.defect() == FigureDefect::VertexOnEdge);
    CHECK(e.vertices() == std::vector<int>{2});
  }
  SECTION("crossings are reported before later defects, smallest edges first") {
    std::vector<Vec2> pts;
    RawEdges edges;
    // 150 horizontal and 150 vertical segments: 22,500 crossings.
    for (int i = 0; i < 150; ++i) {
      pts.push_back({0.0, i + 0.5});
      pts.push_back({150.0, i + 0.5});
      edges.push_back({2 * i, 2 * i + 1});
    }
    for (int i = 0; i < 150; ++i) {
      pts.push_back({i + 0.5, -1.0});
      pts.push_back({i + 0.5, 151.0});
      edges.push_back({300 + 2 * i, 301 + 2 * i});
    }
    auto e = rejection(pts, edges);
    CHECK(e.defect() == FigureDefect::CrossingEdges);
    CHECK(e.edges().size() == 2);
  }
}

TEST_CASE("a figure may have several parts, lone vertices included", "[make_stick_figure]") {
  // Issue 14: two strokes, two dots, a triangle and a dot.
  CHECK(is_valid(make_stick_figure({{0, 0}, {1, 0}, {5, 5}, {6, 5}}, {{0, 1}, {2, 3}})));
  CHECK(is_valid(make_stick_figure({{0, 0}, {1, 0}}, {})));
  CHECK(is_valid(make_stick_figure({{0, 0}, {4, 0}, {0, 4}, {1, 1}}, {{0, 1}, {1, 2}, {2, 0}})));
  // Parts are checked against each other like edges of one part.
  auto e = rejection({{0, 0}, {4, 0}, {0, 4}, {2, -1}, {2, 1}}, {{0, 1}, {1, 2}, {2, 0}, {3, 4}});
  CHECK(e.defect() == FigureDefect::CrossingEdges);
  e = rejection({{0, 0}, {4, 0}, {0, 4}, {2, 0}}, {{0, 1}, {1, 2}, {2, 0}});
  CHECK(e.defect() == FigureDefect::VertexOnEdge);
  CHECK(e.vertices() == std::vector<int>{3});
}

TEST_CASE("validate re-checks a figure built by hand", "[make_stick_figure]") {
  StickFigure f = polygon(regular(5));
  CHECK(is_valid(f));
  f.edges.push_back({0, 2});  // a chord of a convex polygon: still valid
  CHECK(is_valid(f));
  f.edges.push_back({1, 3});  // crosses the chord
  CHECK_FALSE(is_valid(f));
  CHECK_THROWS_AS(validate(f), InvalidFigureError);
}
