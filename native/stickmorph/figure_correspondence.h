// Automatic correspondence of two stick figures drawn separately.
//
// Surazhsky & Gotsman 2001, section 6: figures that do not correspond vertex
// by vertex are made to by "dummy vertices". Two figures drawn separately
// differ in vertex count, numbering, edge order and in how their strokes are
// subdivided, but a user who morphs one into the other means the same
// drawing: the same junctions joined by the same strokes. So the figures are
// matched as their skeletons, and the strokes are matched by arc length:
//
//   1. the skeleton of a figure is its vertices of degree != 2 (junctions and
//      ends, the nodes) and the chains of degree-2 vertices between them; a
//      figure with no node is one closed loop;
//   2. the skeletons are matched as plane maps: isomorphisms that keep the
//      counter-clockwise order of the chains around every node and the
//      exterior face (so that the matched figures are compatible in the sense
//      of section 2.1); they are found dart by dart, since an orientation-
//      preserving isomorphism of a connected plane map is fixed by the image
//      of one dart. A pair matched only by reflecting is refused as a mirror
//      image;
//   3. among the isomorphisms the one with the least geometric cost wins: the
//      residual of the best similarity (rotation, scale, translation, never a
//      reflection) between arc-length samples of the matched chains, plus a
//      small charge for the rotation so that a nearly symmetric figure does
//      not spin; near ties go to the smallest rotation. Two loops are matched
//      by the cyclic shift of least cost, both run counter-clockwise;
//   4. every matched chain pair is resampled by arc length, piecewise between
//      anchors: its ends, its pins, and its corners (turns of 40 degrees or
//      more) matched to corners of the other drawing by an order-keeping
//      alignment, so that a letter's corners in one font meet its corners in
//      another. Every vertex of either figure is kept, a vertex close to one
//      of the other figure (under a third of the spacing on both sides) is
//      matched to it, and every other vertex gets a dummy partner on the
//      other figure's edge at the same arc length.
//
// The result is a pair of figures on the same m vertices and edges, the
// source's a subdivision of the source drawing and the target's of the
// target drawing; it is compatible by construction, and is checked to be.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// How the vertices of a pair correspond: by index (the contract's default:
/// vertex i of the source becomes vertex i of the target) or found by
/// correspond_figures.
enum class CorrespondenceMode { ByIndex, Auto };

/// "index", "auto" -> mode. @throws InvalidArgumentError naming the accepted names.
CorrespondenceMode parse_correspondence_mode(const std::string& name);
std::string correspondence_mode_name(CorrespondenceMode mode);

/// A vertex pair that the matching must respect: source vertex `source`
/// becomes target vertex `target`. Both must be nodes of the same degree, or
/// both vertices of degree 2.
struct VertexPin {
  int source = -1;
  int target = -1;
};

/// What breaks the pin rules (correspond_figures refuses it).
enum class PinDefect {
  None,
  MissingSourceVertex,  ///< the source has no such vertex
  MissingTargetVertex,  ///< the target has no such vertex
  SourcePinnedTwice,    ///< a source vertex in two pins
  TargetPinnedTwice,    ///< a target vertex in two pins
  KindsDiffer,          ///< a node (end, junction) and a vertex inside a stroke, or nodes of different degrees
};

/// The first pin that breaks the rules, and why.
struct PinCheck {
  PinDefect defect = PinDefect::None;
  int pin = -1;                               ///< its index in the list
  int source_degree = 0, target_degree = 0;  ///< KindsDiffer: the two vertices' degrees
  std::string reason;                         ///< "pin S:T ...", as correspond's error says it
  bool ok() const { return defect == PinDefect::None; }
};

/// The pin rules, in one place: each pin names a vertex of each figure, no
/// vertex is pinned twice, and a pin joins two ends, two junctions of the
/// same degree or two vertices inside strokes (a skeleton isomorphism maps
/// nodes to nodes of the same degree, section 2.1). `source_degree` and
/// `target_degree` are #V lists of vertex degrees. Pins are checked in
/// order, the first problem reported.
PinCheck check_vertex_pins(const std::vector<int>& source_degree, const std::vector<int>& target_degree,
                           const std::vector<VertexPin>& pins);

/// "3:7" -> {3, 7}. @throws InvalidArgumentError quoting the text.
VertexPin parse_vertex_pin(const std::string& text);

/// One side of a matched vertex: an original vertex of that figure, or a
/// dummy on one of its edges.
struct MatchedPlace {
  int vertex = -1;       ///< the figure's vertex, or -1 for a dummy
  int edge = -1;         ///< dummy: the figure's edge it lies on; -1 for a vertex
  double fraction = 0;   ///< dummy: along edges[edge] from its first vertex to its second, in (0, 1)
};

/// What correspond_figures found.
struct FigureCorrespondence {
  /// The matched figure on the source drawing and on the target drawing:
  /// the same m vertices (by index) and the same edges. Vertices 0..n-1 are
  /// the source's n vertices in order; then come the dummies on source
  /// edges, one per target vertex with no source partner, in target order.
  StickFigure source;
  StickFigure target;
  /// #m: where each matched vertex is in the source and in the target.
  std::vector<MatchedPlace> source_places;
  std::vector<MatchedPlace> target_places;
  // How the match was found.
  int skeleton_nodes = 0;      ///< nodes (degree != 2) of each figure; 0 for a loop
  int skeleton_chains = 0;     ///< chains between them; 1 for a loop
  int candidates = 0;          ///< isomorphisms (or loop shifts) whose cost was compared
  double residual = 0;         ///< the winner's similarity residual in [0, 1]; 0 is a perfect fit
  double rotation_degrees = 0; ///< the winner's best-fit rotation, counter-clockwise
  double milliseconds = 0;     ///< wall-clock time of the match
  /// source and target as checked at the end of the match (section 2.1):
  /// morph_stick_figures morphs this pair rather than checking it again.
  std::optional<CompatiblePair> pair;
};

/// What the matching must respect.
struct CorrespondenceOptions {
  std::vector<VertexPin> pins;
};

/// Matches two valid figures (make_stick_figure) and builds the matched pair.
///
/// @throws InvalidArgumentError: a pin names a vertex that does not exist,
///         pins one vertex twice, or joins vertices of different kinds (a
///         node and a degree-2 vertex, or nodes of different degrees);
///         IncompatibleFiguresError: the topologies cannot be matched, saying
///         what differs (kind TopologyDiffers: loops, ends, junction
///         degrees, the arrangement of the chains; MirrorImage; ExteriorDiffers;
///         PinsUnsatisfiable: no matching respects every pin);
///         VerificationError if the matched figure is not valid in floating
///         point (a nearly degenerate drawing: vertices of one figure closer
///         together than the other figure's edges can resolve, after the
///         dummies of a merged run were spread along their edge);
///         InternalError if the matched pair is valid but not compatible
///         (a bug).
FigureCorrespondence correspond_figures(const StickFigure& source, const StickFigure& target,
                                        const CorrespondenceOptions& options = {});

/// True iff `correspondence` is a matching of `source` and `target`: every
/// source vertex and every target vertex appears exactly once, an original
/// vertex is at its exact position, a dummy at the rounded point
/// a + fraction (b - a) of its edge (a, b), the matched figures are valid,
/// share their edges, and every matched edge lies on one original edge
/// (the matched figures subdivide the drawings).
bool is_valid(const FigureCorrespondence& correspondence, const StickFigure& source, const StickFigure& target);

}  // namespace stickmorph
