// internal::check_pins and chain_map (correspondence_pins.h): the pins' own
// rules and the arc-length map of a chain pair through its pins.
#include "catch.h"

#include "stickmorph/errors.h"
#include "stickmorph/internal/correspondence_pins.h"

using namespace stickmorph;
using namespace stickmorph::internal;
using stickmorph_test::Contains;

TEST_CASE("check_pins refuses pins that break their own rules", "[correspondence_pins]") {
  const std::vector<int> degree{1, 2, 1};
  CHECK_NOTHROW(check_pins(degree, degree, {{0, 2}, {1, 1}}));
  CHECK_THROWS_WITH(check_pins(degree, degree, {{5, 0}}),
                    Contains("pin 5:0: the source has no vertex 5 (it has 3 vertices)"));
  CHECK_THROWS_WITH(check_pins(degree, degree, {{0, 7}}), Contains("the target has no vertex 7"));
  CHECK_THROWS_WITH(check_pins(degree, degree, {{0, 0}, {0, 2}}), Contains("source vertex 0 is pinned twice"));
  CHECK_THROWS_WITH(check_pins(degree, degree, {{0, 0}, {2, 0}}), Contains("target vertex 0 is pinned twice"));
  CHECK_THROWS_AS(check_pins(degree, degree, {{0, 1}}), InvalidArgumentError);
  CHECK_THROWS_WITH(check_pins(degree, degree, {{0, 1}}), Contains("joins a vertex of degree 1 to one of degree 2"));
}

TEST_CASE("chain_map runs through the pins of a chain pair in order", "[correspondence_pins]") {
  PinPlace pin;
  pin.source_chain = 0;
  pin.target_chain = 1;
  pin.u = 0.5;
  pin.w = 0.25;
  const std::optional<ParameterMap> forward = chain_map({pin}, 0, 1, false);
  REQUIRE(forward);
  CHECK(forward->u == std::vector<double>{0, 0.5, 1});
  CHECK(forward->w == std::vector<double>{0, 0.25, 1});
  const std::optional<ParameterMap> backward = chain_map({pin}, 0, 1, true);
  REQUIRE(backward);
  CHECK(backward->w == std::vector<double>{0, 0.75, 1});
  // A pin of another source chain does not matter; one sent to another
  // target chain, or pins out of order, rule the pair out.
  CHECK(chain_map({pin}, 2, 1, false));
  CHECK_FALSE(chain_map({pin}, 0, 0, false));
  PinPlace later = pin;
  later.u = 0.75;
  later.w = 0.125;
  CHECK_FALSE(chain_map({pin, later}, 0, 1, false));
}
