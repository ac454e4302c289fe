// Correspondence of two connected figures (connected_correspondence.h;
// Surazhsky & Gotsman 2001, section 6).
#include "stickmorph/internal/connected_correspondence.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/internal/arc_length_resampling.h"
#include "stickmorph/internal/corner_anchors.h"
#include "stickmorph/internal/correspondence_choice.h"
#include "stickmorph/internal/correspondence_pins.h"
#include "stickmorph/internal/correspondence_skeleton.h"
#include "stickmorph/internal/dummy_placement.h"
#include "stickmorph/internal/plane_map_isomorphism.h"

namespace stickmorph::internal {

StickFigure reflected_figure(const StickFigure& figure) {
  std::vector<Vec2> vertices = figure.vertices;
  for (Vec2& p : vertices) p[0] = -p[0];
  return StickFigure{std::move(vertices), figure.edges, figure.name};
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// One connected figure matched to another (steps 1 to 4 of the header);
// `reference_rotation`: Skeleton::reference_rotation.
FigureCorrespondence correspond_connected(const StickFigure& source, const StickFigure& target,
                                          const CorrespondenceOptions& options, double reference_rotation) {
  const auto start = std::chrono::steady_clock::now();
  Skeleton s = make_skeleton(source);
  s.reference_rotation = reference_rotation;
  const Skeleton t = make_skeleton(target);
  std::vector<std::pair<int, int>> node_pins;
  std::vector<PinPlace> chain_pins;
  classify_pins(s, t, options.pins, node_pins, chain_pins);
  compare_invariants(s, t);

  FigureCorrespondence result;
  result.skeleton_nodes = int(s.nodes.size());
  result.skeleton_chains = int(s.chains.size());
  Candidate chosen;
  if (source.edges.empty()) {
    // Two single vertices (compare_invariants): they match.
    chosen.node_image = {0};
    chosen.fit.residual = 0;  // a point fits a point exactly
    result.candidates = 1;
  } else if (s.is_loop()) {
    chosen = match_loops(s, t, chain_pins, result.candidates);
  } else {
    IsomorphismSearch search = search_isomorphisms(s, t, node_pins, chain_pins, true);
    if (search.images.empty()) {
      if (!search.any_isomorphism) {
        // Reflected, would the skeletons match? Then say so.
        const StickFigure mirrored = reflected_figure(target);
        const Skeleton m = make_skeleton(mirrored);
        if (search_isomorphisms(s, m, {}, {}, false).any_exterior)
          throw IncompatibleFiguresError(Incompatibility::MirrorImage,
                                         "correspond: the target is a mirror image of the source: its junctions "
                                         "see their strokes in the reverse order, and a morph cannot reflect");
        topology_differs("the strokes meet in another arrangement (no matching of the junctions keeps the "
                         "counter-clockwise order of the strokes around every junction)");
      }
      if (!search.any_exterior)
        throw IncompatibleFiguresError(Incompatibility::ExteriorDiffers,
                                       "correspond: the figures match only with another face outside (the source's "
                                       "outer boundary would become an inner one)");
      throw IncompatibleFiguresError(Incompatibility::PinsUnsatisfiable,
                                     "correspond: no matching respects every pin (the first one tried breaks one: " +
                                         search.pin_conflict + ")");
    }
    result.candidates = int(search.images.size());
    // The winner rebuilt in full from its seed image (the search kept its fit only).
    const std::size_t best = best_fit(search.fits);
    const std::optional<std::vector<int>> map = extend_isomorphism(s, t, search.seed, search.images[best]);
    std::string broken;
    std::optional<Candidate> winner = map ? make_candidate(s, t, *map, node_pins, chain_pins, broken) : std::nullopt;
    if (!winner) throw InternalError("correspond: the best matching could not be rebuilt");
    chosen = std::move(*winner);
    chosen.fit = search.fits[best];
  }
  result.residual = chosen.fit.residual;
  result.rotation_degrees = chosen.fit.rotation * 180.0 / kPi;

  // The matched vertices: the source's first, then dummies for the
  // target's vertices that have no source partner, in target order.
  const int ns = int(source.vertices.size()), nt = int(target.vertices.size());
  std::vector<int> target_partner(std::size_t(ns), -1);   // source vertex -> target vertex or -1
  std::vector<int> matched_of_target(std::size_t(nt), -1);
  std::vector<Vec2> source_positions = source.vertices;
  std::vector<Vec2> target_positions(static_cast<std::size_t>(ns));
  result.source_places.resize(std::size_t(ns));
  result.target_places.resize(std::size_t(ns));
  for (int v = 0; v < ns; ++v) result.source_places[std::size_t(v)].vertex = v;
  for (int v = 0; v < ns; ++v)
    if (chosen.node_image[std::size_t(v)] >= 0) {
      const int image = chosen.node_image[std::size_t(v)];
      target_partner[std::size_t(v)] = image;
      result.target_places[std::size_t(v)].vertex = image;
      target_positions[std::size_t(v)] = target.vertices[std::size_t(image)];
      matched_of_target[std::size_t(image)] = v;
    }
  std::vector<std::pair<int, int>> all_pins;
  for (const VertexPin& pin : options.pins) all_pins.emplace_back(pin.source, pin.target);

  struct PendingDummy {  // a target vertex with no source partner
    int target_vertex;
    MatchedPlace source_place;
    Vec2 source_position;
  };
  std::vector<PendingDummy> dummies;
  // Edges as (matched vertex, matched vertex) with the target vertex of a
  // dummy standing in until the dummies are numbered (encoded as -1 - t).
  std::vector<std::array<int, 2>> chain_edges;
  for (const ChainMatch& match : chosen.chains) {
    const Track& st = s.chains[std::size_t(match.source_chain)];
    const Track& tt = t.chains[std::size_t(match.target_chain)];
    ChainMatch anchored = match;
    anchor_corners(source, st, target, tt, anchored);
    const std::vector<MatchedItem> items = resample(st, tt, anchored, all_pins);
    // Where each item lies on the other drawing, then kept apart where
    // rounding would merge points of one edge (separate_on_edges).
    std::vector<MatchedPlace> source_side(items.size()), target_side(items.size());
    std::vector<Vec2> source_side_at(items.size()), target_side_at(items.size());
    std::vector<char> source_along(items.size(), 1), target_along(items.size(), 1);
    const std::vector<int> source_slots = dummy_slots(
        st, source.vertices.size(), items, [](const MatchedItem& item) { return item.source.vertex; }, false);
    const std::vector<int> target_slots =
        dummy_slots(tt, target.vertices.size(), items, [](const MatchedItem& item) { return item.target.vertex; },
                    anchored.reversed);
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (items[k].source.vertex < 0)
        source_side[k] =
            matched_place(source, st, items[k].source, source_side_at[k], &source_along[k], source_slots[k]);
      target_side[k] =
          matched_place(target, tt, items[k].target, target_side_at[k], &target_along[k], target_slots[k]);
    }
    separate_on_edges(source, source_side, source_side_at, source_along);
    separate_on_edges(target, target_side, target_side_at, target_along);
    std::vector<int> sequence;
    if (!st.closed) sequence.push_back(st.vertices.front());
    for (std::size_t k = 0; k < items.size(); ++k) {
      const MatchedItem& item = items[k];
      if (item.source.vertex >= 0) {
        const int v = item.source.vertex;
        result.target_places[std::size_t(v)] = target_side[k];
        target_positions[std::size_t(v)] = target_side_at[k];
        if (item.target.vertex >= 0) {
          target_partner[std::size_t(v)] = item.target.vertex;
          matched_of_target[std::size_t(item.target.vertex)] = v;
        }
        sequence.push_back(v);
      } else {
        dummies.push_back(PendingDummy{item.target.vertex, source_side[k], source_side_at[k]});
        sequence.push_back(-1 - item.target.vertex);
      }
    }
    if (!st.closed) sequence.push_back(st.vertices.back());
    const std::size_t count = st.closed ? sequence.size() : sequence.size() - 1;
    for (std::size_t k = 0; k < count; ++k) chain_edges.push_back({sequence[k], sequence[(k + 1) % sequence.size()]});
  }
  // Dummies numbered in target order after the source's vertices.
  std::sort(dummies.begin(), dummies.end(),
            [](const PendingDummy& a, const PendingDummy& b) { return a.target_vertex < b.target_vertex; });
  for (const PendingDummy& dummy : dummies) {
    const int index = int(source_positions.size());
    matched_of_target[std::size_t(dummy.target_vertex)] = index;
    source_positions.push_back(dummy.source_position);
    target_positions.push_back(target.vertices[std::size_t(dummy.target_vertex)]);
    result.source_places.push_back(dummy.source_place);
    MatchedPlace place;
    place.vertex = dummy.target_vertex;
    result.target_places.push_back(place);
  }
  for (int v = 0; v < nt; ++v)
    if (matched_of_target[std::size_t(v)] < 0)
      throw InternalError("correspond: target vertex " + std::to_string(v) + " was left unmatched");
  auto resolve = [&](int code) { return code >= 0 ? code : matched_of_target[std::size_t(-1 - code)]; };
  std::vector<std::array<std::int64_t, 2>> edges;
  edges.reserve(chain_edges.size());
  for (const auto& [a, b] : chain_edges) edges.push_back({resolve(a), resolve(b)});

  // The matched figures, validated like any input; then the proof that the
  // pair is compatible (section 2.1), which the construction promises.
  try {
    result.source = make_stick_figure(std::move(source_positions), edges, source.name);
    result.target = make_stick_figure(std::move(target_positions), edges, target.name);
  } catch (const InvalidFigureError& error) {
    throw VerificationError(std::string("correspond: the matched figure cannot be drawn in floating point: ") +
                            error.what() + " (vertices of one drawing closer together, or to an edge, than the other's rounding)");
  }
  CompatibilityReport report;
  result.pair = CompatiblePair::try_check(result.source, decompose(result.source), result.target,
                                          decompose(result.target), report);
  if (!result.pair)
    throw InternalError("correspond: the matched figures are not compatible: " + report.reason);
  result.milliseconds = milliseconds_since(start);
  return result;
}

}  // namespace stickmorph::internal
