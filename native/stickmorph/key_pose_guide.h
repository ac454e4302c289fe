// The as-rigid-as-possible trajectory of a stick figure through K key poses
// (issue 28): the motion a sequence morph follows wherever it is valid, as
// RigidGuide (rigid_guide.h) is for a pair.
//
// RigidGuide turns every edge at a constant rate from one figure to the
// next. Chaining such guides key to key gives a motion whose velocity
// jumps at every interior key (each segment starts and ends on its own).
// Here every quantity the pair guide interpolates linearly follows one
// cubic spline through all keys instead, C1 at the interior keys:
//   - every edge's direction angle, the turn from key to key taken as the
//     pair guide takes it (internal/edge_turns.h: consistent round every
//     vertex, each part's mean turn nearest the figure's similarity
//     rotation between the keys, in the segment's direction and with its
//     whole turns), accumulated along the sequence so that turns add up;
//   - every edge's log-length (a length stays positive);
//   - every connected part's centroid;
// and the frame at t is the least-squares figure of the edges at t
// (internal/edge_vector_fit.h), each part on its centroid. On a tree the fit
// is exact, so at every key the guide is that key up to rounding.
//
// The spline is piecewise cubic Hermite with knots at the key times; its
// tangent at an interior key is the derivative there of the parabola
// through that key and its two neighbours (the Bessel tangent, which takes
// uneven key spacing into account), so both segments meeting at a key share
// it: the guide's velocity is continuous. At the first and last key (no
// loop) the tangent is the parabola's through the first or last three keys,
// so three keys give one parabola per quantity; two keys give straight
// lines (constant turn rates, as the pair guide, with lengths changing
// geometrically). With `loop` the last key is followed by key 1 at time 1
// and the tangents are periodic, so the motion joins itself smoothly; a
// held key has tangent zero: the motion stops there.
//
// The log-lengths take the same values and tangents at the knots but not
// the cubic between them: each follows its segment's straight line and
// turns into the knot's tangent only within a quarter of the segment from
// either end (x (1 - x/b)^2 blends, value 0 and slope 1 at the knot, flat
// from b on). Still C1, and an edge changes its length linearly over most
// of a segment, as in the pair morph; a cubic bends the whole segment
// (issue 28 holds each segment to the pair morph's rigidity target).
//
// Like RigidGuide, nothing here keeps the guide from self-intersecting (and
// between keys a spline may overshoot where a linear turn would not): the
// sequence morph follows it only as closely as validity allows, and checks
// every frame exactly.
#pragma once

#include <memory>
#include <vector>

#include "stickmorph/similarity_motion.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

struct KeyPoseGuideOptions {
  /// After the last key the motion returns to the first, at time 1.
  bool loop = false;
  /// Per key (empty: none): the motion stops at that key.
  std::vector<bool> hold;
  /// Per segment (empty: Short, no extra turns for all): which way the
  /// figure turns from a key to the next, and how many whole turns it adds
  /// (as the pair morph's rotation and turns options). A sequence of K keys
  /// has K - 1 segments, K with `loop`.
  std::vector<RotationDirection> rotation;
  std::vector<int> turns;
};

class KeyPoseGuide {
 public:
  /// `keys`: K >= 2 drawings of one figure, #V by 2 each, joined by `edges`
  /// (every edge of nonzero length in every key, as in a valid figure);
  /// `key_times`: K times, strictly increasing from 0, the last 1 without
  /// `loop` and below 1 with it.
  /// @throws InvalidArgumentError naming the key, the time or the option
  ///         that is wrong.
  KeyPoseGuide(const std::vector<std::vector<Vec2>>& keys, const std::vector<Edge>& edges,
               const std::vector<double>& key_times, const KeyPoseGuideOptions& options = {});
  ~KeyPoseGuide();
  KeyPoseGuide(KeyPoseGuide&&) noexcept;
  KeyPoseGuide& operator=(KeyPoseGuide&&) noexcept;

  /// The guide's #V vertex positions at time t in [0, 1]: key k at its
  /// time up to rounding (exactly the least-squares fit of its own edges).
  /// @throws InvalidArgumentError for t outside [0, 1].
  std::vector<Vec2> at(double t) const;

  /// The figure on segment `segment` (0-based) with edge e at parameter
  /// edge_u[e] of the segment (0 its first key, 1 its last; as at(t) maps
  /// the segment's times) and every part's centroid at `u`: what local
  /// timing (local_timing.h) asks of the sequence's guide. With every
  /// edge_u[e] equal to u, at() of the time at u.
  /// @throws InvalidArgumentError for a segment or a parameter out of range,
  ///         or not one parameter per edge.
  std::vector<Vec2> in_segment(int segment, const std::vector<double>& edge_u, double u) const;

  /// The segment that time t lies in: s for t in [time s, time s + 1), the
  /// last segment at t = 1.
  int segment_at(double t) const;

  /// The knot times: the K key times, then 1 with `loop` (the first key again).
  const std::vector<double>& knot_times() const;

  /// The connected part of every vertex (#V), numbered as the guide's fit
  /// numbers them, and their count.
  const std::vector<int>& part() const;
  int part_count() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace stickmorph
