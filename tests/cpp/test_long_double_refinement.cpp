// refine_in_long_double: iterative refinement with the residual in long
// double, the correction from a double factorization.
#include "catch.h"

#include <cmath>
#include <limits>
#include <vector>

#include "stickmorph/internal/compact_lu.h"
#include "stickmorph/internal/long_double_refinement.h"

#include "chain_systems.h"

using namespace stickmorph::internal;
using namespace stickmorph::test;

namespace {

LongMatrixX2 right_hand_side(int m) {
  LongMatrixX2 b(m, 2);
  for (int i = 0; i < m; ++i) {
    b(i, 0) = std::cos(0.3 * i);
    b(i, 1) = 1 + 0.01 * i;
  }
  return b;
}

// The largest entry of b - A x, in long double, A's entries from `entry`.
template <class Entry>
long double residual(const SparseMatrix& a, const Entry& entry, const LongMatrixX2& b, const LongMatrixX2& x) {
  LongMatrixX2 r = b;
  for (Eigen::Index col = 0; col < a.outerSize(); ++col)
    for (Eigen::Index e = a.outerIndexPtr()[col]; e < a.outerIndexPtr()[col + 1]; ++e)
      for (int c = 0; c < 2; ++c) r(a.innerIndexPtr()[e], c) -= entry(e) * x(col, c);
  return r.cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("refine_in_long_double on the matrix's own factors reaches the residual of long double",
          "[long_double_refinement]") {
  const int m = 200;
  const SparseMatrix a = chain_system(m, 0.0);
  const CompactLU factors = factors_of(a);
  const LongMatrixX2 b = right_hand_side(m);
  const auto entry = [&](Eigen::Index e) { return static_cast<long double>(a.valuePtr()[e]); };
  LongMatrixX2 x = factors.solve(Eigen::MatrixX2d(b.cast<double>())).cast<long double>();
  const long double before = residual(a, entry, b, x);
  REQUIRE(refine_in_long_double(a, entry, b, factors, x, 3));
  const long double after = residual(a, entry, b, x);
  CHECK(after <= before);
  CHECK(after < 1e-15L);
}

TEST_CASE("refine_in_long_double with a nearby matrix's factors converges to the blended system's solution",
          "[long_double_refinement]") {
  // As MorphSolver::refine: A(t) = (1 - t) A0 + t A1 blended in long
  // double, corrections from the factors of A0.
  const int m = 100;
  const SparseMatrix a0 = chain_system(m, 0.0), a1 = chain_system(m, 0.2);
  const CompactLU factors = factors_of(a0);
  const long double t = 0.1L;
  const auto entry = [&](Eigen::Index e) { return (1 - t) * a0.valuePtr()[e] + t * a1.valuePtr()[e]; };
  const LongMatrixX2 b = right_hand_side(m);
  LongMatrixX2 x = LongMatrixX2::Zero(m, 2);
  REQUIRE(refine_in_long_double(a0, entry, b, factors, x, 60));
  CHECK(residual(a0, entry, b, x) < 1e-14L);
}

TEST_CASE("refine_in_long_double stops at a correction that is not finite, keeping the rounds before",
          "[long_double_refinement]") {
  const int m = 10;
  const SparseMatrix a = chain_system(m, 0.0);
  const CompactLU factors = factors_of(a);
  LongMatrixX2 b = right_hand_side(m);
  b(3, 1) = std::numeric_limits<long double>::quiet_NaN();
  const auto entry = [&](Eigen::Index e) { return static_cast<long double>(a.valuePtr()[e]); };
  LongMatrixX2 x = LongMatrixX2::Constant(m, 2, 0.5L);
  const LongMatrixX2 start = x;
  CHECK_FALSE(refine_in_long_double(a, entry, b, factors, x, 3));
  CHECK(x == start);
  // No rounds, nothing to fail.
  CHECK(refine_in_long_double(a, entry, b, factors, x, 0));
}
