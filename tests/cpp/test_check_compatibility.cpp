#include "catch.h"

#include "figures.h"
#include "stickmorph/compatibility.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

StickFigure transformed(const StickFigure& f, double a, double b, double c, double d, double tx, double ty) {
  StickFigure g = f;
  for (Vec2& p : g.vertices) p = {a * p[0] + b * p[1] + tx, c * p[0] + d * p[1] + ty};
  return g;
}

// Figure 2(a) of the paper in spirit: a square with a dangling edge inside,
// a tail outside, and a tree hanging off the tail.
const std::vector<Vec2> kFig2a = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}, {6, 2}, {8, 3}, {8, 1}};
const RawEdges kFig2Edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {5, 6}, {5, 7}};

}  // namespace

TEST_CASE("a figure is compatible with its moved, scaled and rotated copies", "[check_compatibility]") {
  const StickFigure a = figure(kFig2a, kFig2Edges);
  CHECK(check_compatibility(a, a).compatible());
  CHECK(check_compatibility(a, transformed(a, 3, 0, 0, 3, 100, -50)).compatible());
  CHECK(check_compatibility(a, transformed(a, 0, -1, 1, 0, 0, 0)).compatible());   // 90 degrees
  CHECK(check_compatibility(a, transformed(a, -1, 0, 0, -1, 0, 0)).compatible());  // 180 degrees
}

TEST_CASE("Figure 2(c): a different drawing with the same decomposition", "[check_compatibility]") {
  const StickFigure a = figure(kFig2a, kFig2Edges);
  // Distorted square, the inner edge bent to another corner direction, the
  // tail longer and the tree's branches spread.
  const StickFigure c = figure({{0, 0}, {5, 1}, {4, 5}, {-1, 3}, {1, 1.5}, {9, 0}, {12, 4}, {10, -3}}, kFig2Edges);
  const CompatibilityReport r = check_compatibility(a, c);
  CHECK(r.compatible());
  CHECK(r.reason.empty());
}

TEST_CASE("edge order and direction do not matter", "[check_compatibility]") {
  const StickFigure a = figure(kFig2a, kFig2Edges);
  RawEdges shuffled = {{7, 5}, {4, 0}, {2, 1}, {0, 3}, {5, 1}, {6, 5}, {1, 0}, {3, 2}};
  CHECK(check_compatibility(a, figure(kFig2a, shuffled)).compatible());
}

TEST_CASE("Figure 2(b): the dangling edge moved outside changes a rotation", "[check_compatibility]") {
  const StickFigure a = figure(kFig2a, kFig2Edges);
  std::vector<Vec2> b = kFig2a;
  b[4] = {-2, -2};  // the edge 0-4 now points out of the square
  const CompatibilityReport r = check_compatibility(a, figure(b, kFig2Edges));
  CHECK(r.kind == Incompatibility::RotationDiffers);
  CHECK(r.vertices == std::vector<int>{0});
  CHECK_THAT(r.reason, Contains("around vertex 0 differs"));
}

TEST_CASE("a junction with permuted branches", "[check_compatibility]") {
  const RawEdges star = {{0, 1}, {0, 2}, {0, 3}, {0, 4}};
  const StickFigure s = figure({{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}}, star);
  const StickFigure t = figure({{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}}, star);
  const CompatibilityReport r = check_compatibility(s, t);
  CHECK(r.kind == Incompatibility::RotationDiffers);
  CHECK_THAT(r.reason, Contains("vertex 0") && Contains("1, 2, 3, 4") && Contains("1, 3, 2, 4"));
}

