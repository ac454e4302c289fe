// Algorithm 3 of Surazhsky & Gotsman 2001 ("MorphStickFigures"), end to end.
//
//   1. decompose both figures into cyclic sequences and check compatibility
//   2. compatibly triangulate every pair of interior faces
//   3. enclose both in one convex polygon, cut and triangulate the annulus
//   4. morph the triangulation by Floater & Gotsman's convex combinations
//   5. discard the helper vertices (enclosure and Steiner), keep the figure
//
// Steps 1-3 are triangulate_figures, step 4 morph_triangulation; this entry
// checks the options once, runs them in order, times them and does step 5,
// so that the CLI, the Python module, the tests, the fuzzer and the
// benchmarks all run the same pipeline. The straight-line baseline of the
// paper's Figure 8d (method Linear) runs through the same entry.
//
// Method Rigid (the default, issue 12) runs the same steps with the motion
// made natural: the global similarity is factored out first (section 6's
// rotated enclosure, similarity_motion.h), steps 1-3 triangulate the source
// and the target mapped back by it, and step 4 follows the figure's
// as-rigid-as-possible guide wherever that is valid (guided_morph.h, after
// the paper's [17]), at even speed. Every frame is verified exactly, as in
// method Barycentric, which is step 4 as the paper has it.
//
// With correspond = Auto (issue 13) the two figures need not correspond by
// index: correspond_figures matches them first (section 6's dummy vertices)
// and every step above runs on the matched figure.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stickmorph/argument_limits.h"
#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/guided_morph.h"
#include "stickmorph/local_timing.h"
#include "stickmorph/morph.h"
#include "stickmorph/morph_options.h"  // check_morph_options and the options' rules
#include "stickmorph/rigid_guide.h"
#include "stickmorph/similarity_motion.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

enum class MorphMethod {
  /// Algorithm 3 with the similarity factored out and step 4 following an
  /// as-rigid-as-possible guide where it is valid: valid frames, verified
  /// unless verify is false, moving as rigidly as validity allows.
  Rigid,
  Barycentric,  ///< Algorithm 3 as the paper has it: valid frames, verified unless verify is false
  Linear,       ///< straight lines (Figure 8d); self-intersecting frames are listed, not refused
};

/// "rigid", "barycentric", "linear" -> method.
/// @throws InvalidArgumentError naming the accepted names.
MorphMethod parse_morph_method(const std::string& name);
std::string morph_method_name(MorphMethod method);

/// What to run. The options that only some methods use are optional: unset
/// means the default, set means the caller asked for it, and asking for one
/// with a method that would ignore it is refused (the triangulation's options
/// with the linear method, the rotation's and the easing with any method but
/// rigid): a user who asked for a setting would get something else.
struct MorphStickFiguresOptions {
  MorphMethod method = MorphMethod::Rigid;
  /// N, kMinMorphFrames to kMaxMorphFrames: t_f = f / (N - 1). long long so
  /// that an interface can hand over an out-of-range value unchanged for
  /// the message.
  long long frames = kDefaultMorphFrames;
  std::optional<SteinerMethod> steiner;        ///< default SteinerMethod::Improved
  std::optional<WeightKind> weights;           ///< default WeightKind::MeanValue
  std::optional<long long> enclosure_sides;    ///< default kDefaultEnclosureSides
  std::optional<bool> verify;                  ///< default true: every frame checked exactly
  /// How each frame is checked (frame_certificate.h); default
  /// FrameCheck::Certificate. Refused with verify false and with Linear.
  std::optional<FrameCheck> frame_check;
  // The rigid method's own; asking for them with another method is refused.
  std::optional<RotationDirection> rotation;   ///< default RotationDirection::Short
  std::optional<long long> turns;              ///< extra whole turns, ccw positive; default 0
  std::optional<Easing> easing;                ///< default Easing::None (even speed)
  /// Per-vertex delay weights (one per source vertex, also with
  /// correspond = Auto: the morph carries them onto the matched figure) and
  /// an overlap: parts lag on their local clocks (local_timing.h, issue
  /// 31). Unset, or overlap 0: the plain morph, bit for bit.
  std::optional<LocalTiming> timing;
  /// ByIndex (default): vertex i becomes vertex i. Auto: the figures are
  /// matched (correspond_figures) and the matched figure is morphed.
  CorrespondenceMode correspond = CorrespondenceMode::ByIndex;
  /// Auto only: vertex pairs the matching must respect; given with ByIndex
  /// they are refused (pins have no meaning where the indices decide).
  std::vector<VertexPin> pins;
  /// Also return every frame with all n+k+s triangulation nodes
  /// (MorphStickFiguresResult::node_frames), for drawing the triangulation
  /// under the figure or re-checking its triangles. Rigid and barycentric
  /// only; the linear method has no helper nodes, so there it is refused.
  bool keep_node_frames = false;
  /// How messages name options: as the CLI's flags or as keywords.
  OptionSpelling spelling = OptionSpelling::Keyword;
};

