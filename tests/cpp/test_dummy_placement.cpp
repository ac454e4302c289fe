// internal::matched_place, dummy_slots and separate_on_edges
// (dummy_placement.h): dummy vertices placed strictly inside edges.
#include "catch.h"

#include "stickmorph/internal/dummy_placement.h"

using namespace stickmorph;
using namespace stickmorph::internal;

TEST_CASE("matched_place puts a dummy on its edge as listed", "[dummy_placement]") {
  // Edge 0 is listed against the track's direction.
  const StickFigure f = make_stick_figure({{0, 0}, {1, 0}, {1, 1}}, {{1, 0}, {1, 2}});
  const Track t = make_track(f, {0, 1, 2}, {0, 1}, false);
  Vec2 at{};
  char along = 1;
  const MatchedPlace dummy = matched_place(f, t, TrackPlace{-1, 0.25}, at, &along);
  CHECK(dummy.vertex == -1);
  CHECK(dummy.edge == 0);
  CHECK(dummy.fraction == Approx(0.5));
  CHECK(along == 0);
  CHECK(at == Vec2{0.5, 0});
  const MatchedPlace vertex = matched_place(f, t, TrackPlace{2, 1.0}, at);
  CHECK(vertex.vertex == 2);
  CHECK(vertex.edge == -1);
  CHECK(at == Vec2{1, 1});
  // A slot forces the edge when the parameter falls on a neighbour.
  const MatchedPlace forced = matched_place(f, t, TrackPlace{-1, 0.75}, at, nullptr, 0);
  CHECK(forced.edge == 0);
}

TEST_CASE("dummy_slots names the edge between a dummy's vertex neighbours", "[dummy_placement]") {
  const StickFigure f = make_stick_figure({{0, 0}, {1, 0}, {2, 0}}, {{0, 1}, {1, 2}});
  const Track t = make_track(f, {0, 1, 2}, {0, 1}, false);
  // Interior items: a dummy, vertex 1, a dummy.
  std::vector<MatchedItem> items(3);
  items[0].source = {-1, 0.25};
  items[1].source = {1, 0.5};
  items[2].source = {-1, 0.75};
  const std::vector<int> slots =
      dummy_slots(t, f.vertices.size(), items, [](const MatchedItem& item) { return item.source.vertex; }, false);
  CHECK(slots == std::vector<int>{0, -1, 1});
}

TEST_CASE("separate_on_edges spreads a run that rounding merged", "[dummy_placement]") {
  const StickFigure f = make_stick_figure({{0, 0}, {1, 0}}, {{0, 1}});
  MatchedPlace dummy;
  dummy.edge = 0;
  dummy.fraction = 0.5;
  std::vector<MatchedPlace> places(3, dummy);
  std::vector<Vec2> at(3, Vec2{0.5, 0});
  separate_on_edges(f, places, at, {1, 1, 1});
  CHECK(at == std::vector<Vec2>{{0.25, 0}, {0.5, 0}, {0.75, 0}});
  CHECK(places[2].fraction == 0.75);
  // Apart already: left as they are.
  std::vector<MatchedPlace> apart(2, dummy);
  apart[0].fraction = 0.2;
  apart[1].fraction = 0.4;
  std::vector<Vec2> apart_at{{0.2, 0}, {0.4, 0}};
  separate_on_edges(f, apart, apart_at, {1, 1});
  CHECK(apart_at == std::vector<Vec2>{{0.2, 0}, {0.4, 0}});
}
