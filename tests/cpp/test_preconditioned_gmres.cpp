// preconditioned_gmres: GMRES on both coordinates, right-preconditioned by
// the LU of a nearby matrix.
#include "catch.h"

#include <cmath>
#include <vector>

#include "stickmorph/internal/compact_lu.h"
#include "stickmorph/internal/preconditioned_gmres.h"

#include "chain_systems.h"

using namespace stickmorph::internal;
using namespace stickmorph::test;

TEST_CASE("preconditioned_gmres: the matrix's own LU solves in one step", "[preconditioned_gmres]") {
  const SparseMatrix a = chain_system(200, 0.0);
  const CompactLU lu = factors_of(a);
  Eigen::MatrixX2d b(200, 2);
  for (int i = 0; i < 200; ++i) b.row(i) << 1.0, double(i % 7);
  Eigen::MatrixX2d x = Eigen::MatrixX2d::Zero(200, 2);
  GmresWorkspace work;
  int steps = -1;
  const double tolerance = 1e-10 * b.norm();
  REQUIRE(preconditioned_gmres(a, lu, b, x, tolerance, 8, work, &steps));
  CHECK(steps == 1);
  CHECK((b - a * x).norm() <= tolerance);
}

TEST_CASE("preconditioned_gmres: a nearby matrix's LU converges within a few steps", "[preconditioned_gmres]") {
  const SparseMatrix anchor = chain_system(300, 0.0), a = chain_system(300, 0.05);
  const CompactLU lu = factors_of(anchor);
  Eigen::MatrixX2d b(300, 2);
  for (int i = 0; i < 300; ++i) b.row(i) << std::cos(0.1 * i), 1.0;
  Eigen::MatrixX2d x = lu.solve(b);  // the anchor's solution: the warm start
  const double tolerance = 1e-10 * b.norm();
  const double start = (b - a * x).norm();
  REQUIRE(start > tolerance);
  GmresWorkspace work;
  int steps = 0;
  REQUIRE(preconditioned_gmres(a, lu, b, x, tolerance, 16, work, &steps));
  CHECK(steps >= 1);
  CHECK(steps <= 16);
  CHECK((b - a * x).norm() <= tolerance);
  // A second solve with the same workspace reuses its storage and agrees.
  Eigen::MatrixX2d again = lu.solve(b);
  REQUIRE(preconditioned_gmres(a, lu, b, again, tolerance, 16, work));
  CHECK((again - x).norm() == 0);
}

TEST_CASE("preconditioned_gmres: gives up on a far preconditioner without making x worse", "[preconditioned_gmres]") {
  const int m = 400;
  const SparseMatrix anchor = chain_system(m, 0.0, 0.5), a = chain_system(m, 1.5, 0.9999);
  const CompactLU lu = factors_of(anchor);
  const Eigen::MatrixX2d b = Eigen::MatrixX2d::Ones(m, 2);
  Eigen::MatrixX2d x = Eigen::MatrixX2d::Zero(m, 2);
  const double start = (b - a * x).norm();
  GmresWorkspace work;
  int steps = 0;
  CHECK_FALSE(preconditioned_gmres(a, lu, b, x, 1e-12 * b.norm(), 2, work, &steps));
  CHECK(steps >= 1);
  CHECK(steps <= 2);
  CHECK((b - a * x).norm() <= start);  // GMRES minimises the residual
}
