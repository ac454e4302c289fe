// internal::spiderweb_depth_total, internal::routed_cut_candidates,
// internal::routed_pieces and internal::routed_piece: cutting a deep polygon
// pair in two along a path routed in both polygons, and the Improved
// method taking such a cut.
#include "catch.h"

#include <cmath>

#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/internal/routed_cut.h"
#include "stickmorph/polygon_triangulation.h"
#include "stickmorph/verification.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

// Two strips of `half` corners a side, bottom left to right, then top right
// to left. In the source the top corners are spread quadratically, in the
// target evenly, so a corner faces different corners across the two strips
// and they share few diagonals: a corridor in both whose spiderweb is
// quadratic.
PolygonPair warped_strips(int half) {
  PolygonPair pair;
  const double length = half - 1;
  for (int i = 0; i < half; ++i) {
    pair.corners.push_back(i);
    pair.source_positions.push_back({double(i), 0.0});
    pair.target_positions.push_back({double(i), 0.0});
  }
  for (int j = half - 1; j >= 0; --j) {
    const double u = double(j) / length;
    pair.corners.push_back(int(pair.source_positions.size()));
    pair.source_positions.push_back({length * u * u, 1.0});
    pair.target_positions.push_back({double(j), 1.0 + 0.1 * std::sin(double(j))});
  }
  return pair;
}

}  // namespace

TEST_CASE("routed cuts split a deep pair into two pieces valid in both polygons", "[routed_cut]") {
  const PolygonPair pair = warped_strips(120);
  const int n = int(pair.corners.size());
  const auto source_base = triangulate_polygon(pair.source());
  const auto target_base = triangulate_polygon(pair.target());
  const long total = spiderweb_depth_total(pair, source_base, target_base);
  CHECK(total > 12L * n);

  const std::vector<RoutedCut> cuts = routed_cut_candidates(pair, source_base, target_base);
  REQUIRE_FALSE(cuts.empty());
  long best = total;
  for (const RoutedCut& cut : cuts) {
    CHECK(cut.a < cut.b);
    CHECK(cut.b - cut.a > 1);
    CHECK(cut.source_bends.size() == cut.target_bends.size());
    const int m = int(cut.source_bends.size());
    const auto nodes = routed_pieces(n, cut);
    CHECK(nodes[0].size() + nodes[1].size() == std::size_t(n + 2 + 2 * m));
    // Each piece is weakly simple and counter-clockwise in both polygons
    // (routed_piece triangulates it, which would throw otherwise).
    long cost = m;
    for (int p = 0; p < 2; ++p) {
      const RoutedPiece piece = routed_piece(pair, cut, nodes[std::size_t(p)]);
      CHECK(piece.pair.corners.size() == nodes[std::size_t(p)].size());
      if (piece.nodes.size() > 3) cost += spiderweb_depth_total(piece.pair, piece.source_base, piece.target_base);
    }
    best = std::min(best, cost);
  }
  // Some cut shrinks the spiderweb.
  CHECK(best < total);
}

TEST_CASE("the improved method cuts a deep pair and stays valid", "[routed_cut]") {
  const PolygonPair pair = warped_strips(120);
  const auto source_base = triangulate_polygon(pair.source());
  const auto target_base = triangulate_polygon(pair.target());
  const long total = spiderweb_depth_total(pair, source_base, target_base);
  CompatibleTriangulationStats stats;
  const CompatibleTriangulation tri = compatible_triangulation(pair, {}, &stats);
  CHECK_NOTHROW(verify_compatible_triangulation(pair, tri, "strips"));
  CHECK(long(stats.spiderweb_steiner_vertices) < total);
  CHECK(stats.steiner_vertices <= stats.spiderweb_steiner_vertices);
}

TEST_CASE("a shallow pair has no candidate worth cutting for", "[routed_cut]") {
  // A square in both: too few corners for a cut.
  const PolygonPair square{{0, 1, 2, 3}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const auto base = triangulate_polygon(square.source());
  CHECK(routed_cut_candidates(square, base, base).empty());
}

TEST_CASE("a routed cut bends only where a straight segment would leave the faces it passes", "[routed_cut]") {
  // Across two strips a cut's dual path crosses many diagonals (the source's
  // top corners crowd at the left, a fan), but straight segments pass most
  // of them: the bends stay few (measured: at most 2 per candidate here,
  // against 54 when every diagonal crossed was a bend, before fd32d19).
  const PolygonPair pair = warped_strips(120);
  const auto source_base = triangulate_polygon(pair.source());
  const auto target_base = triangulate_polygon(pair.target());
  const std::vector<RoutedCut> cuts = routed_cut_candidates(pair, source_base, target_base);
  REQUIRE_FALSE(cuts.empty());
  std::size_t most = 0;
  for (const RoutedCut& cut : cuts) {
    most = std::max(most, cut.source_bends.size());
    // Still two pieces valid in both polygons.
    for (const std::vector<int>& nodes : routed_pieces(int(pair.corners.size()), cut))
      CHECK_NOTHROW(routed_piece(pair, cut, nodes));
  }
  INFO("most bends " << most);
  CHECK(most <= 4);
}
