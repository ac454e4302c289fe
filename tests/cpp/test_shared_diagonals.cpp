// internal::common_diagonals, internal::pieces_of and internal::cut_room:
// cutting a polygon pair along the diagonals both polygons share.
#include "catch.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "stickmorph/internal/compatible_mesh.h"
#include "stickmorph/internal/shared_diagonals.h"
#include "stickmorph/polygon_triangulation.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

// Two rhombi on the same four corners: the source long in x (its Delaunay
// diagonal is the short one, 1-3), the target long in y (diagonal 0-2).
// Each polygon's diagonal is the other's long diagonal, inside it too.
const PolygonPair kRhombi{{0, 1, 2, 3},
                          {{-3, 0}, {0, -1}, {3, 0}, {0, 1}},
                          {{-1, 0}, {0, -3}, {1, 0}, {0, 3}}};

// Two darts: reflex at corner 0 in the source (only diagonal 0-2), at
// corner 1 in the target (only diagonal 1-3). No diagonal is shared.
const PolygonPair kDarts{{0, 1, 2, 3},
                         {{0.3, 0.3}, {1, -1}, {1, 1}, {-1, 1}},
                         {{-1, -1}, {-0.3, 0.3}, {1, 1}, {-1, 1}}};

PolygonPair swapped(const PolygonPair& pair) { return {pair.corners, pair.target_positions, pair.source_positions}; }

}  // namespace

TEST_CASE("common_diagonals: the source's diagonals that are diagonals of the target", "[shared_diagonals]") {
  const auto source_base = triangulate_polygon(kRhombi.source());
  const auto target_base = triangulate_polygon(kRhombi.target());
  using Cuts = std::set<std::pair<int, int>>;
  CHECK(common_diagonals(kRhombi, source_base, kMinNewAngle) == Cuts{{1, 3}});
  CHECK(common_diagonals(swapped(kRhombi), target_base, kMinNewAngle) == Cuts{{0, 2}});
  CHECK(common_diagonals(kDarts, triangulate_polygon(kDarts.source()), kMinNewAngle).empty());
  CHECK(common_diagonals(swapped(kDarts), triangulate_polygon(kDarts.target()), kMinNewAngle).empty());
}

TEST_CASE("pieces_of: the cycles of the polygon cut along diagonals", "[shared_diagonals]") {
  const auto source_base = triangulate_polygon(kRhombi.source());
  std::vector<std::vector<int>> pieces = pieces_of(source_base, {{1, 3}});
  std::sort(pieces.begin(), pieces.end());
  CHECK(pieces == std::vector<std::vector<int>>{{0, 1, 3}, {1, 2, 3}});
  // No cut: one piece, the polygon itself from its smallest corner.
  CHECK(pieces_of(source_base, {}) == std::vector<std::vector<int>>{{0, 1, 2, 3}});
}

TEST_CASE("cut_room: smallest altitude next to a cut in units of the spacing of doubles", "[shared_diagonals]") {
  const auto source_base = triangulate_polygon(kRhombi.source());
  CHECK(std::isinf(cut_room(kRhombi, source_base, {})));
  // The thinnest triangle next to the cut 1-3 is the target's (0,-3),
  // (1,0), (0,3): altitude 1 over its side 1-3, coordinates up to 3.
  CHECK(cut_room(kRhombi, source_base, {{1, 3}}) == Approx(1.0 / (3 * DBL_EPSILON)));
}
