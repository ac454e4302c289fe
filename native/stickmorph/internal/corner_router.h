// Routing a path between two corners of a plane straight-line graph, in the
// region both corners open onto: the path of the annulus cut (paper,
// section 3, Algorithm 3, step 3) and of the bridges between the parts of a
// figure (issue 14).
//
// A constrained Delaunay triangulation (CGAL, exact predicates) of the nodes
// with the graph's edges as constraints, and a shortest dual path (fewest
// triangles) from the triangles in the first corner's wedge to those in the
// second's. The path bends at the midpoints of the triangle edges it
// crosses, so it stays inside the triangles it walks through and meets no
// constraint. Callers check the result exactly (rounding of a midpoint is
// the one inexact step).
#pragma once

#include <memory>
#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph::internal {

/// A corner of a walk round a face: the walk arrives at `vertex` from
/// `prev` and leaves to `next` (the same vertex at the tip of a dangling
/// edge). `next` and `prev` are -1 at a lone vertex, whose one corner is
/// every direction; as a goal, such a corner accepts any triangle at the
/// vertex.
struct RouteCorner {
  int vertex = -1;
  int next = -1, prev = -1;
};

class CornerRouterImpl;

class CornerRouter {
 public:
  /// `nodes` (#N by 2) are the triangulation's vertices, `constraints`
  /// node pairs that no route may cross. Nodes must be distinct and the
  /// constraints must not cross (a valid figure and its enclosure).
  /// `frame`: more points, unconstrained and not addressable, that widen
  /// the triangulation beyond the nodes' convex hull, so that a route can
  /// leave a corner that faces outwards on the hull (a box around a figure
  /// whose exterior is routed through).
  CornerRouter(const std::vector<Vec2>& nodes, const std::vector<Edge>& constraints,
               const std::vector<Vec2>& frame = {});
  ~CornerRouter();
  CornerRouter(CornerRouter&&) noexcept;
  CornerRouter& operator=(CornerRouter&&) noexcept;

  /// Adds a node at `position` (not on any constraint) and returns its index.
  int add_node(const Vec2& position);
  /// Adds the constraint from node a to node b, which must cross none.
  void add_constraint(int a, int b);

  /// Bends of a route from corner `from`'s wedge to corner `to`'s, or false
  /// if the two wedges open onto different regions.
  bool route(const RouteCorner& from, const RouteCorner& to, std::vector<Vec2>& bends) const;

 private:
  std::unique_ptr<CornerRouterImpl> impl_;  // keeps CGAL out of this header
};

/// Adds points on the longest segments of the path from -> bends -> to
/// until it has `count` bends; the added bends are straight (section 3:
/// redundant vertices on a straight path are harmless to the triangulation).
void pad_bends(const Vec2& from, const Vec2& to, std::vector<Vec2>& bends, int count);

}  // namespace stickmorph::internal
