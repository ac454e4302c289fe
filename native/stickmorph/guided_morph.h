// The rigid morph: a convex-combination morph that follows an
// as-rigid-as-possible guide wherever the guide is valid (issue 12).
//
// Surazhsky & Gotsman 2001, "Controllable morphing of compatible planar
// triangulations" (ACM TOG 20(4), the paper's [17]): the morph of [8] may
// take any positive, row-stochastic weights at time t, not just the blend
// (1 - t) W0 + t W1, and stays valid by Tutte's theorem. So a node whose
// star is valid in a desired frame can take its weights from that frame
// (mean value coordinates, positive there), and the solve then reproduces
// the desired frame wherever all the stars are valid, and stays a valid
// triangulation everywhere else.
//
// Here, at morph parameter u (RigidGuide::parameter_at of the animation
// time, for even speed):
//   1. the guide (RigidGuide, ARAP on the figure's edges, in output space)
//      is mapped back by the similarity (similarity_motion.h) into the
//      normalised morph's space, where the enclosure is fixed;
//   2. the Steiner vertices are placed with the figure held at the guide,
//      one of two ways for the whole morph (chosen at construction from 15
//      sampled guide frames: the rigid one only where the guide is trusted
//      with it at every sample, or at two more, than with W(u)): by the
//      blended weights W(u) of [8], or as rigidly as possible
//      (internal/rigid_steiner_placement.h: every triangle's source-to-
//      target map interpolated as Alexa et al. 2000 do, turning the way
//      the guide turns its figure edges, and the Steiner vertices the
//      least-squares fit; issue 30). That is the guide frame G. Where the
//      guide runs its vertices on local clocks (local_timing.h, issue 31)
//      every node takes a local time too (a Steiner vertex the least of
//      its neighbours' nearer the figure), W(u) is blended row by row at
//      each node's own time (any positive weights, [17]) and the rigid
//      placement interpolates each triangle at its corners' mean time;
//   3. if every judged node trusts G fully (its star there valid and not
//      much thinner than at the ends), G is the frame. The judged nodes are
//      the figure's vertices, and with the rigid placement the Steiner
//      vertices too: then the mean value weights of every interior star
//      reproduce G and are positive; with W(u) the Steiner vertices are
//      W(u)'s convex combinations of their neighbours by construction.
//      Either way G solves a system with positive weights, so with the
//      fixed convex enclosure it is a triangulation with the source's
//      connectivity by Tutte's theorem (morph_topology.h);
//   4. otherwise every judged node v takes the weights
//      a_v MVC_G(v) + (1 - a_v) W(u)_v, where a_v in [0, 1] falls smoothly to
//      0 as v's star in G approaches invalid (so that nothing pops between
//      frames), the other interior nodes W(u); all weights are positive and
//      sum to 1, so the solve is valid by Tutte's theorem, and as close to
//      the guide as the valid stars allow;
//   5. the frame is moved by the similarity at u, and checked exactly in
//      output space: every triangle counter-clockwise with the enclosure a
//      convex polygon (a similarity image, no longer fixed: a triangulated
//      disk whose triangles are all positive and whose boundary is simple is
//      embedded, the certificate of frame_certificate.h), and with
//      FrameCheck::Full also verify_frame on the figure. A frame that fails (only
//      rounding can make it fail) is first refined in long double, then has
//      the Steiner vertices of its inverted triangles moved into their
//      stars' kernels (untangle_steiner_vertices, the figure untouched),
//      checked again after each; failing that it falls back to the plain
//      barycentric frame of [8] at u with its refinement
//      (checked_morph_frame), moved by the similarity and checked again;
//      only then is it refused.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "stickmorph/decomposition.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/morph.h"
#include "stickmorph/rigid_guide.h"
#include "stickmorph/similarity_motion.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// How a frame of the rigid morph was made.
enum class GuideFit {
  Exact,        ///< the guide frame itself (step 3)
  Blended,      ///< guide weights where the guide's stars are valid (step 4)
  Barycentric,  ///< the barycentric frame of [8] (the fallback of step 5)
};

struct GuidedFrame {
  std::vector<Vec2> positions;  ///< all n+k+s node positions, output space
  GuideFit fit = GuideFit::Exact;
  double parameter = 0;         ///< the morph parameter u of the animation time
  bool refined = false;         ///< the frame needed long double refinement (or Steiner vertices moved into their kernels)
  double verify_ms = 0;
};

