// Correspondence of two connected figures: steps 1 to 4 of
// figure_correspondence.h put together (skeletons, plane-map isomorphisms,
// the choice among them, resampling with dummy vertices), and the matched
// pair built and checked.
//
// Surazhsky & Gotsman 2001, section 6: the matched pair subdivides the two
// drawings on the same vertices and edges and is compatible (section 2.1)
// by construction; it is validated and checked all the same.
#pragma once

#include <chrono>

#include "stickmorph/figure_correspondence.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::internal {

// One connected figure matched to another (steps 1 to 4 of the header);
// `reference_rotation`: Skeleton::reference_rotation.
FigureCorrespondence correspond_connected(const StickFigure& source, const StickFigure& target,
                                          const CorrespondenceOptions& options, double reference_rotation = 0);

/// Wall-clock milliseconds since `start` (FigureCorrespondence::milliseconds).
double milliseconds_since(std::chrono::steady_clock::time_point start);

}  // namespace stickmorph::internal
