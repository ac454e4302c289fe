// Dummy vertices placed on edges (dummy_placement.h; Surazhsky & Gotsman
// 2001, section 6).
#include "stickmorph/internal/dummy_placement.h"

#include <algorithm>
#include <cmath>

namespace stickmorph::internal {

MatchedPlace matched_place(const StickFigure& figure, const Track& track, const TrackPlace& place, Vec2& position,
                           char* track_runs_along, int slot) {
  MatchedPlace result;
  if (place.vertex >= 0) {
    result.vertex = place.vertex;
    position = figure.vertices[std::size_t(place.vertex)];
    return result;
  }
  auto [k, f] = locate(track, place.p);
  if (slot >= 0 && k != std::size_t(slot)) {
    // The parameter fell on a neighbouring edge: edges shorter than the
    // rounding of the arc length around them have the same arc values, and
    // locate takes the last. On the right edge, as near the parameter as
    // the arc allows (separate_on_edges parts it from the edge's ends).
    k = std::size_t(slot);
    double u = place.p;
    if (track.closed) u -= std::floor(u);
    const double at = std::clamp(u, 0.0, 1.0) * track.length();
    const double span = track.arc[k + 1] - track.arc[k];
    f = span > 0 ? std::clamp((at - track.arc[k]) / span, 0.0, 1.0) : 0.5;
  }
  const int a = track.vertices[k];
  const int edge = track.edges[k];
  // Reported along edges[edge] as listed.
  const bool along = figure.edges[std::size_t(edge)][0] == a;
  if (track_runs_along) *track_runs_along = along;
  result.edge = edge;
  result.fraction = along ? f : 1.0 - f;
  const Edge& e = figure.edges[std::size_t(edge)];
  position = point_on(figure.vertices[std::size_t(e[0])], figure.vertices[std::size_t(e[1])], result.fraction);
  return result;
}

void separate_on_edges(const StickFigure& figure, std::vector<MatchedPlace>& places, std::vector<Vec2>& at,
                       const std::vector<char>& track_runs_along) {
  std::size_t begin = 0;
  while (begin < places.size()) {
    if (places[begin].vertex >= 0 || places[begin].edge < 0) {
      ++begin;
      continue;
    }
    const int edge = places[begin].edge;
    std::size_t end = begin + 1;
    while (end < places.size() && places[end].vertex < 0 && places[end].edge == edge) ++end;
    const Edge& e = figure.edges[std::size_t(edge)];
    const Vec2& a = figure.vertices[std::size_t(e[0])];
    const Vec2& b = figure.vertices[std::size_t(e[1])];
    // The track runs along the edge as listed or against it (not read from
    // the fractions: rounded ones tie).
    const bool along = track_runs_along[begin] != 0;
    const Vec2& first = along ? a : b;
    const Vec2& last = along ? b : a;
    bool merged = at[begin] == first || at[end - 1] == last;
    for (std::size_t k = begin + 1; k < end && !merged; ++k) merged = at[k] == at[k - 1];
    if (merged) {
      const double count = double(end - begin + 1);
      for (std::size_t k = begin; k < end; ++k) {
        const double g = double(k - begin + 1) / count;
        places[k].fraction = along ? g : 1.0 - g;
        at[k] = point_on(a, b, places[k].fraction);
      }
    }
    begin = end;
  }
}

}  // namespace stickmorph::internal
