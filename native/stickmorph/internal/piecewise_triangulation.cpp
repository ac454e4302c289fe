// The Improved method's recursion; see piecewise_triangulation.h.
#include "stickmorph/internal/piecewise_triangulation.h"

#include <algorithm>
#include <set>
#include <utility>

#include "stickmorph/cancellation.h"
#include "stickmorph/internal/routed_cut.h"
#include "stickmorph/internal/shared_diagonals.h"
#include "stickmorph/internal/spiderweb_triangulation.h"
#include "stickmorph/internal/steiner_reduction.h"

namespace stickmorph::internal {
namespace {

// How deep piecewise_mesh is in its own recursion on this thread: the
// outermost call of a large pair reports its pieces' corners as the
// stage's progress (cancellation.h), the recursion into them does not (it
// would restart the count), nor does a small pair (a figure of many small
// faces counts faces instead, figure_triangulation.cpp). Thread-local, as
// the Progress it reports to.
thread_local int t_piecewise_depth = 0;
constexpr int kCountedCorners = 1000;
struct PiecewiseDepth {
  PiecewiseDepth() { ++t_piecewise_depth; }
  ~PiecewiseDepth() { --t_piecewise_depth; }
  PiecewiseDepth(const PiecewiseDepth&) = delete;
  PiecewiseDepth& operator=(const PiecewiseDepth&) = delete;
  bool outermost() const { return t_piecewise_depth == 1; }
};

// A pair is considered for a routed cut (routed_cut.h) when its spiderweb
// would give the corners more than kDeepAverage Steiner vertices each on
// average and it has at least kRoutedCutMinCorners corners; the cut is
// taken when its pieces' spiderwebs together, with the cut's bends, come to
// at most kCutGain of the whole pair's. Below that the spiderweb is cheap
// and its Steiner count as good as the cut's.
constexpr long kDeepAverage = 12;
constexpr int kRoutedCutMinCorners = 64;
constexpr double kCutGain = 0.8;
// Candidates measured exactly at most per pair (see gaining_routed_cut).
constexpr int kMeasuredCuts = 4;

// Glues `piece` into `mesh`: its corner k is mesh node nodes[k] (a corner of
// the pair, or a bend of a routed cut), its Steiner vertices are appended as
// new nodes, and its live triangles are renumbered accordingly.
void glue_piece(const CompatibleMesh& piece, const std::vector<int>& nodes, CompatibleMesh& mesh) {
  const int size = int(nodes.size());
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
      global[j] = v < size ? nodes[std::size_t(v)] : offset + (v - size);
    }
    mesh.triangles.push_back(global);
  }
}

// The pair cut along `cut` into `pieces`, each triangulated by
// piecewise_mesh and glued: corners first, then the cut's bends, then the
// pieces' Steiner vertices. Bends that are redundant in both polygons once
// the pieces are glued are removed.
CompatibleMesh routed_mesh(const PolygonPair& pair, const RoutedCut& cut, const std::array<RoutedPiece, 2>& pieces,
                           const CompatibleTriangulationOptions& options, int& spiderweb_steiner,
                           int* routed_cuts_taken) {
  const int n = int(pair.corners.size());
  const int m = int(cut.source_bends.size());
  CompatibleMesh mesh;
  mesh.corners = n;
  for (int k = 0; k < n; ++k) {
    mesh.source.push_back(pair.source_positions[pair.corners[k]]);
    mesh.target.push_back(pair.target_positions[pair.corners[k]]);
  }
  mesh.source.insert(mesh.source.end(), cut.source_bends.begin(), cut.source_bends.end());
  mesh.target.insert(mesh.target.end(), cut.target_bends.begin(), cut.target_bends.end());
  spiderweb_steiner += m;
  for (const RoutedPiece& routed : pieces) {
    const int size = int(routed.nodes.size());
    CompatibleMesh piece;
    if (size == 3) {
      piece.corners = 3;
      piece.triangles.push_back({0, 1, 2});
    } else {
      piece = piecewise_mesh(routed.pair, routed.source_base, routed.target_base, options, spiderweb_steiner,
                             routed_cuts_taken);
    }
    glue_piece(piece, routed.nodes, mesh);
  }
  mesh.alive.assign(mesh.triangles.size(), 1);
  // Only the bends are new here: every other Steiner vertex already failed
  // with the star it still has.
  std::vector<char> candidates(mesh.source.size(), 0);
  for (int i = 0; i < m; ++i) candidates[std::size_t(n + i)] = 1;
  remove_redundant_steiner(pair, mesh, &candidates);
  return mesh;
}

