// Small sparse systems for the solver tests: a 1D chain I - W with uneven
// weights summing to `mass` (an M-matrix, the shape of the morph's systems
// around a polyline), and its factors as the solvers keep them.
#pragma once

#include <cmath>
#include <vector>

#include <Eigen/SparseCore>

#include "catch.h"
#include "stickmorph/internal/compact_lu.h"

namespace stickmorph::test {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// The chain of m unknowns; `phase` varies the weights.
inline SparseMatrix chain_system(int m, double phase, double mass = 0.999) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (int i = 0; i < m; ++i) {
    triplets.emplace_back(i, i, 1.0);
    const double left = 0.5 + 0.4 * std::sin(phase + 0.9 * i);
    if (i > 0) triplets.emplace_back(i, i - 1, -mass * left);
    if (i + 1 < m) triplets.emplace_back(i, i + 1, -mass * (1 - left));
  }
  SparseMatrix a(m, m);
  a.setFromTriplets(triplets.begin(), triplets.end());
  a.makeCompressed();
  return a;
}

/// `a` factorized as MorphSolver keeps its anchors.
inline internal::CompactLU factors_of(const SparseMatrix& a) {
  internal::SymmetricOrderedLU lu;
  lu.analyzePattern(a);
  lu.factorize(a);
  REQUIRE(lu.info() == Eigen::Success);
  return internal::CompactLU(lu);
}

}  // namespace stickmorph::test
