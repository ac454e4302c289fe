// edge_set_difference: the undirected edges only one of two lists has
// (section 2.1's first test of compatibility).
#include "catch.h"

#include <vector>

#include "stickmorph/compatibility.h"

using namespace stickmorph;

TEST_CASE("edge_set_difference ignores order, direction and repeats", "[edge_set_difference]") {
  const EdgeSetDifference same = edge_set_difference({{0, 1}, {1, 2}, {2, 0}}, {{0, 2}, {1, 0}, {2, 1}, {1, 2}});
  CHECK(same.empty());
  CHECK(edge_set_difference({}, {}).empty());
}

TEST_CASE("edge_set_difference lists each side's own edges, low index first, sorted", "[edge_set_difference]") {
  const EdgeSetDifference d = edge_set_difference({{3, 1}, {0, 1}, {2, 1}}, {{1, 0}, {3, 0}, {2, 3}});
  CHECK(d.only_in_source == std::vector<Edge>{{1, 2}, {1, 3}});
  CHECK(d.only_in_target == std::vector<Edge>{{0, 3}, {2, 3}});
  CHECK_FALSE(d.empty());
}

TEST_CASE("check_compatibility names the first differing edge of the source's list", "[edge_set_difference]") {
  StickFigure source = make_stick_figure({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1}, {1, 2}, {2, 3}});
  StickFigure target = make_stick_figure({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1}, {1, 2}, {3, 0}});
  const CompatibilityReport report = check_compatibility(source, target);
  CHECK(report.kind == Incompatibility::EdgeSetDiffers);
  CHECK(report.vertices == std::vector<int>{2, 3});
  CHECK(report.reason.find("of the source is not an edge of the target") != std::string::npos);
}
