// A reduced basis for the solutions x(t) of a linear system A(t) x = b(t)
// whose matrix and right-hand side blend linearly between two endpoints,
// A(t) = (1 - t) A0 + t A1 (the morph's system, morph_solver.h; Floater &
// Gotsman 1999, the paper's [8]): the Galerkin projection onto the span of
// some solutions and derivatives (moment matching: Grimme 1997, "Krylov
// projection methods for model reduction", chapter 5; the blocked
// orthogonalization is BCGS2, Barlow & Smoktunowicz 2013).
//
// x(t) is analytic in one parameter, so a few dozen vectors span it to many
// digits; the projection then costs far less than a triangular solve, and
// MorphSolver takes it as a frame's solution when its true residual meets
// the tolerance (otherwise as a warm start). What goes into the space (the
// moments, which solutions) is MorphSolver's choice; this class keeps the
// basis and the projected endpoint matrices.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "stickmorph/internal/compact_lu.h"
#include "stickmorph/internal/long_double_refinement.h"  // LongMatrixX2

namespace stickmorph {
namespace internal {

/// One orthonormal basis per coordinate (x and y) of the solutions, each
/// with V^T A0 V, V^T A1 V, V^T b0 and V^T b1 kept so that the projected
/// system at any t is a blend of small matrices.
class SolutionSpace {
 public:
  /// Each coordinate space's capacity for a system of `unknowns` rows:
  /// kMaxSpace columns, fewer for a system so large that both would take
  /// more than kSpaceBudgetBytes.
  static Eigen::Index capacity_for(int unknowns);

  /// The endpoint systems A0 x = b0 and A1 x = b1 on one sparsity pattern,
  /// kept by reference (they must outlive the space); `capacity` columns per
  /// coordinate at most.
  SolutionSpace(const Eigen::SparseMatrix<double>& a0, const Eigen::SparseMatrix<double>& a1,
                const LongMatrixX2& b0, const LongMatrixX2& b1, Eigen::Index capacity);

  /// The Galerkin projection at t into x: for each coordinate c,
  /// V^T A(t) V y = V^T b_c(t), x_c = V y. False if either space is empty
  /// or the projection is not finite. Its residual is the caller's to check.
  bool guess(double t, Eigen::MatrixX2d& x) const;

  /// Adds each coordinate of the solution x to its space (add_block).
  void add(const Eigen::MatrixX2d& x);

  /// Adds the columns of `block` to coordinate c's space: what is new in
  /// them, orthonormalized; columns already in the space to rounding, and
  /// those beyond the capacity, are left out.
  void add_block(int c, Eigen::MatrixXd block);

  /// Adds the moments at a time t_a to both coordinates' spaces: the
  /// solution x(t_a) there and its first `max_levels` derivatives in t
  /// (each scaled to unit norm; fewer if one is not finite), from
  /// `factors` of A(t_a) and db = b1 - b0.
  void add_moments(const CompactLU& factors, const Eigen::MatrixX2d& solution, const Eigen::MatrixX2d& db,
                   int max_levels);

  /// Whether either coordinate's space is at least half full.
  bool half_full() const;
  /// Columns of both coordinates' spaces (at most the capacity each).
  int size() const;

  static constexpr Eigen::Index kMaxSpace = 80;
  static constexpr double kSpaceBudgetBytes = 64.0 * 1024 * 1024;

 private:
  const Eigen::SparseMatrix<double>& a0_;
  const Eigen::SparseMatrix<double>& a1_;
  const LongMatrixX2& b0_;
  const LongMatrixX2& b1_;
  // Per coordinate, the space V (its first k columns; allocated at
  // capacity_ on first use), V^T A0 V, V^T A1 V, V^T b0 and V^T b1 of that
  // coordinate. (Coordinate c's solution is A(t)^-1 b_c(t): its own
  // moments span it, and two spaces of k columns cost a quarter of one of
  // 2k in the projection and half in the setup.)
  struct Space {
    Eigen::MatrixXd v, g0, g1;
    Eigen::VectorXd c0, c1;
    Eigen::Index k = 0;
  };
  Space space_[2];
  Eigen::Index capacity_ = 0;  // per coordinate
};

}  // namespace internal
}  // namespace stickmorph
