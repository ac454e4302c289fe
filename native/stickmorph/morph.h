// Morphing a compatible triangulation with a fixed convex boundary
// (Algorithm 3, step 4).
//
// Floater & Gotsman, "How to morph tilings injectively", J. Comput. Appl.
// Math. 101 (1999), the paper's [8], as summarised in Surazhsky & Gotsman
// 2001, section 2.2: a valid triangulation with a convex boundary is
// represented by a row-stochastic matrix W of convex-combination weights
// (every interior node is a positive convex combination of its neighbours,
// Tutte 1963 / Floater 1997), and its geometry is the fixed point
// x = W x with the boundary held in place. Morph in matrix space, not in
// shape space: W(t) = (1 - t) W0 + t W1 is again positive and
// row-stochastic, so by Tutte's theorem the solution of
// (I - W_interior(t)) x = W_boundary(t) x_boundary is a valid triangulation
// with the same connectivity for every t. Step 5 of Algorithm 3 then keeps
// only the figure's edges, so every frame is a stick figure compatible with
// the source.
//
// Node layout (FigureTriangulation, ../shared/FORMAT.md): n figure vertices,
// then k enclosure vertices (the fixed boundary), then s Steiner vertices.
#pragma once

#include <Eigen/SparseCore>
#include <optional>
#include <string>
#include <vector>

#include "stickmorph/figure_triangulation.h"
#include "stickmorph/frame_certificate.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// How each interior node is written as a convex combination of its
/// neighbours. All three reproduce the embedding they are computed from
/// (sum_j w_ij p_j = p_i), which is what makes frame 0 the source and the
/// last frame the target.
enum class WeightKind {
  /// Mean value coordinates (Floater 2003, "Mean value coordinates"):
  /// w_ij ~ (tan(a_{j-1}/2) + tan(a_j/2)) / |p_j - p_i|, a_j the angle at
  /// p_i between p_j and the next neighbour. Positive in a valid
  /// triangulation, smooth in the positions.
  MeanValue,
  /// Tutte's uniform weights 1/deg, made to reproduce the embedding: the
  /// weights nearest to 1/deg (least squares) among those with
  /// sum_j w_ij p_j = p_i and unit sum, blended toward mean value
  /// coordinates just enough to stay positive. Exactly 1/deg at a node that
  /// is the centroid of its neighbours. (Plain 1/deg does not reproduce the
  /// source, so [8] cannot use it: frames would jump away from the source.)
  Uniform,
  /// Floater's shape-preserving weights (Floater 1997, "Parametrization and
  /// smooth approximation of surface triangulations", the weights of [8]):
  /// the average over neighbours l of p_i's barycentric coordinates in the
  /// triangle (p_l, p_r, p_r+1) that the ray from p_l through p_i exits.
  Floater,
};

/// "mvc", "uniform", "floater" -> kind.
/// @throws InvalidArgumentError naming the accepted names.
WeightKind parse_weight_kind(const std::string& name);
std::string weight_kind_name(WeightKind kind);

/// Frames allowed in one morph: every frame stores all node positions.
constexpr int kMaxMorphFrames = 100000;

struct MorphOptions {
  int frames = 50;                          ///< N >= 2: t_f = f / (N - 1), f = 0..N-1
  WeightKind weights = WeightKind::MeanValue;
  /// Verify every frame exactly and refine or refuse frames that fail.
  bool verify = true;
  /// How (frame_certificate.h): the certificate, all triangles
  /// counter-clockwise inside the convex enclosure, which proves the frame
  /// valid in O(T); or Full, the certificate and verify_frame's independent
  /// rebuild of the figure (a stick figure compatible with the source).
  FrameCheck frame_check = FrameCheck::Certificate;
};

/// What the morph measured.
struct MorphStats {
  double factorize_ms = 0;  ///< weights, assembly, symbolic analysis, and any numeric LU
  double solve_ms = 0;      ///< iterative solves, triangular solves and refinement
  double verify_ms = 0;     ///< exact per-frame checks
  int refined_frames = 0;   ///< frames that needed long double refinement
  /// Numeric LU factorizations: the first interior frame, frames the
  /// anchored iteration could not solve quickly, frames that failed the exact
  /// check after an iterative solve. The rest cost a few triangular solves.
  int factorizations = 0;
};

struct MorphResult {
  std::vector<double> times;               ///< N times, 0 first, 1 last
  std::vector<std::vector<Vec2>> frames;   ///< frames[f]: positions at times[f]
  MorphStats stats;
};

/// Morphs a compatible triangulation by [8], N = options.frames frames.
///
/// `triangulation`: nodes as documented on FigureTriangulation; the k
/// enclosure nodes must sit at the same positions in source and target and
/// form a strictly convex counter-clockwise polygon that is the
/// triangulation's boundary; every triangle counter-clockwise in both
/// embeddings. `source`: the figure on the first n nodes (its positions
/// equal triangulation.source[0..n)), whose edges define each frame's figure.
///
/// frames[f] holds all n+k+s node positions. frames[0] and frames[N-1] are
/// exactly triangulation.source and triangulation.target.
///
/// With options.verify, every returned frame has passed (1) an exact
/// orientation test of every triangle and (2) verify_frame on its first n
/// positions; a frame that fails is refined in long double and re-checked.
/// @throws InvalidArgumentError (frames out of [2, kMaxMorphFrames], a
///         malformed or invalid triangulation, a source that does not match
///         it), VerificationError naming the frame index, its time and the
///         triangle or figure defect when refinement does not repair it.
MorphResult morph_triangulation(const FigureTriangulation& triangulation, const StickFigure& source,
                                const MorphOptions& options = {});

