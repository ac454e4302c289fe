// internal::make_skeleton, compare_invariants and plural
// (correspondence_skeleton.h): a figure's nodes and chains, and the
// invariants any matching needs.
#include "catch.h"

#include "stickmorph/compatibility.h"
#include "stickmorph/internal/correspondence_skeleton.h"

using namespace stickmorph;
using namespace stickmorph::internal;
using stickmorph_test::Contains;

namespace {
// A Y: junction 0, an arm subdivided by vertex 1 ending at 2, arms to 3 and 4.
StickFigure y_shape() {
  return make_stick_figure({{0, 0}, {0, 1}, {0, 2}, {-2, -1}, {2, -1}}, {{0, 1}, {1, 2}, {0, 3}, {0, 4}});
}
StickFigure path() { return make_stick_figure({{0, 0}, {1, 0}, {2, 1}}, {{0, 1}, {1, 2}}); }
}  // namespace

TEST_CASE("make_skeleton finds the nodes and the chains between them", "[correspondence_skeleton]") {
  const StickFigure f = y_shape();
  const Skeleton s = make_skeleton(f);
  CHECK(s.nodes == std::vector<int>{0, 2, 3, 4});
  CHECK(s.chains.size() == 3);
  CHECK(s.loops == 0);
  CHECK_FALSE(s.is_loop());
  const int chain = s.chain_of_vertex[1];
  REQUIRE(chain >= 0);
  CHECK(s.slot_of_vertex[1] == 1);
  CHECK(s.chains[std::size_t(chain)].vertices == std::vector<int>{0, 1, 2});
  // Every dart leaving a node starts a chain at one end or the other.
  for (int dart = 0; dart < s.dart_count(); ++dart)
    if (s.leaves_node(dart)) CHECK(s.chain_of_dart[std::size_t(s.far_dart[std::size_t(dart)])] == s.chain_of_dart[std::size_t(dart)]);
}

TEST_CASE("make_skeleton walks a loop counter-clockwise from vertex 0", "[correspondence_skeleton]") {
  // Listed clockwise.
  const StickFigure f = make_stick_figure({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}});
  const Skeleton s = make_skeleton(f);
  REQUIRE(s.is_loop());
  REQUIRE(s.chains.size() == 1);
  const Track& t = s.chains[0];
  CHECK(t.closed);
  CHECK(t.vertices == std::vector<int>{0, 3, 2, 1});
  CHECK(s.loops == 1);
}

TEST_CASE("compare_invariants says what differs", "[correspondence_skeleton]") {
  const StickFigure y = y_shape(), p = path();
  const Skeleton a = make_skeleton(y), b = make_skeleton(p);
  CHECK_NOTHROW(compare_invariants(a, a));
  try {
    compare_invariants(a, b);
    FAIL("no error");
  } catch (const IncompatibleFiguresError& error) {
    CHECK(error.kind() == Incompatibility::TopologyDiffers);
    CHECK_THAT(error.what(), Contains("3 ends and a junction of degree 3"));
    CHECK_THAT(error.what(), Contains("2 ends and no junction"));
  }
}

TEST_CASE("plural names a count with its noun", "[correspondence_skeleton]") {
  CHECK(plural(1, "vertex", "vertices") == "1 vertex");
  CHECK(plural(3, "vertex", "vertices") == "3 vertices");
}
