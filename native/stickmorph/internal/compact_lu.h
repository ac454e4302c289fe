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
#include <cstdint>
#include <vector>

namespace stickmorph::internal {

/// The sparse LU both stateful solvers factorize with: Eigen's SparseLU
/// (partial pivoting) on the matrix permuted symmetrically, B = P A P^T,
/// by a minimum degree ordering P of the pattern of A + A^T.
///
/// Why symmetric: the morph's systems I - W have the pattern of the
/// triangulation's graph (structurally symmetric) and a unit diagonal that
/// dominates each row, so the diagonal pivots serve and the fill is that of
/// a symmetric elimination. SparseLU's own orderings permute the columns
/// only; a symmetric ordering applied that way moves the diagonal off it,
/// and the pivot search then filled in 3 to 15 times more than COLAMD,
/// which is designed for column orderings (so COLAMD was used before).
/// Measured on the benchmark's systems (benchmark_morph's seven families,
/// the blended system at t = 1/2), AMD applied to rows and columns alike
/// against COLAMD: at 10^3 vertices 2-52% fewer nonzeros in six families
/// (thinned 36 against 44 per row, spiral 10 against 21; the tree 9% more)
/// and the fresh analyse, factorize and solve 1.3-2.9 times faster in all
/// seven; at 10^4 vertices 2.0 (thinned) and 2.4 times (spiral) faster.
/// METIS's nested dissection, applied the same way, filled slightly more
/// than AMD at 10^3 vertices and took longer to order.
class SymmetricOrderedLU {
 public:
  using Factors = Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::NaturalOrdering<int>>;
  using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

  /// The ordering and SparseLU's symbolic analysis of P A P^T.
  void analyzePattern(const Eigen::SparseMatrix<double>& a);
  /// Factorizes a matrix with the analysed pattern; info() tells whether
  /// it succeeded.
  void factorize(const Eigen::SparseMatrix<double>& a);
  Eigen::ComputationInfo info() const { return factors_.info(); }
  /// x = A^-1 b, #A by 2.
  Eigen::MatrixX2d solve(const Eigen::MatrixX2d& b) const;

  /// SparseLU's factors of P A P^T, and P.
  const Factors& factors() const { return factors_; }
  const Permutation& ordering() const { return p_; }

 private:
  Permutation p_;
  Eigen::SparseMatrix<double> permuted_;  // P A P^T of the latest factorize()
  Factors factors_;
};

class CompactLU {
 public:
  CompactLU() = default;
  /// A copy of the factors of `lu`, which must have factorized successfully,
  /// with its ordering folded into the row and column permutations.
  explicit CompactLU(const SymmetricOrderedLU& lu);

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
  /// The same on the structure and pivot order of `base` (another anchor
  /// of the same system), into these factors: their structure becomes
  /// base's (its indices copied, 4 bytes a nonzero, unless both came from
  /// the same SparseLU factorization; base's values are not needed), so the
  /// result is bit for bit what base.refactorize(a) would give, and base
  /// is left as it is. False as refactorize().
  bool refactorize_from(const CompactLU& base, const Eigen::SparseMatrix<double>& a);

 private:
  std::vector<int> pr_, pc_;            // P_r, P_c as index maps
  std::vector<int> lp_, li_, up_, ui_;  // column starts and rows: strictly lower L, strictly upper U
  std::vector<double> lv_, uv_, ud_;    // their values; U's diagonal (L's is one)
  // refactorize()'s: the inverse of P_c, and scratch (a dense column and
  // the stamp of the column whose pattern holds each row).
  std::size_t updates_ = 0;
  bool upper_sorted_ = false;  // U's columns in row order (refactorize's need)
  void sort_upper_columns();
  std::vector<int> pc_inverse_;
  // Per column r of L, the last column of its supernode: the columns
  // r .. supernode_end_[r] whose rows below the diagonal are each the next
  // column's row and then the same rows (the dense blocks of SparseLU's
  // supernodes, as copied). Found on the first refactorize().
  std::vector<int> supernode_end_;
  // Which SparseLU factorization the structure was copied from (0: none);
  // refactorize_from copies a structure only when this differs.
  std::uint64_t pattern_ = 0;
  void find_supernodes();
  // refactorize()'s: one supernode's nonzero entries of U(:, j), their
  // rows (then where their columns' rows below the supernode start) and values.
  std::vector<int> segment_start_;
  std::vector<double> segment_value_;
  std::vector<double> work_;
  std::vector<int> stamp_;
};

/// Factors of `a` into `factors`, for a x = b: first, when
/// `try_refactorization` and factors.refactorization_pays(), a static-pivot
/// refactorization on `factors`' own structure (CompactLU::refactorize),
/// kept only when its solution's residual is at most `tolerance` |b|: a
/// pivot order kept from another matrix can grow the factors; otherwise
/// (and when the refactorization is refused) `lu`, analysed for a's
/// pattern, factorizes with pivoting. Both stateful solvers factorize this
/// way (MorphSolver, GuidedMorph's systems). The solution of a x = b goes
/// to `solution` if given (the refactorization's check computes it anyway).
/// False if `lu` finds `a` singular.
bool factorize_checked(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixX2d& b, double tolerance,
                       bool try_refactorization, SymmetricOrderedLU& lu, CompactLU& factors,
                       Eigen::MatrixX2d* solution = nullptr);
/// The same with the refactorization tried on the structure of `base`
/// (CompactLU::refactorize_from) and the new factors going to `factors`,
/// base unchanged: a system that keeps several anchors (ConvexCombination
/// System) makes a new one next to the one it iterated on. `base` may be
/// `factors` itself; it is not read unless `try_refactorization`.
bool factorize_checked(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixX2d& b, double tolerance,
                       bool try_refactorization, SymmetricOrderedLU& lu, const CompactLU& base, CompactLU& factors,
                       Eigen::MatrixX2d* solution = nullptr);

}  // namespace stickmorph::internal
