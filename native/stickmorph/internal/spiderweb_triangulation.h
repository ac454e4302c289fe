// One polygon pair triangulated by a spiderweb (paper, sections 4.1-4.2).
//
// Surazhsky & Gotsman 2001, section 4.1: each polygon's triangulation gives
// every corner a milestone (the depth of its shallowest face in the dual
// tree from the center face); the common depth of a corner is the larger of
// its two milestones (Sg2001), or the same number of complete layers for
// every corner (Aronov, Seidel & Souvaine's universal spiderweb). The
// spiderweb of those depths (spiderweb.h) is embedded in both polygons
// (spiderweb_embedding.h) and, for the Improved method, its redundant
// Steiner vertices are removed (section 4.2, steiner_reduction.h).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/internal/compatible_mesh.h"

namespace stickmorph::internal {

/// triangulate_polygon, with `label` and the side ("source"/"target") put in
/// front of an InvalidFigureError's message.
std::vector<std::array<int, 3>> triangulate_checked(const CornerPolygon& polygon, const std::string& label,
                                                    bool target);

/// The spiderweb triangulation of `pair` for options.method, from each
/// polygon's triangulation (`source_base`, `target_base`). Of the (at most
/// two) center faces of each polygon, the combination with the smallest
/// total common depth is used. Adds the spiderweb's Steiner count (before
/// any removal) to `spiderweb_steiner`.
/// @throws VerificationError naming options.label if no valid embedding was
///         found in both polygons.
CompatibleMesh spiderweb_mesh(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                              const std::vector<std::array<int, 3>>& target_base,
                              const CompatibleTriangulationOptions& options, int& spiderweb_steiner);

}  // namespace stickmorph::internal
