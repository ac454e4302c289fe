// One polygon pair triangulated by a spiderweb (paper, sections 4.1-4.2);
// see spiderweb_triangulation.h.
#include "stickmorph/internal/spiderweb_triangulation.h"

#include <algorithm>
#include <limits>

#include "stickmorph/cancellation.h"
#include "stickmorph/internal/spiderweb.h"
#include "stickmorph/internal/spiderweb_embedding.h"
#include "stickmorph/internal/steiner_reduction.h"
#include "stickmorph/polygon_triangulation.h"

namespace stickmorph::internal {

std::vector<std::array<int, 3>> triangulate_checked(const CornerPolygon& polygon, const std::string& label,
                                                    bool target) {
  try {
    return triangulate_polygon(polygon);
  } catch (const InvalidFigureError& e) {
    throw InvalidFigureError(e.defect(), label + " in the " + (target ? "target" : "source") + ": " + e.what(),
                             e.vertices(), e.edges(), target ? "target" : "source");
  }
}

// Section 4.1 (and for Improved, 4.2) on one polygon pair: the spiderweb
// embedded in both, with redundant vertices removed for Improved.
CompatibleMesh spiderweb_mesh(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                              const std::vector<std::array<int, 3>>& target_base,
                              const CompatibleTriangulationOptions& options, int& spiderweb_steiner) {
  const int n = int(pair.corners.size());
  const CornerPolygon polygons[2] = {pair.source(), pair.target()};
  const std::vector<std::array<int, 3>>* base[2] = {&source_base, &target_base};
  // Choose each polygon's center (one of at most two) to minimise the total
  // common depth: the paper's maximum of the two milestones per corner.
  std::array<PolygonTriangulation, 2> pts;
  std::vector<int> level;
  long best_total = std::numeric_limits<long>::max();
  for (int cs = 0; cs < 2; ++cs)
    for (int ct = 0; ct < 2; ++ct) {
      std::array<PolygonTriangulation, 2> candidate = {dual_tree_depths(polygons[0], *base[0], cs),
                                                       dual_tree_depths(polygons[1], *base[1], ct)};
      if ((cs && candidate[0].center_faces.size() < 2) || (ct && candidate[1].center_faces.size() < 2)) continue;
      std::vector<int> common(n);
      for (int k = 0; k < n; ++k) common[k] = std::max(candidate[0].milestone[k], candidate[1].milestone[k]);
      long total = 0;
      for (int l : common) total += l;
      if (total < best_total) best_total = total, pts = candidate, level = common;
    }

  if (options.method == SteinerMethod::Aronov) {
    // Universal spiderweb: complete layers, ceil((n-5)/2) of them as in
    // Aronov, Seidel & Souvaine, or more if a polygon's own dual-tree paths
    // need them.
    int layers = n > 4 ? (n - 5 + 1) / 2 : 0;
    for (int l : level) layers = std::max(layers, l);
    std::fill(level.begin(), level.end(), layers);
  }
  enforce_tip_levels(pair, level);

  poll_cancellation();  // between the long steps (cancellation.h)
  const Spiderweb web = build_spiderweb(level, pair.corners);
  const Placement placement = embed_in_both(pair, pts, web);
  poll_cancellation();
  if (!placement.ok)
    throw VerificationError(options.label + ": no valid embedding of the spiderweb was found in both polygons (" +
                            std::to_string(n) + " corners, method " + steiner_method_name(options.method) +
                            "): " + placement.failure);
  CompatibleMesh mesh;
  mesh.corners = n;
  mesh.source = placement.source;
  mesh.target = placement.target;
  mesh.triangles = placement.triangles;
  mesh.alive.assign(mesh.triangles.size(), 1);
  spiderweb_steiner += int(mesh.source.size()) - n;
  if (options.method == SteinerMethod::Improved) remove_redundant_steiner(pair, mesh);
  return mesh;
}

}  // namespace stickmorph::internal
