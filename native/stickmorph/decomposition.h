// Decomposition of a stick figure into cyclic sequences (Algorithm 1).
//
// Surazhsky & Gotsman 2001, section 2.1, Algorithm 1 "Decompose(S)": order the
// edges around each vertex, double every edge into two directed edges
// (darts), and walk each dart to the edge immediately following it in
// clockwise order around its head. Each closed walk is a cyclic sequence; one
// of them bounds the unbounded region (the exterior sequence).
//
// With this rule every interior sequence runs counter-clockwise (its region
// lies to the left) and the exterior sequence runs clockwise.
#pragma once

#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// Dart (directed edge) numbering: dart 2*e runs edges[e][0] -> edges[e][1],
/// dart 2*e+1 the other way.
inline int dart_edge(int dart) { return dart / 2; }
inline int dart_twin(int dart) { return dart ^ 1; }
int dart_tail(const StickFigure& figure, int dart);
int dart_head(const StickFigure& figure, int dart);

/// The rotation system: for each vertex, its outgoing darts in
/// counter-clockwise angular order, starting from the first direction at or
/// after the positive x axis. Decided by exact predicates.
struct RotationSystem {
  std::vector<std::vector<int>> outgoing_ccw;  ///< #V lists of darts
  std::vector<int> position;  ///< #darts: index of each dart in its tail's list
  std::vector<int> tail;      ///< #darts: vertex each dart leaves

  /// The dart leaving head(d) immediately after twin(d) in clockwise order:
  /// Algorithm 1, line 11.
  int next_in_face(int dart) const;
};

/// One cyclic sequence of Algorithm 1 and the polygon it bounds.
struct CyclicSequence {
  /// Darts in walk order; the region lies to the left of each.
  std::vector<int> darts;
  /// Line 10 of Algorithm 1: vertices[k] is the head of darts[k]. A vertex
  /// repeats where the walk passes it more than once (cut vertices, dangling
  /// edges, trees).
  std::vector<int> vertices;
  /// Sum of the polygon's angles, each the clockwise sweep from the incoming
  /// edge to the outgoing edge, in (0, 2*pi]; 2*pi at the tip of a dangling
  /// edge. Interior sequences sum to pi*(n-2), the exterior to pi*(n+2).
  double angle_sum = 0.0;
  /// True for the sequence bounding the unbounded region.
  bool exterior = false;
};

/// The result of Algorithm 1.
struct Decomposition {
  RotationSystem rotation;
  std::vector<CyclicSequence> sequences;  ///< in order of first unmarked dart
  std::vector<int> sequence_of_dart;      ///< #darts: index into sequences
  /// Index of the exterior sequence of part 0, the one holding vertex 0
  /// (the exterior sequence of a figure of one part).
  int exterior = -1;
  /// #parts: the exterior sequence of each part (figure_parts.h), in the
  /// parts' order. A figure of several parts (issue 14) has one per part;
  /// how the parts nest is figure_parts.h's `part_nesting`.
  std::vector<int> exterior_of_part;
};

/// Orders the darts around each vertex counter-clockwise (exact).
RotationSystem rotation_system(const StickFigure& figure);

/// Algorithm 1. `figure` must be valid (make_stick_figure). A lone vertex
/// (a vertex with no edges) has one exterior sequence with that vertex, no
/// darts and angle_sum 0 (it has no corners to sum). Each part of a figure
/// of several parts is decomposed on its own terms: the sequences are those
/// of its parts, each part with its own exterior sequence (listed after the
/// sequences with darts, the lone vertices' last).
///
/// Interior and exterior are told apart by the paper's angle-sum rule. Each
/// angle's half-turn class (below, at or above pi) is decided by an exact
/// orientation predicate and only its distance from that class boundary is
/// measured in floating point, to a few ulps; the two possible sums differ by
/// 4*pi, far beyond the accumulated rounding, so the classification is exact.
Decomposition decompose(const StickFigure& figure);

/// Checks the combinatorial invariants of a decomposition of `figure`: every
/// dart in exactly one sequence, consecutive darts chained by next_in_face,
/// exactly one exterior sequence per part, and Euler's formula V - E + F = 2P
/// for P parts.
bool is_valid(const Decomposition& decomposition, const StickFigure& figure);

}  // namespace stickmorph
