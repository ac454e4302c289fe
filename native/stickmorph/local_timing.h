// Local control of a morph's timing: per-vertex delay weights and an
// overlap, so that a part of the figure lags the rest (overlapping action,
// follow-through; issue 31).
//
// The paper (section 2.2) names the limit of the morph of [8]: it is
// global and permits no local control of the vertex trajectories, which its
// reference [17] (Surazhsky & Gotsman 2001, "Controllable morphing of compatible
// planar triangulations") addresses: any positive convex-combination
// weights at time t keep the morph valid, so the morph may follow any
// desired motion where that motion is valid (guided_morph.h). Here the
// desired motion is the rigid guide run on local clocks: vertex v with
// delay weight w_v in [0, 1] and overlap d in [0, 1) moves at its local time
//
//     tau_v(u) = clamp((u - d w_v) / (1 - d), 0, 1)
//
// of the morph's parameter u: weight-0 parts start at once and finish at
// 1 - d, weight-1 parts start at d and finish at 1. Every edge turns and
// changes its length at the mean of its ends' local times (LocalClock), so
// a lagging limb stays attached at its junction and turns late rather than
// being dragged; each connected part is placed by its leading vertices
// (LocalClock::place_parts). The guide frames so timed are followed by the
// same machinery as the plain guide's: where the delayed motion is not
// valid, the morph gives way as little as validity needs, and every frame is
// checked exactly.
//
// d = 0 is the plain morph bit for bit: the guides make no LocalClock then.
#pragma once

#include <string>
#include <vector>

#include "stickmorph/figure_correspondence.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// clamp((t - overlap weight) / (1 - overlap), 0, 1): 0 at t = 0 and 1 at
/// t = 1 for every weight in [0, 1] and overlap in [0, 1).
double local_time(double t, double weight, double overlap);

/// Delay weights and an overlap, checked: every weight in [0, 1], the
/// overlap in [0, 1). The vertex count is checked against the figure when
/// the morph gets it (check_vertex_count), since interfaces check options
/// before they read figures.
class LocalTiming {
 public:
  /// @throws InvalidArgumentError naming the entry: "delay[3] is 1.5,
  ///         outside [0, 1]" (not a number too), "overlap is 1, outside
  ///         [0, 1)".
  LocalTiming(std::vector<double> delay, double overlap);

  /// #V delay weights, one per source vertex.
  const std::vector<double>& delay() const { return delay_; }
  double overlap() const { return overlap_; }
  /// Overlap 0: every part on the morph's own clock, which is the plain
  /// morph (the guides then make no LocalClock).
  bool is_plain() const { return overlap_ == 0; }

  /// @throws InvalidArgumentError "delay has 10 entries for 12 vertices of
  ///         <figure>".
  void check_vertex_count(std::size_t vertex_count, const std::string& figure = "the source") const;

  /// The weights on a matched figure (figure_correspondence.h): matched
  /// vertex i at `places[i]` of the figure these weights are of, whose
  /// edges are `edges`; a dummy takes the weight interpolated along its
  /// edge. The overlap is kept.
  /// @throws InternalError if a place names a vertex or an edge outside the figure.
  LocalTiming on_matched_figure(const std::vector<MatchedPlace>& places, const std::vector<Edge>& edges) const;

 private:
  std::vector<double> delay_;
  double overlap_ = 0;
};

/// A figure's local clocks: per edge and per vertex, its local time at
/// morph parameter u in [0, 1], and each part's placement.
class LocalClock {
 public:
  /// `timing` (not plain, its weights one per vertex of the figure) on the
  /// figure with `edges`, whose vertex v lies in part `part[v]` of
  /// `part_count`; `first` and `last` (#V by 2) the figure's positions at
  /// u = 0 and 1, whose straight lines place the parts (place_parts).
  /// @throws InternalError if the sizes disagree.
  LocalClock(const LocalTiming& timing, const std::vector<Edge>& edges, const std::vector<int>& part,
             int part_count, std::vector<Vec2> first, std::vector<Vec2> last);

  double overlap() const { return overlap_; }

  /// #E: every edge's local time at u, the mean of its ends'.
  std::vector<double> edge_times(double u) const;
  /// #V: every vertex's local time at u.
  std::vector<double> vertex_times(double u) const;

  /// Moves each part of `positions` (#V by 2, a figure whose edges are at
  /// their local times) rigidly, so that the centroid of its vertices, each
  /// weighted by how far it leads its part (1 - (w_v - least w of the part)),
  /// lies where their straight lines from `first` to `last` at their local
  /// times put that centroid. A part whose weights are all equal is then
  /// placed exactly as its straight-line centroid at that shared time; a
  /// lagging limb leaves the rest where it would be without it.
  void place_parts(double u, std::vector<Vec2>& positions) const;

 private:
  double overlap_ = 0;
  std::vector<double> weight_;  // per vertex
  std::vector<Edge> edges_;
  std::vector<int> part_;
  std::vector<double> lead_;     // per vertex: 1 - (w_v - least w of its part)
  std::vector<double> lead_sum_; // per part
  std::vector<Vec2> first_, last_;
};

}  // namespace stickmorph
