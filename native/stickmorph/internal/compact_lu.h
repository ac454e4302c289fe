// Sparse LU factors as plain compressed columns, for repeated solves with
// two right-hand sides (the morph's x and y coordinates).
//
// Eigen's SparseLU stores L in supernodes and its solve packs every
// supernode for a dense product, which for two right-hand sides costs more
// than the arithmetic: measured with perf on a 10^4-vertex triangulation,
// the packing alone was a sixth of a whole playback (MorphSolver), and on
// the spiral at 10^3 vertices Eigen's solve was a fifth of the rigid
// morph's blended frames (GuidedMorph). Here each nonzero of L and U is
// one multiply-add per coordinate, both coordinates interleaved.
#pragma once

#include <Eigen/SparseLU>

#include <cstddef>
#include <vector>

namespace stickmorph::internal {

/// The sparse LU both stateful solvers factorize with (COLAMD: on these
/// planar systems AMD and the natural ordering gave 1.1-4 times the fill,
/// measured in morph_solver.cpp).
using SparseLU = Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>;

class CompactLU {
 public:
  CompactLU() = default;
  /// A copy of the factors of `lu`, which must have factorized successfully.
  explicit CompactLU(const SparseLU& lu);

  /// x = A^-1 b for the factorized A (P_r A P_c^T = L U), #A by 2.
  Eigen::MatrixX2d solve(const Eigen::MatrixX2d& b) const;

  /// Nonzeros of L and U.
  std::size_t nonzeros() const { return lv_.size() + uv_.size() + ud_.size(); }
  /// Multiply-adds of one refactorize(): over the entries U(r, j), the
  /// length of L's column r.
  std::size_t elimination_updates() const { return updates_; }
  /// Whether refactorize() is worth trying instead of SparseLU: its
  /// column-by-column updates against SparseLU's dense supernode kernels,
  /// which win where the factors fill in densely. Measured (the morph's
  /// systems of the benchmark families at 10^3 and 10^4 vertices; time of
  /// refactorize over SparseLU::factorize, by multiply-adds per nonzero of
  /// the factors): 2 -> 0.11, 4-10 -> 0.18-0.29, 15-21 -> 0.43-0.59, 54-58
  /// -> 1.1-1.4. Structural, so the choice (and every result) is the same
  /// on every run.
  bool refactorization_pays() const { return updates_ <= 32 * nonzeros(); }

  /// Factorizes `a` anew on these factors' structure and pivot order (a
  /// static-pivot refactorization, as KLU's klu_refactor: the numeric
  /// phase of left-looking Gilbert-Peierls elimination on the known
  /// patterns of L and U, none of the symbolic work or the pivot search
  /// that SparseLU repeats on every factorization). `a` must have the
  /// sparsity pattern of the matrix these factors came from; its values
  /// may differ. False, leaving the factors unusable, if the pattern does
  /// not hold the elimination (an entry outside it) or a pivot is zero,
  /// not finite or below 1e-12 of its column: the pivot order chosen for
  /// the earlier matrix does not suit this one, and the caller factorizes
  /// with pivoting. A pivot order kept from a nearby matrix can still grow
  /// the factors, so callers check the residual of what they solve.
  bool refactorize(const Eigen::SparseMatrix<double>& a);

 private:
  std::vector<int> pr_, pc_;            // P_r, P_c as index maps
  std::vector<int> lp_, li_, up_, ui_;  // column starts and rows: strictly lower L, strictly upper U
  std::vector<double> lv_, uv_, ud_;    // their values; U's diagonal (L's is one)
  // refactorize()'s: the inverse of P_c, and scratch (a dense column and
  // the stamp of the column whose pattern holds each row).
  std::size_t updates_ = 0;
  std::vector<int> pc_inverse_;
  std::vector<double> work_;
  std::vector<int> stamp_;
};

}  // namespace stickmorph::internal
