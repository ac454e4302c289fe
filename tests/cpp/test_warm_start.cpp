// extrapolated_starts and least_squares_start: warm starts from kept
// solutions.
#include "catch.h"

#include <vector>

#include "stickmorph/internal/warm_start.h"

using namespace stickmorph::internal;

namespace {

// x(t) = x0 + t x1 + t^2 x2, a polynomial of degree two in t.
Eigen::MatrixX2d quadratic(double t) {
  Eigen::MatrixX2d x(3, 2);
  x << 1 + t + t * t, 2 - t, 3 * t * t, 0.5, -t, t + 2 * t * t;
  return x;
}

}  // namespace

TEST_CASE("extrapolated_starts: the quadratic, the line and the nearest solution", "[warm_start]") {
  const std::vector<KeptSolution> kept = {{0.1, quadratic(0.1)}, {0.2, quadratic(0.2)}, {0.3, quadratic(0.3)}};
  const std::vector<Eigen::MatrixX2d> guesses = extrapolated_starts(kept, 0.4);
  REQUIRE(guesses.size() == 3);
  CHECK((guesses[0] - quadratic(0.4)).cwiseAbs().maxCoeff() < 1e-12);  // exact for a quadratic
  const Eigen::MatrixX2d line = 2 * quadratic(0.3) - quadratic(0.2);
  CHECK((guesses[1] - line).cwiseAbs().maxCoeff() < 1e-12);
  CHECK(guesses[2] == quadratic(0.3));  // the nearest
  // Back in time, the nearest is the earliest.
  CHECK(extrapolated_starts(kept, 0.0).back() == quadratic(0.1));
}

TEST_CASE("extrapolated_starts leaves out polynomials through coinciding times", "[warm_start]") {
  const std::vector<KeptSolution> one = {{0.5, quadratic(0.5)}};
  REQUIRE(extrapolated_starts(one, 0.7).size() == 1);
  const std::vector<KeptSolution> same = {{0.2, quadratic(0.2)}, {0.5, quadratic(0.5)}, {0.5, quadratic(0.5)}};
  const std::vector<Eigen::MatrixX2d> guesses = extrapolated_starts(same, 0.7);
  REQUIRE(guesses.size() == 1);  // neither the quadratic nor the line
  CHECK(guesses[0] == quadratic(0.5));
}

TEST_CASE("least_squares_start: the latest, the line through two, the span of three or more", "[warm_start]") {
  // A diagonal system whose solution is quadratic in t.
  Eigen::SparseMatrix<double> a(3, 3);
  a.insert(0, 0) = 2;
  a.insert(1, 1) = 1;
  a.insert(2, 2) = 4;
  a.makeCompressed();
  LeastSquaresStartStorage storage;
  const double t = 0.45;
  const Eigen::MatrixX2d b = a * quadratic(t);
  const std::vector<KeptSolution> one = {{0.3, quadratic(0.3)}};
  CHECK(least_squares_start(a, b, one, t, storage) == quadratic(0.3));
  const std::vector<KeptSolution> two = {{0.3, quadratic(0.3)}, {0.4, quadratic(0.4)}};
  const Eigen::MatrixX2d line = quadratic(0.4) + 0.5 * (quadratic(0.4) - quadratic(0.3));
  CHECK((least_squares_start(a, b, two, t, storage) - line).cwiseAbs().maxCoeff() < 1e-12);
  // Three solutions of a quadratic span x(t) (all six columns of a 3-row
  // system span everything): the start is the solution.
  const std::vector<KeptSolution> three = {{0.2, quadratic(0.2)}, {0.3, quadratic(0.3)}, {0.4, quadratic(0.4)}};
  CHECK((least_squares_start(a, b, three, t, storage) - quadratic(t)).cwiseAbs().maxCoeff() < 1e-12);
}
