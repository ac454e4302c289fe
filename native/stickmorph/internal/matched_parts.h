// Parts of a figure as figures of their own, and the matched figure of
// several parts put together from the matches of its part pairs (issue 14;
// Surazhsky & Gotsman 2001, section 6, for figures of several parts).
//
// part_correspondence.h pairs the parts and matches each pair as a
// connected figure (connected_correspondence.h); this is the stage on
// either side of that: cutting a figure into its parts, and gluing the
// matched parts back into one matched pair, checked once.
#pragma once

#include <vector>

#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_parts.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::internal {

/// One part as a figure of its own, with the way back to the whole figure.
struct PartFigure {
  StickFigure figure;
  std::vector<int> global_vertex;  ///< local vertex -> figure vertex
  std::vector<int> global_edge;    ///< local edge -> figure edge
};

/// Part `part` of a valid figure as a figure of its own, valid by
/// construction (a subset of a plane graph's vertices with every edge
/// between them), its edges in the whole figure's order and direction.
PartFigure part_figure(const StickFigure& whole, const FigureParts& parts, int part);

/// The matched pair of figures of several parts: source part a matched to
/// target part partner[a] as matched[a] (#parts each). The source's
/// vertices keep their numbers; the dummies of every part follow, ordered
/// by the target vertex they stand for. The statistics are the parts'
/// (the residual weighted by matched vertices, the rotation the largest
/// part's); the pair is validated and checked once (FigureCorrespondence::pair).
/// @throws VerificationError where rounding made the matched parts touch;
///         IncompatibleFiguresError (NestingDiffers) where the matched
///         parts nest differently; InternalError for any other
///         incompatibility (a broken construction).
FigureCorrespondence assemble_matched_parts(const StickFigure& source, const StickFigure& target,
                                            const std::vector<PartFigure>& source_pieces,
                                            const std::vector<PartFigure>& target_pieces,
                                            const std::vector<FigureCorrespondence>& matched,
                                            const std::vector<int>& partner);

}  // namespace stickmorph::internal
