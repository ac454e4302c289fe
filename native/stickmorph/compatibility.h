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

#include <string>
#include <vector>

#include "stickmorph/decomposition.h"
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

/// Decides compatibility of two valid figures whose vertices correspond by
/// index. Edge order and direction in the two edge lists may differ.
CompatibilityReport check_compatibility(const StickFigure& source, const StickFigure& target);

/// As above, reusing decompositions already computed for the two figures.
CompatibilityReport check_compatibility(const StickFigure& source, const Decomposition& source_dec,
                                        const StickFigure& target, const Decomposition& target_dec);

/// Throws IncompatibleFiguresError with the report's reason unless compatible.
void require_compatible(const StickFigure& source, const StickFigure& target);

}  // namespace stickmorph
