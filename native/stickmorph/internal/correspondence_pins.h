// Pins of the correspondence: vertex pairs the matching must respect
// (VertexPin, figure_correspondence.h).
//
// Checked before any matching (a bad pin is the caller's mistake whatever
// the figures are) and sorted into node pins, which filter the plane-map
// isomorphisms, and pins inside strokes, which become anchors of a chain
// pair's arc-length map.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "stickmorph/figure_correspondence.h"
#include "stickmorph/internal/correspondence_skeleton.h"
#include "stickmorph/internal/correspondence_track.h"

namespace stickmorph::internal {

/// A pin inside a stroke: the chains it joins and its parameters on them.
struct PinPlace {
  int source_chain = -1, target_chain = -1;
  double u = 0, w = 0;  ///< parameters along the stored tracks
};

/// Checks the pins against the figures (InvalidArgumentError) and sorts them
/// into node pins (source node -> target node) and chain pins.
/// The pins' own rules, before any matching (InvalidArgumentError): each
/// names vertices that exist, pins no vertex twice, and joins vertices of
/// one kind (nodes of the same degree, or two vertices of degree 2).
void check_pins(const std::vector<int>& source_degree, const std::vector<int>& target_degree,
                const std::vector<VertexPin>& pins);

/// check_pins, then node pins (source node -> target node) into
/// `node_pins` and pins inside strokes into `chain_pins`.
void classify_pins(const Skeleton& source, const Skeleton& target, const std::vector<VertexPin>& pins,
                   std::vector<std::pair<int, int>>& node_pins, std::vector<PinPlace>& chain_pins);

/// The parameter map of an open chain pair through its pins, or nothing if
/// the pins on it are out of order in the matched direction.
std::optional<ParameterMap> chain_map(const std::vector<PinPlace>& pins, int source_chain, int target_chain,
                                      bool reversed);

}  // namespace stickmorph::internal
