// Bridges between the parts of a figure (issue 14), so that Algorithm 3
// (paper, section 3) can triangulate a figure of several parts as one.
//
// Surazhsky & Gotsman 2001 triangulate connected figures; section 6 leaves
// disconnected ones to future work. Two compatible figures of several parts
// (figure_parts.h: each part compatible, the parts nested alike) are made
// connected by bridges: paths, valid in both figures, from a corner of one
// part's exterior sequence to a corner of the face it lies in (its parent's
// bounded face, or another part's exterior), the same corners in both
// figures. Each bridge joins two components, so it splits no face; leaving
// both ends inside the same corners in both figures keeps the rotation
// systems equal, so the bridged figures are compatible (and are checked to
// be). Bridges are edges of the triangulation, not of the figure: their
// bends become Steiner vertices (figure_triangulation.h).
//
// A straight bridge valid in both figures is taken when one of the nearest
// corner pairs has it; otherwise each figure routes its own path between
// the two corners (corner_router.h), shortened where a straight shortcut is
// valid, the shorter one padded to as many bends as the other.
#pragma once

#include <optional>

#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::internal {

struct BridgedFigures {
  /// The figures with their bridges: the n figure vertices, then the
  /// bridges' bends (as many in both); the figure's edges in their order,
  /// then the bridges' edges.
  StickFigure source, target;
  /// The same two, checked compatible (exactly, as the construction
  /// promises): what the triangulation of the bridged figure takes.
  std::optional<CompatiblePair> pair;
  int bridges = 0;  ///< number of bridges: parts - 1
  int bends = 0;    ///< vertices added on them
};

/// Bridges the parts of a checked pair, by the parts and nesting its check
/// found. The corners are the source's: compatible figures have the same
/// rotation systems, so a corner (vertex, next, previous) is the same
/// corner in the target.
/// @throws VerificationError if rounding made a bridge invalid in exact
///         arithmetic (the bridged figures are checked exactly).
BridgedFigures bridge_parts(const CompatiblePair& pair);

}  // namespace stickmorph::internal
