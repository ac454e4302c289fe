// The combinatorial check that triangles form a disk (paper, sections 2.2
// and 4): the one topology verifier of the engine.
//
// A compatible triangulation (section 4) is a triangulated disk bounded by
// the polygon, and the morph of [8] (section 2.2) needs a triangulated disk
// bounded by the fixed convex enclosure. Both are checked here the same
// way, on the connectivity alone: every directed side in at most one
// triangle, the boundary's sides each with a triangle on the left and none
// on the right, every other side with triangles on both, one closed fan
// round every interior node and one open fan (from the next boundary node
// to the previous) round every boundary node. With every triangle
// positively oriented (checked separately, exactly, by the callers) that
// makes the triangles an embedding: a generic point inside the boundary is
// covered by exactly one triangle (Floater & Gotsman 1999, section 2).
// Callers word the defect in their own terms.
#pragma once

#include <vector>

#include "stickmorph/internal/triangle_adjacency.h"

namespace stickmorph::internal {

struct DiskDefect {
  enum class Kind {
    None,
    RepeatedSide,         ///< side a -> b in `triangle` and `other_triangle`
    BoundarySideMissing,  ///< boundary side a -> b is in no triangle
    OutsideBoundary,      ///< a triangle (`triangle`) is right of boundary side a -> b
    SideBordersNothing,   ///< interior side a -> b of `triangle` has no twin
    NodeInNoTriangle,     ///< node a
    BoundaryFanBroken,    ///< the triangles at boundary node a are not one open fan
    InteriorFanGap,       ///< the fan round interior node a is open
    InteriorFanNotClosed, ///< the fan round interior node a does not close once
  };
  Kind kind = Kind::None;
  int a = -1, b = -1;
  int triangle = -1, other_triangle = -1;
  explicit operator bool() const { return kind != Kind::None; }
};

/// The first defect, in this order: repeated sides (triangle order), the
/// boundary's sides (in boundary order; missing, then a triangle outside),
/// sides without a twin (triangle order), then node by node: in no
/// triangle, or its fan. `boundary`: the boundary nodes counter-clockwise,
/// distinct, at least 3.
/// With `rings`, receives for every interior node its neighbours
/// counter-clockwise (starting from the first side of its first triangle),
/// and nothing for boundary nodes; filled only up to the first defect.
DiskDefect find_disk_defect(const TriangleAdjacency& adjacency, const std::vector<Triangle>& triangles,
                            const std::vector<int>& boundary, std::vector<std::vector<int>>* rings = nullptr);

}  // namespace stickmorph::internal
