// untangle_steiner_vertices: a frame flipped by rounding at a Steiner vertex
// is repaired by moving that vertex alone into its star's kernel.
#include "catch.h"

#include <vector>

#include "stickmorph/figure_triangulation.h"
#include "stickmorph/frame_certificate.h"
#include "stickmorph/morph.h"

using namespace stickmorph;

namespace {

// Figure vertices 0 and 1 (an edge) inside the square enclosure 2..5
// (corners (+-2, +-2)), Steiner vertex 6 above the edge; eight triangles.
FigureTriangulation edge_with_steiner_vertex() {
  FigureTriangulation tri;
  tri.figure_vertices = 2;
  tri.enclosure_vertices = 4;
  tri.steiner_vertices = 1;
  tri.source = {{-0.5, 0}, {0.5, 0}, {-2, -2}, {2, -2}, {2, 2}, {-2, 2}, {0, 1}};
  tri.target = tri.source;
  tri.triangles = {{2, 3, 1}, {2, 1, 0}, {3, 4, 1}, {0, 5, 2}, {1, 4, 6}, {4, 5, 6}, {5, 0, 6}, {0, 1, 6}};
  return tri;
}

}  // namespace

TEST_CASE("untangle_steiner_vertices moves an inverted Steiner vertex back into its kernel", "[untangle]") {
  const FigureTriangulation tri = edge_with_steiner_vertex();
  REQUIRE(certificate_defect(tri, tri.source).empty());
  std::vector<Vec2> frame = tri.source;
  frame[6] = {0, -0.1};  // below the edge: triangle (0, 1, 6) is clockwise
  REQUIRE_FALSE(certificate_defect(tri, frame).empty());
  std::vector<Vec2> repaired = frame;
  REQUIRE(untangle_steiner_vertices(tri, repaired));
  CHECK(certificate_defect(tri, repaired).empty());
  for (int v = 0; v < 6; ++v) CHECK(repaired[v] == frame[v]);  // the figure and the enclosure stay
  CHECK(repaired[6][1] > 0);
}

TEST_CASE("untangle_steiner_vertices leaves a frame alone when a figure vertex is what flipped", "[untangle]") {
  const FigureTriangulation tri = edge_with_steiner_vertex();
  std::vector<Vec2> frame = tri.source;
  frame[0] = {0.6, 0.05};  // past vertex 1: triangles at the figure's edge flip
  REQUIRE_FALSE(certificate_defect(tri, frame).empty());
  std::vector<Vec2> attempt = frame;
  CHECK_FALSE(untangle_steiner_vertices(tri, attempt));
  CHECK(attempt == frame);
  std::vector<Vec2> short_frame(3, Vec2{0, 0});
  CHECK_FALSE(untangle_steiner_vertices(tri, short_frame));
}
