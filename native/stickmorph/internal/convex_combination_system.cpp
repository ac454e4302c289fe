// A convex-combination system solved frame after frame; see
// convex_combination_system.h.
#include "stickmorph/internal/convex_combination_system.h"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "stickmorph/internal/long_double_refinement.h"

namespace stickmorph {
namespace internal {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The anchor's step budget (kAnchorIterations, kAnchorIterationsDense in
// the header) and the skipping after a failure (solve):
// GMRES steps before the anchor counts as too far. Four since
// factorizations are static-pivot refactorizations (CompactLU::
// refactorize), 0.1-0.6 of SparseLU's at 10^3 vertices: measured at 10^3 vertices (48
// frames), rigid frame / fresh LU with 16, 8 and 4 steps: spiral 0.60,
// 0.51, 0.45; polygon 0.59, 0.46, 0.42; rings 0.51, 0.45, 0.48; thinned
// 0.32, 0.28, 0.29 (two steps: no better than four, twice the
// factorizations). With SparseLU's factorizations sixteen steps were
// best.
// Where the factors fill in too densely for the static refactorization
// (CompactLU::refactorization_pays false: every factorization is
// SparseLU's with pivoting and a copy into CompactLU, 20-30 times a
// GMRES step), more steps before giving up on the anchor, and no solves
// skipped after a failure. Measured on thinned at 10^4 vertices (65
// nonzeros of L and U per row; 48 blended frames in order after
// prepare_rigid_morph): 4 steps with skipping, as elsewhere, 42
// factorizations and 25.7 ms a frame; without skipping, 8, 12, 16 and 24
// steps: 9, 5, 4 and 3 factorizations, 16.4, 16.4, 17.3 and 19.6 ms.
// The steps grow with the anchor's age, from 4-6 to about 14 over 15
// frames.

ConvexCombinationSystem::ConvexCombinationSystem(const Topology& topo, std::vector<int> rows, double tolerance)
    : topo_(topo), nodes_(std::move(rows)), tolerance_(tolerance) {
  unknown_.assign(topo.nodes, -1);
  for (int r = 0; r < int(nodes_.size()); ++r) unknown_[nodes_[r]] = r;
  // The pattern is the same in every frame (one row per node, one entry
  // per unknown neighbour), so it is built once here and each solve only
  // writes the values through slot_: rebuilding the triplets and calling
  // setFromTriplets, with their allocations, was about 4% of the blended
  // frames (perf, spiral at 10^3 vertices). The entries are summed in the
  // triplets' order, as
  // setFromTriplets sums duplicates, so the matrix is the same bit for bit.
  const int m = size();
  std::vector<Eigen::Triplet<double>> triplets;
  for (int row = 0; row < m; ++row) {
    const int v = nodes_[row];
    triplets.emplace_back(row, row, 0.0);
    for (int u : topo_.ring[v])
      if (unknown_[u] >= 0) triplets.emplace_back(row, unknown_[u], 0.0);
  }
  a_.resize(m, m);
  a_.setFromTriplets(triplets.begin(), triplets.end());
  a_.makeCompressed();
  auto slot_of = [&](int row, int column) {
    const int* begin = a_.innerIndexPtr() + a_.outerIndexPtr()[column];
    const int* end = a_.innerIndexPtr() + a_.outerIndexPtr()[column + 1];
    return int(std::lower_bound(begin, end, row) - a_.innerIndexPtr());
  };
  diagonal_slot_.resize(std::size_t(m));
  ring_start_.assign(1, 0);
  for (int row = 0; row < m; ++row) {
    const int v = nodes_[row];
    diagonal_slot_[std::size_t(row)] = slot_of(row, row);
    for (int u : topo_.ring[v]) slot_.push_back(unknown_[u] >= 0 ? slot_of(row, unknown_[u]) : -1);
    ring_start_.push_back(int(slot_.size()));
  }
  b_.resize(m, 2);
}

// The iteration is GMRES right-preconditioned with the anchor's LU
// (preconditioned_gmres.h). Why not the iterative refinement used
// before: the blended system's rows change quickly wherever a figure
// vertex's trust or its guide star does, and refinement on an anchor a
// frame or two old stopped converging (rate above 0.7): 53-62
// factorizations in the 48 frames of spiral and polygon at 10^3 vertices,
// about one a frame (two for each failure, see solve). GMRES converges
// where refinement diverges and, per step, at least as fast (measured
// there: 33 and 28 factorizations; with the warm start and CompactLU, 29
// and 27).

bool ConvexCombinationSystem::solve(double u, const Weights& weights, std::vector<Vec2>& positions) {
  if (nodes_.empty()) return true;
  const int m = size();
  double* values = a_.valuePtr();
  std::fill(values, values + a_.nonZeros(), 0.0);
  b_.setZero();
  for (int row = 0; row < m; ++row) {
    const int v = nodes_[row];
    const std::vector<double>& w = weights(v);
    const int* slot = slot_.data() + ring_start_[std::size_t(row)];
    values[diagonal_slot_[std::size_t(row)]] += 1.0;
    for (std::size_t j = 0; j < w.size(); ++j) {
      if (slot[j] >= 0) {
        values[slot[j]] += -w[j];
      } else {
        const int u = topo_.ring[v][j];
        b_(row, 0) += w[j] * positions[u][0];
        b_(row, 1) += w[j] * positions[u][1];
      }
    }
  }
  const Eigen::MatrixX2d& b = b_;
  if (!analysed_) {
    lu_.analyzePattern(a_);
    analysed_ = true;
  }
  // As MorphSolver does (morph_solver.cpp, where the choice is measured):
  // consecutive frames' systems differ only a little, so an iteration
  // preconditioned with the last factorization (the anchor), from the
  // warm start, converges in a few steps; factorize only when it does
  // not. The result is never trusted on its own: every frame is checked
  // exactly.
  Eigen::MatrixX2d x;
  bool solved = false;
  // After an iteration that did not converge the anchor is too far:
  // factorize without trying (as MorphSolver does) for the next solves,
  // one after the first failure, then twice as many after each further
  // one in a row (up to kMostSkipped), none again after a success. The
  // blended system of the star polygon, the rings and the spiral at 10^3
  // vertices never converged in its kAnchorIterations steps: it
  // refactorized in every frame, and skipping only the solve after each
  // failure still spent a warm start and four steps on every other one
  // (measured: 0.2-0.25 ms of a 1.1-1.2 ms frame there). Trying in every
  // solve instead saves factorizations (spiral 29 -> 23, rings 13 -> 7,
  // measured with GMRES) but costs as much in steps.
  if (factorized_ && !history_.empty() && skipped_ == 0) {
    const double tolerance = tolerance_ * std::max(b.norm(), 1e-300);
    x = least_squares_start(a_, b, history_, u, warm_start_storage_);
    // Densely filled factors (see kAnchorIterationsDense) iterate longer
    // and, after a failure, try again on the anchor just made: the next
    // frame converges on it in 4-6 steps, a fifth of what factorizing
    // again costs there.
    const bool dense = !factors_.refactorization_pays();
    solved = preconditioned_gmres(a_, factors_, b, x, tolerance,
                                  dense ? kAnchorIterationsDense : kAnchorIterations, gmres_);
    failures_in_a_row_ = solved ? 0 : failures_in_a_row_ + 1;
    if (!solved && !dense) skipped_ = std::min(kMostSkipped, 1 << std::min(failures_in_a_row_ - 1, 8));
  } else if (skipped_ > 0) {
    --skipped_;
  }
  if (!solved) {
    // A static-pivot refactorization on the last factors' structure
    // first, kept when its solution meets the tolerance; else SparseLU
    // with pivoting (factorize_checked, as MorphSolver does).
    factorized_ = factorize_checked(a_, b, tolerance_, factorized_, lu_, factors_, &x);
    if (!factorized_) return false;
    ++factorizations_;
  }
  if (!x.allFinite()) return false;
  if (history_.size() == kHistory) history_.erase(history_.begin());
  history_.push_back({u, x});
  for (int row = 0; row < m; ++row) positions[nodes_[row]] = {x(row, 0), x(row, 1)};
  return true;
}

// Iterative refinement of the latest solve, whose unknowns `positions`
// holds: `rounds` rounds of the residual of the system as assembled
// (a_, b_) accumulated in long double, corrected with the kept factors
// (of this system, or of a nearby one when the solve iterated on them).
// For a frame that rounding flipped (GuidedMorph::frame): the solve's
// tolerance leaves errors that a triangle near the tightly wound start
// of a 10^4-vertex spiral, thinner than 1e-8 of the figure, does not
// survive; refined, the positions are the exact solution's to about the
// spacing of doubles.
void ConvexCombinationSystem::refine(std::vector<Vec2>& positions, int rounds) const {
  if (nodes_.empty() || !factorized_) return;
  const int m = size();
  LongMatrixX2 x(m, 2);
  for (int row = 0; row < m; ++row) {
    x(row, 0) = positions[nodes_[row]][0];
    x(row, 1) = positions[nodes_[row]][1];
  }
  const double* values = a_.valuePtr();
  const bool finite = refine_in_long_double(
      a_, [&](Eigen::Index e) { return static_cast<long double>(values[e]); }, b_.cast<long double>(), factors_, x,
      rounds);
  // A correction that is not finite: the positions stay as solved.
  if (!finite) return;
  for (int row = 0; row < m; ++row) positions[nodes_[row]] = {double(x(row, 0)), double(x(row, 1))};
}

}  // namespace internal
}  // namespace stickmorph
