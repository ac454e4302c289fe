// Per-vertex delay weights and an overlap; see local_timing.h.
#include "stickmorph/local_timing.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "stickmorph/errors.h"

namespace stickmorph {

double local_time(double t, double weight, double overlap) {
  if (overlap == 0) return t;
  return std::clamp((t - overlap * weight) / (1 - overlap), 0.0, 1.0);
}

LocalTiming::LocalTiming(std::vector<double> delay, double overlap) : delay_(std::move(delay)), overlap_(overlap) {
  for (std::size_t v = 0; v < delay_.size(); ++v)
    if (!(delay_[v] >= 0 && delay_[v] <= 1))
      throw InvalidArgumentError("delay[" + std::to_string(v) + "] is " + format_double(delay_[v]) +
                                 ", outside [0, 1]");
  if (!(overlap_ >= 0 && overlap_ < 1))
    throw InvalidArgumentError("overlap is " + format_double(overlap_) + ", outside [0, 1)");
}

void LocalTiming::check_vertex_count(std::size_t vertex_count, const std::string& figure) const {
  if (delay_.size() != vertex_count)
    throw InvalidArgumentError("delay has " + std::to_string(delay_.size()) + (delay_.size() == 1 ? " entry" : " entries") +
                               " for " + std::to_string(vertex_count) + " vertices of " + figure);
}

LocalTiming LocalTiming::on_matched_figure(const std::vector<MatchedPlace>& places,
                                           const std::vector<Edge>& edges) const {
  std::vector<double> matched(places.size());
  for (std::size_t i = 0; i < places.size(); ++i) {
    const MatchedPlace& place = places[i];
    auto weight_of = [&](int v) {
      if (v < 0 || std::size_t(v) >= delay_.size())
        throw InternalError("LocalTiming::on_matched_figure: matched vertex " + std::to_string(i) + " names vertex " +
                            std::to_string(v) + " of " + std::to_string(delay_.size()));
      return delay_[std::size_t(v)];
    };
    if (place.vertex >= 0) {
      matched[i] = weight_of(place.vertex);
      continue;
    }
    if (place.edge < 0 || std::size_t(place.edge) >= edges.size())
      throw InternalError("LocalTiming::on_matched_figure: matched vertex " + std::to_string(i) + " names edge " +
                          std::to_string(place.edge) + " of " + std::to_string(edges.size()));
    const Edge& edge = edges[std::size_t(place.edge)];
    // Along the edge from its first vertex to its second, as the dummy
    // itself lies; kept inside [0, 1] against rounding.
    matched[i] = std::clamp((1 - place.fraction) * weight_of(edge[0]) + place.fraction * weight_of(edge[1]), 0.0, 1.0);
  }
  return LocalTiming(std::move(matched), overlap_);
}

LocalClock::LocalClock(const LocalTiming& timing, const std::vector<Edge>& edges, const std::vector<int>& part,
                       int part_count, std::vector<Vec2> first, std::vector<Vec2> last)
    : overlap_(timing.overlap()),
      weight_(timing.delay()),
      edges_(edges),
      part_(part),
      first_(std::move(first)),
      last_(std::move(last)) {
  const std::size_t n = weight_.size();
  if (part_.size() != n || first_.size() != n || last_.size() != n)
    throw InternalError("LocalClock: " + std::to_string(n) + " weights, " + std::to_string(part_.size()) +
                        " part labels, " + std::to_string(first_.size()) + " and " + std::to_string(last_.size()) +
                        " positions");
  std::vector<double> least(std::size_t(std::max(part_count, 0)), 1.0);
  for (std::size_t v = 0; v < n; ++v) {
    if (part_[v] < 0 || part_[v] >= part_count)
      throw InternalError("LocalClock: vertex " + std::to_string(v) + " is in part " + std::to_string(part_[v]) +
                          " of " + std::to_string(part_count));
    least[std::size_t(part_[v])] = std::min(least[std::size_t(part_[v])], weight_[v]);
  }
  for (const Edge& edge : edges_)
    if (edge[0] < 0 || edge[1] < 0 || std::size_t(edge[0]) >= n || std::size_t(edge[1]) >= n)
      throw InternalError("LocalClock: an edge names a vertex outside 0.." + std::to_string(n));
  lead_.resize(n);
  lead_sum_.assign(least.size(), 0.0);
  for (std::size_t v = 0; v < n; ++v) {
    // 1 for the part's leading vertices, down to 0 for one a whole overlap
    // behind them: never all zero in a part.
    lead_[v] = 1 - (weight_[v] - least[std::size_t(part_[v])]);
    lead_sum_[std::size_t(part_[v])] += lead_[v];
  }
}

std::vector<double> LocalClock::edge_times(double u) const {
  std::vector<double> times(edges_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e)
    times[e] = 0.5 * (local_time(u, weight_[std::size_t(edges_[e][0])], overlap_) +
                      local_time(u, weight_[std::size_t(edges_[e][1])], overlap_));
  return times;
}

std::vector<double> LocalClock::vertex_times(double u) const {
  std::vector<double> times(weight_.size());
  for (std::size_t v = 0; v < weight_.size(); ++v) times[v] = local_time(u, weight_[v], overlap_);
  return times;
}

void LocalClock::place_parts(double u, std::vector<Vec2>& positions) const {
  if (positions.size() != weight_.size())
    throw InternalError("LocalClock::place_parts: " + std::to_string(positions.size()) + " positions for " +
                        std::to_string(weight_.size()) + " vertices");
  // Per part: the lead-weighted centroid where it is, and where the
  // vertices' straight lines at their local times put it.
  std::vector<Vec2> shift(lead_sum_.size(), Vec2{0, 0});
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const double tau = local_time(u, weight_[v], overlap_);
    const double a = lead_[v];
    Vec2& s = shift[std::size_t(part_[v])];
    for (int c = 0; c < 2; ++c) s[c] += a * ((1 - tau) * first_[v][c] + tau * last_[v][c] - positions[v][c]);
  }
  for (std::size_t q = 0; q < shift.size(); ++q)
    for (int c = 0; c < 2; ++c) shift[q][c] /= lead_sum_[q];
  for (std::size_t v = 0; v < positions.size(); ++v)
    for (int c = 0; c < 2; ++c) positions[v][c] += shift[std::size_t(part_[v])][c];
}

}  // namespace stickmorph
