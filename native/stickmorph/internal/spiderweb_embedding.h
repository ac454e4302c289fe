// Embedding the spiderweb in both polygons (paper, section 4.1).
//
// Surazhsky & Gotsman 2001, section 4.1: the spiderweb's connectivity
// (spiderweb.h) is shared, but each polygon gets its own positions. Here the
// spiderweb is embedded along each polygon's own triangulation: the radial
// path of a corner follows the dual tree from the corner's shallowest face
// to the center face, with one Steiner vertex on each diagonal it crosses
// (ordered along the diagonal as the corners are ordered along the polygon,
// so paths never cross). Rungs between neighbouring paths then lie on
// diagonals and every ladder cell is convex. Levels a polygon does not need
// (redundant in that polygon: above its own milestone) are placed close to
// the corner along a direction chosen so that the thin triangles they form
// are positive, and pulled closer until exact verification passes.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/internal/spiderweb.h"
#include "stickmorph/polygon_triangulation.h"

namespace stickmorph::internal {

/// Result of embedding the spiderweb in both polygons with chosen splits.
struct Placement {
  std::vector<Vec2> source, target;  ///< #web.node_count
  std::vector<Triangle> triangles;   ///< web.fixed, then one split of each quad
  bool ok = false;                   ///< every triangle positive in both (exact)
  std::string failure;               ///< what stayed inverted at the last attempt
};

/// Embeds `web` in both polygons of `pair`, `pts` being each polygon's
/// triangulation with its dual tree (the center the web was built for).
/// Each ladder cell takes the split that is positive in both with the larger
/// smallest angle. Redundant vertices start at their full cluster distance
/// and are pulled towards their corners, in the polygon(s) where something
/// is still inverted, until every triangle is positive in both (all decided
/// exactly) or 80 attempts have failed.
Placement embed_in_both(const PolygonPair& pair, const std::array<PolygonTriangulation, 2>& pts,
                        const Spiderweb& web);

}  // namespace stickmorph::internal
