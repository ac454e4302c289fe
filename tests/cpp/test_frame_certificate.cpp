// certificate_defect, require_figure_edges and the FrameCheck option
// (frame_certificate.h): the certificate accepts exactly the frames the
// theorem covers, names what breaks, and never disagrees with verify_frame
// on a morph's frames.
#include "catch.h"

#include <cmath>
#include <random>

#include "figures.h"
#include "stickmorph/frame_certificate.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/morph_stick_figures.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

// A square enclosure (nodes 3-6) round the figure path 0-1-2 (a triangle
// fan with every figure edge a triangulation edge).
FigureTriangulation path_in_square() {
  FigureTriangulation tri;
  tri.figure_vertices = 3;
  tri.enclosure_vertices = 4;
  tri.source = {{-2, 0}, {2, 0}, {0, 1}, {-10, -10}, {10, -10}, {10, 10}, {-10, 10}};
  tri.target = tri.source;
  tri.triangles = {{3, 1, 0}, {3, 4, 1}, {4, 5, 1}, {5, 2, 1}, {5, 6, 2}, {6, 0, 2}, {6, 3, 0}, {0, 1, 2}};
  return tri;
}

}  // namespace

TEST_CASE("the certificate accepts a positive frame in a convex enclosure", "[frame_certificate]") {
  const FigureTriangulation tri = path_in_square();
  CHECK(certificate_defect(tri, tri.source).empty());
  std::vector<Vec2> p = tri.source;
  p[2] = {0.5, 3};  // still inside its fan
  CHECK(certificate_defect(tri, p).empty());
  // Rotated and scaled as a whole (the rigid morph moves the enclosure).
  for (Vec2& q : p) q = {0.6 * q[0] - 0.8 * q[1] + 5, 0.8 * q[0] + 0.6 * q[1] - 1};
  CHECK(certificate_defect(tri, p).empty());
}

TEST_CASE("the certificate names a triangle that is not counter-clockwise", "[frame_certificate]") {
  const FigureTriangulation tri = path_in_square();
  std::vector<Vec2> p = tri.source;
  p[2] = {0, -1};  // below the edge 0-1: triangle 7 (0, 1, 2) turns over
  CHECK_THAT(certificate_defect(tri, p), Contains("triangle") && Contains("is not counter-clockwise"));
  p[2] = {0, 0};  // on the edge: zero area is not positive either
  CHECK_THAT(certificate_defect(tri, p), Contains("is not counter-clockwise"));
}

TEST_CASE("the certificate names an enclosure that is not convex or winds twice", "[frame_certificate]") {
  const FigureTriangulation tri = path_in_square();
  std::vector<Vec2> p = tri.source;
  p[4] = {0, 8};  // enclosure corner pushed in: a reflex corner
  CHECK_THAT(certificate_defect(tri, p), Contains("the enclosure is not convex at node"));
  // Five enclosure nodes placed as a pentagram: every corner a left turn,
  // but the boundary winds round twice. Only the enclosure is looked at
  // before the triangles, so the triangles may be anything.
  FigureTriangulation star;
  star.figure_vertices = 0;
  star.enclosure_vertices = 5;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * M_PI * (2 * i) / 5;
    star.source.push_back({std::cos(a), std::sin(a)});
  }
  star.target = star.source;
  star.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
  CHECK_THAT(certificate_defect(star, star.source), Contains("the enclosure winds 2 times"));
}

TEST_CASE("the certificate needs one position per node", "[frame_certificate]") {
  const FigureTriangulation tri = path_in_square();
  CHECK_THROWS_AS(certificate_defect(tri, {tri.source.begin(), tri.source.begin() + 3}), InvalidArgumentError);
}

TEST_CASE("require_figure_edges names a figure edge the triangulation lacks", "[frame_certificate]") {
  const FigureTriangulation tri = path_in_square();
  CHECK_NOTHROW(require_figure_edges(tri, figure({tri.source.begin(), tri.source.begin() + 3}, {{0, 1}, {1, 2}})));
  FigureTriangulation fewer = tri;
  // Flip the edge 0-1 (triangles 3-1-0 and 0-1-2 become 3-1-2 and 3-2-0).
  fewer.triangles[0] = {3, 1, 2};
  fewer.triangles[7] = {3, 2, 0};
  CHECK_THROWS_WITH(
      require_figure_edges(fewer, figure({tri.source.begin(), tri.source.begin() + 3}, {{1, 2}, {0, 1}})),
      Contains("figure edge 1 (0-1) is not an edge of the triangulation"));
}

TEST_CASE("frame checks are named certificate and full", "[frame_certificate]") {
  CHECK(parse_frame_check("certificate") == FrameCheck::Certificate);
  CHECK(parse_frame_check("full") == FrameCheck::Full);
  CHECK(frame_check_name(FrameCheck::Full) == "full");
  CHECK(frame_check_name(FrameCheck::Certificate) == "certificate");
  CHECK_THROWS_WITH(parse_frame_check("fast"), Contains("unknown frame check 'fast' (choose certificate or full)"));
}

TEST_CASE("certified frames pass the full check, and both checks give the same frames", "[frame_certificate]") {
  // Every method on random compatible pairs: the frames made under the
  // certificate are bit for bit those made under the full check, and each
  // passes verify_frame on its own.
  std::mt19937 rng(15);
  int morphed = 0;
  for (int round = 0; round < 24 && morphed < 8; ++round) {
    const auto pair = random_compatible_pair(rng, round, 12, 20);
    if (!pair) continue;
    for (const MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric}) {
      MorphStickFiguresOptions options;
      options.method = method;
      options.frames = 12;
      const MorphStickFiguresResult certified = morph_stick_figures(pair->first, pair->second, options);
      options.frame_check = FrameCheck::Full;
      const MorphStickFiguresResult full = morph_stick_figures(pair->first, pair->second, options);
      REQUIRE(certified.frames.size() == full.frames.size());
      for (std::size_t f = 0; f < full.frames.size(); ++f) {
        CHECK(certified.frames[f] == full.frames[f]);
        CHECK(is_frame_valid(pair->first, certified.frames[f]));
      }
    }
    ++morphed;
  }
  CHECK(morphed == 8);
}

TEST_CASE("frame_check is refused where no frame is checked", "[frame_certificate]") {
  const StickFigure a = polyline({{0, 0}, {1, 0}, {2, 1}});
  const StickFigure b = polyline({{0, 0}, {1, 1}, {2, 1}});
  MorphStickFiguresOptions options;
  options.frame_check = FrameCheck::Full;
  options.verify = false;
  CHECK_THROWS_WITH(morph_stick_figures(a, b, options),
                    Contains("frame_check has no effect with verify=False"));
  options.verify.reset();
  options.method = MorphMethod::Linear;
  CHECK_THROWS_WITH(morph_stick_figures(a, b, options), Contains("frame_check has no effect with method='linear'"));
}
