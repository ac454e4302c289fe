// Tracks along a figure and arc-length parameters (correspondence_track.h;
// Surazhsky & Gotsman 2001, section 6).
#include "stickmorph/internal/correspondence_track.h"

#include <algorithm>
#include <cmath>

namespace stickmorph::internal {

double distance(const Vec2& a, const Vec2& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }

Track make_track(const StickFigure& figure, std::vector<int> vertices, std::vector<int> edges, bool closed) {
  Track track;
  track.closed = closed;
  track.arc.push_back(0);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const int a = vertices[k], b = vertices[(k + 1) % vertices.size()];
    track.arc.push_back(track.arc.back() + distance(figure.vertices[a], figure.vertices[b]));
  }
  track.vertices = std::move(vertices);
  track.edges = std::move(edges);
  return track;
}

double vertex_parameter(const Track& track, std::size_t k) { return track.arc[k] / track.length(); }

std::pair<std::size_t, double> locate(const Track& track, double u) {
  if (track.closed) u -= std::floor(u);
  u = std::clamp(u, 0.0, 1.0);
  const double s = u * track.length();
  std::size_t k = std::size_t(std::upper_bound(track.arc.begin(), track.arc.end(), s) - track.arc.begin());
  k = std::min(std::max<std::size_t>(k, 1), track.edges.size()) - 1;
  const double span = track.arc[k + 1] - track.arc[k];
  return {k, span > 0 ? std::clamp((s - track.arc[k]) / span, 0.0, 1.0) : 0.0};
}

Vec2 point_on(const Vec2& a, const Vec2& b, double f) {
  return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])};
}

Vec2 point_at(const StickFigure& figure, const Track& track, double u) {
  const auto [k, f] = locate(track, u);
  const Vec2& a = figure.vertices[track.vertices[k]];
  const Vec2& b = figure.vertices[track.vertices[(k + 1) % track.vertices.size()]];
  return point_on(a, b, f);
}

double run_parameter(double w, bool reversed) { return reversed ? 1.0 - w : w; }

}  // namespace stickmorph::internal
