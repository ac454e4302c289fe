// Orientation-preserving isomorphisms of two skeletons as plane maps
// (step 2 of figure_correspondence.h).
//
// Surazhsky & Gotsman 2001, section 2.1: compatible figures have the same
// counter-clockwise order of edges around every vertex and the same exterior
// face. An isomorphism of the skeletons that keeps both is fixed by the image
// of one dart, so the candidates are found by extending each possible image
// of one seed dart, breadth first.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stickmorph/internal/correspondence_choice.h"
#include "stickmorph/internal/correspondence_pins.h"
#include "stickmorph/internal/correspondence_skeleton.h"

namespace stickmorph::internal {

/// The orientation-preserving isomorphism of the skeletons that sends
/// source dart `seed` to target dart `image`, if there is one: breadth first
/// over the two relations an isomorphism keeps, the next dart around a node
/// and the dart at the far end of a chain. Returns the image of every
/// source dart that leaves a node (-1 elsewhere).
std::optional<std::vector<int>> extend_isomorphism(const Skeleton& source, const Skeleton& target, int seed,
                                                   int image);

/// A source dart on the exterior face that leaves a node.
int exterior_dart(const Skeleton& skeleton);

/// The candidate an isomorphism (the image of every source dart leaving a
/// node) gives, or nothing with `broken` saying which pin it breaks.
std::optional<Candidate> make_candidate(const Skeleton& source, const Skeleton& target, const std::vector<int>& map,
                                        const std::vector<std::pair<int, int>>& node_pins,
                                        const std::vector<PinPlace>& chain_pins, std::string& broken);

/// What search_isomorphisms found.
struct IsomorphismSearch {
  int seed = -1;                 ///< the source dart every isomorphism is extended from
  std::vector<int> images;       ///< its image in each candidate keeping the exterior and the pins
  std::vector<Fit> fits;         ///< and each one's fit (only the winner is rebuilt in full)
  bool any_isomorphism = false;  ///< ignoring the exterior and the pins
  bool any_exterior = false;     ///< keeping the exterior, ignoring the pins
  std::string pin_conflict;      ///< why the first isomorphism keeping the exterior broke the pins
};

// Every orientation-preserving isomorphism is tried, pins or not, so that
// a pair whose pins no matching respects is told apart from a pair that
// matches in no way at all; the pins only filter. Each candidate is scored
// and dropped, so memory stays that of one candidate (a wheel of k spokes
// has k of them).
IsomorphismSearch search_isomorphisms(const Skeleton& source, const Skeleton& target,
                           const std::vector<std::pair<int, int>>& node_pins, const std::vector<PinPlace>& chain_pins,
                           bool with_cost);

}  // namespace stickmorph::internal
