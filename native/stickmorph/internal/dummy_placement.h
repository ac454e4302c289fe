// Placement of dummy vertices on the figures' edges (step 4 of
// figure_correspondence.h).
//
// Surazhsky & Gotsman 2001, section 6: a dummy vertex subdivides an edge of
// one figure to stand for a vertex of the other. A resampled place becomes a
// point strictly inside one edge, on the edge its neighbours in the matched
// sequence pin down (arc lengths alone cannot tell where edges are shorter
// than their rounding), and runs that rounding would merge are spread.
#pragma once

#include <cstddef>
#include <vector>

#include "stickmorph/figure_correspondence.h"
#include "stickmorph/internal/arc_length_resampling.h"
#include "stickmorph/internal/correspondence_track.h"

namespace stickmorph::internal {

/// Where a place lies in the figure: its vertex, or a dummy on an edge.
/// `slot` (if not -1) is the track's edge the place must lie on: the one
/// between its neighbours in the matched sequence (dummy_slots).
MatchedPlace matched_place(const StickFigure& figure, const Track& track, const TrackPlace& place, Vec2& position,
                           char* track_runs_along = nullptr, int slot = -1);

/// Per item, the edge of `track` (its slot) that the item's place on this
/// side must lie on when it is not one of the track's vertices (-1 where it
/// is, or where the neighbours do not pin one edge down): the edge between
/// the nearest items before and after it that are the track's vertices, or
/// the chain's end nodes. The parameters alone cannot tell where edges are
/// shorter than the rounding of the arc length (a 10^37-long drawing with
/// vertices 10^20 apart: fuzz_correspond_pair), and a dummy on the wrong
/// side of a vertex breaks the subdivision. `vertex_of(item)` is the item's
/// vertex on this side or -1; `reversed` when the items run the track
/// backwards.
template <class VertexOf>
std::vector<int> dummy_slots(const Track& track, std::size_t figure_vertices, const std::vector<MatchedItem>& items,
                             const VertexOf& vertex_of, bool reversed) {
  const int n = int(track.vertices.size());
  std::vector<int> slot_of(figure_vertices, -1);
  for (int k = 0; k < n; ++k) slot_of[std::size_t(track.vertices[std::size_t(k)])] = k;
  std::vector<int> vertex_slot(items.size(), -1);
  for (std::size_t k = 0; k < items.size(); ++k) {
    const int v = vertex_of(items[k]);
    if (v >= 0) vertex_slot[k] = slot_of[std::size_t(v)];
  }
  const int m = int(items.size());
  // The slots of the track's vertices before and after each item in the
  // sequence, in one pass each way (a long run of dummies between two
  // vertices must not be walked once per dummy): a chain starts at one end
  // node and stops at the other, a loop wraps round, so its first items
  // follow its last vertex and its last items precede its first.
  const int none = -1;
  int last_vertex = none, first_vertex = none;
  for (int k = 0; k < m; ++k)
    if (vertex_slot[std::size_t(k)] >= 0) {
      if (first_vertex == none) first_vertex = vertex_slot[std::size_t(k)];
      last_vertex = vertex_slot[std::size_t(k)];
    }
  std::vector<int> before(items.size()), after(items.size());
  int seen = track.closed ? last_vertex : (reversed ? n - 1 : 0);
  for (int k = 0; k < m; ++k) {
    before[std::size_t(k)] = seen;
    if (vertex_slot[std::size_t(k)] >= 0) seen = vertex_slot[std::size_t(k)];
  }
  seen = track.closed ? first_vertex : (reversed ? 0 : n - 1);
  for (int k = m - 1; k >= 0; --k) {
    after[std::size_t(k)] = seen;
    if (vertex_slot[std::size_t(k)] >= 0) seen = vertex_slot[std::size_t(k)];
  }
  std::vector<int> slots(items.size(), -1);
  for (int k = 0; k < m; ++k) {
    const int b = before[std::size_t(k)], a = after[std::size_t(k)];
    if (vertex_slot[std::size_t(k)] >= 0 || b < 0 || a < 0) continue;
    // One edge apart along the track, in the items' direction.
    const int next = track.closed ? (b + (reversed ? n - 1 : 1)) % n : b + (reversed ? -1 : 1);
    if (next == a) slots[std::size_t(k)] = reversed ? a : b;
  }
  return slots;
}

/// Points placed inside one edge (dummies on a source edge, or source
/// vertices on a target edge), in the chain's order: a run of consecutive
/// places on the same edge. Where rounding a + f (b - a) merges two of them,
/// or one with an end of the edge (an edge far longer than the spacing of
/// the other drawing's vertices: 10 target vertices within 1e-16 of the
/// edge's length), the run is spread evenly along the whole edge instead,
/// in the same order. Only such a nearly degenerate run moves; the matched
/// figure is validated exactly afterwards all the same.
void separate_on_edges(const StickFigure& figure, std::vector<MatchedPlace>& places, std::vector<Vec2>& at,
                       const std::vector<char>& track_runs_along);

}  // namespace stickmorph::internal
