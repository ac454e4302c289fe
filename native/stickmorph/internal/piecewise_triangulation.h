// The Improved method's recursion: cut along shared diagonals, then a
// spiderweb per piece (paper, section 4.2, plus the cutting of
// shared_diagonals.h).
//
// Surazhsky & Gotsman 2001, section 4.2 reduces the spiderweb of section
// 4.1. Before building it, the pair is cut along diagonals that both
// polygons share; each piece is triangulated anew in both polygons and
// handled the same way, until a piece has no shared diagonal (a spiderweb
// triangulates it) or is a triangle (nothing to add).
#pragma once

#include <array>
#include <vector>

#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/internal/compatible_mesh.h"

namespace stickmorph::internal {

/// The Improved method's compatible triangulation of `pair` (corners first,
/// then every piece's Steiner vertices in the order the pieces come), from
/// each polygon's triangulation. Adds the spiderwebs' Steiner counts before
/// removal to `spiderweb_steiner`.
/// Where no diagonal is shared with angles of at least kMinNewAngle and the
/// spiderweb finds no room (a needle thinner than the spacing of doubles),
/// diagonals that the exact predicates accept however thin are used instead.
/// A piece whose spiderweb would be deep is cut in two along a path routed
/// in both polygons first (routed_cut.h, unless options.routed_cuts is
/// false), if that shrinks the spiderwebs; `routed_cuts_taken` (optional)
/// counts those cuts.
/// @throws as spiderweb_mesh and triangulate_checked.
CompatibleMesh piecewise_mesh(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                              const std::vector<std::array<int, 3>>& target_base,
                              const CompatibleTriangulationOptions& options, int& spiderweb_steiner,
                              int* routed_cuts_taken = nullptr);

}  // namespace stickmorph::internal