/// As above, with decompose(source) already made (a CompatiblePair's), so
/// that the frames are checked against it without decomposing it again.
MorphResult morph_triangulation(const FigureTriangulation& triangulation, const StickFigure& source,
                                const Decomposition& source_decomposition, const MorphOptions& options);

/// The weight matrix of one embedding of `triangulation` (positions: its
/// source or target, node_count() by 2). #nodes by #nodes, row-major; the
/// row of an interior node (figure or Steiner) holds its weights over its
/// neighbours, positive and summing to 1; enclosure rows are empty.
/// @throws InvalidArgumentError as morph_triangulation does for a malformed
///         triangulation or a triangle that is not counter-clockwise in
///         `positions`.
Eigen::SparseMatrix<double, Eigen::RowMajor> barycentric_weights(const FigureTriangulation& triangulation,
                                                                 const std::vector<Vec2>& positions,
                                                                 WeightKind kind);

class MorphSolver;
struct Decomposition;

/// One frame as morph_triangulation makes it, from the solver's state.
struct CheckedFrame {
  std::vector<Vec2> positions;  ///< all n+k+s node positions
  bool refined = false;         ///< the exact check needed long double refinement
  double verify_ms = 0;         ///< time spent in the exact checks
};

/// The frame at time t in [0, 1] the way morph_triangulation computes it,
/// for the morph's frame loop and for scrubbing (stickmorph.MorphSolver):
/// at t = 0 and 1 the inputs themselves (the contract promises them bit for
/// bit), otherwise `solver`'s warm-started solve. With `verify`, the frame's
/// exact check `check`: the certificate (frame_certificate.h: every triangle
/// counter-clockwise, which with the convex enclosure proves the frame a
/// triangulation with the source's connectivity), and with FrameCheck::Full
/// also verify_frame, the figure rebuilt and found a stick figure compatible
/// with the source. A frame that fails is solved directly at t, then refined
/// in long double (rounding can flip a nearly flat triangle that is positive
/// in exact arithmetic, where the theorem of [8] holds), then its Steiner
/// vertices of inverted triangles are moved into their stars' kernels
/// (untangle_steiner_vertices), and only then refused. `frame` names the frame in messages (frame_label; negative: by
/// its time alone); `context` leads every message ("morph: ").
/// @throws VerificationError "<context><frame label>: <defect>".
/// `label_time`, if given, is the time that messages name instead of t
/// (the rigid morph's fallback solves at its morph parameter u, while its
/// frames are named by their animation time).
CheckedFrame checked_morph_frame(MorphSolver& solver, const FigureTriangulation& triangulation,
                                 const StickFigure& source, const Decomposition& source_decomposition,
                                 double t, int frame, bool verify, const std::string& context,
                                 FrameCheck check = FrameCheck::Certificate,
                                 std::optional<double> label_time = std::nullopt);

/// Moves the Steiner vertices (nodes after the figure and the enclosure)
/// of inverted triangles of the frame `positions` into the kernels of their
/// stars, exactly checked (internal/rounding_repair.h's untangle): a frame
/// whose triangles are thinner than doubles resolve, flipped by rounding
/// alone. The figure's and the enclosure's positions are not touched. True
/// (and `positions` changed) iff every triangle is counter-clockwise
/// afterwards; the caller still checks the frame.
bool untangle_steiner_vertices(const FigureTriangulation& triangulation, std::vector<Vec2>& positions);

/// The solve of [8] alone at one time t in [0, 1]: all node positions of
/// (I - W_interior(t)) x = W_boundary(t) x_boundary, without substituting
/// the exact endpoints and without verification. For tests and diagnostics.
std::vector<Vec2> solve_morph_frame(const FigureTriangulation& triangulation, double t,
                                    WeightKind kind = WeightKind::MeanValue);

/// Straight-line interpolation of the n figure vertices: the naive morph of
/// the paper's section 1 and Figure 8d, the baseline that can self-intersect.
/// frames[f] holds n positions; frames[0] and frames[N-1] are exactly the
/// source's and the target's vertices. `source` and `target` need the same
/// number of vertices; the frames use the source's edges.
///
/// @param invalid_frames  if not null, receives the indices of the frames
///        that are not stick figures compatible with the source
///        (is_frame_valid), in increasing order; this function does not
///        fail on them. If null, no frame is checked.
/// @throws InvalidArgumentError (frames out of [2, kMaxMorphFrames],
///         vertex counts differ).
MorphResult linear_morph(const StickFigure& source, const StickFigure& target, int frames,
                         std::vector<int>* invalid_frames = nullptr);

/// As above; `source_decomposition`, if not null, is decompose(source)
/// (a CompatiblePair's), which the frame checks then reuse.
MorphResult linear_morph(const StickFigure& source, const StickFigure& target, int frames,
                         std::vector<int>* invalid_frames, const Decomposition* source_decomposition);

}  // namespace stickmorph
