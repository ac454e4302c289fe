// Removal of redundant Steiner vertices (paper, section 4.2).
//
// Surazhsky & Gotsman 2001, section 4.2: the reduced spiderweb of section
// 4.1 still has Steiner vertices that neither polygon needs, for instance
// those lying on straight layer edges in both spiderwebs. Here a Steiner
// vertex counts as redundant in both polygons when its star can be
// re-triangulated without it so that every new triangle is positive in both.
// That includes the paper's vertices, and makes identical polygons come out
// with no Steiner vertex at all.
#pragma once

#include <vector>

#include "stickmorph/internal/compatible_mesh.h"

namespace stickmorph::internal {

/// Removes every Steiner vertex of `mesh` that is redundant in both polygons
/// of `pair`, re-triangulating its link for the largest smallest angle over
/// both (dynamic programming over the link polygon). A new triangle must be
/// positive in both polygons (exact), no thinner than kMinNewAngle, and
/// must not double an existing edge by vertex identity (edge_key).
/// Positivity of every triangle of a triangulated simple polygon without
/// interior vertices makes it an embedding, so validity is kept exactly.
/// Afterwards the surviving nodes are renumbered in order and only live
/// triangles are kept. Returns the number of vertices removed.
/// `candidates` (per node, optional): only these are tried at first; any
/// other is tried once its star changes. A vertex that already failed with
/// its present star needs no second try (see the .cpp: the outcome depends
/// only on its link, and added edges can only forbid more).
int remove_redundant_steiner(const PolygonPair& pair, CompatibleMesh& mesh,
                             const std::vector<char>* candidates = nullptr);

}  // namespace stickmorph::internal
