#include "stickmorph/compatibility.h"

#include "stickmorph/internal/stage_counters.h"

#include <algorithm>
#include <iterator>
#include <set>
#include <utility>

#include "stickmorph/figure_parts.h"

namespace stickmorph {
namespace {

using DirectedEdge = std::pair<int, int>;

// Neighbour vertices of v in counter-clockwise order, rotated so that the
// smallest index comes first: equal lists mean equal cyclic orders.
std::vector<int> canonical_neighbours(const StickFigure& figure, const RotationSystem& rs, int v) {
  std::vector<int> around;
  for (int d : rs.outgoing_ccw[v]) around.push_back(dart_head(figure, d));
  if (!around.empty())
    std::rotate(around.begin(), std::min_element(around.begin(), around.end()), around.end());
  return around;
}

std::vector<int> canonical_reversed(std::vector<int> around) {
  std::reverse(around.begin(), around.end());
  if (!around.empty())
    std::rotate(around.begin(), std::min_element(around.begin(), around.end()), around.end());
  return around;
}

std::string list_text(const std::vector<int>& items, const char* separator, std::size_t limit = 16) {
  std::string text;
  for (std::size_t k = 0; k < items.size() && k < limit; ++k)
    text += (k ? separator : "") + std::to_string(items[k]);
  if (items.size() > limit) text += std::string(separator) + "... (" + std::to_string(items.size()) + " in all)";
  return text;
}

// The exterior sequences (one per part) as a set of directed edges (tail,
// head): comparable across figures whose edge lists differ in order or
// direction.
std::set<DirectedEdge> exterior_edges(const StickFigure& figure, const Decomposition& dec) {
  std::set<DirectedEdge> result;
  for (int sequence : dec.exterior_of_part)
    for (int d : dec.sequences[std::size_t(sequence)].darts)
      result.emplace(dart_tail(figure, d), dart_head(figure, d));
  return result;
}

// A face named the same way in two figures on the same edge set: its
// smallest directed edge (a bounded face has at least one dart).
DirectedEdge face_key(const StickFigure& figure, const Decomposition& dec, int sequence) {
  DirectedEdge key{-1, -1};
  for (int d : dec.sequences[std::size_t(sequence)].darts) {
    const DirectedEdge side{dart_tail(figure, d), dart_head(figure, d)};
    if (key.first < 0 || side < key) key = side;
  }
  return key;
}

// The face's corners from its smallest vertex, for messages.
std::vector<int> face_vertices(const Decomposition& dec, int sequence) {
  std::vector<int> vs = dec.sequences[std::size_t(sequence)].vertices;
  std::rotate(vs.begin(), std::min_element(vs.begin(), vs.end()), vs.end());
  return vs;
}

// The exterior sequence's vertices, starting from its smallest vertex, for
// messages.
std::vector<int> exterior_vertices(const Decomposition& dec) {
  std::vector<int> vs = dec.sequences[dec.exterior].vertices;
  if (!vs.empty()) std::rotate(vs.begin(), std::min_element(vs.begin(), vs.end()), vs.end());
  return vs;
}

CompatibilityReport incompatible(Incompatibility kind, std::string reason, std::vector<int> vertices) {
  CompatibilityReport report;
  report.kind = kind;
  report.reason = std::move(reason);
  report.vertices = std::move(vertices);
  return report;
}

std::vector<Edge> undirected_sorted(const std::vector<Edge>& edges) {
  std::vector<Edge> result;
  result.reserve(edges.size());
  for (const Edge& e : edges) result.push_back({std::min(e[0], e[1]), std::max(e[0], e[1])});
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

// check_compatibility, also giving the parts and the source's nesting it
// found (CompatiblePair keeps them; nothing recomputes them).
CompatibilityReport compare_figures(const StickFigure& source, const Decomposition& source_dec,
                                    const StickFigure& target, const Decomposition& target_dec, FigureParts* parts_out,
                                    PartNesting* source_nesting_out) {
  internal::stage_counters().compatibility_checks.fetch_add(1, std::memory_order_relaxed);
  const std::size_t n = source.vertices.size();
  if (n != target.vertices.size())
    return incompatible(Incompatibility::VertexCountDiffers,
                        "the source has " + std::to_string(n) + " vertices and the target " +
                            std::to_string(target.vertices.size()),
                        {});

  // Section 2.1 compares figures whose vertices correspond; their edges must
  // correspond too. The first edge of either list (in its own order) that
  // the other lacks is named.
  const EdgeSetDifference difference = edge_set_difference(source.edges, target.edges);
  if (!difference.empty()) {
    const bool in_source = !difference.only_in_source.empty();
    const StickFigure& figure = in_source ? source : target;
    const std::vector<Edge>& only = in_source ? difference.only_in_source : difference.only_in_target;
    for (const Edge& e : figure.edges)
      if (std::binary_search(only.begin(), only.end(), Edge{std::min(e[0], e[1]), std::max(e[0], e[1])}))
        return incompatible(Incompatibility::EdgeSetDiffers,
                            "edge " + describe_edge(figure, find_edge(figure, e[0], e[1])) +
                                (in_source ? " of the source is not an edge of the target"
                                           : " of the target is not an edge of the source"),
                            {e[0], e[1]});
  }

  // Isomorphic cyclic sequences under the correspondence <=> every vertex sees
  // its neighbours in the same cyclic order (the sequences are traced from
  // these orders by Algorithm 1).
  int first_differing = -1;
  bool all_reversed = true;  // every differing vertex is exactly reversed
  std::vector<int> source_around, target_around;
  for (std::size_t v = 0; v < n; ++v) {
    std::vector<int> s = canonical_neighbours(source, source_dec.rotation, int(v));
    std::vector<int> t = canonical_neighbours(target, target_dec.rotation, int(v));
    if (s == t) continue;
    if (first_differing < 0) {
      first_differing = int(v);
      source_around = s;
      target_around = t;
    }
    if (canonical_reversed(s) != t) all_reversed = false;
  }

  // A reflection reverses every cyclic order and every cyclic sequence,
  // the exterior one included.
  const std::set<DirectedEdge> source_exterior = exterior_edges(source, source_dec);
  const std::set<DirectedEdge> target_exterior = exterior_edges(target, target_dec);
  std::set<DirectedEdge> reversed_source_exterior;
  for (const auto& [a, b] : source_exterior) reversed_source_exterior.emplace(b, a);
  const bool exterior_same = source_exterior == target_exterior;
  const bool exterior_reversed = reversed_source_exterior == target_exterior;

  // A tree's exterior walks every edge both ways, so it equals its own
  // reverse; then the reversed junctions alone reveal the reflection.
  if (all_reversed && exterior_reversed && (first_differing >= 0 || !exterior_same)) {
    std::string reason = "the target is a mirror image of the source: ";
    if (first_differing >= 0)
      reason += "the cyclic order of edges is reversed at every junction (vertex " +
                std::to_string(first_differing) + ": source " + list_text(source_around, ", ") +
                "; target " + list_text(target_around, ", ") + ") and ";
    reason += "the exterior sequence runs the other way (source " +
              list_text(exterior_vertices(source_dec), " ") + "; target " +
              list_text(exterior_vertices(target_dec), " ") + ")";
    return incompatible(Incompatibility::MirrorImage, reason,
                        first_differing >= 0 ? std::vector<int>{first_differing} : std::vector<int>{});
  }
  if (first_differing >= 0)
    return incompatible(Incompatibility::RotationDiffers,
                        "the cyclic order of edges around vertex " + std::to_string(first_differing) +
                            " differs: counter-clockwise the source has neighbours " +
                            list_text(source_around, ", ") + ", the target " +
                            list_text(target_around, ", "),
                        {first_differing});
  if (!exterior_same) {
    // Name a side of the source's unbounded region that bounds an interior
    // region in the target.
    DirectedEdge witness{-1, -1};
    for (const DirectedEdge& side : source_exterior)
      if (!target_exterior.count(side)) {
        witness = side;
        break;
      }
    return incompatible(Incompatibility::ExteriorDiffers,
                        "the exterior sequences differ: the unbounded region is bounded by " +
                            list_text(exterior_vertices(source_dec), " ") + " in the source and by " +
                            list_text(exterior_vertices(target_dec), " ") +
                            " in the target (the edge from vertex " + std::to_string(witness.first) +
                            " to vertex " + std::to_string(witness.second) +
                            " faces the unbounded region only in the source)",
                        {witness.first, witness.second});
  }

  // Issue 14: each part is compatible on its own (above); the parts must also
  // nest alike. Same edge sets give the same parts.
  FigureParts parts = figure_parts(source);
  PartNesting source_nesting;
  if (parts.count() > 1 || source_nesting_out) source_nesting = part_nesting(source, source_dec, parts);
  if (parts.count() > 1) {
    const PartNesting target_nesting = part_nesting(target, target_dec, parts);
    // Where part D lies relative to part C: the key of C's bounded face
    // holding it, or {-1, -1} for C's exterior.
    auto place = [](const StickFigure& figure, const Decomposition& dec, const PartNesting& nesting, int part,
                    int container) {
      for (const auto& [c, sequence] : nesting.enclosing[std::size_t(part)])
        if (c == container) return std::make_pair(face_key(figure, dec, sequence), sequence);
      return std::make_pair(DirectedEdge{-1, -1}, -1);
    };
    for (int part = 0; part < parts.count(); ++part) {
      // The containers to compare: those of either figure, in order.
      std::vector<int> containers;
      const PartNesting* both[] = {&source_nesting, &target_nesting};
      for (const PartNesting* nesting : both)
        for (const auto& entry : nesting->enclosing[std::size_t(part)]) containers.push_back(entry.first);
      std::sort(containers.begin(), containers.end());
      for (int container : containers) {
        const auto [source_key, source_face] = place(source, source_dec, source_nesting, part, container);
        const auto [target_key, target_face] = place(target, target_dec, target_nesting, part, container);
        if (source_key == target_key) continue;
        auto where = [&](const Decomposition& dec, int face) {
          if (face < 0) return "outside part " + std::to_string(container);
          return "inside part " + std::to_string(container) + ", in its face bounded by " +
                 list_text(face_vertices(dec, face), " ");
        };
        const int first = parts.vertices[std::size_t(part)].front();
        return incompatible(Incompatibility::NestingDiffers,
                            "the parts nest differently: " + describe_part(parts, part) + " lies " +
                                where(source_dec, source_face) + " in the source, but " + where(target_dec, target_face) +
                                " in the target",
                            {first, parts.vertices[std::size_t(container)].front()});
      }
    }
  }
  if (parts_out) *parts_out = std::move(parts);
  if (source_nesting_out) *source_nesting_out = std::move(source_nesting);
  return CompatibilityReport{};
}

}  // namespace

EdgeSetDifference edge_set_difference(const std::vector<Edge>& source, const std::vector<Edge>& target) {
  const std::vector<Edge> a = undirected_sorted(source), b = undirected_sorted(target);
  EdgeSetDifference difference;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(difference.only_in_source));
  std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(difference.only_in_target));
  return difference;
}

