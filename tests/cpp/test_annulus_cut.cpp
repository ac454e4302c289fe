// internal::choose_annulus_cut and its parts (Algorithm 3, step 3): the
// path that cuts the annulus between the figure and the enclosure open.
#include "catch.h"

#include "figures.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/annulus_cut.h"

using namespace stickmorph;
using namespace stickmorph::internal;
using namespace stickmorph::test;

namespace {

// A "C" open to the right (vertices 1 to 4) with a spur from its top-right
// end to vertex 0 at the centre: from vertex 0 the way out to the left is
// blocked by the C's back, x = -2.
StickFigure c_with_spur(bool reversed_edges = false) {
  RawEdges edges{{0, 1}, {1, 2}, {2, 3}, {3, 4}};
  if (reversed_edges) edges = {{4, 3}, {3, 2}, {2, 1}, {1, 0}};
  return figure({{0, 0}, {2, 2}, {-2, 2}, {-2, -2}, {2, -2}}, edges);
}

// A convex, counter-clockwise hexagon of radius 10 round the origin.
const std::vector<Vec2> kEnclosure = {{5, -8.66}, {10, 0}, {5, 8.66}, {-5, 8.66}, {-10, 0}, {-5, -8.66}};

ExteriorCorner corner_at(const StickFigure& f, const Decomposition& d, int vertex) {
  const CyclicSequence& ext = d.sequences[d.exterior];
  for (int c = 0; c < int(ext.vertices.size()); ++c)
    if (ext.vertices[c] == vertex) return exterior_corner(f, d, c);
  FAIL("vertex " << vertex << " is not on the exterior");
  return {};
}

}  // namespace

TEST_CASE("pad_bends splits the longest segment until the count is reached", "[annulus_cut]") {
  std::vector<Vec2> bends;
  pad_bends({0, 0}, {4, 0}, bends, 1);
  CHECK(bends == std::vector<Vec2>{{2, 0}});
  // Two segments of length 2 now: the first one is split, then the last.
  pad_bends({0, 0}, {4, 0}, bends, 3);
  CHECK(bends == std::vector<Vec2>{{1, 0}, {2, 0}, {3, 0}});
  pad_bends({0, 0}, {4, 0}, bends, 2);  // never removes
  CHECK(bends.size() == 3);
}

TEST_CASE("corner_admits and segment_is_free decide exactly", "[annulus_cut]") {
  const StickFigure f = c_with_spur();
  const Decomposition d = decompose(f);
  const ExteriorCorner tip = corner_at(f, d, 0);
  CHECK(tip.vertex == 0);
  CHECK(tip.next == 1);
  CHECK(tip.prev == 1);
  // At the tip of the spur, everything but the spur's own direction.
  CHECK_FALSE(corner_admits(f, tip, {10, 10}));
  CHECK(corner_admits(f, tip, {-10, 0}));
  CHECK_FALSE(segment_is_free(f, 0, {-10, 0}));  // crosses the C's back
  CHECK(segment_is_free(f, 0, {10, 0}));         // out through the opening
  CHECK(segment_is_free(f, 2, {-10, 10}));       // touches only its own edges at vertex 2
}

TEST_CASE("matching_exterior_corner follows the walk, not the list position", "[annulus_cut]") {
  const StickFigure source = c_with_spur(), target = c_with_spur(true);
  const Decomposition sd = decompose(source), td = decompose(target);
  const int m = int(sd.sequences[sd.exterior].vertices.size());
  REQUIRE(m == 8);  // a tree of 4 edges: every dart once
  for (int c = 0; c < m; ++c) {
    const ExteriorCorner s = exterior_corner(source, sd, c);
    const ExteriorCorner t = exterior_corner(target, td, matching_exterior_corner(sd, td, c));
    CHECK(s.vertex == t.vertex);
    CHECK(s.next == t.next);
    CHECK(s.prev == t.prev);
  }
}

TEST_CASE("AnnulusRouter bends round the figure where the straight way is blocked", "[annulus_cut]") {
  const StickFigure f = c_with_spur();
  const Decomposition d = decompose(f);
  AnnulusRouter router(f, kEnclosure);
  std::vector<Vec2> bends;
  REQUIRE(router.route(corner_at(f, d, 0), 5 + 4, bends));  // to (-10, 0)
  CHECK_FALSE(bends.empty());
  // Every segment of the route meets the figure nowhere but at vertex 0.
  std::vector<Vec2> path{f.vertices[0]};
  path.insert(path.end(), bends.begin(), bends.end());
  path.push_back(kEnclosure[4]);
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    for (const Edge& e : f.edges) {
      const SegmentContact contact = segment_contact(path[i], path[i + 1], f.vertices[e[0]], f.vertices[e[1]]);
      const bool at_start = i == 0 && contact == SegmentContact::Touching && (e[0] == 0 || e[1] == 0);
      CHECK((contact == SegmentContact::Disjoint || at_start));
    }
}

TEST_CASE("choose_annulus_cut takes a straight cut when one is valid in both", "[annulus_cut]") {
  const StickFigure source = c_with_spur(), target = c_with_spur(true);
  const Decomposition sd = decompose(source), td = decompose(target);
  const AnnulusCut cut = choose_annulus_cut(source, sd, target, td, kEnclosure);
  CHECK(cut.source_bends.empty());
  CHECK(cut.target_bends.empty());
  REQUIRE(cut.enclosure_index >= 0);
  const Vec2& q = kEnclosure[cut.enclosure_index];
  CHECK(corner_admits(source, cut.corner, q));
  CHECK(segment_is_free(source, cut.corner.vertex, q));
  CHECK(segment_is_free(target, cut.corner.vertex, q));
}
