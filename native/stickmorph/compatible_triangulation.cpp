// Compatible triangulation of two corresponding polygons (paper, section 4):
// the public entry. The algorithms live in internal/, one per file:
//   spiderweb.h                the spiderweb's connectivity (section 4.1)
//   spiderweb_embedding.h      its embedding in both polygons (section 4.1)
//   rounding_repair.h          moving rounded Steiner vertices back into their kernels
//   steiner_reduction.h        removal of redundant Steiner vertices (section 4.2)
//   smoothing.h                Laplacian smoothing of Steiner vertices (section 4.2)
//   shared_diagonals.h         cutting along diagonals both polygons share
//   spiderweb_triangulation.h  one pair by a spiderweb (sections 4.1-4.2)
//   piecewise_triangulation.h  the Improved method's recursion over the cut pieces
//   compatible_mesh.h          the working form they all share
#include "stickmorph/compatible_triangulation.h"

#include <algorithm>

#include "stickmorph/cancellation.h"
#include "stickmorph/internal/compatible_mesh.h"
#include "stickmorph/internal/geometry.h"
#include "stickmorph/internal/piecewise_triangulation.h"
#include "stickmorph/internal/smoothing.h"
#include "stickmorph/internal/spiderweb_triangulation.h"
#include "stickmorph/verification.h"

namespace stickmorph {

using internal::kPi;
using internal::Triangle;
using internal::triangle_min_angle;

SteinerMethod parse_steiner_method(const std::string& name) {
  if (name == "aronov") return SteinerMethod::Aronov;
  if (name == "sg2001") return SteinerMethod::Sg2001;
  if (name == "improved") return SteinerMethod::Improved;
  throw InvalidArgumentError("unknown Steiner method '" + name + "' (choose aronov, sg2001 or improved)");
}

std::string steiner_method_name(SteinerMethod method) {
  switch (method) {
    case SteinerMethod::Aronov: return "aronov";
    case SteinerMethod::Sg2001: return "sg2001";
    case SteinerMethod::Improved: return "improved";
  }
  return "?";
}

double min_angle(const PolygonPair& pair, const CompatibleTriangulation& tri) {
  const int c = tri.corner_count;
  auto pos = [&](int node, bool target) {
    if (node < c) return target ? pair.target_positions[pair.corners[node]] : pair.source_positions[pair.corners[node]];
    return target ? tri.target_steiner[node - c] : tri.source_steiner[node - c];
  };
  double m = kPi;
  for (const Triangle& t : tri.triangles)
    for (bool target : {false, true})
      m = std::min(m, triangle_min_angle(pos(t[0], target), pos(t[1], target), pos(t[2], target)));
  return m;
}

namespace {
CompatibleTriangulation compatible_triangulation_once(const PolygonPair& pair,
                                                      const CompatibleTriangulationOptions& options,
                                                      CompatibleTriangulationStats* stats, int& routed_cuts);
}  // namespace

CompatibleTriangulation compatible_triangulation(const PolygonPair& pair,
                                                 const CompatibleTriangulationOptions& options,
                                                 CompatibleTriangulationStats* stats) {
  // Routed cuts add bends as Steiner vertices, and the whole is verified
  // only at the end: if a result with such cuts fails, it is built again
  // without them.
  int routed_cuts = 0;
  try {
    return compatible_triangulation_once(pair, options, stats, routed_cuts);
  } catch (const VerificationError&) {
    if (routed_cuts == 0) throw;
  }
  CompatibleTriangulationOptions plain = options;
  plain.routed_cuts = false;
  return compatible_triangulation_once(pair, plain, stats, routed_cuts);
}

namespace {

CompatibleTriangulation compatible_triangulation_once(const PolygonPair& pair,
                                                      const CompatibleTriangulationOptions& options,
                                                      CompatibleTriangulationStats* stats, int& routed_cuts) {
  const int n = int(pair.corners.size());
  const std::vector<std::array<int, 3>> source_base = internal::triangulate_checked(pair.source(), options.label, false);
  const std::vector<std::array<int, 3>> target_base = internal::triangulate_checked(pair.target(), options.label, true);

  CompatibleTriangulationStats local;
  internal::CompatibleMesh mesh =
      options.method == SteinerMethod::Improved
          ? internal::piecewise_mesh(pair, source_base, target_base, options, local.spiderweb_steiner_vertices,
                                     &routed_cuts)
          : internal::spiderweb_mesh(pair, source_base, target_base, options, local.spiderweb_steiner_vertices);
  poll_cancellation();  // between the long steps (cancellation.h); the steps poll inside too
  local.min_angle_before_smoothing = internal::mesh_min_angle(mesh);
  internal::smooth(mesh, false, options.smoothing_rounds);
  internal::smooth(mesh, true, options.smoothing_rounds);
  local.min_angle_after_smoothing = internal::mesh_min_angle(mesh);

  CompatibleTriangulation result;
  result.corner_count = n;
  result.source_steiner.assign(mesh.source.begin() + n, mesh.source.end());
  result.target_steiner.assign(mesh.target.begin() + n, mesh.target.end());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (mesh.alive.empty() || mesh.alive[t]) result.triangles.push_back(mesh.triangles[t]);
  poll_cancellation();
  verify_compatible_triangulation(pair, result, options.label);
  local.steiner_vertices = result.steiner_count();
  if (stats) *stats = local;
  return result;
}

}  // namespace

}  // namespace stickmorph
