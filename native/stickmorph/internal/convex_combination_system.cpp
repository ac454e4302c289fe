// A convex-combination system solved frame after frame; see
// convex_combination_system.h.
#include "stickmorph/internal/convex_combination_system.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
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
  ++solves_;
  if (factorized_) {
    current_ = choose_anchor(u);
    anchors_[current_].used = solves_;
  }
  if (factorized_ && !pool_.empty() && skipped_ == 0) {
    const double tolerance = tolerance_ * std::max(b.norm(), 1e-300);
    x = least_squares_start(a_, b, nearest_solutions(u), u, warm_start_storage_);
    const CompactLU& factors = anchors_[current_].factors;
    // Densely filled factors (see kAnchorIterationsDense) iterate longer
    // and, after a failure, try again on the anchor just made: the next
    // frame converges on it in 4-6 steps, a fifth of what factorizing
    // again costs there.
    const bool dense = !factors.refactorization_pays();
    solved = preconditioned_gmres(a_, factors, b, x, tolerance, dense ? kAnchorIterationsDense : kAnchorIterations,
                                  gmres_);
    failures_in_a_row_ = solved ? 0 : failures_in_a_row_ + 1;
    if (!solved && !dense) skipped_ = std::min(kMostSkipped, 1 << std::min(failures_in_a_row_ - 1, 8));
  } else if (skipped_ > 0) {
    --skipped_;
  }
  if (!solved) {
    // A static-pivot refactorization on the structure of the anchor just
    // chosen first, kept when its solution meets the tolerance; else
    // SparseLU with pivoting (factorize_checked, as MorphSolver does). The
    // new factors are a new anchor at u (or replace the least recently
    // used one), the chosen one is kept.
    const std::size_t base = current_;
    const std::size_t slot = free_anchor_slot();
    factorized_ = factorize_checked(a_, b, tolerance_, factorized_, lu_, anchors_[base].factors,
                                    anchors_[slot].factors, &x);
    if (!factorized_) {
      anchors_.clear();
      current_ = 0;
      return false;
    }
    anchors_[slot].u = u;
    anchors_[slot].used = solves_;
    current_ = slot;
    ++factorizations_;
  }
  if (!x.allFinite()) return false;
  keep_solution(u, x);
  for (int row = 0; row < m; ++row) positions[nodes_[row]] = {x(row, 0), x(row, 1)};
  return true;
}

// The anchor nearest in u, the one of the latest solve on a tie. In a
// playback in order (u never decreasing since begin_playback) every anchor
// was made at or before the latest solve's u, so the latest factorization is
// the nearest: the choice is the single anchor of before (issue 29).
//
// Issue 29, measured at 10^4 vertices (benchmark_scrub's seeded scrub of
// 240 random times after a playback of 240): with one anchor and the latest
// six solutions, a jump left the anchor and the warm start far from the
// frame, and the densely filled blended system of the thinned family
// (67 nonzeros of L and U per row, SparseLU every time) factorized in 166
// of the 240 frames, 31 frames per second of CPU time against 68 in order;
// with sixteen anchors and the six kept solutions nearest in u, 1-2
// factorizations and 70 frames per second, the steps per frame (5.4) those
// of the playback in order. Where the blended system refactorizes in
// nearly every frame even in order (polygon, rings: its weights follow the
// guide's trust and stars, and a frame-old anchor already misses by more
// than four steps), the anchors cannot save factorizations; there the
// nearest anchor's structure makes the static-pivot refactorization fail
// less often (polygon: 47 SparseLU factorizations of 240 in the scrub
// before, 1 after), and the refactorization itself was made faster
// (compact_lu.cpp).
std::size_t ConvexCombinationSystem::choose_anchor(double u) const {
  std::size_t best = current_;
  for (std::size_t i = 0; i < anchors_.size(); ++i)
    if (std::abs(anchors_[i].u - u) < std::abs(anchors_[best].u - u)) best = i;
  return best;
}

