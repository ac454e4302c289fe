// SolutionSpace: the Galerkin projection onto a space of solutions of a
// linearly blended system A(t) x = b(t).
#include "catch.h"

#include <cmath>
#include <vector>

#include <Eigen/SparseLU>

#include "stickmorph/internal/solution_space.h"

#include "chain_systems.h"

using namespace stickmorph::internal;
using namespace stickmorph::test;

namespace {

LongMatrixX2 right_hand_side(int m, double phase) {
  LongMatrixX2 b(m, 2);
  for (int i = 0; i < m; ++i) {
    b(i, 0) = std::cos(phase + 0.3 * i);
    b(i, 1) = 1 + 0.01 * i + phase;
  }
  return b;
}

// The solution of the system blended to t, directly.
Eigen::MatrixX2d solution(const SparseMatrix& a0, const SparseMatrix& a1, const LongMatrixX2& b0,
                          const LongMatrixX2& b1, double t) {
  const SparseMatrix a = (1 - t) * a0 + t * a1;
  Eigen::SparseLU<SparseMatrix> lu(a);
  REQUIRE(lu.info() == Eigen::Success);
  const Eigen::MatrixX2d b = ((1 - t) * b0.cast<double>() + t * b1.cast<double>());
  return lu.solve(b);
}

}  // namespace

TEST_CASE("SolutionSpace::capacity_for: 80 columns, fewer for systems too large for the budget",
          "[solution_space]") {
  CHECK(SolutionSpace::capacity_for(0) == 80);
  CHECK(SolutionSpace::capacity_for(1000) == 80);
  // 64 MiB over 16 bytes a row and column pair: 4 columns at 10^6 rows.
  CHECK(SolutionSpace::capacity_for(1000000) == 4);
  CHECK(SolutionSpace::capacity_for(1000000000) == 1);
}

TEST_CASE("SolutionSpace projects exactly what its columns span", "[solution_space]") {
  // A constant matrix with a right-hand side linear in t: x(t) is the
  // blend of x(0) and x(1), which the space then spans.
  const int m = 60;
  const SparseMatrix a = chain_system(m, 0.0);
  const LongMatrixX2 b0 = right_hand_side(m, 0.0), b1 = right_hand_side(m, 1.0);
  SolutionSpace space(a, a, b0, b1, SolutionSpace::capacity_for(m));
  Eigen::MatrixX2d x;
  CHECK_FALSE(space.guess(0.5, x));  // empty
  CHECK(space.size() == 0);
  space.add(solution(a, a, b0, b1, 0));
  space.add(solution(a, a, b0, b1, 1));
  CHECK(space.size() == 4);  // two columns per coordinate
  for (double t : {0.0, 0.3, 0.77, 1.0}) {
    REQUIRE(space.guess(t, x));
    const Eigen::MatrixX2d exact = solution(a, a, b0, b1, t);
    CHECK((x - exact).cwiseAbs().maxCoeff() <= 1e-10 * exact.cwiseAbs().maxCoeff());
  }
  // A solution already spanned adds nothing.
  space.add(solution(a, a, b0, b1, 0.5));
  CHECK(space.size() == 4);
  CHECK_FALSE(space.half_full());
}

TEST_CASE("SolutionSpace of a blended matrix interpolates between the solutions it holds", "[solution_space]") {
  const int m = 40;
  const SparseMatrix a0 = chain_system(m, 0.0), a1 = chain_system(m, 0.3);
  const LongMatrixX2 b0 = right_hand_side(m, 0.0), b1 = right_hand_side(m, 0.5);
  SolutionSpace space(a0, a1, b0, b1, SolutionSpace::capacity_for(m));
  for (int i = 0; i <= 8; ++i) space.add(solution(a0, a1, b0, b1, i / 8.0));
  Eigen::MatrixX2d x;
  REQUIRE(space.guess(0.4375, x));
  const Eigen::MatrixX2d exact = solution(a0, a1, b0, b1, 0.4375);
  CHECK((x - exact).cwiseAbs().maxCoeff() <= 1e-6 * exact.cwiseAbs().maxCoeff());
}

TEST_CASE("SolutionSpace::add_block keeps at most its capacity and reports half full", "[solution_space]") {
  const int m = 30;
  const SparseMatrix a = chain_system(m, 0.0);
  const LongMatrixX2 b = right_hand_side(m, 0.0);
  SolutionSpace space(a, a, b, b, 6);
  space.add_block(0, Eigen::MatrixXd::Identity(m, 3));
  CHECK(space.size() == 3);
  CHECK(space.half_full());
  space.add_block(0, Eigen::MatrixXd::Identity(m, 10));
  CHECK(space.size() == 6);  // the capacity
  space.add_block(1, Eigen::MatrixXd::Zero(m, 2));  // nothing new
  CHECK(space.size() == 6);
  Eigen::MatrixX2d x;
  CHECK_FALSE(space.guess(0.5, x));  // coordinate 1's space is empty
}

TEST_CASE("SolutionSpace::add_moments spans a solution linear in t from one time", "[solution_space]") {
  // A constant matrix, b linear in t: x(t) = x(0) + t x'(0), which the
  // moments at t = 0 hold (the later derivatives vanish up to rounding:
  // A0 d - A1 d is not evaluated as exactly zero, so their directions of
  // rounding noise may join the space too, harmlessly).
  const int m = 50;
  const SparseMatrix a = chain_system(m, 0.4);
  const LongMatrixX2 b0 = right_hand_side(m, 0.0), b1 = right_hand_side(m, 2.0);
  SymmetricOrderedLU lu;
  lu.analyzePattern(a);
  lu.factorize(a);
  REQUIRE(lu.info() == Eigen::Success);
  const CompactLU factors(lu);
  SolutionSpace space(a, a, b0, b1, SolutionSpace::capacity_for(m));
  const Eigen::MatrixX2d db = (b1 - b0).cast<double>();
  space.add_moments(factors, solution(a, a, b0, b1, 0), db, 9);
  CHECK(space.size() >= 4);  // at least x(0) and x'(0) per coordinate
  Eigen::MatrixX2d x;
  for (double t : {0.25, 0.9}) {
    REQUIRE(space.guess(t, x));
    const Eigen::MatrixX2d exact = solution(a, a, b0, b1, t);
    CHECK((x - exact).cwiseAbs().maxCoeff() <= 1e-10 * exact.cwiseAbs().maxCoeff());
  }
}
