// Skeleton of a figure for the correspondence: its nodes (vertices of
// degree != 2) and the chains of degree-2 vertices between them, as a plane
// map (step 1 of figure_correspondence.h).
//
// Surazhsky & Gotsman 2001, section 6: two drawings of "the same" figure
// differ in how their strokes are subdivided but not in their junctions and
// ends, so the skeleton, not the vertex list, is what is matched. Also the
// invariants any matching needs (loops, node degrees), compared first so
// that a refusal says what differs in the user's terms.
#pragma once

#include <string>
#include <vector>

#include "stickmorph/decomposition.h"
#include "stickmorph/internal/correspondence_track.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::internal {

/// A figure's skeleton: the nodes (degree != 2) and the chains between them,
/// as a plane map whose darts are the figure darts that leave a node.
struct Skeleton {
  const StickFigure* figure = nullptr;
  Decomposition decomposition;
  std::vector<int> degree;
  std::vector<int> nodes;             ///< vertices of degree != 2, increasing
  std::vector<Track> chains;
  std::vector<int> chain_first;       ///< per chain: the dart leaving vertices[0] into it (-1 for a loop)
  std::vector<int> chain_of_dart;     ///< per figure dart leaving a node: its chain, else -1
  std::vector<char> forward;          ///< per such dart: runs the chain from vertices[0]
  std::vector<int> far_dart;          ///< per such dart: the dart leaving the other end into the chain
  std::vector<int> chain_of_vertex;   ///< per vertex of degree 2: its chain (or 0 for a loop)
  std::vector<int> slot_of_vertex;    ///< per vertex of degree 2: its index in the chain's vertices
  int loops = 0;                      ///< independent cycles, E - V + 1
  /// The rotation (radians) that fits are charged from: 0 for a figure on
  /// its own; for a part of a figure of several, the whole figure's, so that
  /// a symmetric part turns with the rest.
  double reference_rotation = 0;

  bool is_loop() const { return nodes.empty() && !figure->edges.empty(); }
  int dart_count() const { return int(chain_of_dart.size()); }
  bool leaves_node(int dart) const { return chain_of_dart[std::size_t(dart)] >= 0; }
  int node_of(int dart) const { return decomposition.rotation.tail[std::size_t(dart)]; }
  /// The next dart counter-clockwise around the dart's node.
  int ccw_next(int dart) const {
    const RotationSystem& rotation = decomposition.rotation;
    const auto& around = rotation.outgoing_ccw[std::size_t(node_of(dart))];
    return around[std::size_t((rotation.position[std::size_t(dart)] + 1) % int(around.size()))];
  }
};

Skeleton make_skeleton(const StickFigure& figure);

/// "3 vertices", "1 vertex": a count with its noun.
std::string plural(long long count, const char* one, const char* many);

/// Throws IncompatibleFiguresError (TopologyDiffers) saying `what` differs.
[[noreturn]] void topology_differs(const std::string& what);

// The invariants that any matching needs, compared first so that the
// message says what differs in the user's terms.
void compare_invariants(const Skeleton& source, const Skeleton& target);

}  // namespace stickmorph::internal
