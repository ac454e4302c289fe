// Smoothing of Steiner vertices (paper, section 4.2, the optimisation after
// the reduction).
//
// Surazhsky & Gotsman 2001, section 4.2 improves the triangulation's
// smallest angle once its connectivity is fixed: each polygon's Steiner
// vertices move independently of the other polygon's, since compatibility
// is a property of the connectivity only.
#pragma once

#include "stickmorph/internal/compatible_mesh.h"

namespace stickmorph::internal {

/// `rounds` rounds of Laplacian smoothing of the Steiner vertices of one
/// polygon of `mesh` (the target's if `target`). Each vertex moves towards
/// the average of its neighbours, by the full step, half or a quarter. A
/// move is kept only if every triangle around the vertex stays positive
/// (exact; the vertex then stays in the kernel of its unchanged link, so the
/// embedding stays valid) and the smallest angle among those triangles does
/// not shrink (so the triangulation's smallest angle never gets worse).
void smooth(CompatibleMesh& mesh, bool target, int rounds);

}  // namespace stickmorph::internal
