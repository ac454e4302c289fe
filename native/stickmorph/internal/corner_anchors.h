// Corners as anchors of a chain pair's arc-length map (step 4 of
// figure_correspondence.h).
//
// Surazhsky & Gotsman 2001, section 6 places dummy vertices; where they go
// along a stroke decides how the morph looks. The same letter drawn in two
// fonts has its corners at slightly different arc lengths, and a corner that
// landed on the other drawing's straight edge would round off while its
// partner grows beside it; so corners are matched to corners first.
#pragma once

#include <cstddef>

#include "stickmorph/internal/correspondence_track.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::internal {

/// Signed turn at slot k of a track (counter-clockwise positive), walked in
/// the stored direction; 0 at a chain's ends.
double turn_at(const StickFigure& figure, const Track& track, std::size_t k);

/// Adds matched corners to a chain pair's map as anchors: the order-keeping
/// matching of source corners to target corners of the same sense, each
/// pair within kCornerWindow under the map so far, that maximises the sum
/// of (1 - (gap / window)^2) * (smaller turn / larger turn) (a dynamic
/// programme like an alignment of two sequences). Anchors already there
/// (the ends, the pins, a loop's shift) stay, and a corner pair that would
/// cross one is dropped, so the map stays increasing.
void anchor_corners(const StickFigure& source, const Track& s, const StickFigure& target, const Track& t,
                    ChainMatch& match);

}  // namespace stickmorph::internal
