// internal::Fit, best_fit, candidate_fit and match_loops
// (correspondence_choice.h): the cost of a matching and the choice among
// matchings.
#include "catch.h"

#include <cmath>

#include "stickmorph/internal/correspondence_choice.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {
Fit fit(double residual, double rotation) {
  Fit f;
  f.residual = residual;
  f.rotation = rotation;
  return f;
}
// A triangle with three different sides, turned by `angle` about the origin
// and scaled by `scale`.
StickFigure triangle(double angle, double scale) {
  std::vector<Vec2> points{{0, 0}, {3, 0}, {1, 2}};
  for (Vec2& p : points)
    p = {scale * (std::cos(angle) * p[0] - std::sin(angle) * p[1]),
         scale * (std::sin(angle) * p[0] + std::cos(angle) * p[1])};
  return make_stick_figure(points, {{0, 1}, {1, 2}, {2, 0}});
}
}  // namespace

TEST_CASE("Fit charges the rotation from the reference", "[correspondence_choice]") {
  CHECK(fit(0.1, 0).cost() == Approx(0.1));
  CHECK(fit(0.1, kPi).cost() == Approx(0.3));
  CHECK(fit(0, kPi).cost() == 0);  // an exact fit is never charged
  Fit turned = fit(0.1, kPi);
  turned.reference = kPi;
  CHECK(turned.cost() == Approx(0.1));
  CHECK(turned.turn() == Approx(0).margin(1e-15));
}

TEST_CASE("best_fit takes the least cost and breaks near ties by the smaller turn", "[correspondence_choice]") {
  CHECK(best_fit({fit(0.5, 0), fit(0.1, 0.2), fit(0.3, 0)}) == 1);
  CHECK(best_fit({fit(0.1, 0.5), fit(0.1, -0.1), fit(0.1, 0.3)}) == 1);
  CHECK(best_fit({fit(0.1, 0.1), fit(0.1003, 0.0)}) == 1);  // a near tie: the smaller turn wins
}

TEST_CASE("match_loops finds the shift and the rotation of a turned loop", "[correspondence_choice]") {
  const StickFigure a = triangle(0, 1), b = triangle(0.5, 2);
  const Skeleton s = make_skeleton(a), t = make_skeleton(b);
  int compared = 0;
  const Candidate c = match_loops(s, t, {}, compared);
  CHECK(compared >= 1);
  REQUIRE(c.chains.size() == 1);
  CHECK(c.fit.residual == Approx(0).margin(1e-8));
  CHECK(c.fit.rotation == Approx(0.5).margin(1e-4));
  // The fit of the same pair at the chosen map, recomputed (the shift was
  // fitted unwrapped and is stored in [0, 1): equal up to roundoff).
  const Fit again = candidate_fit(s, t, c.chains, kLoopSamples);
  CHECK(again.residual == Approx(c.fit.residual).margin(1e-12));
  CHECK(again.rotation == Approx(c.fit.rotation).margin(1e-12));
}
