// Tracks and arc-length parameter maps of the figure correspondence.
//
// Surazhsky & Gotsman 2001, section 6 (dummy vertices), as
// figure_correspondence.h applies it: strokes of two drawings are matched by
// arc length, so every stage works on a stroke as a walk along the figure
// (a Track) and on monotone maps between two strokes' parameters
// (ParameterMap). Shared by every stage, hence its own header.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph::internal {

constexpr double kPi = 3.14159265358979323846;

/// A chain between two nodes, or a whole loop, as a walk along the figure:
/// vertices[k] to vertices[k + 1] over edges[k]. A loop repeats nothing: its
/// last edge closes back to vertices[0].
struct Track {
  std::vector<int> vertices;
  std::vector<int> edges;
  std::vector<double> arc;  ///< arc[k]: length from vertices[0] to vertices[k]; arc.back() the total
  bool closed = false;
  double length() const { return arc.back(); }
};

double distance(const Vec2& a, const Vec2& b);

Track make_track(const StickFigure& figure, std::vector<int> vertices, std::vector<int> edges, bool closed);

/// Parameter (arc length over total) of the track's k-th vertex.
double vertex_parameter(const Track& track, std::size_t k);

/// The point at parameter u in [0, 1] (a loop wraps u into [0, 1)): the
/// segment slot k it falls in and the fraction along that slot.
std::pair<std::size_t, double> locate(const Track& track, double u);

Vec2 point_on(const Vec2& a, const Vec2& b, double f);

Vec2 point_at(const StickFigure& figure, const Track& track, double u);

/// A monotone map from a source track's parameter to a target track's,
/// piecewise linear through anchors (u_k, w_k): the chain's ends and its
/// pins; for a loop, the pins or one shift, continued periodically.
struct ParameterMap {
  std::vector<double> u, w;  ///< increasing; a loop's w may exceed 1 (unwrapped)
  bool closed = false;

  double to_target(double x) const { return apply(u, w, x); }
  double to_source(double y) const { return apply(w, u, y); }

 private:
  double apply(const std::vector<double>& from, const std::vector<double>& to, double x) const {
    if (!closed) {
      std::size_t k = std::size_t(std::upper_bound(from.begin(), from.end(), x) - from.begin());
      k = std::min(std::max<std::size_t>(k, 1), from.size() - 1) - 1;
      const double span = from[k + 1] - from[k];
      return to[k] + (span > 0 ? (x - from[k]) / span : 0.0) * (to[k + 1] - to[k]);
    }
    // Periodic: shift x into [from[0], from[0] + 1) and add the closing anchor.
    const double base = from[0];
    double y = x - std::floor(x - base);
    std::size_t k = std::size_t(std::upper_bound(from.begin(), from.end(), y) - from.begin()) - 1;
    const double f0 = from[k], t0 = to[k];
    const double f1 = k + 1 < from.size() ? from[k + 1] : from[0] + 1;
    const double t1 = k + 1 < to.size() ? to[k + 1] : to[0] + 1;
    const double r = f1 > f0 ? (y - f0) / (f1 - f0) : 0.0;
    y = t0 + r * (t1 - t0);
    return y - std::floor(y);
  }
};

/// One chain of the source matched with one of the target, in a direction.
struct ChainMatch {
  int source_chain = -1;
  int target_chain = -1;
  bool reversed = false;  ///< the target chain is run from its last vertex
  ParameterMap map;       ///< source parameter -> target parameter along the run
};

/// A target track's parameter in the direction the match runs it.
double run_parameter(double w, bool reversed);

}  // namespace stickmorph::internal
