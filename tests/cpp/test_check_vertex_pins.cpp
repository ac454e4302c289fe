// check_vertex_pins: the pin rules of correspond_figures, in one place.
#include "catch.h"

#include <string>
#include <vector>

#include "stickmorph/errors.h"
#include "stickmorph/figure_correspondence.h"

using namespace stickmorph;

namespace {
// A Y: 0 the junction (degree 3), 1 inside the stem, 2 3 4 ends.
const std::vector<int> kY = {3, 2, 1, 1, 1};
// A polyline: 0 and 3 ends, 1 and 2 inside.
const std::vector<int> kLine = {1, 2, 2, 1};
}  // namespace

TEST_CASE("check_vertex_pins accepts like kinds", "[check_vertex_pins]") {
  CHECK(check_vertex_pins(kY, kLine, {}).ok());
  CHECK(check_vertex_pins(kY, kLine, {{2, 0}, {1, 2}, {3, 3}}).ok());
}

TEST_CASE("check_vertex_pins reports the first bad pin, its kind and degrees", "[check_vertex_pins]") {
  PinCheck check = check_vertex_pins(kY, kLine, {{2, 0}, {0, 3}});
  CHECK(check.defect == PinDefect::KindsDiffer);
  CHECK(check.pin == 1);
  CHECK(check.source_degree == 3);
  CHECK(check.target_degree == 1);
  CHECK(check.reason.rfind("pin 0:3 joins a vertex of degree 3 to one of degree 1", 0) == 0);

  check = check_vertex_pins(kY, kLine, {{1, 0}});  // inside a stroke to an end
  CHECK(check.defect == PinDefect::KindsDiffer);

  check = check_vertex_pins(kY, kLine, {{5, 0}});
  CHECK(check.defect == PinDefect::MissingSourceVertex);
  CHECK(check.reason == "pin 5:0: the source has no vertex 5 (it has 5 vertices)");
  CHECK(check_vertex_pins(kY, kLine, {{2, -1}}).defect == PinDefect::MissingTargetVertex);
  CHECK(check_vertex_pins(kY, kLine, {{2, 0}, {2, 3}}).defect == PinDefect::SourcePinnedTwice);
  check = check_vertex_pins(kY, kLine, {{2, 0}, {3, 0}});
  CHECK(check.defect == PinDefect::TargetPinnedTwice);
  CHECK(check.reason == "target vertex 0 is pinned twice");
}

TEST_CASE("correspond_figures refuses with the rule's reason", "[check_vertex_pins]") {
  const StickFigure y = make_stick_figure({{0, 0}, {0, -1}, {0, -2}, {-1, 1}, {1, 1}}, {{0, 1}, {1, 2}, {0, 3}, {0, 4}});
  const StickFigure line = make_stick_figure({{0, 0}, {1, 0}, {2, 0}, {3, 0}}, {{0, 1}, {1, 2}, {2, 3}});
  CorrespondenceOptions options;
  options.pins = {{0, 3}};
  try {
    (void)correspond_figures(y, line, options);
    FAIL("a pin joining a junction to an end was accepted");
  } catch (const InvalidArgumentError& error) {
    CHECK(std::string(error.what()) == "correspond: " + check_vertex_pins(kY, kLine, options.pins).reason);
  }
}
