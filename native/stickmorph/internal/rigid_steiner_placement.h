// Steiner vertices of the rigid morph's guide frame placed as rigidly as
// possible (issue 30, item 1; beyond the paper).
//
// GuidedMorph's guide frame holds the figure where the guide puts it and
// the enclosure where it is; its Steiner vertices are free. Placed by the
// blended weights of [8] (a convex combination of their neighbours, the
// paper's morph with the figure held) they follow the barycentric morph,
// not the guide: around a stroke that turns they lag, and the triangles
// between them and the figure invert although the figure itself is fine,
// which forces blending away from the guide. Compatible refinement makes
// that worse (more Steiner vertices, each placed so).
//
// Here every triangle t is given the shape it has in the as-rigid-as-
// possible interpolation of Alexa, Cohen-Or & Levin 2000 ("As-rigid-as-
// possible shape interpolation"): the affine map from its source shape to
// its target shape, A_t = R(theta_t) S_t (polar decomposition), is
// interpolated as A_t(u) = R(u theta_t) ((1 - u) I + u S_t), whose
// determinant stays positive. The angle theta_t is only known up to whole
// turns; it is taken nearest the turn the guide gives the triangle's figure
// edges (their mean), or, for a triangle without one, nearest the angle of
// a neighbour already chosen (breadth first from the figure), so that the
// triangles turn the way the figure they hold turns: a letter turned
// upside down turns its strokes by nearly half a turn, which the principal
// angles of neighbouring triangles split both ways. The Steiner vertices are then the least-squares fit of every
// triangle's map to its A_t(u), weighted by its source area (the Poisson
// form of Xu et al. 2005, "Poisson shape interpolation"), the figure and
// the enclosure held: one symmetric positive definite system, the same at
// every u (the cotangent Laplacian of the source on the Steiner rows),
// factorized once; each frame is a right-hand side and two triangular
// solves. The placement is continuous in u, so the trust that GuidedMorph
// computes from it changes smoothly too.
//
// Nothing here makes the frame valid: GuidedMorph judges every star of the
// guide frame exactly as before, and the frame it outputs is checked by the
// certificate.
#pragma once

#include <memory>
#include <vector>

#include "stickmorph/figure_triangulation.h"

namespace stickmorph {
namespace internal {

class RigidSteinerPlacement {
 public:
  /// `tri`: the normalised triangulation (enclosure the same in source and
  /// target, every triangle counter-clockwise in both); `edges` the figure's
  /// edges (on the first n nodes) and `turns` how far the guide turns each
  /// of them from u = 0 to 1 in that normalised space (radians,
  /// counter-clockwise).
  RigidSteinerPlacement(const FigureTriangulation& tri, const std::vector<Edge>& edges,
                        const std::vector<double>& turns);
  ~RigidSteinerPlacement();
  RigidSteinerPlacement(RigidSteinerPlacement&&) noexcept;
  RigidSteinerPlacement& operator=(RigidSteinerPlacement&&) noexcept;

  /// Sets the Steiner vertices of `positions` (all n + k + s nodes; the
  /// figure's and the enclosure's are read) at morph parameter u.
  /// False if the system could not be factorized (then `positions` is
  /// unchanged).
  bool place(double u, std::vector<Vec2>& positions) const;
  /// The same with every node on its own clock (local timing, issue 31):
  /// each triangle's map interpolated at the mean of its corners'
  /// `node_times` (all n + k + s nodes), so that the triangles about a
  /// lagging limb turn when it does. Equal times are place(u).
  bool place(const std::vector<double>& node_times, std::vector<Vec2>& positions) const;

 private:
  template <class TriangleTime>
  bool place_at(const TriangleTime& time_of, std::vector<Vec2>& positions) const;
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace internal
}  // namespace stickmorph
