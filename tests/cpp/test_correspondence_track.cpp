// internal::make_track, vertex_parameter, locate, point_at, point_on,
// distance, run_parameter and ParameterMap (correspondence_track.h): the
// arc-length parameters that the correspondence stages share.
#include "catch.h"

#include "stickmorph/internal/correspondence_track.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {
StickFigure bent_path() { return make_stick_figure({{0, 0}, {3, 0}, {3, 4}}, {{0, 1}, {1, 2}}); }
StickFigure unit_square() { return make_stick_figure({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}); }
}  // namespace

TEST_CASE("make_track measures the arc length along a chain", "[correspondence_track]") {
  const StickFigure f = bent_path();
  const Track t = make_track(f, {0, 1, 2}, {0, 1}, false);
  CHECK(t.arc == std::vector<double>{0, 3, 7});
  CHECK(t.length() == 7);
  CHECK(vertex_parameter(t, 1) == Approx(3.0 / 7));
  CHECK(distance({0, 0}, {3, 4}) == 5);
  CHECK(point_on({0, 0}, {2, 4}, 0.5) == Vec2{1, 2});
}

TEST_CASE("locate and point_at find the slot and the point at a parameter", "[correspondence_track]") {
  const StickFigure f = bent_path();
  const Track t = make_track(f, {0, 1, 2}, {0, 1}, false);
  const auto [k, fraction] = locate(t, 5.0 / 7);
  CHECK(k == 1);
  CHECK(fraction == Approx(0.5));
  const Vec2 p = point_at(f, t, 5.0 / 7);
  CHECK(p[0] == Approx(3));
  CHECK(p[1] == Approx(2));
  // An open track clamps: beyond its ends is its ends.
  CHECK(point_at(f, t, 2.0) == Vec2{3, 4});
  CHECK(point_at(f, t, -1.0) == Vec2{0, 0});
}

TEST_CASE("a closed track wraps its parameter round the loop", "[correspondence_track]") {
  const StickFigure f = unit_square();
  const Track t = make_track(f, {0, 1, 2, 3}, {0, 1, 2, 3}, true);
  CHECK(t.arc.size() == 5);
  CHECK(t.length() == 4);
  CHECK(locate(t, 1.375) == locate(t, 0.375));
  const Vec2 p = point_at(f, t, 0.875);  // on the closing edge 3 -> 0
  CHECK(p[0] == Approx(0));
  CHECK(p[1] == Approx(0.5));
}

TEST_CASE("run_parameter runs a target track backwards when reversed", "[correspondence_track]") {
  CHECK(run_parameter(0.25, false) == 0.25);
  CHECK(run_parameter(0.25, true) == 0.75);
}

TEST_CASE("ParameterMap is piecewise linear through its anchors", "[correspondence_track]") {
  ParameterMap open;
  open.u = {0, 0.5, 1};
  open.w = {0, 0.25, 1};
  CHECK(open.to_target(0.25) == Approx(0.125));
  CHECK(open.to_target(0.75) == Approx(0.625));
  CHECK(open.to_source(0.625) == Approx(0.75));
  // A loop's map: one shift, continued periodically.
  ParameterMap loop;
  loop.closed = true;
  loop.u = {0.0};
  loop.w = {0.25};
  CHECK(loop.to_target(0.5) == Approx(0.75));
  CHECK(loop.to_target(0.9) == Approx(0.15));
  CHECK(loop.to_source(0.15) == Approx(0.9));
}