/// Per-frame counts of a rigid morph.
struct GuidedMorphStats {
  int exact_frames = 0;        ///< interior frames that are the guide frame
  int blended_frames = 0;      ///< interior frames that follow the guide where its stars are valid
  int barycentric_frames = 0;  ///< interior frames that fell back to [8]
  double guide_ms = 0;         ///< the guide and the Steiner placement (steps 1-2)
  double solve_ms = 0;         ///< the blended solves (step 4) and fallbacks
  double verify_ms = 0;        ///< exact checks
  int refined_frames = 0;
  /// Of the guide frames sampled at set-up (kTrustSamples - 1 interior
  /// samples), how many every judged node trusts fully: where the guide is
  /// followed exactly. The rigid method's set-up compares triangulations by
  /// it.
  int trusted_samples = 0;
  int samples = 0;
  /// Over the same samples, how far the frames the morph makes there depart
  /// from the guide: each frame's mean over the figure's edges of the
  /// difference of its length from the guide's, over the longer of its two
  /// end lengths (the edge-length deviation it adds), averaged over the
  /// samples (0 where a sample is the guide).
  double guide_departure = 0;
  /// Step 2's placement of the guide frame's Steiner vertices: true if as
  /// rigidly as possible, false if by the blended weights W(u).
  bool rigid_steiner_placement = false;
  /// The guide runs its vertices on local clocks (local_timing.h, issue
  /// 31): the Steiner vertices then lag with the parts beside them.
  bool local_timing = false;
  /// Numeric LU factorizations of the Steiner (W(u)) and the blended
  /// systems, set-up included (the rest are iterations on the latest one, as MorphSolver's).
  int factorizations = 0;
};

/// The stateful rigid morph: constructed once, then frame(t) for any
/// animation time t in [0, 1], in any order (scrubbing).
class GuidedMorph {
 public:
  /// `normalised`: the compatible triangulation of the source and the
  /// target mapped back by `similarity` (its enclosure fixed, as
  /// morph_triangulation requires); `source` the source figure on its first
  /// n nodes; `target_vertices` the real target's n vertex positions (the
  /// last frame, exactly).
  /// @throws InvalidArgumentError as MorphSolver does; VerificationError if
  ///         the triangulation moved to the target by the similarity is not
  ///         positive with a convex enclosure (rounding of a nearly flat
  ///         triangle).
  /// `guide` the figure's as-rigid-as-possible trajectory in output space.
  /// `source_decomposition` is decompose(source), which the caller has
  /// from its CompatiblePair: the per-frame check compares against it.
  GuidedMorph(const FigureTriangulation& normalised, const StickFigure& source,
              const Decomposition& source_decomposition, const std::vector<Vec2>& target_vertices,
              const SimilarityMotion& similarity, RigidGuide guide, WeightKind kind, Easing easing);
  /// The same following any trajectory (a key-pose segment): `guide` must
  /// run from the source to the target vertices, in output space.
  GuidedMorph(const FigureTriangulation& normalised, const StickFigure& source,
              const Decomposition& source_decomposition, const std::vector<Vec2>& target_vertices,
              const SimilarityMotion& similarity, std::unique_ptr<const GuideTrajectory> guide, WeightKind kind,
              Easing easing);
  ~GuidedMorph();
  GuidedMorph(GuidedMorph&&) noexcept;
  GuidedMorph& operator=(GuidedMorph&&) noexcept;

  /// The frame at animation time t: at 0 and 1 the source and the target
  /// triangulations exactly; `frame` names it in messages (negative: by its
  /// time), `context` leads them. With `verify`, every frame is checked
  /// exactly as described above.
  ///
  /// Scrubbing (issue 29): the rigid Steiner placement of step 2 is
  /// factorized once and solved directly per frame; each of the two
  /// convex-combination systems (step 2's by W(u), step 4's blended solve)
  /// keeps up to 16 factorizations (anchors, at most 256 MiB of factors per
  /// system; at 10^4 vertices
  /// 1-8 MiB each) and 32 solutions, and iterates on the anchor nearest in
  /// the morph parameter from the solutions nearest to it, as MorphSolver
  /// does; it factorizes only when that iteration does not converge, and
  /// the new factorization replaces the least recently used anchor. So the
  /// frame depends only on the sequence of times asked since construction
  /// (and `verify`, `check`, which choose among the repairs of a frame that
  /// fails its check): two morphs given the same times agree bit for bit,
  /// and a time asked again after others agrees with its first frame to
  /// the solvers' tolerance (ten digits), not bit for bit. Times asked in
  /// increasing order from construction (guided_morph, a playback) are
  /// solved exactly as with a single anchor and the latest solutions.
  /// @throws InvalidArgumentError for t outside [0, 1]; VerificationError
  ///         "<context><frame label>: <defect>" when no candidate passes.
  GuidedFrame frame(double t, int frame, bool verify, const std::string& context,
                    FrameCheck check = FrameCheck::Certificate);

  /// The triangulation in output space: the source's as given, the
  /// target's positions those of the normalised target moved by the
  /// similarity at t = 1, with the figure's n vertices exactly the target's.
  /// Every triangle counter-clockwise in both, the enclosure convex in both
  /// (the target's is the source's rotated, scaled and moved: section 6's
  /// rotated enclosure).
  const FigureTriangulation& triangulation() const;
  const SimilarityMotion& similarity() const;
  const GuidedMorphStats& stats() const;


 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// A rigid morph of N frames at animation times f / (N - 1), counted in
/// `stats`. frames[f] holds all node positions in output space.
/// @throws as GuidedMorph.
MorphResult guided_morph(GuidedMorph& morph, int frames, bool verify, GuidedMorphStats* stats = nullptr,
                         FrameCheck check = FrameCheck::Certificate);

}  // namespace stickmorph
