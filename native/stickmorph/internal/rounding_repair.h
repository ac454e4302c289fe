// Rounding repair of an embedding (beyond the paper; it keeps section 4.1's
// construction valid in floating point).
//
// The spiderweb of section 4.1 is an embedding in exact arithmetic, but its
// Steiner vertices are stored as doubles: a path crossing placed a small
// fraction along a diagonal of a sliver face (a vertex very close to a
// non-incident edge), or a central vertex in a sliver center face, can land
// on the wrong side of a nearly collinear edge. Such a vertex is moved into
// the kernel of its star, where every triangle around it is positive again.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph::internal {

using Triangle = std::array<int, 3>;

/// Kernel of a star: where node `v` may sit so that every triangle of its
/// star stays positive, the intersection of the half-planes left of each
/// opposite edge. Clipped to the link's bounding box (an interior node's
/// closed link bounds it anyway). Computed relative to `origin`, since far
/// from the origin the absolute coordinates would swallow a thin kernel.
/// Returns the kernel's vertex centroid relative to `origin`, or nothing if
/// the kernel is empty in floating point.
std::optional<Vec2> star_kernel_middle(const std::vector<Vec2>& pos, const std::vector<Triangle>& star, int v,
                                       const Vec2& origin);

/// Moves Steiner vertices (nodes >= `corners`; corners are fixed) of
/// inverted triangles to the middle of their star's kernel. Each accepted
/// move fixes that vertex's inverted triangles without touching any other
/// triangle, so it strictly reduces the number of inverted triangles. Where
/// the kernel is only a few units in the last place wide, the representable
/// points next to its middle are tried too. A move is kept only if the exact
/// predicates accept its whole star.
/// Returns true if every triangle is positive afterwards.
bool untangle(std::vector<Vec2>& pos, const std::vector<Triangle>& triangles, int corners);

}  // namespace stickmorph::internal
