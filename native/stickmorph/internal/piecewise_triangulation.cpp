// The Improved method's recursion; see piecewise_triangulation.h.
#include "stickmorph/internal/piecewise_triangulation.h"

#include <set>
#include <utility>

#include "stickmorph/internal/shared_diagonals.h"
#include "stickmorph/internal/spiderweb_triangulation.h"

namespace stickmorph::internal {

CompatibleMesh piecewise_mesh(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                              const std::vector<std::array<int, 3>>& target_base,
                              const CompatibleTriangulationOptions& options, int& spiderweb_steiner) {
  const int n = int(pair.corners.size());
  CompatibleMesh mesh;
  mesh.corners = n;
  for (int k = 0; k < n; ++k) {
    mesh.source.push_back(pair.source_positions[pair.corners[k]]);
    mesh.target.push_back(pair.target_positions[pair.corners[k]]);
  }
  if (n == 3) {  // a triangle in both (both counter-clockwise): nothing to add
    mesh.triangles.push_back({0, 1, 2});
    mesh.alive.assign(1, 1);
    return mesh;
  }
  // Candidates come from the source's triangulation; if none of them is a
  // diagonal of the target too, the target's are tried in the source (the
  // two Delaunay triangulations can differ only by a sliver's diagonal, as
  // in a quadrilateral whose source copy has a corner flat to 1e-7 rad).
  auto find_cuts = [&](double min_new_angle, const std::vector<std::array<int, 3>>*& base) {
    std::set<std::pair<int, int>> found = common_diagonals(pair, source_base, min_new_angle);
    base = &source_base;
    if (found.empty()) {
      const PolygonPair swapped{pair.corners, pair.target_positions, pair.source_positions};
      found = common_diagonals(swapped, target_base, min_new_angle);
      base = &target_base;
    }
    return found;
  };
  const std::vector<std::array<int, 3>>* cut_base = nullptr;
  std::set<std::pair<int, int>> cuts = find_cuts(kMinNewAngle, cut_base);
  if (cuts.empty()) {
    try {
      return spiderweb_mesh(pair, source_base, target_base, options, spiderweb_steiner);
    } catch (const VerificationError&) {
      // The spiderweb needs room for its Steiner vertices. In a needle (a
      // far corner facing a few nearly collinear ones) every diagonal makes
      // an angle below kMinNewAngle and the center face can be thinner than
      // the spacing of doubles, so no Steiner vertex fits. A diagonal that
      // the exact predicates accept in both polygons is still valid: take
      // it, thin as it is, rather than fail.
      // Of the two candidate sets, the one whose cut-off triangles stand
      // highest above their sides in units of the spacing of doubles there
      // (what every morph frame must resolve) is taken.
      const PolygonPair swapped{pair.corners, pair.target_positions, pair.source_positions};
      std::set<std::pair<int, int>> from_source = common_diagonals(pair, source_base, 0.0);
      std::set<std::pair<int, int>> from_target = common_diagonals(swapped, target_base, 0.0);
      const double source_room = cut_room(pair, source_base, from_source);
      const double target_room = cut_room(pair, target_base, from_target);
      if (from_source.empty() && from_target.empty()) throw;
      if (!from_source.empty() && (from_target.empty() || source_room >= target_room)) {
        cuts = std::move(from_source);
        cut_base = &source_base;
      } else {
        cuts = std::move(from_target);
        cut_base = &target_base;
      }
    }
  }
  for (const std::vector<int>& cycle : pieces_of(*cut_base, cuts)) {
    PolygonPair sub;
    for (int k : cycle) sub.corners.push_back(pair.corners[k]);
    sub.source_positions = pair.source_positions;
    sub.target_positions = pair.target_positions;
    const int m = int(cycle.size());
    CompatibleMesh piece;
    if (m == 3) {
      piece.corners = 3;
      piece.triangles.push_back({0, 1, 2});
    } else {
      piece = piecewise_mesh(sub, triangulate_checked(sub.source(), options.label, false),
                            triangulate_checked(sub.target(), options.label, true), options, spiderweb_steiner);
    }
    // Corners of the piece are corners of the pair; its Steiner vertices are new.
    const int offset = int(mesh.source.size());
    for (std::size_t v = piece.corners; v < piece.source.size(); ++v) {
      mesh.source.push_back(piece.source[v]);
      mesh.target.push_back(piece.target[v]);
    }
    for (std::size_t t = 0; t < piece.triangles.size(); ++t) {
      if (!piece.alive.empty() && !piece.alive[t]) continue;
      Triangle global;
      for (int j = 0; j < 3; ++j) {
        const int v = piece.triangles[t][j];
        global[j] = v < m ? cycle[v] : offset + (v - m);
      }
      mesh.triangles.push_back(global);
    }
  }
  mesh.alive.assign(mesh.triangles.size(), 1);
  return mesh;
}

}  // namespace stickmorph::internal
