// The as-rigid-as-possible trajectory of a stick figure: the motion that the
// rigid morph follows wherever it is valid (issue 12).
//
// As-rigid-as-possible interpolation on the figure's own edges, in the
// spirit of Alexa, Cohen-Or & Levin 2000 ("As-rigid-as-possible shape
// interpolation") with the figure's edges as the elements: every edge vector
// turns at constant speed by its own rotation, taken within 180° of the
// whole figure's rotation (SimilarityMotion::angle, so that all edges of a
// figure turned by 180° turn the same way and whole turns are kept), while
// its length changes linearly; the frame at t is the least-squares fit of
// the vertices to those edge vectors with each connected part's centroid on
// a straight line. On a tree the fit is exact: lengths and the angles
// between edges are interpolated linearly, forward kinematics. On a cycle
// the closure error is spread evenly.
//
// Nothing here keeps the guide from self-intersecting; guided_morph.h makes
// the valid morph follow it as closely as validity allows, and every frame
// is verified exactly there. The time table that evens the speed where the
// guide's own is uneven (issue 12, item 3) is computed on the guide, because
// it is cheap to sample: a triangular solve per sample on a Laplacian
// factored once.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stickmorph/local_timing.h"
#include "stickmorph/similarity_motion.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// Easing on top of even speed.
enum class Easing {
  None,   ///< constant speed along the motion
  InOut,  ///< slow in and slow out: the smoothstep 3u^2 - 2u^3 of the time
};

/// "none", "in-out" -> easing.
/// @throws InvalidArgumentError naming the accepted names.
Easing parse_easing(const std::string& name);
std::string easing_name(Easing easing);

/// What the rigid morph (guided_morph.h) follows: the figure's #V positions
/// in output space at every morph parameter u in [0, 1], and the parameter
/// at every animation time. RigidGuide is the pair's; the key-pose
/// sequence's segments (key_pose_guide.h) are others.
class GuideTrajectory {
 public:
  virtual ~GuideTrajectory() = default;
  /// The #V vertex positions at morph parameter u in [0, 1]: the segment's
  /// first figure at 0 and its last at 1 up to rounding.
  virtual std::vector<Vec2> at(double u) const = 0;
  /// The morph parameter at animation time t in [0, 1]: 0 -> 0, 1 -> 1,
  /// increasing.
  virtual double parameter_at(double t, Easing easing) const = 0;
  /// Whether the morph may retime itself by its own motion where it leaves
  /// the trajectory, for even speed (GuidedMorph). A trajectory whose timing
  /// is part of the motion (a key-pose segment, whose speed at its keys
  /// must match its neighbours') says no, and is followed at its own times.
  virtual bool retimed_by_morph() const { return true; }
  /// Local timing (local_timing.h): every vertex's local time at morph
  /// parameter u (#V), or empty where the whole figure runs on u itself
  /// (no local timing, or overlap 0). GuidedMorph places the guide frame's
  /// Steiner vertices on the same clocks.
  virtual std::vector<double> vertex_times(double /*u*/) const { return {}; }
};

class RigidGuide : public GuideTrajectory {
 public:
  /// `source`'s edges join the vertices; `target_vertices` (#V by 2) are
  /// the target's positions of the same vertices; `similarity` the morph's
  /// whole motion (its angle gives every edge's turn, with the extra turns).
  /// `timing`, if given and not plain (local_timing.h; one weight per
  /// vertex), runs every edge and part on its local clock: at(u) turns and
  /// stretches each edge at its local time and places each part by its
  /// leading vertices. parameter_at stays the plain guide's, so that the
  /// delays are measured on the morph's own clock.
  /// @throws InvalidArgumentError if the vertex counts differ.
  RigidGuide(const StickFigure& source, const std::vector<Vec2>& target_vertices,
             const SimilarityMotion& similarity, const std::optional<LocalTiming>& timing = std::nullopt);
  ~RigidGuide() override;
  RigidGuide(RigidGuide&&) noexcept;
  RigidGuide& operator=(RigidGuide&&) noexcept;

  /// The guide's #V vertex positions at morph parameter u in [0, 1]; the
  /// source at 0 and the target at 1 up to rounding.
  std::vector<Vec2> at(double u) const override;

  /// The morph parameter at animation time t in [0, 1]: the (eased) time
  /// itself while the guide's speed stays within 1.3 times its mean
  /// (internal::kMostUnevenSpeed; then
  /// every edge's length changes linearly in time and its angle at constant
  /// speed, the as-rigid-as-possible interpolation exactly, issue 30);
  /// otherwise the least blend (1 - a) t + a e(t) with the even-speed
  /// parameter e(t) (equal RMS vertex displacement per equal step of time:
  /// the cumulative motion, sampled finely, inverted) that brings the
  /// largest speed within 1.3 times the mean (issue 12's even speed). A
  /// figure that grows or shrinks a lot as it turns moves fastest where it
  /// is largest, which is what such a blend evens. 0 -> 0 and 1 -> 1
  /// exactly; increasing. A guide that does not move (beyond rounding)
  /// keeps t, eased.
  double parameter_at(double t, Easing easing = Easing::None) const override;

  /// Not where local timing delays parts: the delays are part of the
  /// motion, and retiming by the morph's own speed would move them.
  bool retimed_by_morph() const override;
  std::vector<double> vertex_times(double u) const override;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace stickmorph
