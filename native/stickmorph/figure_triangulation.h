// Compatible triangulation of two stick figures (Algorithm 3, steps 1-3).
//
// Surazhsky & Gotsman 2001, section 3, Algorithm 3: decompose both figures
// (Algorithm 1), compatibly triangulate each pair of interior faces
// (section 4), enclose both figures in the same convex polygon, cut the
// annulus between the enclosure and the figure into a (weakly simple)
// polygon along a path valid in both figures, compatibly triangulate it, and
// glue everything into one triangulation of the enclosure.
//
// A figure of several parts (issue 14, the paper's future work) is first
// joined into one by bridges valid in both figures (internal/part_bridges.h);
// the bridges are triangulation edges and their bends Steiner vertices, so
// every frame of the morph keeps each part in its face.
#pragma once

#include <array>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// One triangulation of the enclosure, embedded in both figures.
/// Node order (as in ../shared/FORMAT.md): the n figure vertices in input
/// order, then the k enclosure vertices counter-clockwise, then the s Steiner
/// vertices. The enclosure is the triangulation's boundary, convex and the
/// same in both; every figure edge is a triangulation edge.
struct FigureTriangulation {
  int figure_vertices = 0;     ///< n
  int enclosure_vertices = 0;  ///< k
  int steiner_vertices = 0;    ///< s
  std::vector<Vec2> source;    ///< (n+k+s) by 2 positions in the source
  std::vector<Vec2> target;    ///< (n+k+s) by 2 positions in the target
  std::vector<std::array<int, 3>> triangles;  ///< #T by 3, counter-clockwise in both
  int node_count() const { return figure_vertices + enclosure_vertices + steiner_vertices; }
};

struct FigureTriangulationOptions {
  SteinerMethod method = SteinerMethod::Improved;
  int enclosure_sides = 6;  ///< a regular hexagon, as in the paper (section 5)
  int smoothing_rounds = 10;
  /// Rounds of flips legal in both embeddings and Steiner vertices moved
  /// on the glued triangulation, for its smallest angle over both (issue
  /// 30, internal/compatible_improvement.h); 0: the paper's triangulation,
  /// which the barycentric method uses. The rigid method asks for them.
  int improvement_rounds = 0;
  /// With improvement_rounds: Steiner vertices that compatible refinement
  /// may add, as a share of the figure's vertex count (the faces' own
  /// included), and as many again for triangles still below 2 degrees.
  /// 0: none (the barycentric method's). The rigid method asks for 0.4
  /// (internal/rigid_morph_setup.cpp), measured in BENCHMARKS.md.
  double refinement_share = 0;
  /// More points that the enclosure must contain besides both figures'
  /// vertices: the rigid morph's guide sampled over time (issue 12), so
  /// that a figure that reaches further on the way than at either end (a
  /// curve straightening) does not have to fold its triangles out to the
  /// enclosure. Empty for the paper's enclosure.
  std::vector<Vec2> enclosed_points;
};

struct FigureTriangulationStats {
  int interior_faces = 0;
  int cut_bends = 0;           ///< Steiner vertices on the annulus cut
  int interior_steiner = 0;    ///< Steiner vertices inside interior faces
  double min_angle = 0;        ///< radians, over both embeddings
  // Wall-clock milliseconds per stage, for benchmarks (BENCHMARKS.md): they
  // add up to nearly the whole call, so a slow case shows where it goes.
  double decompose_ms = 0;         ///< Algorithm 1 on both figures and the compatibility check
  double cut_ms = 0;               ///< enclosure and annulus cut (step 3)
  double interior_faces_ms = 0;    ///< section 4 on every interior face (step 2)
  double exterior_face_ms = 0;     ///< section 4 on the cut-open exterior (step 3)
  double improve_ms = 0;           ///< flips and smoothing of the glued result (issue 30)
  int flips = 0;                   ///< edges flipped there
  int refinement_steiner = 0;      ///< Steiner vertices added there (compatible refinement)
  double verify_ms = 0;            ///< verify_figure_triangulation of the glued result
  // A figure of several parts (issue 14) is bridged into one first.
  int parts = 1;                   ///< parts of the figure (figure_parts.h)
  int bridges = 0;                 ///< bridges between them: parts - 1
  int bridge_bends = 0;            ///< Steiner vertices on the bridges
  double bridge_ms = 0;            ///< choosing the bridges, checked exactly
};

/// Algorithm 3, steps 1-3, for two compatible figures (vertex i of the
/// source corresponds to vertex i of the target; edge lists may differ in
/// order and direction). The result is verified exactly before it is
/// returned (verify_figure_triangulation).
/// @throws IncompatibleFiguresError, InvalidArgumentError (enclosure_sides
///         below 3), VerificationError naming the face.
FigureTriangulation triangulate_figures(const StickFigure& source, const StickFigure& target,
                                        const FigureTriangulationOptions& options = {},
                                        FigureTriangulationStats* stats = nullptr);

/// Steps 2-3 for a pair already checked (step 1 is the pair's, made once):
/// what the morphs call.
/// @throws InvalidArgumentError (enclosure_sides below 3), VerificationError naming the face.
FigureTriangulation triangulate_figures(const CompatiblePair& pair, const FigureTriangulationOptions& options,
                                        FigureTriangulationStats* stats = nullptr);

/// Exact check of a FigureTriangulation against the source figure's edges:
/// every triangle positive in both embeddings, a disk bounded by the
/// enclosure, full turns around every other node, simplicial, and every
/// figure edge present. Throws VerificationError.
void verify_figure_triangulation(const FigureTriangulation& triangulation, const StickFigure& source);

}  // namespace stickmorph
