// Spiderweb connectivity (paper, section 4.1).
//
// Surazhsky & Gotsman 2001, section 4.1, after Aronov, Seidel & Souvaine
// 1993: every corner k of the polygon gets a radial path of level[k]
// Steiner vertices from a central vertex outwards; neighbouring paths are
// joined by "rungs" into ladders. This file builds only the combinatorics,
// which both polygons share; where the vertices go is
// spiderweb_embedding.h's business, and which of the two splits each ladder
// cell takes is decided there too, once positions are known.
#pragma once

#include <array>
#include <vector>

#include "stickmorph/compatible_triangulation.h"

namespace stickmorph::internal {

using Triangle = std::array<int, 3>;

/// The spiderweb's nodes and triangles for given per-corner depths.
/// Node numbering: corners 0..C-1, the central vertex C, then every path's
/// Steiner vertices, corner by corner, innermost first.
struct Spiderweb {
  int corners = 0;
  int center = -1;                        ///< node of the central vertex
  std::vector<int> level;                 ///< #C: common depth of each corner
  std::vector<std::vector<int>> path;     ///< path[k][l]: node at level l (0 = center)
  int node_count = 0;
  std::vector<Triangle> fixed;            ///< triangles with no choice
  /// A ladder cell or top cell: two ways to split it, each two triangles.
  struct Quad {
    std::array<std::array<Triangle, 2>, 2> option;
    std::array<std::array<int, 2>, 2> diagonal;  ///< the edge each option adds
  };
  void add_quad(int a, int b, int c, int d) {
    // Cell a -> b -> c -> d (counter-clockwise), split by a-c or by b-d.
    Quad q;
    q.option[0] = {Triangle{a, b, c}, Triangle{a, c, d}};
    q.option[1] = {Triangle{a, b, d}, Triangle{b, c, d}};
    q.diagonal[0] = {a, c};
    q.diagonal[1] = {b, d};
    quads.push_back(q);
  }
  std::vector<Quad> quads;

  /// Node of corner k's path at level l; level level[k] + 1 is the corner itself.
  int at(int k, int l) const { return l == level[k] + 1 ? k : path[k][l]; }
};

/// The spiderweb for `level` (the common depth of each corner). `vertex[k]`
/// is the figure vertex of corner k: where both neighbours of a corner are
/// the same vertex (the tip of a dangling edge), the tip's first path edge
/// must not have that vertex on both sides, or the two triangles there would
/// be the same triangle twice with opposite orientations. The top cells next
/// to a tip are therefore split on the side away from the tip.
Spiderweb build_spiderweb(const std::vector<int>& level, const std::vector<int>& vertex);

/// Raises `level` where needed to keep the spiderweb a simplicial complex:
/// at the tip of a dangling edge both neighbours are the same vertex, and if
/// the tip's path were longer than both neighbouring paths, that vertex
/// would be joined to the tip's outermost path vertex from both sides
/// (section 3's warning about repeated vertices). Lengthening one
/// neighbour's path prevents it.
void enforce_tip_levels(const PolygonPair& pair, std::vector<int>& level);

}  // namespace stickmorph::internal
