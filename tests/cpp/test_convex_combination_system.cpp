// ConvexCombinationSystem: a Tutte system whose weights change from solve
// to solve, on one sparsity pattern.
#include "catch.h"

#include <Eigen/SparseLU>

#include <cmath>
#include <vector>

#include "stickmorph/internal/convex_combination_system.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

// A k x k grid of nodes with the 4-neighbour rings; the nodes off the
// border are the unknowns, at their grid positions.
struct Grid {
  int k;
  Topology topo;
  std::vector<Vec2> positions;
  std::vector<int> rows;
  int node(int i, int j) const { return i * k + j; }
};

Grid grid(int k) {
  Grid g{k, {}, {}, {}};
  g.topo.nodes = k * k;
  g.topo.ring.resize(std::size_t(k * k));
  g.topo.unknown.assign(std::size_t(k * k), -1);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      g.positions.push_back({double(j), double(i)});
      if (i == 0 || j == 0 || i == k - 1 || j == k - 1) continue;
      const int v = g.node(i, j);
      g.topo.ring[v] = {g.node(i, j + 1), g.node(i + 1, j), g.node(i, j - 1), g.node(i - 1, j)};
      g.topo.unknown[v] = int(g.rows.size());
      g.rows.push_back(v);
      g.topo.interior_nodes.push_back(v);
    }
  return g;
}

// Positive weights summing to 1 over the four neighbours, varying with u.
std::vector<std::vector<double>> weights(const Grid& g, double u) {
  std::vector<std::vector<double>> w(std::size_t(g.topo.nodes));
  for (int v : g.rows) {
    double sum = 0;
    for (int j = 0; j < 4; ++j) {
      w[v].push_back(1 + 0.5 * std::sin(0.7 * v + 1.3 * j + 0.5 * u));
      sum += w[v].back();
    }
    for (double& x : w[v]) x /= sum;
  }
  return w;
}

// The solution by a fresh SparseLU.
std::vector<Vec2> direct(const Grid& g, const std::vector<std::vector<double>>& w) {
  const int m = int(g.rows.size());
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixX2d b = Eigen::MatrixX2d::Zero(m, 2);
  for (int row = 0; row < m; ++row) {
    const int v = g.rows[row];
    triplets.emplace_back(row, row, 1.0);
    for (int j = 0; j < 4; ++j) {
      const int u = g.topo.ring[v][j];
      if (g.topo.unknown[u] >= 0) {
        triplets.emplace_back(row, g.topo.unknown[u], -w[v][j]);
      } else {
        b(row, 0) += w[v][j] * g.positions[u][0];
        b(row, 1) += w[v][j] * g.positions[u][1];
      }
    }
  }
  Eigen::SparseMatrix<double> a(m, m);
  a.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(a);
  REQUIRE(lu.info() == Eigen::Success);
  const Eigen::MatrixX2d x = lu.solve(b);
  std::vector<Vec2> p = g.positions;
  for (int row = 0; row < m; ++row) p[g.rows[row]] = {x(row, 0), x(row, 1)};
  return p;
}

double largest_difference(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
  double d = 0;
  for (std::size_t i = 0; i < p.size(); ++i) d = std::max({d, std::abs(p[i][0] - q[i][0]), std::abs(p[i][1] - q[i][1])});
  return d;
}

}  // namespace

TEST_CASE("ConvexCombinationSystem with uniform weights keeps a grid in place", "[convex_combination_system]") {
  // Linear functions are discrete harmonic on the grid: Tutte's embedding
  // with the border fixed is the grid itself.
  const Grid g = grid(12);
  ConvexCombinationSystem system(g.topo, g.rows, 1e-10);
  CHECK(system.size() == 100);
  CHECK(system.node(0) == g.rows[0]);
  const std::vector<double> quarter(4, 0.25);
  std::vector<Vec2> p = g.positions;
  for (int row = 0; row < system.size(); ++row) p[system.node(row)] = {0, 0};  // no warm start
  REQUIRE(system.solve(0, [&](int) -> const std::vector<double>& { return quarter; }, p));
  CHECK(largest_difference(p, g.positions) < 1e-10);
  CHECK(system.factorizations() == 1);
}

TEST_CASE("ConvexCombinationSystem follows changing weights, iterating on its factors", "[convex_combination_system]") {
  const Grid g = grid(20);
  ConvexCombinationSystem system(g.topo, g.rows, 1e-10);
  int solves = 0;
  for (int f = 0; f <= 20; ++f) {
    const double u = f / 20.0;
    const std::vector<std::vector<double>> w = weights(g, u);
    std::vector<Vec2> p = g.positions;
    REQUIRE(system.solve(u, [&](int v) -> const std::vector<double>& { return w[v]; }, p));
    ++solves;
    // Ten digits of the residual, about as many of the positions here.
    CHECK(largest_difference(p, direct(g, w)) < 1e-7);
  }
  // Consecutive weights are close: most solves iterate on kept factors.
  INFO(system.factorizations() << " factorizations");
  CHECK(system.factorizations() < solves / 2);
}

TEST_CASE("ConvexCombinationSystem::refine brings the latest solve to the direct solution", "[convex_combination_system]") {
  const Grid g = grid(16);
  ConvexCombinationSystem system(g.topo, g.rows, 1e-6);  // a loose tolerance to refine
  std::vector<Vec2> p;
  std::vector<std::vector<double>> w;
  for (int f = 0; f <= 4; ++f) {
    w = weights(g, f / 10.0);
    p = g.positions;
    REQUIRE(system.solve(f / 10.0, [&](int v) -> const std::vector<double>& { return w[v]; }, p));
  }
  const std::vector<Vec2> exact = direct(g, w);
  const double before = largest_difference(p, exact);
  // The factors are an earlier frame's (the solves iterated on them): each
  // round gains about a digit here.
  system.refine(p, 12);
  const double after = largest_difference(p, exact);
  INFO("before " << before << ", after " << after);
  CHECK(after <= before);
  CHECK(after < 1e-12);
}