CompatibilityReport check_compatibility(const StickFigure& source, const Decomposition& source_dec,
                                        const StickFigure& target, const Decomposition& target_dec) {
  return compare_figures(source, source_dec, target, target_dec, nullptr, nullptr);
}

CompatibilityReport check_compatibility(const StickFigure& source, const StickFigure& target) {
  return check_compatibility(source, decompose(source), target, decompose(target));
}

void require_compatible(const StickFigure& source, const StickFigure& target) {
  CompatiblePair::check(source, target);
}

CompatiblePair CompatiblePair::check(StickFigure source, StickFigure target) {
  Decomposition source_dec = decompose(source);
  Decomposition target_dec = decompose(target);
  return check(std::move(source), std::move(source_dec), std::move(target), std::move(target_dec));
}

CompatiblePair CompatiblePair::check(StickFigure source, Decomposition source_dec, StickFigure target,
                                     Decomposition target_dec) {
  CompatibilityReport report;
  std::optional<CompatiblePair> pair =
      try_check(std::move(source), std::move(source_dec), std::move(target), std::move(target_dec), report);
  if (!pair) throw IncompatibleFiguresError(report.kind, "incompatible figures: " + report.reason, report.vertices);
  return std::move(*pair);
}

std::optional<CompatiblePair> CompatiblePair::try_check(StickFigure source, Decomposition source_dec,
                                                        StickFigure target, Decomposition target_dec,
                                                        CompatibilityReport& report) {
  CompatiblePair pair;
  report = compare_figures(source, source_dec, target, target_dec, &pair.figure_parts_, &pair.source_nesting_);
  if (!report.compatible()) return std::nullopt;
  pair.source_ = std::move(source);
  pair.target_ = std::move(target);
  pair.source_dec_ = std::move(source_dec);
  pair.target_dec_ = std::move(target_dec);
  return pair;
}

namespace internal {

StageCounters& stage_counters() {
  static StageCounters counters;
  return counters;
}

}  // namespace internal

}  // namespace stickmorph
