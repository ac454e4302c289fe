// Sparse LU factors as plain compressed columns; see compact_lu.h.
#include "stickmorph/internal/compact_lu.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <type_traits>
#include <utility>

namespace stickmorph::internal {

void SymmetricOrderedLU::analyzePattern(const Eigen::SparseMatrix<double>& a) {
  // AMDOrdering gives the inverse of P (as Eigen's SimplicialLDLT uses it).
  Permutation p_inverse;
  Eigen::AMDOrdering<int> ordering;
  ordering(a, p_inverse);
  p_ = p_inverse.inverse();
  permuted_ = a.twistedBy(p_);
  factors_.analyzePattern(permuted_);
}

void SymmetricOrderedLU::factorize(const Eigen::SparseMatrix<double>& a) {
  permuted_ = a.twistedBy(p_);
  factors_.factorize(permuted_);
}

Eigen::MatrixX2d SymmetricOrderedLU::solve(const Eigen::MatrixX2d& b) const {
  const Eigen::MatrixX2d y = factors_.solve(Eigen::MatrixX2d(p_ * b));
  return p_.transpose() * y;
}

CompactLU::CompactLU(const SymmetricOrderedLU& ordered) {
  static std::atomic<std::uint64_t> patterns{0};
  pattern_ = ++patterns;
  const SymmetricOrderedLU::Factors& lu = ordered.factors();
  const int m = int(lu.rows());
  // B = P A P^T and P_r' B P_c'^T = L U: A's row i is row pr'[p[i]] of
  // L U, its column c column pc'[p[c]].
  const int* p = ordered.ordering().indices().data();
  const int* pr = lu.rowsPermutation().indices().data();
  const int* pc = lu.colsPermutation().indices().data();
  pr_.resize(std::size_t(m));
  pc_.resize(std::size_t(m));
  for (int i = 0; i < m; ++i) {
    pr_[std::size_t(i)] = pr[p[i]];
    pc_[std::size_t(i)] = pc[p[i]];
  }
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
  for (int r : ui_) updates_ += std::size_t(lp_[std::size_t(r) + 1] - lp_[std::size_t(r)]);
  // Only refactorize() needs U's columns in row order, and it runs only
  // where it pays: elsewhere (dense fill, where every factorization is
  // SparseLU's and this copy follows it) the sort was 40% of the copy
  // (thinned at 10^4 vertices, 6.5 10^5 nonzeros, 7087 of 10004 columns
  // out of order: the copy 9.2 ms with it, 5.3 without), and the solve
  // does not care: each entry of a column updates a row of its own.
  if (refactorization_pays()) sort_upper_columns();
}

void CompactLU::sort_upper_columns() {
  // Each column of U in increasing row order, the order in which the
  // left-looking elimination (refactorize) applies L's columns.
  const int m = int(pr_.size());
  std::vector<std::pair<int, double>> column;
  for (int j = 0; j < m; ++j) {
    const int begin = up_[std::size_t(j)], end = up_[std::size_t(j) + 1];
    if (std::is_sorted(ui_.begin() + begin, ui_.begin() + end)) continue;
    column.clear();
    for (int k = begin; k < end; ++k) column.emplace_back(ui_[std::size_t(k)], uv_[std::size_t(k)]);
    std::sort(column.begin(), column.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (int k = begin; k < end; ++k) {
      ui_[std::size_t(k)] = column[std::size_t(k - begin)].first;
      uv_[std::size_t(k)] = column[std::size_t(k - begin)].second;
    }
  }
  upper_sorted_ = true;
}

void CompactLU::find_supernodes() {
  // Columns r and r + 1 of L share a supernode when L(:, r)'s rows are
  // r + 1 followed by L(:, r + 1)'s, in the same order; then each column's
  // rows are the supernode's later columns, then the rows below it.
  const int m = int(pr_.size());
  supernode_end_.assign(std::size_t(m), 0);
  for (int r = m - 1; r >= 0; --r) {
    supernode_end_[std::size_t(r)] = r;
    if (r + 1 >= m) continue;
    const int b = lp_[std::size_t(r)], e = lp_[std::size_t(r) + 1];
    const int nb = lp_[std::size_t(r) + 1], ne = lp_[std::size_t(r) + 2];
    if (e - b == ne - nb + 1 && e > b && li_[std::size_t(b)] == r + 1 &&
        std::equal(li_.begin() + b + 1, li_.begin() + e, li_.begin() + nb))
      supernode_end_[std::size_t(r)] = supernode_end_[std::size_t(r) + 1];
  }
}

bool CompactLU::refactorize(const Eigen::SparseMatrix<double>& a) {
  const int m = int(pr_.size());
  if (a.rows() != m || a.cols() != m) return false;
  if (!upper_sorted_) sort_upper_columns();
  if (pc_inverse_.empty()) {
    pc_inverse_.assign(std::size_t(m), 0);
    for (int i = 0; i < m; ++i) pc_inverse_[std::size_t(pc_[std::size_t(i)])] = i;
    work_.assign(std::size_t(m), 0.0);
    stamp_.assign(std::size_t(m), -1);
  }
  if (supernode_end_.empty()) find_supernodes();
  segment_start_.resize(std::size_t(m));
  segment_value_.resize(std::size_t(m));
  // B = P_r A P_c^T = L U, B(pr[i], pc[c]) = A(i, c); column j of B is
  // column pc^-1(j) of A. Row r is in column j's pattern when stamp_[r] == j.
  double* x = work_.data();
  // A failure leaves partial sums behind: clear them for the next call.
  auto fail = [&] {
    std::fill(work_.begin(), work_.end(), 0.0);
    return false;
  };
  for (int j = 0; j < m; ++j) {
    const int ub = up_[std::size_t(j)], ue = up_[std::size_t(j) + 1];
    const int lb = lp_[std::size_t(j)], le = lp_[std::size_t(j) + 1];
    for (int k = ub; k < ue; ++k) stamp_[std::size_t(ui_[std::size_t(k)])] = j;
    for (int k = lb; k < le; ++k) stamp_[std::size_t(li_[std::size_t(k)])] = j;
    stamp_[std::size_t(j)] = j;
    const int c = pc_inverse_[std::size_t(j)];
    double scale = 0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it) {
      const int r = pr_[std::size_t(it.row())];
      if (stamp_[std::size_t(r)] != j) return fail();
      x[r] = it.value();
      scale = std::max(scale, std::abs(it.value()));
    }
    // U(:, j) by the columns of L to its left, in increasing row order,
    // a supernode's columns at a time (see supernode_end_ in the header):
    // the rows of L(:, r) within the supernode are updated column by column
    // as they become U's values; the rows below it, which all its columns
    // share, each once for all the supernode's columns of U(:, j), their
    // subtractions in the same order as column by column (so the factors
    // are the same bit for bit), the partial sum held in a register and
    // the row and its pattern check read once. Issue 29: on the rings at
    // 10^4 vertices (the rigid morph's blended system, 11 872 unknowns,
    // 86% of the multiply-adds in supernodes of three or more columns)
    // the rigid playback, which refactorizes nearly every frame, went from
    // 47-54 to 62-64 frames per second of CPU time (three runs each);
    // eight rows at a time instead of four was no faster.
    for (int k = ub; k < ue;) {
      const int first = ui_[std::size_t(k)];
      const int last = supernode_end_[std::size_t(first)];
      std::size_t count = 0;
      for (; k < ue && ui_[std::size_t(k)] <= last; ++k) {
        const int r = ui_[std::size_t(k)];
        const double value = x[r];
        uv_[std::size_t(k)] = value;
        x[r] = 0;
        if (value == 0) continue;
        // Two plain arrays: a pair pushed back was stored in two parts and
        // read as one, which stalled store forwarding (perf: a sixth of the
        // refactorization).
        segment_start_[count] = r;
        segment_value_[count++] = value;
        // L(:, r)'s rows r + 1 .. last come first (supernode_end_).
        const int inside = lp_[std::size_t(r)] + (last - r);
        for (int e = lp_[std::size_t(r)]; e < inside; ++e) {
          const int row = li_[std::size_t(e)];
          if (stamp_[std::size_t(row)] != j) return fail();  // fill outside the pattern
          x[row] -= lv_[std::size_t(e)] * value;
        }
      }
      if (count == 0) continue;
      // The rows below the supernode: L(:, last)'s, at offset (last - r)
      // into each column r of it.
      const int below = lp_[std::size_t(last)], rows = lp_[std::size_t(last) + 1] - below;
      for (int i = 0; i < rows; ++i)
        if (stamp_[std::size_t(li_[std::size_t(below + i)])] != j) return fail();
      int* start = segment_start_.data();
      const double* value = segment_value_.data();
      for (std::size_t t = 0; t < count; ++t) start[t] = lp_[std::size_t(start[t])] + (last - start[t]);
      const double* lv = lv_.data();
      if (count == 1) {
        const int first_start = start[0];
        const double first_value = value[0];
        for (int i = 0; i < rows; ++i) x[li_[std::size_t(below + i)]] -= lv[first_start + i] * first_value;
        continue;
      }
      // Four rows at a time: each row's sum is a chain of dependent
      // subtractions, four chains keep the floating-point unit busy.
      const int* below_rows = li_.data() + below;
      int i = 0;
      for (; i + 4 <= rows; i += 4) {
        double s0 = x[below_rows[i]], s1 = x[below_rows[i + 1]], s2 = x[below_rows[i + 2]], s3 = x[below_rows[i + 3]];
        for (std::size_t t = 0; t < count; ++t) {
          const double* l = lv + start[t] + i;
          const double v = value[t];
          s0 -= l[0] * v;
          s1 -= l[1] * v;
          s2 -= l[2] * v;
          s3 -= l[3] * v;
        }
        x[below_rows[i]] = s0;
        x[below_rows[i + 1]] = s1;
        x[below_rows[i + 2]] = s2;
        x[below_rows[i + 3]] = s3;
      }
      for (; i < rows; ++i) {
        double sum = x[below_rows[i]];
        for (std::size_t t = 0; t < count; ++t) sum -= lv[start[t] + i] * value[t];
        x[below_rows[i]] = sum;
      }
    }
    const double pivot = x[j];
    x[j] = 0;
    if (!std::isfinite(pivot) || !(std::abs(pivot) > 1e-12 * scale)) return fail();
    ud_[std::size_t(j)] = pivot;
    for (int k = lb; k < le; ++k) {
      const int r = li_[std::size_t(k)];
      lv_[std::size_t(k)] = x[r] / pivot;
      x[r] = 0;
    }
  }
  return true;
}

bool CompactLU::refactorize_from(const CompactLU& base, const Eigen::SparseMatrix<double>& a) {
  if (&base != this && pattern_ != base.pattern_) {
    // Assignments reuse this anchor's storage (an evicted one's) when it is
    // large enough. The values are all rewritten by refactorize. Factors
    // refactorized from the same SparseLU factorization have the same
    // structure already (pattern_), so a playback that refactorizes every
    // frame into anchors it reuses copies nothing (the copy was 4% of a
    // frame on the rings at 10^4 vertices).
    pr_ = base.pr_;
    pc_ = base.pc_;
    lp_ = base.lp_;
    li_ = base.li_;
    up_ = base.up_;
    ui_ = base.ui_;
    lv_.resize(base.lv_.size());
    uv_.resize(base.uv_.size());
    ud_.resize(base.ud_.size());
    updates_ = base.updates_;
    upper_sorted_ = base.upper_sorted_;
    pc_inverse_ = base.pc_inverse_;
    supernode_end_ = base.supernode_end_;
    pattern_ = base.pattern_;
    work_.assign(base.work_.size(), 0.0);
    stamp_.assign(base.stamp_.size(), -1);
  }
  return refactorize(a);
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

bool factorize_checked(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixX2d& b, double tolerance,
                       bool try_refactorization, SymmetricOrderedLU& lu, CompactLU& factors,
                       Eigen::MatrixX2d* solution) {
  return factorize_checked(a, b, tolerance, try_refactorization, lu, factors, factors, solution);
}

bool factorize_checked(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixX2d& b, double tolerance,
                       bool try_refactorization, SymmetricOrderedLU& lu, const CompactLU& base, CompactLU& factors,
                       Eigen::MatrixX2d* solution) {
  if (try_refactorization && base.refactorization_pays() && factors.refactorize_from(base, a)) {
    Eigen::MatrixX2d x = factors.solve(b);
    if ((b - a * x).norm() <= tolerance * std::max(b.norm(), 1e-300)) {
      if (solution) *solution = std::move(x);
      return true;
    }
  }
  lu.factorize(a);
  if (lu.info() != Eigen::Success) return false;
  factors = CompactLU(lu);
  if (solution) *solution = factors.solve(b);
  return true;
}

}  // namespace stickmorph::internal
