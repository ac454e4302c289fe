// Correspondence of figures of several parts (issue 14).
//
// Surazhsky & Gotsman 2001, section 6 leaves disconnected figures to future
// work. Here the parts are paired first (same shape class, same nesting
// depth and contents, nearest place in the figure), each pair is matched as
// a connected figure (connected_correspondence.h), and the matched parts are
// put together and checked, nesting included.
#pragma once

#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_parts.h"

namespace stickmorph::internal {

/// Matches figures of several parts; `source_parts`, `target_parts` are
/// figure_parts of each. Throws as correspond_figures does, naming the
/// parts where a pair fails.
FigureCorrespondence correspond_parts(const StickFigure& source, const StickFigure& target,
                                      const CorrespondenceOptions& options, const FigureParts& source_parts,
                                      const FigureParts& target_parts);

}  // namespace stickmorph::internal