/// What the run measured and counted.
struct MorphStickFiguresStats {
  int steiner_vertices = 0;  ///< s; 0 for linear
  int triangles = 0;         ///< of the triangulation; 0 for linear
  // Wall-clock milliseconds.
  double triangulate_ms = 0;  ///< steps 1-3; 0 for linear
  double morph_ms = 0;        ///< step 4 (linear: the interpolation and its validity check)
  double factorize_ms = 0;    ///< part of morph_ms, see MorphStats; 0 for linear
  double solve_ms = 0;        ///< part of morph_ms (linear: the interpolation)
  double verify_ms = 0;       ///< part of morph_ms (linear: finding the invalid frames)
  int refined_frames = 0;     ///< see MorphStats; 0 for linear
  double correspond_ms = 0;   ///< correspond = Auto: the matching; not part of the others
  int factorizations = 0;     ///< see MorphStats; 0 for linear
  /// Rigid only: how the interior frames were made (GuideFit) and the
  /// similarity factored out; whether it was (false when the mapped-back
  /// target was not a figure compatible with the source, which rounding of a
  /// nearly degenerate figure can cause: the guide still turns the figure).
  int guide_exact_frames = 0;
  int guide_blended_frames = 0;
  int guide_barycentric_frames = 0;
  bool similarity_factored = false;
  SimilarityMotion similarity;
  /// Linear only: frames that are not stick figures compatible with the
  /// source (is_frame_valid), increasing. Empty for barycentric, whose
  /// frames are all valid when verified.
  std::vector<int> invalid_frames;
  /// Steps 1-3 in detail (per-stage milliseconds, faces, minimum angle);
  /// all zero for linear.
  FigureTriangulationStats triangulation;
};

struct MorphStickFiguresResult {
  std::vector<double> times;  ///< N times, 0 first, 1 last
  /// frames[f]: the figure's n vertex positions at times[f] (step 5 done);
  /// frames[0] and frames[N-1] are exactly the source and target vertices.
  std::vector<std::vector<Vec2>> frames;
  /// Only with options.keep_node_frames: all n+k+s node positions per frame.
  std::vector<std::vector<Vec2>> node_frames;
  /// The triangulation the morph used; empty for linear. For rigid, in
  /// output space: the target's positions are the normalised target's moved
  /// by the similarity, the figure's exactly the target's, so the target's
  /// enclosure is the source's rotated, scaled and moved (GuidedMorph).
  std::optional<FigureTriangulation> triangulation;
  /// The options in effect, defaults filled in (for reports such as the
  /// CLI's stats); meaningful for rigid and barycentric.
  FigureTriangulationOptions triangulation_options;
  MorphOptions morph_options;
  MorphStickFiguresStats stats;
  /// correspond = Auto only: the matching. The frames, node frames and the
  /// triangulation are then the matched figure's (correspondence->source
  /// and ->target: m vertices, their edges), not the inputs'.
  std::optional<FigureCorrespondence> correspondence;
};

/// Algorithm 3 on two figures whose vertices correspond by index, or on the
/// matched figure of two that do not (options.correspond).
/// @throws InvalidArgumentError (check_morph_options, or a pin
///         correspond_figures refuses), IncompatibleFiguresError
///         (correspond_figures' topology, mirror and pin kinds included)
///         (with the compatibility report's kind and vertices),
///         VerificationError (a triangulation or frame that could not be
///         verified), as triangulate_figures and morph_triangulation do;
///         InternalError where those would blame an argument the engine
///         built itself.
MorphStickFiguresResult morph_stick_figures(const StickFigure& source, const StickFigure& target,
                                            const MorphStickFiguresOptions& options = {});

/// The rigid method up to its frames (options.method must be Rigid): the
/// similarity fitted, the pair triangulated in the guide's enclosure, the
/// GuidedMorph built. GuidedMorph::frame(t) then gives the frame at any
/// animation time, checked exactly: what morph_stick_figures computes for its
/// times f / (N - 1), for scrubbing (stickmorph.RigidMorphSolver). `stats`,
/// if given, receives the similarity, the counts and the set-up times.
/// @throws as morph_stick_figures; InvalidArgumentError for another method.
GuidedMorph prepare_rigid_morph(const StickFigure& source, const StickFigure& target,
                                const MorphStickFiguresOptions& options, MorphStickFiguresStats* stats = nullptr);

}  // namespace stickmorph
