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

 private:
  std::vector<int> pr_, pc_;            // P_r, P_c as index maps
  std::vector<int> lp_, li_, up_, ui_;  // column starts and rows: strictly lower L, strictly upper U
  std::vector<double> lv_, uv_, ud_;    // their values; U's diagonal (L's is one)
};

}  // namespace stickmorph::internal
