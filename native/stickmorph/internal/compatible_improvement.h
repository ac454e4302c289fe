// Better-shaped compatible triangulations (issue 30): flips legal in both
// embeddings and Steiner vertices moved, for the smallest angle over both.
//
// Surazhsky & Gotsman 2001, section 4.2 optimises each polygon pair's
// triangulation once its connectivity is fixed (smoothing.h). The glued
// stick-figure triangulation (Algorithm 3) still holds slivers: between a
// face and the next (the annulus cut, the bridges and the faces' own
// diagonals meet there), and wherever the spiderweb's connectivity is a
// poor fit for one of the two shapes. A thin triangle inverts under a small
// motion of the figure, which forces the rigid morph to blend away from its
// guide (guided_morph.h), and costs precision.
//
// Two operations keep the triangulation compatible and the figure in it:
//  - flipping an edge that is not a figure edge (nor on the enclosure) whose
//    two triangles form a strictly convex quadrilateral in both embeddings:
//    both new triangles are positive in both (exact), so the result is again
//    a compatible triangulation of the same disk with the same figure edges,
//    and with it the same rotation system and faces of the figure;
//  - moving a Steiner vertex of one embedding within the kernel of its link
//    there (every triangle of its star stays positive, exact): compatibility
//    is a property of the connectivity only (section 4.2).
// Each step is taken only when it raises the smallest angle of the
// triangles it changes, over both embeddings, so the triangulation's
// smallest angle never drops, and the flips end: every flip raises the
// sorted vector of the triangles' smallest angles lexicographically, and
// there are finitely many triangulations.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "stickmorph/stick_figure.h"  // Vec2

namespace stickmorph::internal {

struct CompatibleImprovementOptions {
  int rounds = 3;                ///< rounds of flips and smoothing
  double goal_angle = 0.35;      ///< radians (20 degrees): refinement's aim for every triangle
  int steiner_budget = 0;        ///< Steiner vertices refinement may add (0: none)
  double rescue_angle = 0.035;   ///< radians (2 degrees): below it after a round, more may be added
  int rescue_budget = 0;         ///< Steiner vertices for those
};

struct CompatibleImprovementStats {
  int flips = 0;  ///< edges flipped, over all rounds
  int added = 0;  ///< Steiner vertices added by refinement
};

/// Improves a compatible triangulation in place: `source` and `target` hold
/// every node's position in each embedding (#nodes by 2), `triangles` are
/// counter-clockwise in both (#T by 3); `fixed_edges` (pairs of nodes) are
/// never flipped (the figure's edges); edges on the boundary never are.
/// Nodes from `first_steiner` on may move; nodes added go at the end.
/// Flips to no further gain, refinement of the triangles below the goal
/// angle (up to the budget), smoothing of the movable nodes in each
/// embedding, then flips and smoothing again for the rounds left.
/// The triangulation must be valid (positive in both); it stays so.
void improve_compatible_triangulation(std::vector<Vec2>& source, std::vector<Vec2>& target,
                                      std::vector<std::array<int, 3>>& triangles,
                                      const std::vector<std::pair<int, int>>& fixed_edges, int first_steiner,
                                      const CompatibleImprovementOptions& options,
                                      CompatibleImprovementStats* stats = nullptr);

}  // namespace stickmorph::internal