// A routed cut whose pieces' spiderwebs gain enough over the pair's own
// (see kCutGain): the first such in the order of the estimate below.
bool gaining_routed_cut(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                        const std::vector<std::array<int, 3>>& target_base, RoutedCut& chosen_cut,
                        std::array<RoutedPiece, 2>& chosen_pieces) {
  const int n = int(pair.corners.size());
  if (n < kRoutedCutMinCorners) return false;
  const long total = spiderweb_depth_total(pair, source_base, target_base);
  if (total <= kDeepAverage * n) return false;
  const double enough = kCutGain * double(total);
  // Measuring a cut exactly triangulates both pieces in both polygons, the
  // bulk of a deep pair's cost: candidates are measured in the order of
  // their pieces' size by estimate, and the first that gains enough is
  // taken; at most kMeasuredCuts are measured (one whose rounded bends
  // leave a piece not weakly simple does not count). A corridor's spiderweb
  // grows as the square of its corners, so the estimate is the sum of the
  // squares of the pieces' sizes (corners plus bends).
  //
  // Taking the least measured cost of the first four instead was measured
  // against this (triangulate_figures, the seven benchmark families at 100
  // to 3000 vertices): the estimate's first choice came out with as few
  // Steiner vertices or fewer in 26 of the 28 cases (the spiral at 3000:
  // 501 against 600, the star polygon at 3000: 2007 against 2052; at 1000:
  // 686 against 678), and the spiral triangulated 20-32% faster (1000
  // vertices: 163 ms against 222).
  std::vector<RoutedCut> candidates = routed_cut_candidates(pair, source_base, target_base);
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const std::array<std::vector<int>, 2> nodes = routed_pieces(n, candidates[i]);
    const double first = double(nodes[0].size()), second = double(nodes[1].size());
    order.push_back({first * first + second * second, i});
  }
  std::sort(order.begin(), order.end());
  int measured = 0;
  for (const auto& [estimate, index] : order) {
    if (measured == kMeasuredCuts) break;
    RoutedCut& cut = candidates[index];
    std::array<RoutedPiece, 2> pieces;
    const std::array<std::vector<int>, 2> nodes = routed_pieces(n, cut);
    try {
      for (int p = 0; p < 2; ++p) pieces[p] = routed_piece(pair, cut, nodes[p]);
    } catch (const InvalidFigureError&) {
      continue;  // a rounded bend left a piece not weakly simple
    }
    ++measured;
    double cost = double(cut.source_bends.size());
    for (const RoutedPiece& piece : pieces)
      if (piece.nodes.size() > 3) cost += double(spiderweb_depth_total(piece.pair, piece.source_base, piece.target_base));
    if (cost < enough) {
      chosen_cut = std::move(cut);
      chosen_pieces = std::move(pieces);
      return true;
    }
  }
  return false;
}

}  // namespace

CompatibleMesh piecewise_mesh(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                              const std::vector<std::array<int, 3>>& target_base,
                              const CompatibleTriangulationOptions& options, int& spiderweb_steiner,
                              int* routed_cuts_taken) {
  const PiecewiseDepth depth;
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
    // A deep pair: cut along a routed path if that shrinks the spiderweb.
    RoutedCut cut;
    std::array<RoutedPiece, 2> pieces;
    if (options.routed_cuts && gaining_routed_cut(pair, source_base, target_base, cut, pieces)) {
      const int counted = spiderweb_steiner;
      const int taken = routed_cuts_taken ? *routed_cuts_taken : 0;
      try {
        CompatibleMesh routed = routed_mesh(pair, cut, pieces, options, spiderweb_steiner, routed_cuts_taken);
        if (routed_cuts_taken) ++*routed_cuts_taken;
        return routed;
      } catch (const VerificationError&) {
        // Fall back on the pair's own spiderweb.
        spiderweb_steiner = counted;
        if (routed_cuts_taken) *routed_cuts_taken = taken;
      }
    }
  }
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
  // At 10^5 corners this loop is nearly all of a morph's triangulation
  // (a polyline's exterior face cut into 10^5 pieces): it polls for
  // cancellation on every piece, and the outermost call counts corners
  // glued against all its pieces' corners, real progress if not even time.
  const std::vector<std::vector<int>> pieces = pieces_of(*cut_base, cuts);
  long corners_total = 0, corners_done = 0;
  for (const std::vector<int>& cycle : pieces) corners_total += long(cycle.size());
  const bool counted = depth.outermost() && n >= kCountedCorners;
  for (const std::vector<int>& cycle : pieces) {
    if (counted)
      report_progress(corners_done, corners_total);
    else
      poll_cancellation();
    corners_done += long(cycle.size());
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
                            triangulate_checked(sub.target(), options.label, true), options, spiderweb_steiner,
                            routed_cuts_taken);
    }
    // Corners of the piece are corners of the pair; its Steiner vertices are new.
    glue_piece(piece, cycle, mesh);
  }
  if (counted) report_progress(corners_total, corners_total);
  mesh.alive.assign(mesh.triangles.size(), 1);
  return mesh;
}

}  // namespace stickmorph::internal
