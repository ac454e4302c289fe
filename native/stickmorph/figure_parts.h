// The parts of a stick figure and how they nest (issue 14).
//
// Surazhsky & Gotsman 2001, section 6, leave "arbitrary (disconnected)
// straight line plane figures" to future work. A figure of several parts
// (connected components; a lone vertex is a part) is decomposed part by
// part (Algorithm 1, decomposition.h), and its parts nest: every part lies
// in one face of every other part, either a bounded one (the ring inside a
// ring, the counter of an O) or the other part's exterior. Two figures of
// several parts are compatible when each part is compatible on the paper's
// terms and every part lies in the same face of every other part in both
// (compatibility.h); the morph keeps both (figure_triangulation.h bridges
// the parts into one triangulation).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "stickmorph/decomposition.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// The connected components of a figure. Parts are numbered in the order of
/// their smallest vertex, so part 0 holds vertex 0, and the numbering is the
/// same in two figures on the same edge set.
struct FigureParts {
  std::vector<int> part_of_vertex;         ///< #V: the part of each vertex
  std::vector<std::vector<int>> vertices;  ///< #parts lists of vertices, ascending
  int count() const { return int(vertices.size()); }
};

/// The parts of `figure` (union-find on its edges). Linear time.
FigureParts figure_parts(const StickFigure& figure);
/// The same for any graph on vertex_count vertices (positions play no
/// part): every index of `edges` must be in 0..vertex_count-1.
FigureParts figure_parts(int vertex_count, const std::vector<Edge>& edges);

/// The bounded faces that hold each part.
struct PartNesting {
  /// #parts lists: for part D, every (container part C, sequence index of
  /// C's bounded face that holds D), sorted by C. A part at the top level
  /// (in every other part's exterior) has an empty list.
  std::vector<std::vector<std::pair<int, int>>> enclosing;
  /// #parts: the innermost of those, the face that D lies in directly
  /// (its container part and sequence), -1 and -1 at the top level.
  std::vector<int> parent_part, parent_sequence;
};

/// Which face of every other part each part lies in. `decomposition` is
/// `figure`'s (decompose). Decided exactly: the winding number of a bounded
/// face's walk around a vertex of the other part, with exact orientation
/// predicates; parts do not touch, so the vertex is never on the walk.
PartNesting part_nesting(const StickFigure& figure, const Decomposition& decomposition, const FigureParts& parts);

/// "part 2 (vertices 8, 9, 10, 11)", for messages.
std::string describe_part(const FigureParts& parts, int part);

/// True iff `nesting` is consistent: every enclosing face is a bounded
/// sequence of its container, no part encloses itself, and the parents are
/// the innermost of the enclosing faces.
bool is_valid(const PartNesting& nesting, const Decomposition& decomposition, const FigureParts& parts);

}  // namespace stickmorph
