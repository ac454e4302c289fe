// Cleaning a drawing into a stick figure (issue 32).
//
// Surazhsky & Gotsman, "Morphing Stick Figures Using Optimized Compatible
// Triangulations" (2001), section 1, morph *stick figures*: straight-line
// plane graphs whose edges meet only at shared vertices. What people draw is
// not one: a Grease Pencil stroke crosses another without a shared point, a
// hand stops just short of the body it should touch, a pen pause repeats a
// point. This stage turns such a drawing (strokes: polylines of points, or a
// figure's edges) into a valid StickFigure and says what it changed:
//
//  - points closer than the merge distance (tolerance / 100; exact
//    duplicates always) become one vertex, so zero-length edges vanish;
//  - crossings and touchings become shared vertices (T- and X-junctions);
//  - a free stroke end within the tolerance of another stroke, or of a part
//    of its own stroke that is not just behind it, snaps onto it: an end
//    that stopped short, or overshot by less than the tolerance, makes a
//    T-junction; two ends that nearly meet join. A tail that runs along what
//    it snaps to (a ring closed past its start) merges into the junction;
//    a longer overshoot keeps its stub, the crossing makes its junction;
//  - strokes that run along each other (collinear for a length) and a
//    stroke that retraces itself are errors, naming the strokes: there is no
//    one right way to pull them apart.
//
// Every geometric decision (crossing, touching, collinear overlap) uses exact
// predicates (exact_predicates.h); new points (crossings, snap targets) are
// rounded to doubles, so the stage repeats until nothing changes and the
// result goes through make_stick_figure, the same exact check as every
// figure. Nothing is changed silently: every moved or merged input point and
// every junction is one DrawingChange.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// A drawing: strokes over a list of points.
///
/// A Grease Pencil or curve drawing gives each stroke its own points
/// (drawing_from_strokes); a figure (an edge mesh) shares its vertices
/// between edges, one stroke per edge (drawing_from_figure), and its points
/// on no edge stay lone vertices.
struct Drawing {
  std::vector<Vec2> points;               ///< #P by 2
  std::vector<std::vector<int>> strokes;  ///< each a path of point indices
  std::vector<bool> cyclic;               ///< per stroke: a closing edge from last to first
  std::string name;                       ///< carried to the figure
  /// Messages say "edge i (a-b)" and "vertex v" for a figure, "stroke i"
  /// and "point j of stroke i" for strokes.
  bool from_figure = false;
};

/// A drawing of strokes, each #P_i by 2 points in order. No check here:
/// clean_drawing checks everything and names the stroke.
Drawing drawing_from_strokes(const std::vector<std::vector<Vec2>>& strokes, std::vector<bool> cyclic = {},
                             std::string name = {});

/// A figure's vertices and edges as a drawing (stroke i = edge i).
/// @throws InvalidDrawingError for an edge index outside the vertices.
Drawing drawing_from_figure(std::vector<Vec2> vertices, const std::vector<std::array<std::int64_t, 2>>& edges,
                            std::string name = {});

enum class DrawingChangeKind {
  Merge,     ///< a point merged onto a vertex within the merge distance (a duplicate)
  Snap,      ///< a free stroke end moved onto a stroke within the tolerance
  Crossing,  ///< two strokes crossed: a new vertex shared by both
  Touch,     ///< a point lay on another stroke: that stroke now passes through it
};

/// "merge", "snap", "crossing", "touch".
const char* drawing_change_name(DrawingChangeKind kind);

/// One thing clean_drawing did. Indices are the input's: for strokes,
/// `point` is the point's index within `stroke`; for a figure, `stroke` is
/// an edge (-1 for a lone vertex) and `point` a vertex.
struct DrawingChange {
  DrawingChangeKind kind;
  int stroke = -1;        ///< the stroke changed (the one whose point moved, or the first of a crossing)
  int point = -1;         ///< the point that moved or touched; -1 for a crossing
  int other_stroke = -1;  ///< the stroke it joined or crossed; -1 if none (a merge with no stroke)
  Vec2 at{};              ///< the vertex in the cleaned figure where it happened
  double distance = 0;    ///< how far the point moved from where it was drawn (0 for a crossing)
};

struct DrawingCleaningOptions {
  /// Ends this close to a stroke snap onto it; points within tolerance / 100
  /// merge. Default: 1% of the diagonal of the drawing's bounding box. 0
  /// snaps nothing and merges only exact duplicates.
  std::optional<double> tolerance;
};

/// The merge distance that goes with a tolerance.
constexpr double kMergeDistanceFraction = 0.01;
/// The default tolerance as a fraction of the bounding-box diagonal.
constexpr double kDefaultToleranceFraction = 0.01;

/// A drawing cleaned into a stick figure.
///
/// Vertices are numbered in the order of the first input point that became
/// each; vertices made by crossings come after, in the order made.
struct CleanedDrawing {
  StickFigure figure;                            ///< valid (make_stick_figure)
  std::vector<std::vector<int>> stroke_vertices; ///< per stroke, its vertices in order (a cyclic one not repeating its first)
  std::vector<bool> cyclic;                      ///< per stroke
  std::vector<int> point_vertex;                 ///< per input point, the vertex it became
  std::vector<DrawingChange> changes;            ///< in the order made
  double tolerance = 0;                          ///< the tolerance used
  int junctions_made = 0;                        ///< crossings and touches
  int ends_snapped = 0;
  int points_merged = 0;

  /// "2 junctions made, 1 end snapped, 3 points merged", or "no changes".
  std::string summary() const;
};

/// Cleans `drawing` into a stick figure (see the top of this file).
///
/// @throws InvalidDrawingError naming the stroke (and point) for: no
///         strokes, a stroke of fewer than two points or collapsing to one,
///         a coordinate that is not finite or too large, strokes that
///         overlap along a length, a stroke that retraces itself, and a
///         drawing the rounds cannot make valid (naming where);
///         InvalidArgumentError for a tolerance that is negative or not finite.
CleanedDrawing clean_drawing(const Drawing& drawing, const DrawingCleaningOptions& options = {});

/// Throws InternalError unless `cleaned` is a cleaning of `drawing`: a valid
/// figure, every stroke's path made of its edges and every edge on a path,
/// every input point mapped to a vertex, and every point that is not where
/// it was drawn named by a merge or snap change with that distance.
void validate_cleaning(const CleanedDrawing& cleaned, const Drawing& drawing);

/// True iff validate_cleaning would not throw.
bool is_valid(const CleanedDrawing& cleaned, const Drawing& drawing);

}  // namespace stickmorph
