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

/// The figure reflected in the y axis (x -> -x), for telling a mirror image
/// from another arrangement of the strokes.
///
/// Valid by construction, so built without make_stick_figure's checks:
/// negating a coordinate is exact, so every coordinate stays finite and
/// within kMaxCoordinateMagnitude and no two vertices come to coincide; a
/// reflection reverses the sign of every orientation predicate at once, so
/// edges that met only at shared endpoints still do; the edges are the
/// figure's own.
StickFigure reflected_figure(const StickFigure& figure);

/// Wall-clock milliseconds since `start` (FigureCorrespondence::milliseconds).
double milliseconds_since(std::chrono::steady_clock::time_point start);

}  // namespace stickmorph::internal
