// Routing between corners; see corner_router.h.
#include "stickmorph/internal/corner_router.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <map>
#include <queue>
#include <set>
#include <utility>

#include "stickmorph/errors.h"

namespace stickmorph::internal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;

class CornerRouterImpl {
 public:
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handle;

  int add_node(const Vec2& p) {
    auto h = cdt.insert(Kernel::Point_2(p[0], p[1]));
    h->info() = int(handle.size());
    handle.push_back(h);
    return h->info();
  }

  // The finite triangles in the corner's wedge: counter-clockwise around
  // the vertex from the edge to `next` until a constraint (the edge from
  // `prev`) closes the wedge; every triangle at a lone vertex.
  std::vector<Cdt::Face_handle> wedge(const RouteCorner& corner) const {
    std::vector<Cdt::Face_handle> faces;
    const auto v = handle[std::size_t(corner.vertex)];
    if (corner.next < 0) {
      Cdt::Face_circulator fc = cdt.incident_faces(v), done = fc;
      if (fc != nullptr) do
          if (!cdt.is_infinite(fc)) faces.push_back(fc);
        while (++fc != done);
      return faces;
    }
    Cdt::Face_handle f;
    int i;
    if (!cdt.is_edge(v, handle[std::size_t(corner.next)], f, i)) return faces;
    // f lies left of the edge from v to next when v precedes next in it.
    if (f->vertex(Cdt::ccw(i)) != v) f = f->neighbor(i);
    for (std::size_t guard = 0; guard <= handle.size() + 3; ++guard) {
      if (!cdt.is_infinite(f)) faces.push_back(f);
      const int j = f->index(v);
      if (cdt.is_constrained({f, Cdt::ccw(j)})) break;
      f = f->neighbor(Cdt::ccw(j));
    }
    return faces;
  }
};

CornerRouter::CornerRouter(const std::vector<Vec2>& nodes, const std::vector<Edge>& constraints,
                           const std::vector<Vec2>& frame)
    : impl_(std::make_unique<CornerRouterImpl>()) {
  for (const Vec2& p : nodes) impl_->add_node(p);
  for (const Vec2& p : frame) impl_->cdt.insert(Kernel::Point_2(p[0], p[1]))->info() = -1;
  for (const Edge& e : constraints) add_constraint(e[0], e[1]);
}
CornerRouter::~CornerRouter() = default;
CornerRouter::CornerRouter(CornerRouter&&) noexcept = default;
CornerRouter& CornerRouter::operator=(CornerRouter&&) noexcept = default;

int CornerRouter::add_node(const Vec2& position) { return impl_->add_node(position); }

void CornerRouter::add_constraint(int a, int b) {
  try {
    impl_->cdt.insert_constraint(impl_->handle[std::size_t(a)], impl_->handle[std::size_t(b)]);
  } catch (const std::exception& error) {
    // CGAL refuses a constraint that crosses another or passes through a
    // node (No_constraint_intersection_tag). Callers check their segments
    // exactly first, so this is a broken promise, not a bad input.
    throw InternalError("corner router: the segment from node " + std::to_string(a) + " to node " +
                        std::to_string(b) + " meets a constraint or node: " + error.what());
  }
}

bool CornerRouter::route(const RouteCorner& from, const RouteCorner& to, std::vector<Vec2>& bends) const {
  const Cdt& cdt = impl_->cdt;
  const std::vector<Cdt::Face_handle> goal_faces = impl_->wedge(to);
  const std::set<Cdt::Face_handle> goals(goal_faces.begin(), goal_faces.end());
  // Breadth-first search across unconstrained edges.
  std::map<Cdt::Face_handle, std::pair<Cdt::Face_handle, int>> came_from;
  std::queue<Cdt::Face_handle> queue;
  for (auto f : impl_->wedge(from)) {
    came_from[f] = {Cdt::Face_handle(), -1};
    queue.push(f);
  }
  Cdt::Face_handle goal;
  while (!queue.empty()) {
    Cdt::Face_handle f = queue.front();
    queue.pop();
    if (goals.count(f)) {
      goal = f;
      break;
    }
    for (int j = 0; j < 3; ++j) {
      if (cdt.is_constrained({f, j})) continue;
      Cdt::Face_handle g = f->neighbor(j);
      if (cdt.is_infinite(g) || came_from.count(g)) continue;
      came_from[g] = {f, j};
      queue.push(g);
    }
  }
  if (goal == Cdt::Face_handle()) return false;
  std::vector<Vec2> reversed;
  for (Cdt::Face_handle f = goal; came_from[f].first != Cdt::Face_handle(); f = came_from[f].first) {
    const auto [from_face, j] = came_from[f];
    const auto a = from_face->vertex(Cdt::ccw(j))->point(), b = from_face->vertex(Cdt::cw(j))->point();
    reversed.push_back({0.5 * (a.x() + b.x()), 0.5 * (a.y() + b.y())});
  }
  bends.assign(reversed.rbegin(), reversed.rend());
  return true;
}

// Adds points on the longest segments until the path has `count` bends;
// the added bends are straight (section 3: redundant vertices on a straight
// cut are harmless to the triangulation).
void pad_bends(const Vec2& from, const Vec2& to, std::vector<Vec2>& bends, int count) {
  while (int(bends.size()) < count) {
    std::vector<Vec2> path{from};
    path.insert(path.end(), bends.begin(), bends.end());
    path.push_back(to);
    std::size_t longest = 0;
    double best = -1;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      const double len = std::hypot(path[i + 1][0] - path[i][0], path[i + 1][1] - path[i][1]);
      if (len > best) best = len, longest = i;
    }
    const Vec2 mid{0.5 * (path[longest][0] + path[longest + 1][0]), 0.5 * (path[longest][1] + path[longest + 1][1])};
    bends.insert(bends.begin() + long(longest), mid);
  }
}

}  // namespace stickmorph::internal
