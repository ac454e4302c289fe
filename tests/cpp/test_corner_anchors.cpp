// internal::turn_at and anchor_corners (corner_anchors.h): corners of two
// drawings of a stroke matched as anchors of its arc-length map.
#include "catch.h"

#include "stickmorph/internal/corner_anchors.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {
// An L: right, then up.
StickFigure ell() { return make_stick_figure({{0, 0}, {1, 0}, {1, 1}}, {{0, 1}, {1, 2}}); }
}  // namespace

TEST_CASE("turn_at is the signed turn at a vertex of a track", "[corner_anchors]") {
  const StickFigure f = ell();
  const Track t = make_track(f, {0, 1, 2}, {0, 1}, false);
  CHECK(turn_at(f, t, 1) == Approx(kPi / 2));
  CHECK(turn_at(f, t, 0) == 0);  // a chain's ends do not turn
  CHECK(turn_at(f, t, 2) == 0);
  const Track back = make_track(f, {2, 1, 0}, {1, 0}, false);
  CHECK(turn_at(f, back, 1) == Approx(-kPi / 2));
}

TEST_CASE("anchor_corners adds a matched corner pair as an anchor", "[corner_anchors]") {
  const StickFigure f = ell();
  const Track t = make_track(f, {0, 1, 2}, {0, 1}, false);
  ChainMatch match;
  match.source_chain = match.target_chain = 0;
  match.map.u = {0, 1};
  match.map.w = {0, 1};
  anchor_corners(f, t, f, t, match);
  CHECK(match.map.u == std::vector<double>{0, 0.5, 1});
  CHECK(match.map.w == std::vector<double>{0, 0.5, 1});
}

TEST_CASE("anchor_corners leaves a map without corners alone", "[corner_anchors]") {
  const StickFigure straight = make_stick_figure({{0, 0}, {1, 0}, {2, 0}}, {{0, 1}, {1, 2}});
  const Track t = make_track(straight, {0, 1, 2}, {0, 1}, false);
  ChainMatch match;
  match.map.u = {0, 1};
  match.map.w = {0, 1};
  anchor_corners(straight, t, straight, t, match);
  CHECK(match.map.u == std::vector<double>{0, 1});
}
