// The least-squares figure of given edge vectors; see edge_vector_fit.h.
#include "stickmorph/internal/edge_vector_fit.h"

#include <numeric>

#include "stickmorph/cancellation.h"
#include "stickmorph/errors.h"

namespace stickmorph {
namespace internal {

EdgeVectorFit::EdgeVectorFit(int vertex_count, const std::vector<Edge>& edges) : n_(vertex_count), edges_(edges) {
  // Connected parts by union-find.
  std::vector<int> parent(n_);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Edge& e : edges_) parent[find(e[0])] = find(e[1]);
  part_.assign(n_, -1);
  std::vector<int> part_of_root(n_, -1);
  for (int v = 0; v < n_; ++v) {
    const int r = find(v);
    if (part_of_root[r] < 0) {
      part_of_root[r] = int(root_.size());
      root_.push_back(v);  // the part's lowest vertex
      part_size_.push_back(0);
    }
    part_[v] = part_of_root[r];
    ++part_size_[part_[v]];
  }
  unknown_.assign(n_, -1);
  for (int v = 0; v < n_; ++v)
    if (root_[part_[v]] != v) unknown_[v] = unknowns_++;
  // The normal equations of min sum_e |p_j - p_i - d_e|^2 with the roots
  // fixed: the graph Laplacian without the roots' rows and columns,
  // positive definite, the same for every set of edge vectors.
  std::vector<Eigen::Triplet<double>> triplets;
  for (const Edge& e : edges_) {
    const int a = unknown_[e[0]], b = unknown_[e[1]];
    if (a >= 0) triplets.emplace_back(a, a, 1.0);
    if (b >= 0) triplets.emplace_back(b, b, 1.0);
    if (a >= 0 && b >= 0) {
      triplets.emplace_back(a, b, -1.0);
      triplets.emplace_back(b, a, -1.0);
    }
  }
  if (unknowns_ > 0) {
    Eigen::SparseMatrix<double> L(unknowns_, unknowns_);
    L.setFromTriplets(triplets.begin(), triplets.end());
    laplacian_.compute(L);
    if (laplacian_.info() != Eigen::Success)
      throw InternalError("EdgeVectorFit: the figure's reduced Laplacian is not positive definite");
  }
}

std::vector<Vec2> EdgeVectorFit::part_centroids(const std::vector<Vec2>& points) const {
  std::vector<Vec2> centroids(root_.size(), Vec2{0, 0});
  for (int v = 0; v < n_; ++v)
    for (int c = 0; c < 2; ++c) centroids[part_[v]][c] += points[v][c];
  for (std::size_t p = 0; p < root_.size(); ++p)
    for (int c = 0; c < 2; ++c) centroids[p][c] /= part_size_[p];
  return centroids;
}

std::vector<Vec2> EdgeVectorFit::positions(const std::vector<Vec2>& edge_vectors,
                                           const std::vector<Vec2>& centroids) const {
  // One solve per guide sample: the rigid method's set-up samples the
  // guide a few dozen times, seconds at 10^5 vertices, so each sample is a
  // point where a cancelled call stops (cancellation.h).
  poll_cancellation();
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(unknowns_, 2);
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const double dx = edge_vectors[e][0], dy = edge_vectors[e][1];
    const int i = unknown_[edges_[e][0]], j = unknown_[edges_[e][1]];
    // d/dp of |p_j - p_i - d|^2 / 2: L p = B^T d.
    if (j >= 0) {
      rhs(j, 0) += dx;
      rhs(j, 1) += dy;
    }
    if (i >= 0) {
      rhs(i, 0) -= dx;
      rhs(i, 1) -= dy;
    }
  }
  Eigen::MatrixX2d x;
  if (unknowns_ > 0) x = laplacian_.solve(rhs);
  std::vector<Vec2> p(n_, Vec2{0, 0});
  for (int v = 0; v < n_; ++v)
    if (unknown_[v] >= 0) p[v] = {x(unknown_[v], 0), x(unknown_[v], 1)};
  // Each part moved onto its centroid.
  std::vector<Vec2> mean(root_.size(), Vec2{0, 0});
  for (int v = 0; v < n_; ++v)
    for (int c = 0; c < 2; ++c) mean[part_[v]][c] += p[v][c];
  for (int v = 0; v < n_; ++v) {
    const int q = part_[v];
    for (int c = 0; c < 2; ++c) p[v][c] += centroids[q][c] - mean[q][c] / part_size_[q];
  }
  return p;
}

}  // namespace internal
}  // namespace stickmorph
