// Exact verification of results.
//
// The engine never returns a result it has not verified; tests run these on
// every result too. Orientation decisions are exact (EPICK predicates); angle
// sums are only compared against values a whole turn apart, so their
// floating-point rounding cannot change the verdict.
#pragma once

#include "stickmorph/compatible_triangulation.h"

namespace stickmorph {

/// Checks that `triangulation` is a compatible triangulation of `pair`:
///  - every triangle is positively oriented in the source and in the target;
///  - it is a triangulated disk whose boundary is exactly the polygon's edges
///    (each interior side shared by two triangles, Euler characteristic 1);
///  - the angles around every Steiner vertex sum to one full turn and those
///    at every corner to the polygon's angle there, in both polygons, so the
///    triangles cover the polygon once;
///  - once corners are identified with their vertices it is a simplicial
///    complex: no edge is doubled through repeated corners.
/// Together these make it an embedding of the same triangulation in both.
/// @throws VerificationError naming `label`, the triangle and the polygon.
void verify_compatible_triangulation(const PolygonPair& pair,
                                     const CompatibleTriangulation& triangulation,
                                     const std::string& label = "polygon");

/// As above, returning false instead of throwing.
bool is_valid(const PolygonPair& pair, const CompatibleTriangulation& triangulation);

}  // namespace stickmorph
