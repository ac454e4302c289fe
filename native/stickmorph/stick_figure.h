// Geometry model of a stick figure and its validation.
//
// Surazhsky & Gotsman, "Morphing Stick Figures Using Optimized Compatible
// Triangulations", Pacific Graphics 2001, section 1: a stick figure is a
// connected straight-line plane graph. Polylines, polygons, trees,
// triangulations and tilings are all stick figures. Section 6 leaves
// disconnected figures to future work; here (issue 14) a figure may have
// several parts (connected components, a lone vertex included): a dotted i,
// a ring inside a ring. figure_parts.h names them and says how they nest.
//
// Every geometric decision here uses exact predicates
// (CGAL::Exact_predicates_inexact_constructions_kernel), so a figure is
// accepted exactly when it is a valid plane graph in exact arithmetic on the
// given doubles.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "stickmorph/errors.h"

namespace stickmorph {

/// A point or vector in the plane.
using Vec2 = std::array<double, 2>;
/// An undirected edge between two vertex indices.
using Edge = std::array<int, 2>;

/// Coordinates are limited to this magnitude so that every quantity the
/// engine derives from them in floating point (squared lengths, areas,
/// barycentric weights) stays finite. Exact predicates would not need it;
/// the morph's linear algebra does.
constexpr double kMaxCoordinateMagnitude = 1e100;

/// The nodes of a triangulation (the enclosure, Steiner vertices) may reach
/// further than the figure's vertices: the enclosure of a figure near 1e100
/// lies a little beyond it. Squares of this magnitude stay finite.
constexpr double kMaxNodeMagnitude = 1e150;

/// A validated stick figure.
///
/// Invariants (established by make_stick_figure, checked by is_valid):
/// finite coordinates within kMaxCoordinateMagnitude, edge indices in range,
/// no self-loops, no duplicate edges, no coincident vertices, and edges meet
/// only at shared endpoints, within a part and between parts. The graph may
/// have several parts (figure_parts.h). One vertex with no edges, or a single
/// edge, is a valid figure.
struct StickFigure {
  std::vector<Vec2> vertices;  ///< #V by 2 positions
  std::vector<Edge> edges;     ///< #E by 2 vertex indices, as given
  std::string name;            ///< optional label, carried through
};

/// Builds a stick figure and validates it.
///
/// @param vertices  #V by 2 coordinates
/// @param edges     #E by 2 vertex indices; 64-bit so that out-of-range
///                  values from a file or array are reported, not truncated
/// @param name      optional label
/// @throws InvalidFigureError naming the offending vertex and edge indices;
///         the first defect found, in the order of FigureDefect.
StickFigure make_stick_figure(std::vector<Vec2> vertices,
                              const std::vector<std::array<std::int64_t, 2>>& edges,
                              std::string name = {});

/// Throws InvalidFigureError if `figure` breaks an invariant of StickFigure.
void validate(const StickFigure& figure);

/// True iff `figure` satisfies every invariant of StickFigure.
bool is_valid(const StickFigure& figure);

/// Index of the edge joining vertices a and b, or -1. Linear time.
int find_edge(const StickFigure& figure, int a, int b);

/// Human-readable "i (a-b)" naming of edge i, used in messages.
std::string describe_edge(const StickFigure& figure, int edge);
std::string describe_edge_of(const std::vector<Edge>& edges, int edge);

/// Shortest round-trip decimal text of a double (as in the JSON output).
std::string format_double(double value);

}  // namespace stickmorph
