// Keys drawn separately, matched onto one common figure (issue 28,
// `--correspond auto` with key poses).
//
// The pair matching (figure_correspondence.h, the paper's section 6) makes
// a pair compatible by subdividing both drawings: every vertex of one gets a
// partner, an original vertex or a dummy on an edge of the other. A
// sequence chains it: the common figure starts as key 1; matching it, as
// drawn on key k, with key k + 1 adds dummies on its edges for the vertices
// of key k + 1 it lacks, and places its vertices on key k + 1's drawing.
// Those new dummies lie on edges of the common figure, which are pieces of
// edges of every earlier key too, so each earlier key gets them at the same
// fraction of the same edge: a subdivision of a drawing is the same drawing
// (Section 2.1), and every key stays a subdivision of its own drawing.
//
// Every key vertex is a vertex of the common figure, at its exact position;
// each matched key is validated again (make_stick_figure) after the last
// dummies were placed on it.
#pragma once

#include <vector>

#include "stickmorph/figure_correspondence.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

struct KeyPoseCorrespondenceOptions {
  /// Per consecutive pair (empty, or one list per pair: keys k and k + 1,
  /// each pin in those keys' own vertex numbers): vertices that must match.
  std::vector<std::vector<VertexPin>> pins;
};

/// The keys on one common figure of m vertices.
struct KeyPoseCorrespondence {
  /// K figures on the same m vertices and edges: key k's drawing, subdivided.
  std::vector<StickFigure> keys;
  /// #K by #m: where common vertex i is on key k's own drawing, as the pair
  /// matching says it (a key vertex, or a dummy on one of the key's own
  /// edges at a fraction of it).
  std::vector<std::vector<MatchedPlace>> places;
  /// Per consecutive pair, how its match was found (candidates, residual,
  /// rotation, time), as correspond_figures reports it; `pair` is not kept.
  std::vector<FigureCorrespondence> matches;
  double milliseconds = 0;  ///< the whole chain's time
};

/// Matches `keys` (K >= 2 valid figures, make_stick_figure) onto one common
/// figure, key 1's vertices first, in order.
/// @throws InvalidArgumentError for fewer than two keys, more pin lists than
///         pairs, or a bad pin (naming the keys); IncompatibleFiguresError
///         naming the two keys that cannot be matched; VerificationError if a
///         matched key is not valid in floating point (naming the key).
KeyPoseCorrespondence correspond_key_poses(const std::vector<StickFigure>& keys,
                                           const KeyPoseCorrespondenceOptions& options = {});

/// True iff `c` matches `keys`: K figures on the same vertices and edges,
/// each valid, each key vertex exactly once at its exact position, each
/// dummy on the key edge its place names, key 1's vertices first in order.
bool is_valid(const KeyPoseCorrespondence& c, const std::vector<StickFigure>& keys);

}  // namespace stickmorph
