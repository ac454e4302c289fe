// Right-preconditioned GMRES on two coordinates; see preconditioned_gmres.h.
#include "stickmorph/internal/preconditioned_gmres.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace stickmorph::internal {

bool preconditioned_gmres(const Eigen::SparseMatrix<double>& a, const CompactLU& preconditioner,
                          const Eigen::MatrixX2d& b, Eigen::MatrixX2d& x, double tolerance, int max_steps,
                          GmresWorkspace& work, int* steps_taken) {
  const Eigen::Index m = a.rows();
  const int limit = std::max(1, max_steps);
  int solves = 0;
  if (steps_taken) *steps_taken = 0;
  std::vector<double>& estimates = work.estimates;
  estimates.assign(std::size_t(limit) + 1, 0.0);
  work.basis.resize(m, 2);
  // A second cycle only for a residual that the first one's estimate
  // declared converged but rounding left just above the tolerance.
  for (int cycle = 0; cycle < 2; ++cycle) {
    const Eigen::MatrixX2d r = b - a * x;
    const double norm = r.norm();
    if (steps_taken) *steps_taken = solves;
    if (!std::isfinite(norm)) return false;
    if (norm <= tolerance) return true;
    if (cycle > 0 && !(norm <= 1e3 * tolerance)) return false;
    bool active[2];
    double residual[2];
    for (int c = 0; c < 2; ++c) {
      GmresWorkspace::Krylov& k = work.krylov[c];
      k.v.resize(m, limit + 1);
      k.z.resize(m, limit);
      k.h.setZero(limit + 1, limit);
      k.g.setZero(limit + 1);
      k.cs.resize(limit);
      k.sn.resize(limit);
      k.steps = 0;
      const double beta = r.col(c).norm();
      residual[c] = beta;
      active[c] = beta > 0;
      if (active[c]) k.v.col(0) = r.col(c) / beta;
      k.g(0) = beta;
    }
    estimates[0] = norm;
    bool converged = false;
    for (int j = 0; j < limit && (active[0] || active[1]); ++j) {
      for (int c = 0; c < 2; ++c) {
        if (active[c]) {
          work.basis.col(c) = work.krylov[c].v.col(j);
        } else {
          work.basis.col(c).setZero();
        }
      }
      const Eigen::MatrixX2d z = preconditioner.solve(work.basis);
      ++solves;
      const Eigen::MatrixX2d w = a * z;
      for (int c = 0; c < 2; ++c) {
        if (!active[c]) continue;
        GmresWorkspace::Krylov& k = work.krylov[c];
        k.z.col(j) = z.col(c);
        // Arnoldi (modified Gram-Schmidt), then the Givens rotations that
        // keep H upper triangular and |g(j+1)| the residual's norm.
        Eigen::VectorXd q = w.col(c);
        for (int i = 0; i <= j; ++i) {
          k.h(i, j) = q.dot(k.v.col(i));
          q -= k.h(i, j) * k.v.col(i);
        }
        const double next = q.norm();
        k.h(j + 1, j) = next;
        if (next > 0) k.v.col(j + 1) = q / next;
        for (int i = 0; i < j; ++i) {
          const double t = k.cs(i) * k.h(i, j) + k.sn(i) * k.h(i + 1, j);
          k.h(i + 1, j) = -k.sn(i) * k.h(i, j) + k.cs(i) * k.h(i + 1, j);
          k.h(i, j) = t;
        }
        const double d = std::hypot(k.h(j, j), k.h(j + 1, j));
        k.cs(j) = d > 0 ? k.h(j, j) / d : 1;
        k.sn(j) = d > 0 ? k.h(j + 1, j) / d : 0;
        k.h(j, j) = d;
        k.h(j + 1, j) = 0;
        k.g(j + 1) = -k.sn(j) * k.g(j);
        k.g(j) = k.cs(j) * k.g(j);
        residual[c] = std::abs(k.g(j + 1));
        k.steps = j + 1;
        if (!(next > 0) || !(d > 0)) active[c] = false;  // exact in this space, or breakdown
      }
      const int steps = j + 1;
      const double estimate = std::hypot(residual[0], residual[1]);
      if (!std::isfinite(estimate)) {
        if (steps_taken) *steps_taken = solves;
        return false;
      }
      // Half the tolerance, so that the true residual (recomputed below)
      // passes despite the estimate's rounding.
      if (estimate <= 0.5 * tolerance) {
        converged = true;
        break;
      }
      // Give up when, at the rate of the last two steps, the tolerance is
      // not reached within the steps left.
      estimates[std::size_t(steps)] = estimate;
      if (steps >= 2) {
        const double rate = std::sqrt(estimate / estimates[std::size_t(steps - 2)]);
        if (!(rate < 0.8) || std::log(tolerance / estimate) / std::log(rate) > limit - steps) break;
      }
    }
    // x += Z y with H y = g, H upper triangular after the rotations.
    for (int c = 0; c < 2; ++c) {
      GmresWorkspace::Krylov& k = work.krylov[c];
      const int n = k.steps;
      if (n == 0) continue;
      Eigen::VectorXd y = k.g.head(n);
      for (int i = n - 1; i >= 0; --i) {
        for (int l = i + 1; l < n; ++l) y(i) -= k.h(i, l) * y(l);
        y(i) /= k.h(i, i);
      }
      if (y.allFinite()) x.col(c) += k.z.leftCols(n) * y;
    }
    if (!converged) break;
  }
  if (steps_taken) *steps_taken = solves;
  const double final_norm = (b - a * x).norm();
  return std::isfinite(final_norm) && final_norm <= tolerance;
}

}  // namespace stickmorph::internal
