// Warm starts from kept solutions; see warm_start.h.
#include "stickmorph/internal/warm_start.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace stickmorph {
namespace internal {

// x(t) of the morph is smooth (a rational function of t), so frames at even
// steps are extrapolated to O(h^3) by the quadratic. MorphSolver starts
// from the guess of least residual, so a wild extrapolation (a far jump in
// a scrub) costs one residual, not steps.
std::vector<Eigen::MatrixX2d> extrapolated_starts(const std::vector<KeptSolution>& kept, double t) {
  std::vector<Eigen::MatrixX2d> guesses;
  const std::size_t k = kept.size();
  const Eigen::Index rows = kept.back().x.rows();
  for (std::size_t points = std::min<std::size_t>(k, 3); points >= 2; --points) {
    // Lagrange basis on the `points` latest times.
    const std::size_t first = k - points;
    Eigen::MatrixX2d p = Eigen::MatrixX2d::Zero(rows, 2);
    bool distinct = true;
    for (std::size_t i = first; i < k && distinct; ++i) {
      double weight = 1;
      for (std::size_t j = first; j < k; ++j) {
        if (j == i) continue;
        const double gap = kept[i].t - kept[j].t;
        if (gap == 0) {
          distinct = false;
          break;
        }
        weight *= (t - kept[j].t) / gap;
      }
      p += weight * kept[i].x;
    }
    if (distinct && p.allFinite()) guesses.push_back(std::move(p));
  }
  std::size_t nearest = k - 1;
  for (std::size_t i = 0; i < k; ++i)
    if (std::abs(kept[i].t - t) < std::abs(kept[nearest].t - t)) nearest = i;
  guesses.push_back(kept[nearest].x);
  return guesses;
}

// Six solutions, twelve columns: twelve products with A and a small QR, a
// fraction of one preconditioner solve. Measured at 10^3 vertices, 50
// frames (GuidedMorph's systems): the Steiner system (linear in u) starts
// 10^2 to 10^3 times closer than from the last solution and then converges
// in 1-5 steps instead of 10-15 (polygon, 624 Steiner vertices); the
// blended system only 5 to 10 times closer (its weights follow the trust,
// which has kinks), about a step saved.
//
// The linear and quadratic extrapolations in t through the last two and
// three solutions (Lagrange) were candidates too, each costing a product
// with A for its residual; but they lie in the span, where the least
// squares solution has the least residual of all, column by column, so
// they could win only by rounding. Nor is the least-squares residual a
// product with A: it is b minus the images times the coefficients.
Eigen::MatrixX2d least_squares_start(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixX2d& b,
                                     const std::vector<KeptSolution>& kept, double t,
                                     LeastSquaresStartStorage& storage) {
  std::vector<const KeptSolution*> pointers;
  for (const KeptSolution& solution : kept) pointers.push_back(&solution);
  return least_squares_start(a, b, pointers, t, storage);
}

Eigen::MatrixX2d least_squares_start(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixX2d& b,
                                     const std::vector<const KeptSolution*>& kept, double t,
                                     LeastSquaresStartStorage& storage) {
  const std::size_t h = kept.size();
  Eigen::MatrixX2d best = kept.back()->x;
  double best_norm = (b - a * best).norm();
  if (h == 2) {
    const KeptSolution& p = *kept[0];
    const KeptSolution& q = *kept[1];
    if (p.t != q.t) {
      Eigen::MatrixX2d candidate = q.x + ((t - q.t) / (q.t - p.t)) * (q.x - p.x);
      if ((b - a * candidate).norm() < best_norm) best = std::move(candidate);
    }
  }
  if (h >= 3) {
    Eigen::MatrixXd& basis = storage.basis;
    Eigen::MatrixXd& images = storage.images;
    basis.resize(a.rows(), 2 * int(h));
    for (std::size_t i = 0; i < h; ++i) basis.middleCols(2 * int(i), 2) = kept[i]->x;
    images = a * basis;
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(images);
    const Eigen::MatrixXd y = qr.solve(b);
    if (y.allFinite() && (b - images * y).norm() < best_norm) best = basis * y;
  }
  return best;
}

}  // namespace internal
}  // namespace stickmorph
