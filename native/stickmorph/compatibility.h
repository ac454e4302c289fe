// Compatibility of two corresponding stick figures.
//
// Surazhsky & Gotsman 2001, section 2.1: two stick figures whose vertices
// correspond by index are compatible when their decompositions (Algorithm 1)
// give isomorphic cyclic sequences under the correspondence, with the same
// orientation, and their exterior sequences correspond too. For connected
// figures on the same edge set this holds exactly when every vertex sees its
// edges in the same cyclic order and the exterior sequences agree.
//
// A figure of several parts (issue 14, figure_parts.h) is compatible when
// this holds for every part and, beyond it, every part lies in the same face
// of every other part in both figures (NestingDiffers otherwise).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stickmorph/decomposition.h"
#include "stickmorph/figure_parts.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// Why two figures are not compatible.
enum class Incompatibility {
  None,                ///< compatible
  VertexCountDiffers,  ///< different numbers of vertices
  EdgeSetDiffers,      ///< an edge of one figure is missing from the other
  MirrorImage,         ///< the target is a reflection of the source
  RotationDiffers,     ///< a vertex sees its edges in another cyclic order
  ExteriorDiffers,     ///< same cyclic sequences, another one is exterior
  NestingDiffers,      ///< a part lies in another face of another part (issue 14)
  // Only from correspond_figures (figure_correspondence.h), for figures that
  // do not correspond by index.
  TopologyDiffers,     ///< no matching of the skeletons: loops, ends, junction degrees or their arrangement differ
  PinsUnsatisfiable,   ///< the figures match, but no matching respects every pin
};

/// The answer of check_compatibility, with a reason naming vertices.
struct CompatibilityReport {
  Incompatibility kind = Incompatibility::None;
  std::string reason;        ///< empty when compatible
  std::vector<int> vertices; ///< vertices named in the reason
  bool compatible() const { return kind == Incompatibility::None; }
};

/// The undirected edges (i < j, sorted) that only one of two edge lists
/// has. Section 2.1 compares figures whose vertices correspond, so their
/// edges must be the same set: check_compatibility's first test, and the
/// Blender add-on's early message (stickmorph.edge_set_difference).
struct EdgeSetDifference {
  std::vector<Edge> only_in_source, only_in_target;
  bool empty() const { return only_in_source.empty() && only_in_target.empty(); }
};
EdgeSetDifference edge_set_difference(const std::vector<Edge>& source, const std::vector<Edge>& target);

/// Decides compatibility of two valid figures whose vertices correspond by
/// index. Edge order and direction in the two edge lists may differ.
CompatibilityReport check_compatibility(const StickFigure& source, const StickFigure& target);

/// As above, reusing decompositions already computed for the two figures.
CompatibilityReport check_compatibility(const StickFigure& source, const Decomposition& source_dec,
                                        const StickFigure& target, const Decomposition& target_dec);

/// Throws IncompatibleFiguresError with the report's reason unless compatible.
void require_compatible(const StickFigure& source, const StickFigure& target);

/// A pair of stick figures proven compatible (section 2.1), holding the
/// decompositions (Algorithm 1) that proved it. It is what the stages after
/// the boundary take (triangulate_figures, the morphs): made once per morph,
/// it carries the proof, so that no later stage decomposes or checks the
/// pair again and none can be handed an unchecked one. Only `check` makes
/// one from figures; scaled_pair (working_scale.h) makes the same pair
/// multiplied by a power of two, exactly, which keeps the proof.
class CompatiblePair {
 public:
  /// Decomposes both figures and checks them.
  /// @throws IncompatibleFiguresError naming the vertices, as check_compatibility says.
  static CompatiblePair check(StickFigure source, StickFigure target);
  /// The same with decompositions already made of these figures.
  static CompatiblePair check(StickFigure source, Decomposition source_dec, StickFigure target,
                              Decomposition target_dec);
  /// The same for a caller that words the refusal itself (the
  /// correspondence, whose pair is compatible by construction): nothing and
  /// `report` says why, or the pair.
  static std::optional<CompatiblePair> try_check(StickFigure source, Decomposition source_dec, StickFigure target,
                                                 Decomposition target_dec, CompatibilityReport& report);

  const StickFigure& source() const { return source_; }
  const StickFigure& target() const { return target_; }
  const Decomposition& source_decomposition() const { return source_dec_; }
  const Decomposition& target_decomposition() const { return target_dec_; }
  /// The number of parts (figure_parts.h), the same in both.
  int parts() const { return figure_parts_.count(); }
  /// The parts, the same in both figures (same edges).
  const FigureParts& figure_parts() const { return figure_parts_; }
  /// How the source's parts nest (part_nesting), as the check compared it
  /// with the target's: the same faces, by compatibility.
  const PartNesting& source_nesting() const { return source_nesting_; }

 private:
  CompatiblePair() = default;
  friend CompatiblePair scaled_pair(const CompatiblePair& pair, int exponent, bool* exact);
  StickFigure source_, target_;
  Decomposition source_dec_, target_dec_;
  FigureParts figure_parts_;
  PartNesting source_nesting_;
};

}  // namespace stickmorph
