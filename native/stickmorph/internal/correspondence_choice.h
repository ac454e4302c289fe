// The choice among matchings of the correspondence (step 3 of
// figure_correspondence.h): the geometric cost of a candidate, the winner
// among near ties, and the matching of two loops by cyclic shift.
//
// Surazhsky & Gotsman 2001, section 6 leaves the correspondence to the
// user; here it is chosen as the matching whose arc-length samples fit by
// the best similarity (rotation, scale, translation, never a reflection),
// with a small charge for the rotation so that a nearly symmetric figure
// does not spin.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "stickmorph/internal/correspondence_pins.h"
#include "stickmorph/internal/correspondence_skeleton.h"
#include "stickmorph/internal/correspondence_track.h"

namespace stickmorph::internal {

// Arc-length samples per chain (and per loop) for the geometric cost: enough
// to tell a stroke's shape, independent of how finely it is drawn.
constexpr int kChainSamples = 8;
constexpr int kLoopSamples = 128;
// The cost of a matching is its similarity residual times 1 + this much
// times (1 - cos rotation), up to three times the residual for a half turn:
// a nearly symmetric figure (an X, a letter with a near half-turn symmetry)
// drawn twice can fit slightly better turned half round by accident of
// style, and a morph that spins it by 150 degrees where 30 would do is not
// what anyone drew. A factor, not a sum: an exact fit (residual 0) still
// beats every other, however far it turns, so a figure drawn turned by 120
// degrees keeps its own vertices.
constexpr double kRotationCharge = 1.0;
// Costs within this much of the best are ties, broken by the smaller
// rotation: a square matched onto a square has four equal fits.
constexpr double kTieRelative = 0.02;
constexpr double kTieAbsolute = 1e-9;  // roundoff of the residual of exact symmetries

/// Weighted similarity fit of sample pairs: the residual
/// 1 - |sum w conj(a) b|^2 / (sum w |a|^2 * sum w |b|^2) of centred points
/// (0 for a perfect similarity, 1 for no relation) and the rotation.
struct Fit {
  double residual = 1;
  double rotation = 0;  ///< radians, counter-clockwise, in (-pi, pi]
  double reference = 0;  ///< the rotation charged from (Skeleton::reference_rotation)
  double cost() const { return residual * (1 + kRotationCharge * (1 - std::cos(rotation - reference))); }
  /// How far the rotation is from the reference, in [0, pi].
  double turn() const { return std::abs(std::remainder(rotation - reference, 2 * kPi)); }
};

/// A candidate matching: node images and the chain pairs.
struct Candidate {
  std::vector<int> node_image;     ///< per source vertex: target node, -1 if not a node
  std::vector<ChainMatch> chains;  ///< per source chain
  Fit fit;
};

// Samples of every chain pair for the similarity fit, weighted by the
// chains' share of the drawings' lengths so that a long stroke counts more
// than a short one however finely either is drawn.
Fit candidate_fit(const Skeleton& source, const Skeleton& target, const std::vector<ChainMatch>& chains,
                  int samples_per_chain);

/// The least-cost fit; near ties go to the smallest rotation (from the
/// reference).
std::size_t best_fit(const std::vector<Fit>& fits);

/// Two loops, both counter-clockwise: the shift of least cost (or the pins'
/// map), as one candidate.
Candidate match_loops(const Skeleton& source, const Skeleton& target, const std::vector<PinPlace>& pins,
                      int& compared);

}  // namespace stickmorph::internal
