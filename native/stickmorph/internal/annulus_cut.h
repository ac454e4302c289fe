// The annulus cut (paper, section 3, Algorithm 3, step 3).
//
// Surazhsky & Gotsman 2001, Algorithm 3, step 3: both figures are enclosed
// in the same convex polygon, and the annulus between the enclosure and the
// figure (the exterior face) is cut open into one weakly simple polygon
// along a path from a corner of the exterior sequence to an enclosure
// vertex. The path must be valid in both figures (it leaves the figure
// inside the same corner and meets nothing on its way), and it must have
// the same number of bends in both, since its bends are corners of the
// polygon that section 4 then triangulates compatibly.
#pragma once

#include <memory>
#include <vector>

#include "stickmorph/decomposition.h"
#include "stickmorph/internal/corner_router.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::internal {

/// A corner of a figure's exterior sequence (Algorithm 1's walk round the
/// unbounded face): the walk arrives at `vertex` from `prev` and leaves to
/// `next`. Both are -1 for a figure of one vertex.
struct ExteriorCorner {
  int index = -1;  ///< position in the exterior sequence
  int vertex = -1;
  int next = -1, prev = -1;
};

/// Corner k of the exterior sequence of `d`, the decomposition of `f`.
ExteriorCorner exterior_corner(const StickFigure& f, const Decomposition& d, int k);

/// The position in the target's exterior sequence of corner `c` of the
/// source's. Compatible figures have the same exterior sequence only up to
/// rotation: Algorithm 1 starts each walk at a dart that depends on the order
/// of the figure's edge list, so position c in one list is in general another
/// corner in the other. A corner is identified by its vertex and the next
/// vertex of the walk, since the walk crosses every dart once.
/// @throws InternalError if the target has no such corner.
int matching_exterior_corner(const Decomposition& source_dec, const Decomposition& target_dec, int c);

/// Exact: does the direction from the corner's vertex to q leave the figure
/// strictly inside the corner's wedge (the exterior's side)?
bool corner_admits(const StickFigure& f, const ExteriorCorner& c, const Vec2& q);

/// Exact: does the open segment from figure vertex v to q avoid the whole
/// figure (touching only edges at v itself)?
bool segment_is_free(const StickFigure& f, int v, const Vec2& q);

/// Routing through the unbounded region of one figure (corner_router.h):
/// the figure and the enclosure triangulated once, and for each request a
/// shortest dual path from the corner's wedge to the enclosure vertex.
class AnnulusRouter {
 public:
  AnnulusRouter(const StickFigure& f, const std::vector<Vec2>& enclosure);
  /// Bends of a route from `corner` to enclosure node `enclosure_node`
  /// (n + j for enclosure vertex j), or false if none exists.
  bool route(const ExteriorCorner& corner, int enclosure_node, std::vector<Vec2>& bends) const;

 private:
  CornerRouter router_;
};

/// The chosen cut: from `corner` of the source's exterior sequence to
/// enclosure vertex `enclosure_index`, through source_bends in the source
/// and target_bends in the target (as many in both).
struct AnnulusCut {
  ExteriorCorner corner;
  int enclosure_index = -1;
  std::vector<Vec2> source_bends, target_bends;
};

/// Chooses the cut. Candidates are, for each enclosure vertex, the corners
/// of the figure vertices extreme towards it in either figure. A straight
/// cut valid in both figures is taken first (no Steiner vertex); otherwise
/// the cut is routed through each figure's unbounded region (a shortest
/// dual path in a constrained triangulation of the figure and the
/// enclosure, bending at the midpoints of the edges it crosses, so it never
/// meets the figure) and the candidate with the fewest bends is kept, the
/// other figure's path padded to the same count.
/// @throws VerificationError if no candidate can be routed in both.
AnnulusCut choose_annulus_cut(const StickFigure& source, const Decomposition& source_dec, const StickFigure& target,
                              const Decomposition& target_dec, const std::vector<Vec2>& enclosure);

}  // namespace stickmorph::internal
