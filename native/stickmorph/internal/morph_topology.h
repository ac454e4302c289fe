// What the morph needs to know about a FigureTriangulation's combinatorics
// (Algorithm 3, step 4; Floater & Gotsman 1999, the paper's [8]).
//
// [8] morphs a triangulation of a disk with a fixed convex boundary: every
// interior node is written as a convex combination of its neighbours, in
// counter-clockwise order round it. Here the triangulation is checked once
// to be such a disk (the enclosure as its boundary, a closed fan round
// every other node) and those fans are returned; the checks of positions
// (every triangle counter-clockwise, the enclosure strictly convex and
// fixed) are separate, since they are repeated for every frame.
#pragma once

#include <string>
#include <vector>

#include "stickmorph/figure_triangulation.h"

namespace stickmorph::internal {

/// "node 7 (Steiner vertex 2)" and the like, for messages.
std::string node_text(const FigureTriangulation& tri, int node);
/// "triangle 3 (1, 4, 5)", for messages.
std::string triangle_text(const FigureTriangulation& tri, int t);
/// Throws InvalidArgumentError("invalid triangulation for the morph: " + what).
[[noreturn]] void malformed(const std::string& what);

/// The triangulation's fans, established once.
struct Topology {
  int nodes = 0;
  /// For every interior (non-enclosure) node: its neighbours in
  /// counter-clockwise order, a closed cycle. Empty for enclosure nodes.
  std::vector<std::vector<int>> ring;
  std::vector<int> unknown;         ///< node -> row of the linear system, or -1 (enclosure)
  std::vector<int> interior_nodes;  ///< row -> node
};

bool is_enclosure(const FigureTriangulation& tri, int node);

/// Checks that the triangles form a disk bounded by the enclosure, with a
/// closed fan around every other node, and returns those fans.
///
/// Why this plus positive orientation suffices for an embedding (used for
/// every frame): with the boundary mapped to the fixed convex enclosure
/// traversed once counter-clockwise, a generic point inside is covered by
/// exactly (winding number =) 1 positively oriented triangle and a point
/// outside by none. So no two triangles overlap and the angles around every
/// interior node sum to one turn: the frame is a triangulation with the
/// same connectivity (Floater & Gotsman 1999, section 2).
/// @throws InvalidArgumentError (malformed) naming the defect.
Topology build_topology(const FigureTriangulation& tri);

/// The first triangle that is not counter-clockwise in `positions`
/// (exact), or -1.
int first_non_positive(const FigureTriangulation& tri, const std::vector<Vec2>& positions);

/// malformed() unless every triangle is counter-clockwise in `positions`;
/// `which` names them ("source", "target").
void require_positive(const FigureTriangulation& tri, const std::vector<Vec2>& positions, const char* which);

/// Section 2.2 of the paper: the boundary is common to both triangulations,
/// convex, and stays fixed. Strict convexity (every other corner strictly
/// left of every side, exact) also makes it a simple polygon.
void require_enclosure(const FigureTriangulation& tri);

}  // namespace stickmorph::internal
