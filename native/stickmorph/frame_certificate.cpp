// The per-frame certificate; the theorem is stated in frame_certificate.h.
#include "stickmorph/frame_certificate.h"

#include <algorithm>
#include <cstdint>
#include <unordered_set>

#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/morph_topology.h"

namespace stickmorph {

using internal::first_non_positive;
using internal::node_text;
using internal::triangle_text;

FrameCheck parse_frame_check(const std::string& name) {
  if (name == "certificate") return FrameCheck::Certificate;
  if (name == "full") return FrameCheck::Full;
  throw InvalidArgumentError("unknown frame check '" + name + "' (choose certificate or full)");
}

std::string frame_check_name(FrameCheck check) {
  return check == FrameCheck::Full ? "full" : "certificate";
}

std::string certificate_defect(const FigureTriangulation& tri, const std::vector<Vec2>& p) {
  if (int(p.size()) != tri.node_count())
    throw InvalidArgumentError("a frame of the triangulation needs " + std::to_string(tri.node_count()) +
                               " node positions, got " + std::to_string(p.size()));
  // The boundary: a strictly convex polygon, counter-clockwise, winding once.
  // Every corner a strict left turn makes it locally convex; it then turns
  // once iff its sides go from pointing "down" to pointing "up" exactly once
  // (a side points up when its end is above its start, or level and to the
  // right), counted from exact comparisons of coordinates. A locally convex
  // polygon that turns once is convex and simple.
  const int n = tri.figure_vertices, k = tri.enclosure_vertices;
  auto up = [&](int i) {
    const Vec2& a = p[std::size_t(n + i)];
    const Vec2& b = p[std::size_t(n + (i + 1) % k)];
    return b[1] > a[1] || (b[1] == a[1] && b[0] > a[0]);
  };
  int rises = 0;
  for (int i = 0; i < k; ++i) {
    if (orientation(p[std::size_t(n + i)], p[std::size_t(n + (i + 1) % k)], p[std::size_t(n + (i + 2) % k)]) <= 0)
      return "the enclosure is not convex at " + node_text(tri, n + (i + 1) % k);
    if (!up(i) && up((i + 1) % k)) ++rises;
  }
  if (rises != 1) return "the enclosure winds " + std::to_string(rises) + " times";
  // Every triangle positively oriented, exactly.
  const int t = first_non_positive(tri, p);
  if (t >= 0) return triangle_text(tri, t) + " is not counter-clockwise";
  return {};
}

void require_figure_edges(const FigureTriangulation& tri, const StickFigure& figure) {
  auto key = [](int a, int b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
  };
  std::unordered_set<std::uint64_t> sides;
  sides.reserve(tri.triangles.size() * 3);
  for (const auto& tr : tri.triangles)
    for (int j = 0; j < 3; ++j) sides.insert(key(tr[std::size_t(j)], tr[std::size_t((j + 1) % 3)]));
  for (std::size_t e = 0; e < figure.edges.size(); ++e) {
    const Edge& edge = figure.edges[e];
    if (!sides.count(key(edge[0], edge[1])))
      internal::malformed("figure edge " + std::to_string(e) + " (" + std::to_string(edge[0]) + "-" +
                          std::to_string(edge[1]) + ") is not an edge of the triangulation");
  }
}

}  // namespace stickmorph
