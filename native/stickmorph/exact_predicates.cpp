#include "stickmorph/exact_predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/box_intersection_d.h>

namespace stickmorph {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

Point to_point(const Vec2& p) { return Point(p[0], p[1]); }

int sign_of(CGAL::Sign s) { return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0); }

// Upper half-plane of directions: angle in [0, pi). Decided by comparing the
// doubles themselves, so it is exact.
bool in_upper_half(const Vec2& origin, const Vec2& p) {
  return p[1] > origin[1] || (p[1] == origin[1] && p[0] > origin[0]);
}

}  // namespace

int orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  return sign_of(CGAL::orientation(to_point(a), to_point(b), to_point(c)));
}

int compare_xy(const Vec2& a, const Vec2& b) {
  return sign_of(CGAL::compare_xy(to_point(a), to_point(b)));
}

int compare_direction_ccw(const Vec2& origin, const Vec2& p, const Vec2& q) {
  const bool p_upper = in_upper_half(origin, p);
  const bool q_upper = in_upper_half(origin, q);
  if (p_upper != q_upper) return p_upper ? -1 : 1;
  // Same half-plane: the angle between them is below pi, so the orientation
  // predicate orders them. Collinear means the same direction here.
  return -orientation(origin, p, q);
}

bool on_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Point pp = to_point(p), pa = to_point(a), pb = to_point(b);
  return CGAL::collinear(pa, pb, pp) && CGAL::collinear_are_ordered_along_line(pa, pp, pb);
}

SegmentContact segment_contact(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const Point pa = to_point(a), pb = to_point(b), pc = to_point(c), pd = to_point(d);
  const CGAL::Orientation o1 = CGAL::orientation(pa, pb, pc);
  const CGAL::Orientation o2 = CGAL::orientation(pa, pb, pd);
  const CGAL::Orientation o3 = CGAL::orientation(pc, pd, pa);
  const CGAL::Orientation o4 = CGAL::orientation(pc, pd, pb);

  if (o1 == CGAL::COLLINEAR && o2 == CGAL::COLLINEAR) {
    // All four points on one line: order them along it and measure the
    // shared part. Sort each segment's ends lexicographically, which is the
    // order along the line (or its reverse, consistently for both).
    Point s0 = pa, s1 = pb, t0 = pc, t1 = pd;
    if (CGAL::compare_xy(s1, s0) == CGAL::SMALLER) std::swap(s0, s1);
    if (CGAL::compare_xy(t1, t0) == CGAL::SMALLER) std::swap(t0, t1);
    const Point lo = CGAL::compare_xy(s0, t0) == CGAL::LARGER ? s0 : t0;
    const Point hi = CGAL::compare_xy(s1, t1) == CGAL::SMALLER ? s1 : t1;
    switch (CGAL::compare_xy(lo, hi)) {
      case CGAL::SMALLER: return SegmentContact::Overlapping;
      case CGAL::EQUAL: return SegmentContact::Touching;
      default: return SegmentContact::Disjoint;
    }
  }
  // Not all collinear: the segments meet iff each one's ends are not strictly
  // on one side of the other's line.
  const bool separated = (o1 != CGAL::COLLINEAR && o1 == o2) || (o3 != CGAL::COLLINEAR && o3 == o4);
  if (separated) return SegmentContact::Disjoint;
  if (o1 == CGAL::COLLINEAR || o2 == CGAL::COLLINEAR || o3 == CGAL::COLLINEAR ||
      o4 == CGAL::COLLINEAR)
    return SegmentContact::Touching;
  return SegmentContact::Crossing;
}

bool strictly_inside_corner(const Vec2& v, const Vec2& next, const Vec2& prev, bool tip, const Vec2& q) {
  if (tip) {
    if (orientation(v, next, q) != 0) return true;
    return (q[0] - v[0]) * (next[0] - v[0]) + (q[1] - v[1]) * (next[1] - v[1]) < 0;
  }
  const int turn = orientation(v, next, prev);
  if (turn > 0) return orientation(v, next, q) > 0 && orientation(v, q, prev) > 0;
  // A reflex corner: everything outside the closed convex wedge from prev to next.
  if (turn < 0) return !(orientation(v, prev, q) >= 0 && orientation(v, q, next) >= 0);
  return orientation(v, next, q) > 0;  // a straight corner: the left half-plane
}

std::vector<std::pair<int, int>> overlapping_boxes(const std::vector<Segment>& a, const std::vector<Segment>& b) {
  std::vector<std::pair<int, int>> pairs;
  for_each_overlapping_box(a, b, [&](int i, int j) { pairs.emplace_back(i, j); });
  return pairs;
}

void for_each_overlapping_box(const std::vector<Segment>& a, const std::vector<Segment>& b,
                              const std::function<void(int, int)>& visit) {
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, int>;
  auto boxes = [](const std::vector<Segment>& segments) {
    std::vector<Box> out;
    out.reserve(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Segment& s = segments[i];
      double lo[2] = {std::min(s[0][0], s[1][0]), std::min(s[0][1], s[1][1])};
      double hi[2] = {std::max(s[0][0], s[1][0]), std::max(s[0][1], s[1][1])};
      out.emplace_back(lo, hi, int(i));
    }
    return out;
  };
  std::vector<Box> boxes_a = boxes(a), boxes_b = boxes(b);
  CGAL::box_intersection_d(boxes_a.begin(), boxes_a.end(), boxes_b.begin(), boxes_b.end(),
                           [&](const Box& x, const Box& y) { visit(x.info(), y.info()); });
}

int signed_area_sign(const std::vector<Vec2>& corners) {
  // Twice the shoelace area, accumulated exactly: each product of two doubles
  // and their sum are representable as rationals without rounding.
  CGAL::Exact_rational twice_area(0);
  const std::size_t n = corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = corners[i];
    const Vec2& q = corners[(i + 1) % n];
    twice_area += CGAL::Exact_rational(p[0]) * CGAL::Exact_rational(q[1]) -
                  CGAL::Exact_rational(q[0]) * CGAL::Exact_rational(p[1]);
  }
  return sign_of(CGAL::sign(twice_area));
}

}  // namespace stickmorph
