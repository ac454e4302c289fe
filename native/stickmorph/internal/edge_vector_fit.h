// The figure whose edges best match given edge vectors: the least-squares
// fit that the as-rigid-as-possible guides (rigid_guide.h for a pair,
// key_pose_guide.h through key poses) make of their interpolated edges.
//
// In the spirit of Alexa, Cohen-Or & Levin 2000 ("As-rigid-as-possible
// shape interpolation") with the figure's edges as the elements: given a
// vector d_e for every edge e = (i, j), the positions minimising
// sum_e |p_j - p_i - d_e|^2 solve the normal equations L p = B^T d, L the
// graph Laplacian. That fixes each connected part up to a translation,
// which the caller gives as the part's centroid. On a tree the fit is exact
// (forward kinematics); on a cycle the closure error is spread evenly.
#pragma once

#include <Eigen/SparseCholesky>

#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph {
namespace internal {

class EdgeVectorFit {
 public:
  /// The graph on `vertex_count` vertices with these edges; its parts are
  /// numbered in the order of their lowest vertex.
  /// @throws InternalError if the reduced Laplacian does not factor (it is
  ///         positive definite for any graph).
  EdgeVectorFit(int vertex_count, const std::vector<Edge>& edges);

  int vertex_count() const { return n_; }
  int part_count() const { return int(root_.size()); }
  /// The part of each vertex.
  const std::vector<int>& part() const { return part_; }

  /// Each part's centroid in `points` (#V by 2).
  std::vector<Vec2> part_centroids(const std::vector<Vec2>& points) const;

  /// The #V positions whose edge e = (i, j) best matches p_j - p_i =
  /// edge_vectors[e] (least squares), each part p translated so that its
  /// centroid is centroids[p]. The Laplacian is factored once, in the
  /// constructor: this is one triangular solve.
  std::vector<Vec2> positions(const std::vector<Vec2>& edge_vectors, const std::vector<Vec2>& centroids) const;

 private:
  int n_ = 0;
  std::vector<Edge> edges_;
  // Each part has one fixed root (its lowest vertex); the others are the
  // unknowns of one reduced Laplacian.
  std::vector<int> part_;       // vertex -> part
  std::vector<int> root_;       // part -> root vertex
  std::vector<int> unknown_;    // vertex -> row, -1 for roots
  std::vector<int> part_size_;  // part -> vertices
  int unknowns_ = 0;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> laplacian_;
};

}  // namespace internal
}  // namespace stickmorph
