// Warm starts for an iterative solve from the solutions kept of earlier
// solves of a system that depends smoothly on one parameter t (the morph's
// time or the guide's parameter u): polynomial extrapolation (Lagrange
// interpolation through the latest solutions) and the least-squares
// combination of the kept solutions (the minimal-residual projection onto
// their span, as in the "previous solutions" starts of Fischer 1998,
// "Projection techniques for iterative solution of Ax = b with successive
// right-hand sides").
//
// Each solver uses the one that suits it, measured: MorphSolver tries the
// extrapolations and the nearest solution against its moment space's
// projection (its residuals are cheap, its matrix a blend of two); a
// ConvexCombinationSystem, whose weights change with every solve, takes
// the least-squares start, which every extrapolation through the same
// solutions lies in the span of.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <vector>

namespace stickmorph {
namespace internal {

/// One earlier solution (both coordinates) and its parameter.
struct KeptSolution {
  double t;
  Eigen::MatrixX2d x;
};

/// Guesses for the solution at t from `kept` (the latest last, not empty),
/// in order: the polynomial through the latest three solutions evaluated at
/// t, that through the latest two (each left out where two of its times
/// coincide or it is not finite), and the kept solution nearest in t (the
/// latest on a tie).
std::vector<Eigen::MatrixX2d> extrapolated_starts(const std::vector<KeptSolution>& kept, double t);

/// Storage for least_squares_start, kept between calls.
struct LeastSquaresStartStorage {
  Eigen::MatrixXd basis, images;
};

/// The start of least residual |b - A x| from `kept` (oldest first, not
/// empty): with three or more, the least-squares solution over their span
/// (both coordinates of each, 2 * kept.size() columns), unless the latest
/// itself has a smaller residual (a rank-deficient span); with two, the
/// latest or the linear extrapolation in t through both; with one, it.
Eigen::MatrixX2d least_squares_start(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixX2d& b,
                                     const std::vector<KeptSolution>& kept, double t,
                                     LeastSquaresStartStorage& storage);
/// The same over solutions kept elsewhere (oldest first): ConvexCombinationSystem
/// picks them from its pool by nearness in t, without copying them.
Eigen::MatrixX2d least_squares_start(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixX2d& b,
                                     const std::vector<const KeptSolution*>& kept, double t,
                                     LeastSquaresStartStorage& storage);

}  // namespace internal
}  // namespace stickmorph
