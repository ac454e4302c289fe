// The set-up of a rigid morph on a checked pair (issue 12; issue 28 for the
// segments of a key-pose sequence): the similarity factored out where the
// pair allows, the compatible triangulation in an enclosure that holds the
// guide's whole way, and the GuidedMorph that follows the guide, each
// attempt verified, with the fallbacks in order (the pair itself, then the
// paper's own triangulation).
#pragma once

#include <functional>
#include <memory>

#include "stickmorph/compatibility.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/guided_morph.h"
#include "stickmorph/morph_stick_figures.h"
#include "stickmorph/rigid_guide.h"
#include "stickmorph/similarity_motion.h"

namespace stickmorph {
namespace internal {

/// The GuidedMorph of `pair` under `similarity` (its whole rotation, scale
/// and move, source to target), following the trajectory `make_guide`
/// makes (from the source's vertices to the target's, output space; called
/// again for each attempt, since a morph takes its guide). Fills the
/// triangulation, timing and similarity-factored fields of `stats`.
/// @throws as triangulate_figures and GuidedMorph, after the fallbacks;
///         InternalError where the engine refused its own intermediate result.
GuidedMorph prepare_guided_morph(const CompatiblePair& pair, const SimilarityMotion& similarity,
                                 const std::function<std::unique_ptr<const GuideTrajectory>()>& make_guide,
                                 const FigureTriangulationOptions& paper_options, WeightKind weights, Easing easing,
                                 MorphStickFiguresStats& stats);

}  // namespace internal
}  // namespace stickmorph
