// The annulus cut (paper, section 3, Algorithm 3, step 3); see annulus_cut.h.
#include "stickmorph/internal/annulus_cut.h"


#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"

namespace stickmorph::internal {

ExteriorCorner exterior_corner(const StickFigure& f, const Decomposition& d, int k) {
  const CyclicSequence& ext = d.sequences[d.exterior];
  ExteriorCorner c;
  c.index = k;
  c.vertex = ext.vertices[k];
  if (ext.darts.empty()) return c;
  const int m = int(ext.vertices.size());
  c.next = ext.vertices[(k + 1) % m];
  c.prev = dart_tail(f, ext.darts[k]);
  return c;
}

// The position in the target's exterior sequence of corner `c` of the
// source's. Compatible figures have the same exterior sequence only up to
// rotation: Algorithm 1 starts each walk at a dart that depends on the order
// of the figure's edge list, so position c in one list is in general another
// corner in the other. A corner is identified by its vertex and the next
// vertex of the walk, since the walk crosses every dart once.
int matching_exterior_corner(const Decomposition& source_dec, const Decomposition& target_dec, int c) {
  const CyclicSequence& source_ext = source_dec.sequences[source_dec.exterior];
  const CyclicSequence& target_ext = target_dec.sequences[target_dec.exterior];
  if (source_ext.darts.empty()) return c;  // a single vertex: one corner
  const int m = int(source_ext.vertices.size());
  const int vertex = source_ext.vertices[c], next = source_ext.vertices[(c + 1) % m];
  if (int(target_ext.vertices.size()) == m)
    for (int t = 0; t < m; ++t)
      if (target_ext.vertices[t] == vertex && target_ext.vertices[(t + 1) % m] == next) return t;
  throw InternalError("annulus cut: corner " + std::to_string(c) + " (vertex " + std::to_string(vertex) +
                      ", next " + std::to_string(next) +
                      ") of the source's exterior sequence is missing from the target's, "
                      "although the figures were found compatible");
}

bool corner_admits(const StickFigure& f, const ExteriorCorner& c, const Vec2& q) {
  const bool lone = c.next < 0;
  const Vec2& v = f.vertices[c.vertex];
  if (lone) return true;  // a figure of one vertex: every direction is free
  return strictly_inside_corner(v, f.vertices[c.next], f.vertices[c.prev], c.next == c.prev, q);
}

// Does the open segment from figure vertex v to q avoid the whole figure?
bool segment_is_free(const StickFigure& f, int v, const Vec2& q) {
  const Vec2& p = f.vertices[v];
  for (const Edge& e : f.edges) {
    const SegmentContact contact = segment_contact(p, q, f.vertices[e[0]], f.vertices[e[1]]);
    if (contact == SegmentContact::Disjoint) continue;
    if (contact == SegmentContact::Touching && (e[0] == v || e[1] == v)) continue;
    return false;
  }
  return true;
}

AnnulusRouter::AnnulusRouter(const StickFigure& f, const std::vector<Vec2>& enclosure)
    : router_([&] {
        // The figure's vertices, then the enclosure's (node n + j); the
        // figure's edges and the enclosure's sides as constraints.
        const int n = int(f.vertices.size()), k = int(enclosure.size());
        std::vector<Vec2> nodes = f.vertices;
        nodes.insert(nodes.end(), enclosure.begin(), enclosure.end());
        std::vector<Edge> constraints = f.edges;
        for (int j = 0; j < k; ++j) constraints.push_back({n + j, n + (j + 1) % k});
        return CornerRouter(nodes, constraints);
      }()) {}

bool AnnulusRouter::route(const ExteriorCorner& corner, int enclosure_node, std::vector<Vec2>& bends) const {
  return router_.route({corner.vertex, corner.next, corner.prev}, {enclosure_node, -1, -1}, bends);
}

AnnulusCut choose_annulus_cut(const StickFigure& source, const Decomposition& source_dec, const StickFigure& target,
                              const Decomposition& target_dec, const std::vector<Vec2>& enclosure) {
  const int k = int(enclosure.size());
  const int n = int(source.vertices.size());
  const CyclicSequence& ext = source_dec.sequences[source_dec.exterior];
  const int m = int(ext.vertices.size());
  Vec2 center{0, 0};
  for (const Vec2& q : enclosure) center[0] += q[0] / k, center[1] += q[1] / k;

  // Candidate corners: for each enclosure vertex, the corners of the figure
  // vertices extreme towards it in either figure.
  std::vector<std::pair<int, int>> candidates;  // (exterior corner index, j)
  for (int j = 0; j < k; ++j) {
    const Vec2 dir{enclosure[j][0] - center[0], enclosure[j][1] - center[1]};
    for (const StickFigure* f : {&source, &target}) {
      int best = 0;
      for (int v = 1; v < n; ++v)
        if (dir[0] * f->vertices[v][0] + dir[1] * f->vertices[v][1] >
            dir[0] * f->vertices[best][0] + dir[1] * f->vertices[best][1])
          best = v;
      for (int c = 0; c < m; ++c)
        if (ext.vertices[c] == best) candidates.push_back({c, j});
    }
  }
  // A straight cut valid in both figures needs no Steiner vertex.
  for (const auto& [c, j] : candidates) {
    const ExteriorCorner sc = exterior_corner(source, source_dec, c);
    const ExteriorCorner tc = exterior_corner(target, target_dec, matching_exterior_corner(source_dec, target_dec, c));
    if (corner_admits(source, sc, enclosure[j]) && corner_admits(target, tc, enclosure[j]) &&
        segment_is_free(source, sc.vertex, enclosure[j]) && segment_is_free(target, tc.vertex, enclosure[j])) {
      AnnulusCut cut;
      cut.corner = sc;
      cut.enclosure_index = j;
      return cut;
    }
  }
  // Otherwise bend the cut: route it through each figure's unbounded region
  // and keep the candidate with the fewest bends.
  AnnulusRouter source_router(source, enclosure), target_router(target, enclosure);
  AnnulusCut best;
  std::size_t best_bends = std::numeric_limits<std::size_t>::max();
  for (const auto& [c, j] : candidates) {
    const ExteriorCorner sc = exterior_corner(source, source_dec, c);
    const ExteriorCorner tc = exterior_corner(target, target_dec, matching_exterior_corner(source_dec, target_dec, c));
    AnnulusCut cut;
    cut.corner = sc;
    cut.enclosure_index = j;
    const bool source_straight = corner_admits(source, sc, enclosure[j]) && segment_is_free(source, sc.vertex, enclosure[j]);
    const bool target_straight = corner_admits(target, tc, enclosure[j]) && segment_is_free(target, tc.vertex, enclosure[j]);
    if (!source_straight && !source_router.route(sc, n + j, cut.source_bends)) continue;
    if (!target_straight && !target_router.route(tc, n + j, cut.target_bends)) continue;
    const std::size_t bends = std::max(cut.source_bends.size(), cut.target_bends.size());
    if (bends < best_bends) best_bends = bends, best = cut;
  }
  if (best.enclosure_index < 0)
    throw VerificationError("exterior face: no path from the figure to the enclosure was found for the annulus cut");
  const int count = int(best_bends);
  pad_bends(source.vertices[best.corner.vertex], enclosure[best.enclosure_index], best.source_bends, count);
  pad_bends(target.vertices[best.corner.vertex], enclosure[best.enclosure_index], best.target_bends, count);
  return best;
}

}  // namespace stickmorph::internal