// Where a new factorization goes: the set-up's anchor itself (see below),
// else a new anchor while fewer than kMaxAnchors
// are kept and their factors fit in kAnchorBudgetBytes (each about 12 bytes
// a nonzero of L and U: its values, row indices and scratch), otherwise the
// least recently used one other than the one just chosen (whose structure
// the refactorization starts from).
std::size_t ConvexCombinationSystem::free_anchor_slot() {
  // The set-up's anchor is refactorized in place (so it is the only anchor
  // until then): kept beside the playback's, it would be nearer than the
  // latest to some frames of a playback in order.
  if (!anchors_.empty() && anchors_[current_].before_playback) {
    anchors_[current_].before_playback = false;
    return current_;
  }
  const double bytes =
      anchors_.empty() ? 0.0 : 12.0 * double(anchors_[current_].factors.nonzeros()) * double(anchors_.size() + 1);
  if (anchors_.size() < kMaxAnchors && bytes <= kAnchorBudgetBytes) {
    anchors_.emplace_back();
    return anchors_.size() - 1;
  }
  if (anchors_.size() < 2) return current_;  // one fits: refactorized in place, as before issue 29
  std::size_t oldest = current_ == 0 ? 1 : 0;
  for (std::size_t i = 0; i < anchors_.size(); ++i)
    if (i != current_ && anchors_[i].used < anchors_[oldest].used) oldest = i;
  return oldest;
}

// Keeps x, the solution at u. A full pool drops one of its solutions other
// than the kHistory latest (which a playback in order combines): one from
// before begin_playback first, else the one nearest in u to another kept
// one (the older of such a pair), so that the pool spreads over the u
// asked and a scrub finds solutions on both sides of most times.
void ConvexCombinationSystem::keep_solution(double u, const Eigen::MatrixX2d& x) {
  if (pool_.size() >= kPool) {
    // pool_ is in the order solved: its last kHistory are the latest.
    const std::size_t latest = pool_.size() - kHistory;
    std::size_t drop = pool_.size();
    double drop_gap = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < latest; ++i) {
      const Kept& k = pool_[i];
      if (k.before_playback) {
        if (drop == pool_.size() || !pool_[drop].before_playback || k.order < pool_[drop].order) {
          drop = i;
          drop_gap = -1;
        }
        continue;
      }
      if (drop != pool_.size() && pool_[drop].before_playback) continue;
      double gap = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < pool_.size(); ++j)
        if (j != i) gap = std::min(gap, std::abs(pool_[j].solution.t - k.solution.t));
      if (gap < drop_gap || (gap == drop_gap && k.order < pool_[drop].order)) {
        drop = i;
        drop_gap = gap;
      }
    }
    if (drop == pool_.size()) drop = 0;
    pool_.erase(pool_.begin() + std::ptrdiff_t(drop));
  }
  Kept kept;
  kept.solution = {u, x};
  kept.order = solves_;
  pool_.push_back(std::move(kept));
}

// The kHistory kept solutions nearest in u (the later on a tie; those from
// before begin_playback only after all later ones, the latest first),
// oldest first as least_squares_start takes them. In a playback in order
// they are the kHistory latest.
std::vector<const KeptSolution*> ConvexCombinationSystem::nearest_solutions(double u) const {
  std::vector<const Kept*> order;
  for (const Kept& k : pool_) order.push_back(&k);
  auto nearer = [u](const Kept* p, const Kept* q) {
    if (p->before_playback != q->before_playback) return q->before_playback;
    if (!p->before_playback) {
      const double dp = std::abs(p->solution.t - u), dq = std::abs(q->solution.t - u);
      if (dp != dq) return dp < dq;
    }
    return p->order > q->order;
  };
  const std::size_t h = std::min(kHistory, order.size());
  std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(h), order.end(), nearer);
  order.resize(h);
  std::sort(order.begin(), order.end(), [](const Kept* p, const Kept* q) { return p->order < q->order; });
  std::vector<const KeptSolution*> nearest;
  for (const Kept* k : order) nearest.push_back(&k->solution);
  return nearest;
}

void ConvexCombinationSystem::begin_playback() {
  if (!anchors_.empty()) {
    Anchor latest = std::move(anchors_[current_]);
    anchors_.clear();
    anchors_.push_back(std::move(latest));
    anchors_.front().before_playback = true;
    current_ = 0;
  }
  // The kHistory latest solutions, which the first solves combine as before.
  while (pool_.size() > kHistory) pool_.erase(pool_.begin());
  for (Kept& k : pool_) k.before_playback = true;
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
  const CompactLU& factors = anchors_[current_].factors;
  const int m = size();
  LongMatrixX2 x(m, 2);
  for (int row = 0; row < m; ++row) {
    x(row, 0) = positions[nodes_[row]][0];
    x(row, 1) = positions[nodes_[row]][1];
  }
  const double* values = a_.valuePtr();
  const bool finite = refine_in_long_double(
      a_, [&](Eigen::Index e) { return static_cast<long double>(values[e]); }, b_.cast<long double>(), factors, x,
      rounds);
  // A correction that is not finite: the positions stay as solved.
  if (!finite) return;
  for (int row = 0; row < m; ++row) positions[nodes_[row]] = {double(x(row, 0)), double(x(row, 1))};
}

}  // namespace internal
}  // namespace stickmorph
