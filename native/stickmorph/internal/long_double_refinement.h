// Iterative refinement with the residual in extended precision (Wilkinson
// 1963, "Rounding Errors in Algebraic Processes"; Higham 2002, "Accuracy and
// Stability of Numerical Algorithms", chapter 12): x += A^-1 (b - A x), the
// residual accumulated in long double, the correction solved with a double
// factorization of A or of a nearby matrix.
//
// Shared by the two convex-combination systems: MorphSolver's refine (A and
// b blended from the endpoint values in long double, so the blend itself is
// not rounded to double) and ConvexCombinationSystem's refine for a frame
// that rounding flipped (A and b as assembled). Each caller supplies A's
// entries through `entry`, which is where they differ.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "stickmorph/internal/compact_lu.h"

namespace stickmorph {
namespace internal {

/// Two columns (x and y coordinates) in long double.
using LongMatrixX2 = Eigen::Matrix<long double, Eigen::Dynamic, 2>;

/// `rounds` rounds of refinement of x for A x = b. A has `pattern`'s
/// compressed-column structure, and entry(e) is the long double value of
/// its e-th nonzero (in the order of pattern's value array); the residual
/// b - A x is summed column by column in that order, rounded to double, and
/// corrected with `factors`. A template (header-only) so that `entry` is
/// inlined in the innermost loop.
/// @returns false if a correction was not finite; x then holds the rounds
///          before it (the caller decides whether to keep them).
template <class Entry>
bool refine_in_long_double(const Eigen::SparseMatrix<double>& pattern, const Entry& entry, const LongMatrixX2& b,
                           const CompactLU& factors, LongMatrixX2& x, int rounds) {
  for (int round = 0; round < rounds; ++round) {
    LongMatrixX2 r = b;
    for (Eigen::Index col = 0; col < pattern.outerSize(); ++col)
      for (Eigen::Index e = pattern.outerIndexPtr()[col]; e < pattern.outerIndexPtr()[col + 1]; ++e) {
        const Eigen::Index row = pattern.innerIndexPtr()[e];
        const long double a = entry(e);
        r(row, 0) -= a * x(col, 0);
        r(row, 1) -= a * x(col, 1);
      }
    const Eigen::MatrixX2d correction = factors.solve(Eigen::MatrixX2d(r.cast<double>()));
    if (!correction.allFinite()) return false;
    x += correction.cast<long double>();
  }
  return true;
}

}  // namespace internal
}  // namespace stickmorph
