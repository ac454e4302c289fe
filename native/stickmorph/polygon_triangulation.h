// Triangulation of one polygon and its dual-tree depths (paper, section 4.1).
//
// Surazhsky & Gotsman 2001, section 4.1: triangulate the polygon (constrained
// Delaunay), take the dual tree, find its center by removing all leaves at
// once until one node remains, give each face its depth (dual distance from
// the center) and each corner its milestone (the least depth of the faces at
// that corner).
//
// Polygons here are corner sequences that may repeat a vertex (section 3:
// cut vertices, dangling edges with 2*pi angles, trees). Rather than uniting
// and splitting repeated vertices by hand, the triangulation is built on the
// distinct vertices with every polygon edge as a constraint, and each
// triangle corner is assigned to the polygon corner whose angular wedge
// contains it.
#pragma once

#include <array>
#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// A polygon as a cyclic sequence of corners, counter-clockwise: the region
/// lies to the left of each edge corners[k] -> corners[k+1]. A vertex may
/// appear at several corners (weakly simple polygons).
struct CornerPolygon {
  std::vector<int> corners;    ///< #C vertex ids
  std::vector<Vec2> positions; ///< indexed by vertex id
  Vec2 at(int corner) const { return positions[corners[corner]]; }
  int size() const { return int(corners.size()); }
};

/// A triangulation of a CornerPolygon without Steiner vertices, with its dual
/// tree rooted at the center.
struct PolygonTriangulation {
  std::vector<std::array<int, 3>> triangles;  ///< #C-2 corner triples, counter-clockwise
  /// neighbour[t][j]: triangle across the side opposite corner slot j, or -1
  /// on the polygon boundary.
  std::vector<std::array<int, 3>> neighbour;
  int center = -1;             ///< the root face
  std::vector<int> center_faces;  ///< the one or two faces left by peeling
  std::vector<int> parent;     ///< #T: parent face, -1 at the center
  std::vector<int> depth;      ///< #T: dual distance from the center
  std::vector<int> milestone;  ///< #C: least depth of the faces at each corner
  std::vector<int> shallowest; ///< #C: the face attaining the milestone
};

/// Constrained Delaunay triangulation of the polygon's interior (CGAL), with
/// triangles expressed as corner triples. Throws InvalidFigureError if the
/// polygon is not weakly simple or not counter-clockwise, naming corners.
std::vector<std::array<int, 3>> triangulate_polygon(const CornerPolygon& polygon);

/// Dual tree, center, depths and milestones of a triangulation of `polygon`.
/// `center_choice` picks between the two middle faces when peeling leaves
/// ends with two adjacent faces (0 or 1); it is ignored otherwise.
PolygonTriangulation dual_tree_depths(const CornerPolygon& polygon,
                                      std::vector<std::array<int, 3>> triangles,
                                      int center_choice = 0);

}  // namespace stickmorph