TEST_CASE("mirror images are named as such", "[check_compatibility]") {
  SECTION("a figure with junctions") {
    const StickFigure a = figure(kFig2a, kFig2Edges);
    const CompatibilityReport r = check_compatibility(a, transformed(a, -1, 0, 0, 1, 0, 0));
    CHECK(r.kind == Incompatibility::MirrorImage);
    CHECK_THAT(r.reason, Contains("mirror image"));
  }
  SECTION("a polygon: no junctions, only the orientation of its sequences") {
    const StickFigure p = polygon(regular(5));
    const CompatibilityReport r = check_compatibility(p, transformed(p, 1, 0, 0, -1, 0, 0));
    CHECK(r.kind == Incompatibility::MirrorImage);
    CHECK_THAT(r.reason, Contains("exterior sequence runs the other way"));
  }
  SECTION("a polyline is its own mirror image") {
    const StickFigure l = polyline({{0, 0}, {1, 1}, {2, 0}, {3, 1}});
    CHECK(check_compatibility(l, transformed(l, -1, 0, 0, 1, 0, 0)).compatible());
  }
}

TEST_CASE("the same sequences with another one exterior", "[check_compatibility]") {
  // A theta graph: vertices 0 and 1 joined by three two-edge paths through
  // 2, 3 and 4. Both drawings have the same rotation at every vertex, but
  // the unbounded region is bounded by paths 2 and 4 in one and 2 and 3 in
  // the other.
  const RawEdges theta = {{0, 2}, {2, 1}, {0, 3}, {3, 1}, {0, 4}, {4, 1}};
  const StickFigure s = figure({{0, 0}, {4, 0}, {2, 2}, {2, 0.5}, {2, -2}}, theta);
  const StickFigure t = figure({{0, 0}, {4, 0}, {2, -2}, {2, 2}, {2, 0}}, theta);
  const CompatibilityReport r = check_compatibility(s, t);
  CHECK(r.kind == Incompatibility::ExteriorDiffers);
  CHECK_THAT(r.reason, Contains("exterior sequences differ") && Contains("0 2 1 4") && Contains("0 3 1 2"));
  // The witness is a side of the source's exterior that is interior in the target.
  REQUIRE(r.vertices.size() == 2);
  CHECK(r.vertices[0] != r.vertices[1]);
}

TEST_CASE("vertex and edge sets must correspond", "[check_compatibility]") {
  const StickFigure a = figure(kFig2a, kFig2Edges);
  std::vector<Vec2> more = kFig2a;
  more.push_back({9, 9});
  RawEdges more_edges = kFig2Edges;
  more_edges.push_back({6, 8});
  CompatibilityReport r = check_compatibility(a, figure(more, more_edges));
  CHECK(r.kind == Incompatibility::VertexCountDiffers);
  CHECK_THAT(r.reason, Contains("8 vertices") && Contains("9"));

  RawEdges other = kFig2Edges;
  other[4] = {1, 4};  // 0-4 replaced by 1-4
  r = check_compatibility(a, figure(kFig2a, other));
  CHECK(r.kind == Incompatibility::EdgeSetDiffers);
  CHECK_THAT(r.reason, Contains("edge 4 (0-4) of the source is not an edge of the target"));
}

TEST_CASE("require_compatible throws the reason", "[check_compatibility]") {
  const StickFigure p = polygon(regular(4));
  CHECK_NOTHROW(require_compatible(p, p));
  CHECK_THROWS_WITH(require_compatible(p, transformed(p, -1, 0, 0, 1, 0, 0)), Contains("mirror image"));
  CHECK_THROWS_AS(require_compatible(p, transformed(p, -1, 0, 0, 1, 0, 0)), IncompatibleFiguresError);
}

TEST_CASE("a mirrored tree is a mirror image, not just another rotation", "[check_compatibility]") {
  // A tree's exterior sequence walks every edge in both directions, so it is
  // its own reverse; the reversed junction must still be named a reflection.
  const StickFigure tree = figure({{0, 0}, {1, 0}, {0, 1}, {-1, -1}, {2, 1}}, {{0, 1}, {0, 2}, {0, 3}, {1, 4}});
  const CompatibilityReport r = check_compatibility(tree, transformed(tree, -1, 0, 0, 1, 0, 0));
  CHECK(r.kind == Incompatibility::MirrorImage);
  CHECK(r.vertices == std::vector<int>{0});
}
