#include "stickmorph/figure_parts.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"

namespace stickmorph {
namespace {

// Winding number of the closed walk `darts` around p, with exact
// orientation tests (the crossing rule of Sunday's winding-number
// algorithm: an upward edge with p strictly left counts +1, a downward one
// with p strictly right -1; y comparisons of doubles are exact). p is not
// on the walk.
int winding_number(const StickFigure& figure, const std::vector<int>& darts, const Vec2& p) {
  int winding = 0;
  for (int d : darts) {
    const Vec2& a = figure.vertices[std::size_t(dart_tail(figure, d))];
    const Vec2& b = figure.vertices[std::size_t(dart_head(figure, d))];
    if (a[1] <= p[1]) {
      if (b[1] > p[1] && orientation(a, b, p) > 0) ++winding;
    } else if (b[1] <= p[1] && orientation(a, b, p) < 0) {
      --winding;
    }
  }
  return winding;
}

}  // namespace

FigureParts figure_parts(const StickFigure& figure) { return figure_parts(int(figure.vertices.size()), figure.edges); }

FigureParts figure_parts(int vertex_count, const std::vector<Edge>& edges) {
  const std::size_t n = std::size_t(vertex_count);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[std::size_t(v)] != v) v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
    return v;
  };
  for (const Edge& e : edges) {
    const int a = find(e[0]), b = find(e[1]);
    // The smaller root wins, so each root is its part's smallest vertex.
    if (a != b) parent[std::size_t(std::max(a, b))] = std::min(a, b);
  }
  FigureParts parts;
  parts.part_of_vertex.assign(n, -1);
  std::vector<int> part_of_root(n, -1);
  for (std::size_t v = 0; v < n; ++v) {
    const int root = find(int(v));
    if (part_of_root[std::size_t(root)] < 0) {
      part_of_root[std::size_t(root)] = parts.count();
      parts.vertices.emplace_back();
    }
    parts.part_of_vertex[v] = part_of_root[std::size_t(root)];
    parts.vertices[std::size_t(part_of_root[std::size_t(root)])].push_back(int(v));
  }
  return parts;
}

PartNesting part_nesting(const StickFigure& figure, const Decomposition& dec, const FigureParts& parts) {
  const int count = parts.count();
  PartNesting nesting;
  nesting.enclosing.assign(std::size_t(count), {});
  nesting.parent_part.assign(std::size_t(count), -1);
  nesting.parent_sequence.assign(std::size_t(count), -1);
  if (count < 2) return nesting;

  // Each part D is represented by its smallest vertex: D does not touch the
  // container, so all of D lies in the face its vertex lies in.
  std::vector<Vec2> representative;
  representative.reserve(std::size_t(count));
  for (const std::vector<int>& vs : parts.vertices) representative.push_back(figure.vertices[std::size_t(vs.front())]);

  for (std::size_t s = 0; s < dec.sequences.size(); ++s) {
    const CyclicSequence& seq = dec.sequences[s];
    if (seq.exterior) continue;
    const int container = parts.part_of_vertex[std::size_t(seq.vertices.front())];
    // A bounding box first: most parts are far from most faces.
    std::array<double, 2> lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    std::array<double, 2> hi{-lo[0], -lo[1]};
    for (int v : seq.vertices)
      for (int c = 0; c < 2; ++c) {
        lo[std::size_t(c)] = std::min(lo[std::size_t(c)], figure.vertices[std::size_t(v)][std::size_t(c)]);
        hi[std::size_t(c)] = std::max(hi[std::size_t(c)], figure.vertices[std::size_t(v)][std::size_t(c)]);
      }
    for (int part = 0; part < count; ++part) {
      if (part == container) continue;
      const Vec2& p = representative[std::size_t(part)];
      if (p[0] <= lo[0] || p[0] >= hi[0] || p[1] <= lo[1] || p[1] >= hi[1]) continue;
      // Interior sequences run counter-clockwise (decomposition.h): +1 inside.
      if (winding_number(figure, seq.darts, p) != 0)
        nesting.enclosing[std::size_t(part)].emplace_back(container, int(s));
    }
  }
  // The enclosing faces of a part are nested in one another; the innermost
  // belongs to the container that is itself enclosed most often.
  for (int part = 0; part < count; ++part) {
    std::vector<std::pair<int, int>>& list = nesting.enclosing[std::size_t(part)];
    std::sort(list.begin(), list.end());
    std::size_t deepest = 0;
    for (const auto& [container, sequence] : list)
      if (nesting.parent_part[std::size_t(part)] < 0 ||
          nesting.enclosing[std::size_t(container)].size() > deepest) {
        nesting.parent_part[std::size_t(part)] = container;
        nesting.parent_sequence[std::size_t(part)] = sequence;
        deepest = nesting.enclosing[std::size_t(container)].size();
      }
  }
  return nesting;
}

std::string describe_part(const FigureParts& parts, int part) {
  const std::vector<int>& vs = parts.vertices[std::size_t(part)];
  std::string text = "part " + std::to_string(part) + " (vert" + (vs.size() == 1 ? "ex " : "ices ");
  constexpr std::size_t kListed = 8;
  for (std::size_t k = 0; k < vs.size() && k < kListed; ++k) text += (k ? ", " : "") + std::to_string(vs[k]);
  if (vs.size() > kListed) text += ", ... (" + std::to_string(vs.size()) + " in all)";
  return text + ")";
}

bool is_valid(const PartNesting& nesting, const Decomposition& dec, const FigureParts& parts) {
  const std::size_t count = std::size_t(parts.count());
  if (nesting.enclosing.size() != count || nesting.parent_part.size() != count ||
      nesting.parent_sequence.size() != count)
    return false;
  for (std::size_t part = 0; part < count; ++part) {
    const auto& list = nesting.enclosing[part];
    std::size_t deepest = 0;
    bool parent_listed = nesting.parent_part[part] < 0 && list.empty();
    for (const auto& [container, sequence] : list) {
      if (container < 0 || std::size_t(container) >= count || std::size_t(container) == part) return false;
      if (sequence < 0 || std::size_t(sequence) >= dec.sequences.size()) return false;
      const CyclicSequence& seq = dec.sequences[std::size_t(sequence)];
      if (seq.exterior || parts.part_of_vertex[std::size_t(seq.vertices.front())] != container) return false;
      deepest = std::max(deepest, nesting.enclosing[std::size_t(container)].size());
      if (container == nesting.parent_part[part] && sequence == nesting.parent_sequence[part]) parent_listed = true;
    }
    if (!parent_listed) return false;
    if (!list.empty() && nesting.enclosing[std::size_t(nesting.parent_part[part])].size() != deepest) return false;
  }
  return true;
}

}  // namespace stickmorph
