// internal::resample (arc_length_resampling.h): the matched vertices along a
// chain pair, close pairs merged and the rest given dummy partners.
#include "catch.h"

#include "stickmorph/internal/arc_length_resampling.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {
ChainMatch identity_match() {
  ChainMatch match;
  match.source_chain = match.target_chain = 0;
  match.map.u = {0, 1};
  match.map.w = {0, 1};
  return match;
}
}  // namespace

TEST_CASE("resample pairs the vertices of a chain with themselves", "[arc_length_resampling]") {
  const StickFigure f = make_stick_figure({{0, 0}, {1, 0}, {2, 0}, {3, 0}}, {{0, 1}, {1, 2}, {2, 3}});
  const Track t = make_track(f, {0, 1, 2, 3}, {0, 1, 2}, false);
  const std::vector<MatchedItem> items = resample(t, t, identity_match(), {});
  REQUIRE(items.size() == 2);  // the interior vertices only
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(items[k].source.vertex == int(k) + 1);
    CHECK(items[k].target.vertex == int(k) + 1);
  }
}

TEST_CASE("resample gives vertices far from any partner a dummy", "[arc_length_resampling]") {
  const StickFigure s = make_stick_figure({{0, 0}, {1, 0}, {2, 0}}, {{0, 1}, {1, 2}});
  const StickFigure t = make_stick_figure({{0, 0}, {2.0 / 3, 0}, {4.0 / 3, 0}, {2, 0}}, {{0, 1}, {1, 2}, {2, 3}});
  const Track st = make_track(s, {0, 1, 2}, {0, 1}, false);
  const Track tt = make_track(t, {0, 1, 2, 3}, {0, 1, 2}, false);
  const std::vector<MatchedItem> items = resample(st, tt, identity_match(), {});
  REQUIRE(items.size() == 3);
  // Target vertex 1, source vertex 1, target vertex 2, in order along the chain.
  CHECK(items[0].source.vertex == -1);
  CHECK(items[0].target.vertex == 1);
  CHECK(items[0].source.p == Approx(1.0 / 3));
  CHECK(items[1].source.vertex == 1);
  CHECK(items[1].target.vertex == -1);
  CHECK(items[1].target.p == Approx(0.5));
  CHECK(items[2].target.vertex == 2);
  CHECK(items[2].source.p == Approx(2.0 / 3));
}

TEST_CASE("resample keeps a pinned pair together", "[arc_length_resampling]") {
  const StickFigure s = make_stick_figure({{0, 0}, {1, 0}, {2, 0}}, {{0, 1}, {1, 2}});
  const StickFigure t = make_stick_figure({{0, 0}, {2.0 / 3, 0}, {4.0 / 3, 0}, {2, 0}}, {{0, 1}, {1, 2}, {2, 3}});
  const Track st = make_track(s, {0, 1, 2}, {0, 1}, false);
  const Track tt = make_track(t, {0, 1, 2, 3}, {0, 1, 2}, false);
  const std::vector<MatchedItem> items = resample(st, tt, identity_match(), {{1, 2}});
  REQUIRE(items.size() == 2);
  CHECK(items[1].source.vertex == 1);
  CHECK(items[1].target.vertex == 2);
}
