// The per-frame certificate of a morph (issue 15): O(T) exact tests that
// prove a frame of a triangulation morph valid without rebuilding the figure.
//
// Theorem (Floater, "One-to-one piecewise linear mappings over
// triangulations", Math. Comp. 72, 2003; for a simple, not necessarily
// convex, boundary: Lipman, "Bijective mappings of meshes with boundary and
// the degree in mesh processing", SIAM J. Imaging Sci. 7, 2014). Let T be a
// triangulation of a disk and phi the piecewise-linear map of T given by new
// vertex positions. If phi maps the boundary cycle onto a simple polygon,
// traversed counter-clockwise, and every triangle of T is positively
// oriented under phi, then phi is one-to-one: its image is a triangulation
// of that polygon with the same connectivity. (Degree argument: a point
// inside the polygon is covered by as many positive triangles as the
// boundary winds round it, i.e. once; a point outside by none.)
//
// The morph's triangulations (Algorithm 3, step 4) are checked once to be
// such disks, bounded by the enclosure (morph_topology.h's build_topology),
// and every figure edge is a triangulation edge (require_figure_edges). So a
// frame whose triangles are all counter-clockwise (exact orientation tests)
// and whose enclosure is a strictly convex polygon winding once (exact, O(k))
// is an embedding of the whole triangulation. The figure is a subcomplex of
// it: its edges do not cross or touch, the rotation at every vertex is the
// source's (phi preserves orientation) and the face outside the enclosure
// stays outside, so the frame is a stick figure compatible with the source
// (section 2.1), every part in its face (issue 14). That is what
// verify_frame (frame_verification.h) checks independently, at the cost of
// rebuilding the figure: FrameCheck::Full runs both, for tests and for users
// who want the second opinion.
#pragma once

#include <string>
#include <vector>

#include "stickmorph/figure_triangulation.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// How each frame of a morph is checked.
enum class FrameCheck {
  Certificate,  ///< the theorem above: O(T) orientation tests plus the enclosure (default)
  Full,         ///< the certificate and verify_frame's independent rebuild of the figure
};

/// "certificate", "full" -> FrameCheck.
/// @throws InvalidArgumentError naming the accepted names.
FrameCheck parse_frame_check(const std::string& name);
std::string frame_check_name(FrameCheck check);

/// The certificate's verdict on node positions `positions` (#N by 2, N =
/// tri.node_count()) of `tri`: empty when the frame is certified, else the
/// first defect found, e.g. "triangle 3 (1, 4, 5) is not counter-clockwise"
/// or "the enclosure is not convex at node 12 (enclosure vertex 2)".
/// Preconditions (checked by the morph's setup, not here): `tri` is a disk
/// bounded by its enclosure, and the figure's edges are edges of `tri`.
/// @throws InvalidArgumentError if positions has the wrong length.
std::string certificate_defect(const FigureTriangulation& tri, const std::vector<Vec2>& positions);

/// Throws InvalidArgumentError ("invalid triangulation for the morph: ...")
/// unless every edge of `figure` is an edge of a triangle of `tri`, naming
/// the first edge that is not: the certificate's second precondition.
void require_figure_edges(const FigureTriangulation& tri, const StickFigure& figure);

}  // namespace stickmorph
