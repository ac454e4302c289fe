// Arc-length resampling of a matched chain pair (step 4 of
// figure_correspondence.h).
//
// Surazhsky & Gotsman 2001, section 6: figures that do not correspond
// vertex by vertex are made to by dummy vertices. Every vertex of either
// chain is kept; a vertex close (in arc length) to one of the other chain is
// matched to it, every other one gets a dummy partner at the same arc length
// under the chain pair's parameter map.
#pragma once

#include <utility>
#include <vector>

#include "stickmorph/internal/correspondence_track.h"

namespace stickmorph::internal {

/// A place on a track: a vertex of it (slot k) or a dummy at parameter p.
struct TrackPlace {
  int vertex = -1;   ///< the figure's vertex, or -1
  double p = 0;      ///< parameter along the stored track
};

/// One matched vertex along a matched chain, in order.
struct MatchedItem {
  double order = 0;  ///< common parameter (the source's), for sorting
  TrackPlace source, target;
};

/// The matched vertices along a chain pair (interior only for a chain, all
/// for a loop), sorted by the source's parameter: every vertex of both
/// tracks exactly once, close pairs merged, the rest given dummy partners.
std::vector<MatchedItem> resample(const Track& s, const Track& t, const ChainMatch& match,
                           const std::vector<std::pair<int, int>>& pinned);

}  // namespace stickmorph::internal
