// Compatible triangulation of two corresponding polygons (paper, section 4).
//
// Surazhsky & Gotsman, "Morphing Stick Figures Using Optimized Compatible
// Triangulations", Pacific Graphics 2001, section 4, building on Aronov,
// Seidel & Souvaine 1993 and Surazhsky & Gotsman 2001 [18].
//
// Three methods, all built on one spiderweb machinery:
//  - Aronov: the universal spiderweb of Aronov, Seidel & Souvaine (their
//    second construction): every corner gets the same number of layers,
//    max(ceil((n-5)/2), the deepest milestone of either polygon), so all
//    concentric layers are complete n-gons.
//  - Sg2001: the reduced spiderweb of [18] (section 4.1): each corner's depth
//    is the larger of its two milestones.
//  - Improved: section 4.2. Starting from the reduced spiderweb, every
//    Steiner vertex that is redundant in both polygons is removed. Redundant
//    here means: its star can be re-triangulated without it so that every new
//    triangle is positive in both polygons. This includes the paper's
//    vertices that lie on straight layer edges in both spiderwebs, and makes
//    identical polygons come out with no Steiner vertex at all.
//
// The spiderweb is embedded along each polygon's own triangulation: the
// radial path of a corner follows the dual tree from the corner's shallowest
// face to the center face, with one Steiner vertex on each diagonal it
// crosses (ordered along the diagonal as the corners are ordered along the
// polygon, so paths never cross). Rungs between neighbouring paths then lie
// on diagonals and every ladder cell is convex. Levels a polygon does not
// need (redundant in that polygon) are placed close to the corner along a
// direction chosen so that the thin triangles they form are positive, and
// pulled closer until exact verification passes.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "stickmorph/polygon_triangulation.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// Two corresponding polygons: one corner sequence, positions from two figures.
struct PolygonPair {
  std::vector<int> corners;           ///< #C vertex ids, counter-clockwise in both
  std::vector<Vec2> source_positions; ///< indexed by vertex id
  std::vector<Vec2> target_positions; ///< indexed by vertex id
  CornerPolygon source() const { return {corners, source_positions}; }
  CornerPolygon target() const { return {corners, target_positions}; }
};

/// A triangulation shared by both polygons of a pair. Nodes 0..C-1 are the
/// corners (in order); nodes C..C+S-1 are Steiner vertices.
struct CompatibleTriangulation {
  int corner_count = 0;
  std::vector<Vec2> source_steiner;  ///< #S positions inside the source polygon
  std::vector<Vec2> target_steiner;  ///< #S positions inside the target polygon
  std::vector<std::array<int, 3>> triangles;  ///< node triples, counter-clockwise in both
  int steiner_count() const { return int(source_steiner.size()); }
};

enum class SteinerMethod { Aronov, Sg2001, Improved };

/// "aronov", "sg2001", "improved" -> method; throws InvalidArgumentError.
SteinerMethod parse_steiner_method(const std::string& name);
std::string steiner_method_name(SteinerMethod method);

struct CompatibleTriangulationOptions {
  SteinerMethod method = SteinerMethod::Improved;
  /// Laplacian smoothing rounds applied to each polygon's Steiner vertices
  /// after a valid placement; a move is kept only if every incident triangle
  /// stays positive (exact).
  int smoothing_rounds = 10;
  /// Name of the face in messages (e.g. "face 3").
  std::string label = "polygon";
  /// Improved method: a pair whose spiderweb would be deep may be cut in
  /// two along a path routed in both polygons (internal/routed_cut.h). If
  /// the result with such cuts fails verification, it is built again
  /// without them.
  bool routed_cuts = true;
};

/// What the solver measured.
struct CompatibleTriangulationStats {
  int steiner_vertices = 0;
  int spiderweb_steiner_vertices = 0;  ///< before redundancy removal
  double min_angle_before_smoothing = 0;  ///< radians, over both polygons
  double min_angle_after_smoothing = 0;
};

/// Compatibly triangulates a polygon pair. The result is verified exactly
/// (verify_compatible_triangulation) before it is returned.
/// @throws InvalidFigureError if a polygon is not weakly simple and
///         counter-clockwise; VerificationError if no valid result was found.
CompatibleTriangulation compatible_triangulation(const PolygonPair& pair,
                                                 const CompatibleTriangulationOptions& options = {},
                                                 CompatibleTriangulationStats* stats = nullptr);

/// Smallest triangle angle of the triangulation in the source and in the
/// target polygon (radians).
double min_angle(const PolygonPair& pair, const CompatibleTriangulation& triangulation);

}  // namespace stickmorph
