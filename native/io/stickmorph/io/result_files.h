// The files the commands write (docs/FORMAT.md, "The morph file" and "The
// triangulation file"), written here and nowhere else: the CLI gives the
// results and writes the returned text to disk.
#pragma once

#include <string>
#include <vector>

#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/key_pose_morph.h"
#include "stickmorph/io/json.h"
#include "stickmorph/morph.h"
#include "stickmorph/similarity_motion.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// How a morph was made: what the morph file's "triangulation" and "stats"
/// say besides the frames.
/// What the rigid method did (stats.rigid, an extension of FORMAT.md).
struct RigidMotionReport {
  std::string rotation = "short";  ///< the rotation direction asked for
  int turns = 0;                   ///< extra whole turns asked for
  std::string easing = "none";
  SimilarityMotion similarity;     ///< the similarity fitted between source and target
  bool similarity_factored = false;
  int exact_frames = 0;            ///< interior frames that are the rigid guide itself
  int blended_frames = 0;          ///< interior frames following the guide where it is valid
  int barycentric_frames = 0;      ///< interior frames that fell back to the paper's morph
  int refinement_steiner = 0;      ///< Steiner vertices compatible refinement added (issue 30)
};

struct MorphProvenance {
  /// "rigid" (the default), "barycentric" (the paper's morph) or "linear"
  /// (the straight-line baseline, FORMAT.md: --method linear).
  std::string method = "barycentric";
  /// The triangulation the barycentric morph used; null for the linear
  /// baseline, which uses none ("triangulation": null, both counts 0, and
  /// no steiner_method, enclosure_sides, weights or verified).
  const FigureTriangulation* triangulation = nullptr;
  FigureTriangulationOptions triangulation_options;  ///< written with a triangulation
  MorphOptions options;                              ///< weights and verify, written with a triangulation
  /// The barycentric morph's statistics (factorize, solve and verify times,
  /// refined_frames, factorizations); null to leave them out.
  const MorphStats* stats = nullptr;
  /// The linear baseline's self-intersecting frames ("invalid_frames");
  /// null to leave the field out.
  const std::vector<int>* invalid_frames = nullptr;
  /// The rigid method's report; null for the other methods.
  const RigidMotionReport* rigid = nullptr;
  /// --correspond auto: the matching ("correspondence", FORMAT.md, and
  /// stats.correspondence); null for figures that correspond by index.
  const FigureCorrespondence* correspondence = nullptr;
  double correspond_ms = 0;   ///< wall-clock time of the matching, with a correspondence
  double triangulate_ms = 0;  ///< wall-clock time of the triangulation
  double morph_ms = 0;        ///< wall-clock time of the morph
  /// The figure's parts (issue 14), "stats.parts", and the Steiner
  /// vertices on the bridges that joined them, "stats.bridge_vertices".
  int parts = 1;
  int bridge_vertices = 0;
};

/// The morph file: the figure's edges, `times`, the first n positions of
/// every frame (frames[f] may hold more, all triangulation nodes), the
/// triangulation and the stats, pretty-printed, ending with a newline.
/// @throws InvalidArgumentError for a non-finite number (JSON has none).
std::string morph_file_json(const StickFigure& source, const std::vector<double>& times,
                            const std::vector<std::vector<Vec2>>& frames, const MorphProvenance& how);

/// The "correspondence" object: for each matched vertex its source vertex
/// and target vertex (-1 for a dummy), and the edge and fraction a dummy
/// lies at ("source_edge", "source_fraction", ...; an extension).
void write_correspondence(JsonWriter& out, const FigureCorrespondence& correspondence);

/// The file of `stickmorph correspond`: the matched figure on the source
/// and on the target drawing, as figure objects, and the correspondence.
std::string correspondence_file_json(const FigureCorrespondence& correspondence);

/// The triangulation file: the triangulation object on its own,
/// pretty-printed, ending with a newline.
std::string triangulation_file_json(const FigureTriangulation& triangulation);

/// The triangulation object of both files: figure vertices, then the
/// enclosure counter-clockwise, then Steiner vertices.
void write_triangulation(JsonWriter& out, const FigureTriangulation& triangulation);

/// The morph file of a key-pose sequence (docs/FORMAT.md, "Key poses"): the
/// figure's edges, `times`, the frames, "keys" (each key's frame, in input
/// order), "triangulations" (one per segment, each a triangulation object)
/// and the stats: per segment its keys, frames, Steiner vertices,
/// triangles, times and guide frames, and the totals.
/// @throws InvalidArgumentError for a non-finite number (JSON has none).
std::string key_pose_file_json(const StickFigure& first_key, const KeyPoseMorphResult& result, bool verified);

}  // namespace stickmorph
