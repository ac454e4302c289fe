// The reduced basis of a linearly blended system's solutions; see
// solution_space.h.
#include "stickmorph/internal/solution_space.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace stickmorph {
namespace internal {

Eigen::Index SolutionSpace::capacity_for(int unknowns) {
  return std::max<Eigen::Index>(
      1, std::min<Eigen::Index>(kMaxSpace, Eigen::Index(kSpaceBudgetBytes / (16.0 * std::max(unknowns, 1)))));
}

SolutionSpace::SolutionSpace(const Eigen::SparseMatrix<double>& a0, const Eigen::SparseMatrix<double>& a1,
                             const LongMatrixX2& b0, const LongMatrixX2& b1, Eigen::Index capacity)
    : a0_(a0), a1_(a1), b0_(b0), b1_(b1), capacity_(capacity) {}

// Past half the capacity, MorphSolver no longer adds the solution of a
// frame projected near the tolerance (see its near_tolerance).
bool SolutionSpace::half_full() const { return 2 * std::max(space_[0].k, space_[1].k) >= capacity_; }

int SolutionSpace::size() const { return int(space_[0].k + space_[1].k); }

// The space of the moments and earlier solutions (a reduced basis): x(t)
// is an analytic function of one parameter, so the solutions at a few
// times span all the others to many digits (measured at 10^3 vertices:
// the singular values of 201 solutions over [0, 1] fall below 1e-11 of
// the first after 30 to 70 vectors across the benchmark's families).
// Each coordinate of every solution whose projection was not near the
// tolerance (near_tolerance) joins that coordinate's orthonormal basis V
// (up to capacity_ columns); the Galerkin projection V^T A(t) V y =
// V^T b_c(t) then costs O(k^3 + m k) per frame and coordinate, with
// V^T A0 V, V^T A1 V, V^T b0 and V^T b1 kept (A(t) and b(t) blend
// linearly), far less than a triangular solve. Its result is accepted
// only by its true residual.
bool SolutionSpace::guess(double t, Eigen::MatrixX2d& x) const {
  if (space_[0].k == 0 || space_[1].k == 0) return false;
  x.resize(a0_.rows(), 2);
  for (int c = 0; c < 2; ++c) {
    const Space& sp = space_[c];
    const Eigen::Index k = sp.k;
    const Eigen::MatrixXd g = (1 - t) * sp.g0.topLeftCorner(k, k) + t * sp.g1.topLeftCorner(k, k);
    const Eigen::VectorXd rhs = (1 - t) * sp.c0.head(k) + t * sp.c1.head(k);
    const Eigen::VectorXd y = Eigen::PartialPivLU<Eigen::MatrixXd>(g).solve(rhs);
    if (!y.allFinite()) return false;
    x.col(c).noalias() = sp.v.leftCols(k) * y;
  }
  return x.allFinite();
}

// Adds each coordinate of the solution x to its space (what is new in
// it, orthonormalized twice; nothing if it is already in the space to
// rounding, or the space is full). A full space keeps what it
// has: a window over the latest solutions (what this replaced) forgot the
// start of a playback, so a scrub after it projected almost nothing, and
// dropping columns spread over time lost the directions that later
// columns are orthogonal to (measured at 10^4 vertices, a 240-frame
// playback then 240 random times: the projection's residual jumped from
// about the tolerance to 1e6 times it either way). The
// storage is allocated once, at the capacity: a column costs its
// orthogonalization and the new row and column of the projected
// matrices, O(m k), and no copy of the space (conservativeResize copied
// it whole for every column: a third of a frame at 10^3 vertices).
void SolutionSpace::add(const Eigen::MatrixX2d& x) {
  for (int c = 0; c < 2; ++c) add_block(c, x.col(c));
}

// Adds the columns of `block` to coordinate c's space: what is new in
// them against the space (block Gram-Schmidt, twice), orthonormalized
// among themselves by a Householder QR; a column whose new part is below
// 1e-12 of its norm is left out (already in the space to rounding), and
// columns beyond the capacity. Blocked (matrix-matrix products), so that
// the moment space's few dozen columns (MorphSystem::build_moment_space) cost about
// one pass over them rather than one per column.
void SolutionSpace::add_block(int c, Eigen::MatrixXd block) {
  Space& sp = space_[c];
  if (sp.v.cols() == 0) {
    sp.v.resize(a0_.rows(), capacity_);
    sp.g0.resize(capacity_, capacity_);
    sp.g1.resize(capacity_, capacity_);
    sp.c0.resize(capacity_);
    sp.c1.resize(capacity_);
  }
  const Eigen::Index room = capacity_ - sp.k;
  if (room <= 0 || block.cols() == 0) return;
  const Eigen::VectorXd norms0 = block.colwise().norm().transpose();
  if (!block.allFinite()) return;
  const auto basis = sp.v.leftCols(sp.k);
  if (sp.k > 0) block.noalias() -= basis * (basis.transpose() * block);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(block);
  std::vector<Eigen::Index> kept;
  // (R's diagonal has min(m, columns) entries: a system smaller than the
  // block, as in a figure of a few vertices, spans at most m directions.)
  const Eigen::Index diagonal = std::min(block.rows(), block.cols());
  for (Eigen::Index j = 0; j < diagonal && Eigen::Index(kept.size()) < room; ++j)
    if (norms0(j) > 0 && std::abs(qr.matrixQR()(j, j)) > 1e-12 * norms0(j)) kept.push_back(j);
  if (kept.empty()) return;
  Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(block.rows(), block.cols());
  Eigen::MatrixXd chosen(block.rows(), Eigen::Index(kept.size()));
  for (std::size_t i = 0; i < kept.size(); ++i) chosen.col(Eigen::Index(i)) = q.col(kept[i]);
  // Twice is enough (block Gram-Schmidt, BCGS2): a column whose new part
  // was tiny came out of the first QR orthogonal to its block but only
  // roughly to the space; a second pass and QR restore both. (Into an
  // empty space the first QR's columns are already orthonormal.)
  if (sp.k > 0) {
    chosen.noalias() -= basis * (basis.transpose() * chosen);
    const Eigen::HouseholderQR<Eigen::MatrixXd> again(chosen);
    q = again.householderQ() * Eigen::MatrixXd::Identity(chosen.rows(), chosen.cols());
  } else {
    q = std::move(chosen);
  }
  const Eigen::Index k = sp.k, added = Eigen::Index(kept.size());
  sp.v.middleCols(k, added) = q;
  const auto fresh = sp.v.middleCols(k, added);
  const auto all = sp.v.leftCols(k + added);
  // The new columns and rows of V^T A0 V and V^T A1 V, and of V^T b.
  const Eigen::MatrixXd a0v = a0_ * fresh, a1v = a1_ * fresh;
  sp.g0.block(0, k, k + added, added).noalias() = all.transpose() * a0v;
  sp.g1.block(0, k, k + added, added).noalias() = all.transpose() * a1v;
  if (k > 0) {
    const Eigen::MatrixXd a0tv = a0_.transpose() * fresh, a1tv = a1_.transpose() * fresh;
    sp.g0.block(k, 0, added, k).noalias() = (basis.transpose() * a0tv).transpose();
    sp.g1.block(k, 0, added, k).noalias() = (basis.transpose() * a1tv).transpose();
  }
  sp.c0.segment(k, added).noalias() = fresh.transpose() * b0_.col(c).cast<double>();
  sp.c1.segment(k, added).noalias() = fresh.transpose() * b1_.col(c).cast<double>();
  sp.k += added;
}

// The derivatives from A(t) x(t) = b(t) with A and b linear in t:
// A x' = (b1 - b0) - (A1 - A0) x and A x^(j) = -j (A1 - A0) x^(j-1), one
// pair of triangular solves each (only their directions are kept, so the
// factor j is dropped). The Galerkin projection onto such a space matches
// the Taylor expansion of x at every t_a to the levels' order (multi-point
// moment matching, the rational Krylov reduction of Grimme 1997, "Krylov
// projection methods for model reduction", chapter 5).
void SolutionSpace::add_moments(const CompactLU& factors, const Eigen::MatrixX2d& solution,
                                const Eigen::MatrixX2d& db, int max_levels) {
  // Column j of coordinate c's block: its j-th derivative.
  Eigen::MatrixXd blocks[2] = {Eigen::MatrixXd(a0_.rows(), max_levels + 1),
                               Eigen::MatrixXd(a0_.rows(), max_levels + 1)};
  Eigen::MatrixX2d d = solution;
  for (int c = 0; c < 2; ++c) blocks[c].col(0) = d.col(c);
  d = factors.solve(Eigen::MatrixX2d(db - (a1_ * d - a0_ * d)));
  int levels = max_levels;
  for (int level = 1; level <= max_levels; ++level) {
    // Only the direction matters: scaled to unit norm against overflow.
    for (int c = 0; c < 2; ++c) {
      const double norm = d.col(c).norm();
      if (norm > 0 && std::isfinite(norm)) d.col(c) /= norm;
    }
    if (!d.allFinite()) {
      levels = level - 1;
      break;
    }
    for (int c = 0; c < 2; ++c) blocks[c].col(level) = d.col(c);
    if (level < max_levels) d = factors.solve(Eigen::MatrixX2d(a0_ * d - a1_ * d));
  }
  for (int c = 0; c < 2; ++c) add_block(c, blocks[c].leftCols(levels + 1));
}

}  // namespace internal
}  // namespace stickmorph
