// Cutting a polygon pair along shared diagonals (beyond the paper; it
// localises section 4.1's spiderweb).
//
// The spiderweb of Surazhsky & Gotsman 2001, section 4.1 has quadratically
// many Steiner vertices in the number of corners it spans. A diagonal of the
// source's triangulation that is also a diagonal of the target (inside it,
// meeting its boundary only at its ends) can be used by both: whether two
// diagonals cross depends only on the cyclic order of their ends, which both
// polygons share, so any set of them cuts both polygons into the same
// pieces, and the spiderweb is then needed only in pieces where the polygons
// differ.
#pragma once

#include <array>
#include <set>
#include <utility>
#include <vector>

#include "stickmorph/compatible_triangulation.h"

namespace stickmorph::internal {

/// The diagonals (a, b), a < b corner indices, of `source_base` (a
/// triangulation of pair.source()) that are also diagonals of the target:
/// between different vertices, leaving each end strictly into that
/// corner's wedge in the target, clear of the corner's edges by
/// `min_new_angle` in both polygons (a diagonal along a nearly straight run
/// of edges would cut off a triangle that is flat in all but rounding), and
/// meeting no edge of the target except at its own ends (exact).
std::set<std::pair<int, int>> common_diagonals(const PolygonPair& pair,
                                               const std::vector<std::array<int, 3>>& source_base,
                                               double min_new_angle);

/// The pieces of the polygon cut along `cuts` (diagonals of `triangles`),
/// each as its corners in counter-clockwise order, starting at its smallest
/// corner index.
std::vector<std::vector<int>> pieces_of(const std::vector<std::array<int, 3>>& triangles,
                                        const std::set<std::pair<int, int>>& cuts);

/// Smallest altitude, in units of the spacing of doubles at its
/// coordinates, of the triangles of `base` next to a cut, in either polygon:
/// how much room rounding has before one of them flattens.
double cut_room(const PolygonPair& pair, const std::vector<std::array<int, 3>>& base,
                const std::set<std::pair<int, int>>& cuts);

}  // namespace stickmorph::internal
