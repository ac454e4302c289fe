// Exact geometric predicates on double coordinates.
//
// Thin wrappers over CGAL::Exact_predicates_inexact_constructions_kernel, kept
// in one translation unit so that CGAL is compiled once. Every geometric
// decision in stickmorph goes through these functions: results are exact for
// the given doubles, never subject to rounding.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// Sign of the signed area of triangle (a, b, c): +1 counter-clockwise,
/// -1 clockwise, 0 collinear.
int orientation(const Vec2& a, const Vec2& b, const Vec2& c);

/// Lexicographic comparison of (x, y): -1, 0 or +1.
int compare_xy(const Vec2& a, const Vec2& b);

/// Angular comparison of directions (p - origin) and (q - origin),
/// counter-clockwise from the positive x axis (angle 0 inclusive, 2*pi
/// exclusive): -1 if p comes first, 0 if same direction, +1 otherwise.
/// p and q must differ from origin.
int compare_direction_ccw(const Vec2& origin, const Vec2& p, const Vec2& q);

/// True iff p lies on the closed segment [a, b].
bool on_segment(const Vec2& p, const Vec2& a, const Vec2& b);

/// How two closed segments [a, b] and [c, d] meet.
enum class SegmentContact {
  Disjoint,       ///< no common point
  Crossing,       ///< one common point, interior to both
  Touching,       ///< one common point, an endpoint of at least one segment
  Overlapping,    ///< collinear with a common sub-segment of positive length
};
SegmentContact segment_contact(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// Is direction q (from v) strictly inside the wedge of a polygon corner at
/// v, swept counter-clockwise from the edge to `next` to the edge to `prev`
/// (the region's side)? At the tip of a dangling edge (`next` and `prev`
/// the same vertex) the wedge is everything but the edge's direction.
bool strictly_inside_corner(const Vec2& v, const Vec2& next, const Vec2& prev, bool tip, const Vec2& q);

/// A closed segment.
using Segment = std::array<Vec2, 2>;

/// Index pairs (i, j) such that the bounding boxes of a[i] and b[j] meet
/// (closed boxes, so touching counts): the candidates that an exact
/// intersection test must look at. CGAL's box intersection, O((m + n) log
/// and the number of pairs); boxes of doubles are exact.
std::vector<std::pair<int, int>> overlapping_boxes(const std::vector<Segment>& a, const std::vector<Segment>& b);

/// The same pairs, each handed to `visit(i, j)` as it is found instead of
/// collected: the number of pairs can be quadratic (the long diagonals of a
/// densely sampled curve's exterior face overlap thousands of edges each;
/// issue 29's 10^5-vertex wavy polyline collected 16 GB of them), and a
/// caller that only needs a verdict per segment keeps none.
void for_each_overlapping_box(const std::vector<Segment>& a, const std::vector<Segment>& b,
                              const std::function<void(int, int)>& visit);

/// Exact sign of the signed area (shoelace sum) of a closed polygon
/// given by its corner positions, in order: +1 counter-clockwise, -1
/// clockwise, 0 zero area. Uses exact arithmetic (not an orientation
/// predicate cascade), so it is correct for any corner sequence.
int signed_area_sign(const std::vector<Vec2>& corners);

}  // namespace stickmorph
