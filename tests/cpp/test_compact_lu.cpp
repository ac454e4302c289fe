// CompactLU: SparseLU's factors as plain columns (solve), and the
// static-pivot refactorization of a matrix with the same pattern.
#include "catch.h"

#include <cmath>
#include <vector>

#include "stickmorph/internal/compact_lu.h"

using namespace stickmorph::internal;

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// I - W on a k by k grid (4-neighbours, unknowns inside, the border known):
// the shape of the morph's systems, an irreducibly diagonally dominant
// M-matrix. The weights of each row are uneven, varied by `phase`, and sum
// to `mass` < 1 over the unknown neighbours and the border together.
SparseMatrix grid_system(int k, double phase) {
  std::vector<Eigen::Triplet<double>> triplets;
  auto index = [k](int i, int j) { return i * k + j; };
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const int row = index(i, j);
      triplets.emplace_back(row, row, 1.0);
      const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
      double w[4], sum = 0;
      for (int n = 0; n < 4; ++n) sum += w[n] = 1.5 + std::sin(phase + 0.7 * row + 1.3 * n);
      for (int n = 0; n < 4; ++n) {
        const int ii = i + di[n], jj = j + dj[n];
        if (ii < 0 || jj < 0 || ii >= k || jj >= k) continue;  // the border: known
        triplets.emplace_back(row, index(ii, jj), -0.999 * w[n] / sum);
      }
    }
  SparseMatrix a(k * k, k * k);
  a.setFromTriplets(triplets.begin(), triplets.end());
  a.makeCompressed();
  return a;
}

Eigen::MatrixX2d right_hand_side(int m) {
  Eigen::MatrixX2d b(m, 2);
  for (int i = 0; i < m; ++i) b.row(i) << std::cos(0.3 * i), std::sin(0.11 * i) + 2;
  return b;
}

// The ordering, the analysis and the factorization of a, which must succeed.
void factorize_ordered(SymmetricOrderedLU& lu, const SparseMatrix& a) {
  lu.analyzePattern(a);
  lu.factorize(a);
  REQUIRE(lu.info() == Eigen::Success);
}

double relative_residual(const SparseMatrix& a, const Eigen::MatrixX2d& x, const Eigen::MatrixX2d& b) {
  return (b - a * x).norm() / b.norm();
}

}  // namespace

TEST_CASE("CompactLU solves as SparseLU does", "[compact_lu]") {
  const SparseMatrix a = grid_system(12, 0.0);
  SymmetricOrderedLU lu;
  factorize_ordered(lu, a);
  const CompactLU compact(lu);
  const Eigen::MatrixX2d b = right_hand_side(int(a.rows()));
  const Eigen::MatrixX2d x = compact.solve(b);
  CHECK(relative_residual(a, x, b) < 1e-14);
  CHECK((x - lu.solve(b)).norm() < 1e-12 * x.norm());
  CHECK(compact.nonzeros() > std::size_t(a.nonZeros()) / 2);
}

TEST_CASE("CompactLU::refactorize factorizes a matrix of the same pattern on the kept structure", "[compact_lu]") {
  const SparseMatrix a = grid_system(15, 0.0), other = grid_system(15, 2.5);
  SymmetricOrderedLU lu;
  factorize_ordered(lu, a);
  CompactLU compact(lu);
  CHECK(compact.refactorization_pays());  // a grid's factors fill in sparsely
  REQUIRE(compact.refactorize(other));
  const Eigen::MatrixX2d b = right_hand_side(int(a.rows()));
  CHECK(relative_residual(other, compact.solve(b), b) < 1e-13);
  // And back: the same factors again, to rounding.
  REQUIRE(compact.refactorize(a));
  CHECK(relative_residual(a, compact.solve(b), b) < 1e-13);
  CHECK((compact.solve(b) - lu.solve(b)).norm() < 1e-11 * b.norm());
}

TEST_CASE("CompactLU::refactorize refuses what the kept structure cannot hold", "[compact_lu]") {
  SECTION("an entry outside the pattern") {
    const SparseMatrix a = grid_system(6, 0.0);
    SymmetricOrderedLU lu;
    factorize_ordered(lu, a);
    CompactLU compact(lu);
    // A coupling between the grid's first and last unknowns: outside the
    // factors' fill.
    SparseMatrix wider = a;
    wider.coeffRef(0, int(a.rows()) - 1) = -1e-3;
    wider.makeCompressed();
    CHECK_FALSE(compact.refactorize(wider));
    // A refusal leaves nothing behind: the right pattern works again.
    REQUIRE(compact.refactorize(a));
    const Eigen::MatrixX2d b = right_hand_side(int(a.rows()));
    CHECK(relative_residual(a, compact.solve(b), b) < 1e-13);
  }
  SECTION("a pivot that vanishes in the kept order") {
    SparseMatrix a(2, 2), singular(2, 2);
    a.insert(0, 0) = 2, a.insert(0, 1) = 1, a.insert(1, 0) = 1, a.insert(1, 1) = 2;
    singular.insert(0, 0) = 1, singular.insert(0, 1) = 1, singular.insert(1, 0) = 1, singular.insert(1, 1) = 1;
    a.makeCompressed();
    singular.makeCompressed();
    SymmetricOrderedLU lu;
    factorize_ordered(lu, a);
    CompactLU compact(lu);
    CHECK_FALSE(compact.refactorize(singular));
    CHECK_FALSE(compact.refactorize(SparseMatrix(3, 3)));  // another size
  }
}

TEST_CASE("SymmetricOrderedLU orders rows and columns alike and fills less than COLAMD", "[compact_lu]") {
  const SparseMatrix a = grid_system(20, 1.0);
  SymmetricOrderedLU lu;
  factorize_ordered(lu, a);
  const Eigen::MatrixX2d b = right_hand_side(int(a.rows()));
  CHECK(relative_residual(a, lu.solve(b), b) < 1e-14);
  // COLAMD, the column ordering used before (compact_lu.h).
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> column_ordered;
  column_ordered.analyzePattern(a);
  column_ordered.factorize(a);
  REQUIRE(column_ordered.info() == Eigen::Success);
  const CompactLU compact(lu);
  CHECK(compact.nonzeros() < std::size_t(column_ordered.nnzL() + column_ordered.nnzU()));
  CHECK(relative_residual(a, compact.solve(b), b) < 1e-14);
}
