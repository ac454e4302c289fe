#include "catch.h"

#include <limits>

#include "figures.h"
#include "stickmorph/frame_verification.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;
using stickmorph_test::StartsWith;

namespace {

// A square with a dangling edge inside, a tail outside and a tree hanging
// off the tail (the paper's Figure 2(a) in spirit).
const std::vector<Vec2> kSquareTail = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}, {6, 2}, {8, 3}, {8, 1}};
const RawEdges kSquareTailEdges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {5, 6}, {5, 7}};

// A junction with four branches, counter-clockwise 1, 2, 3, 4.
const std::vector<Vec2> kStar = {{0, 0}, {2, 0}, {0, 2}, {-2, 0}, {0, -2}};
const RawEdges kStarEdges = {{0, 1}, {0, 2}, {0, 3}, {0, 4}};

}  // namespace

TEST_CASE("a valid frame passes", "[verify_frame]") {
  const StickFigure source = figure(kSquareTail, kSquareTailEdges);
  CHECK_NOTHROW(verify_frame(source, source.vertices, 0, 0.0));
  CHECK(is_frame_valid(source, source.vertices));
  // A distorted drawing with the same decomposition (Figure 2(c)).
  const std::vector<Vec2> moved = {{0, 0}, {5, 1}, {4, 5}, {-1, 3}, {1, 1.5}, {9, 0}, {12, 4}, {10, -3}};
  CHECK_NOTHROW(verify_frame(source, moved, 7, 0.5));
  CHECK(is_frame_valid(source, moved));
  // The overload with a precomputed decomposition agrees.
  const Decomposition dec = decompose(source);
  CHECK(is_frame_valid(source, dec, moved));
  CHECK_NOTHROW(verify_frame(source, dec, moved, 7));
}

TEST_CASE("a frame whose edges cross names the frame, its time and the edges", "[verify_frame]") {
  const StickFigure source = figure(kSquareTail, kSquareTailEdges);
  std::vector<Vec2> p = kSquareTail;
  p[6] = {3, 3};  // edge 5 (5-6) now crosses the square's side 1 (1-2)
  CHECK_FALSE(is_frame_valid(source, p));
  CHECK_THROWS_AS(verify_frame(source, p, 12, 12.0 / 49), VerificationError);
  CHECK_THROWS_WITH(verify_frame(source, p, 12, 12.0 / 49),
                    StartsWith("frame 12 (t = 0.2449): ") && Contains("edges 1 (1-2) and 6 (5-6) cross"));
  // Without a time only the index is named.
  CHECK_THROWS_WITH(verify_frame(source, p, 3), StartsWith("frame 3: edges"));
}

TEST_CASE("a touching frame is refused", "[verify_frame]") {
  const StickFigure source = figure(kSquareTail, kSquareTailEdges);
  SECTION("a vertex on a non-incident edge") {
    std::vector<Vec2> p = kSquareTail;
    p[6] = {4, 3};  // a branch tip touches the square's side 1 (1-2)
    CHECK_FALSE(is_frame_valid(source, p));
    CHECK_THROWS_WITH(verify_frame(source, p, 4, 0.25),
                      StartsWith("frame 4 (t = 0.25): vertex 6") && Contains("lies on edge 1 (1-2)"));
  }
  SECTION("two vertices at one point") {
    std::vector<Vec2> p = kSquareTail;
    p[7] = p[6];
    CHECK_FALSE(is_frame_valid(source, p));
  }
  SECTION("collinear edges that overlap") {
    std::vector<Vec2> p = kSquareTail;
    p[4] = {0, 2};  // the inner dangling edge 0-4 lies along the side 3-0
    CHECK_THROWS_WITH(verify_frame(source, p, 1), Contains("overlap"));
  }
  SECTION("a non-finite coordinate") {
    std::vector<Vec2> p = kSquareTail;
    p[2][1] = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(is_frame_valid(source, p));
  }
}

TEST_CASE("a frame whose junction branches passed through each other is refused", "[verify_frame]") {
  const StickFigure source = figure(kStar, kStarEdges);
  // Branches 2 and 3 swap sides: still a plane graph, but the cyclic order
  // around vertex 0 is now 1, 3, 2, 4.
  const std::vector<Vec2> p = {{0, 0}, {2, 0}, {-2, 0.5}, {0.5, 2}, {0, -2}};
  REQUIRE(is_valid(figure(p, kStarEdges)));
  CHECK_FALSE(is_frame_valid(source, p));
  CHECK_THROWS_WITH(verify_frame(source, p, 30, 0.6),
                    StartsWith("frame 30 (t = 0.6): not compatible with the source") &&
                        Contains("around vertex 0"));
  // The dangling edge of the square swinging out through the corner
  // (Figure 2(b)) changes the rotation at vertex 0.
  const StickFigure square = figure(kSquareTail, kSquareTailEdges);
  std::vector<Vec2> q = kSquareTail;
  q[4] = {-2, -2};
  CHECK_THROWS_WITH(verify_frame(square, q, 2), Contains("vertex 0"));
}

TEST_CASE("a mirrored frame is refused", "[verify_frame]") {
  const StickFigure source = figure(kSquareTail, kSquareTailEdges);
  std::vector<Vec2> p = kSquareTail;
  for (Vec2& v : p) v[0] = -v[0];
  CHECK_FALSE(is_frame_valid(source, p));
  CHECK_THROWS_WITH(verify_frame(source, p, 5), Contains("mirror"));
}

TEST_CASE("a frame of the wrong length is an argument error", "[verify_frame]") {
  const StickFigure source = figure(kStar, kStarEdges);
  std::vector<Vec2> p = kStar;
  p.pop_back();
  CHECK_THROWS_AS(verify_frame(source, p, 0), InvalidArgumentError);
  CHECK_THROWS_AS(is_frame_valid(source, p), InvalidArgumentError);
}

TEST_CASE("frame labels", "[verify_frame]") {
  CHECK(frame_label(12, 12.0 / 49) == "frame 12 (t = 0.2449)");
  CHECK(frame_label(0, 0.0) == "frame 0 (t = 0)");
  CHECK(frame_label(49, 1.0) == "frame 49 (t = 1)");
  CHECK(frame_label(3, std::numeric_limits<double>::quiet_NaN()) == "frame 3");
  // A frame scrubbed at any t (stickmorph.MorphSolver) is named by its time.
  CHECK(frame_label(-1, 0.25) == "t = 0.25");
  CHECK(frame_label(-1, 1.0) == "t = 1");
}
