// Cutting a deep polygon pair in two along a path routed in both polygons
// (beyond the paper; it bounds the size of section 4.1's spiderweb).
//
// Surazhsky & Gotsman 2001, section 4.1: the reduced spiderweb gives every
// corner as many Steiner vertices as the larger of its two milestones (its
// face's depth in each polygon's dual tree). In a long thin polygon, such as
// the exterior face of a path wound into a spiral, the dual tree is one long
// corridor and the depths grow with the number of corners, so the spiderweb
// is quadratic: 10^8 nodes and more than 4 GiB for a 10^4-vertex spiral.
//
// Why a routed cut: a path from corner a to corner b through the interior
// of each polygon, with the same number of bends in both, splits both
// polygons into the same two pieces (corners a..b, then the bends back to
// a; and corners b..a, then the bends), as the annulus cut of section 3,
// Algorithm 3 opens the exterior face. Compatible triangulations of the two
// pieces, glued along the path, are a compatible triangulation of the pair;
// the bends are Steiner vertices shared by both pieces. A cut that halves
// the corners with few bends halves the corridor, so recursing until the
// pieces are shallow costs about n log n instead of n^2.
//
// Invariant: in each polygon the path follows a shortest dual path of the
// polygon's triangulation from a face at corner a to a face at corner b and
// bends at midpoints of the diagonals it crosses, only where it must turn: a
// segment runs on through the next faces as long as it crosses each of
// their shared diagonals strictly inside it (exact orientations), so it
// lies inside the faces it passes and the path meets the boundary only at
// a and b (the shorter path is padded with straight bends, corner_router.h's
// pad_bends). Bending at every diagonal would make a cut out of a fan (one
// far corner facing many, as in both polygons of a spiral's exterior face)
// as long as half the fan, and its bends are corners of both pieces.
// Rounding of a midpoint is the one inexact step: callers triangulate the
// pieces (which rejects any piece that is not weakly simple) and the final
// result is verified exactly.
#pragma once

#include <array>
#include <vector>

#include "stickmorph/compatible_triangulation.h"

namespace stickmorph::internal {

/// Total common depth of the reduced spiderweb (section 4.1) of `pair`: the
/// sum over corners of the larger milestone, for the best of the (at most
/// four) choices of center faces, as spiderweb_mesh chooses them. It is
/// the spiderweb's Steiner count before the tip rule and any removal.
long spiderweb_depth_total(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                           const std::vector<std::array<int, 3>>& target_base);

/// A path from corner a to corner b (a < b, not neighbours), bending at
/// source_bends in the source and target_bends in the target (as many in
/// both, in order from a to b).
struct RoutedCut {
  int a = -1, b = -1;
  std::vector<Vec2> source_bends, target_bends;
};

/// A few cuts worth measuring, best first by the size of their larger
/// piece (corners plus bends), for three balance classes (the smaller piece
/// holding at least 2/5, 1/4 or 1/8 of the corners). The ends are sampled
/// corners a and, for each, the corner b of each class with the fewest
/// bends: the longer of the two shortest dual paths, the other padded.
std::vector<RoutedCut> routed_cut_candidates(const PolygonPair& pair,
                                             const std::vector<std::array<int, 3>>& source_base,
                                             const std::vector<std::array<int, 3>>& target_base);

/// The two pieces of the pair cut along `cut`, as node lists in
/// counter-clockwise order: nodes 0..C-1 are the corners, C + i is bend i.
std::array<std::vector<int>, 2> routed_pieces(int corners, const RoutedCut& cut);

/// One piece as a pair of its own: its vertices numbered anew in the order
/// of `nodes` (a corner keeps its figure vertex's identity, so repeated
/// vertices stay repeated; a bend is a vertex of its own), with both
/// polygons' triangulations (none for a triangle).
struct RoutedPiece {
  std::vector<int> nodes;
  PolygonPair pair;
  std::vector<std::array<int, 3>> source_base, target_base;
};

/// The piece of `pair` cut along `cut` whose nodes are `nodes` (from
/// routed_pieces). @throws InvalidFigureError if it is not weakly simple
/// and counter-clockwise in both polygons (a rounded bend).
RoutedPiece routed_piece(const PolygonPair& pair, const RoutedCut& cut, std::vector<int> nodes);

}  // namespace stickmorph::internal
