// Sparse LU factors as plain compressed columns; see compact_lu.h.
#include "stickmorph/internal/compact_lu.h"

#include <type_traits>

namespace stickmorph::internal {

CompactLU::CompactLU(const SparseLU& lu) {
  const int m = int(lu.rows());
  pr_.assign(lu.rowsPermutation().indices().data(), lu.rowsPermutation().indices().data() + m);
  pc_.assign(lu.colsPermutation().indices().data(), lu.colsPermutation().indices().data() + m);
  const auto l = lu.matrixL();
  const auto u = lu.matrixU();
  using Supernodal = std::decay_t<decltype(l.m_mapL)>;
  using Upper = std::decay_t<decltype(u.m_mapU)>;
  lp_.assign(1, 0);
  up_.assign(1, 0);
  ud_.assign(std::size_t(m), 0.0);
  for (int j = 0; j < m; ++j) {
    // A supernode's columns hold U's dense block above the diagonal.
    for (typename Supernodal::InnerIterator it(l.m_mapL, j); it; ++it) {
      const int r = int(it.row());
      if (r > j) {
        li_.push_back(r);
        lv_.push_back(it.value());
      } else if (r == j) {
        ud_[std::size_t(j)] = it.value();
      } else {
        ui_.push_back(r);
        uv_.push_back(it.value());
      }
    }
    for (typename Upper::InnerIterator it(u.m_mapU, j); it; ++it) {
      ui_.push_back(int(it.index()));
      uv_.push_back(it.value());
    }
    lp_.push_back(int(li_.size()));
    up_.push_back(int(ui_.size()));
  }
}

Eigen::MatrixX2d CompactLU::solve(const Eigen::MatrixX2d& b) const {
  const int m = int(pr_.size());
  std::vector<double> y(2 * std::size_t(m));
  for (int i = 0; i < m; ++i) {
    y[2 * std::size_t(pr_[std::size_t(i)])] = b(i, 0);
    y[2 * std::size_t(pr_[std::size_t(i)]) + 1] = b(i, 1);
  }
  double* v = y.data();
  for (int j = 0; j < m; ++j) {
    const double y0 = v[2 * j], y1 = v[2 * j + 1];
    if (y0 == 0 && y1 == 0) continue;
    for (int k = lp_[std::size_t(j)]; k < lp_[std::size_t(j) + 1]; ++k) {
      const int r = li_[std::size_t(k)];
      v[2 * r] -= lv_[std::size_t(k)] * y0;
      v[2 * r + 1] -= lv_[std::size_t(k)] * y1;
    }
  }
  for (int j = m - 1; j >= 0; --j) {
    const double d = ud_[std::size_t(j)];
    const double y0 = v[2 * j] /= d, y1 = v[2 * j + 1] /= d;
    if (y0 == 0 && y1 == 0) continue;
    for (int k = up_[std::size_t(j)]; k < up_[std::size_t(j) + 1]; ++k) {
      const int r = ui_[std::size_t(k)];
      v[2 * r] -= uv_[std::size_t(k)] * y0;
      v[2 * r + 1] -= uv_[std::size_t(k)] * y1;
    }
  }
  Eigen::MatrixX2d x(m, 2);
  for (int i = 0; i < m; ++i) {
    x(i, 0) = v[2 * std::size_t(pc_[std::size_t(i)])];
    x(i, 1) = v[2 * std::size_t(pc_[std::size_t(i)]) + 1];
  }
  return x;
}

}  // namespace stickmorph::internal
