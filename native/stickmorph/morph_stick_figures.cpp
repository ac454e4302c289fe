#include "stickmorph/morph_stick_figures.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <utility>

#include "stickmorph/cancellation.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/internal/rigid_morph_setup.h"
#include "stickmorph/working_scale.h"

namespace stickmorph {
namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The rigid morph's set-up on a checked pair (internal/rigid_morph_setup.h),
// following the pair's RigidGuide under the similarity the options ask for.
GuidedMorph prepare_rigid_morph_checked(const CompatiblePair& pair, const MorphStickFiguresOptions& options,
                                        const FigureTriangulationOptions& paper_options, WeightKind weights,
                                        MorphStickFiguresStats& stats) {
  const StickFigure& source = pair.source();
  const StickFigure& target = pair.target();
  const SimilarityMotion similarity =
      fit_similarity(source.vertices, target.vertices, options.rotation.value_or(RotationDirection::Short),
                     int(options.turns.value_or(0)));
  stats.similarity = similarity;
  return internal::prepare_guided_morph(
      pair, similarity,
      [&]() -> std::unique_ptr<const GuideTrajectory> {
        return std::make_unique<const RigidGuide>(source, target.vertices, similarity, options.timing);
      },
      paper_options, weights, options.easing.value_or(Easing::None), stats);
}

void morph_rigidly(const CompatiblePair& pair, const MorphStickFiguresOptions& options,
                   MorphStickFiguresResult& result) {
  MorphStickFiguresStats& stats = result.stats;
  const StickFigure& source = pair.source();
  // The triangulation and the solver's set-up on it are one stage here:
  // internal::prepare_guided_morph does both, with its fallbacks.
  report_stage("triangulate");
  GuidedMorph morph = prepare_rigid_morph_checked(pair, options, result.triangulation_options,
                                                  result.morph_options.weights, stats);
  report_stage("frames", result.morph_options.frames);
  GuidedMorphStats guided;
  const auto start = std::chrono::steady_clock::now();
  MorphResult morphed;
  try {
    morphed = guided_morph(morph, result.morph_options.frames, result.morph_options.verify, &guided,
                           result.morph_options.frame_check);
  } catch (const InvalidArgumentError& error) {
    throw InternalError(std::string("morph_stick_figures: the engine refused its own intermediate result: ") +
                        error.what());
  }
  report_progress(result.morph_options.frames, result.morph_options.frames);
  stats.morph_ms = stats.factorize_ms + milliseconds_since(start);
  stats.solve_ms = morphed.stats.solve_ms;
  stats.verify_ms = morphed.stats.verify_ms;
  stats.refined_frames = guided.refined_frames;
  stats.factorizations = guided.factorizations;
  stats.guide_exact_frames = guided.exact_frames;
  stats.guide_blended_frames = guided.blended_frames;
  stats.guide_barycentric_frames = guided.barycentric_frames;
  const std::size_t n = source.vertices.size();
  for (const std::vector<Vec2>& frame : morphed.frames)
    result.frames.emplace_back(frame.begin(), frame.begin() + static_cast<std::ptrdiff_t>(n));
  if (options.keep_node_frames) result.node_frames = std::move(morphed.frames);
  result.times = std::move(morphed.times);
  result.triangulation = morph.triangulation();
}

}  // namespace

MorphMethod parse_morph_method(const std::string& name) {
  if (name == "rigid") return MorphMethod::Rigid;
  if (name == "barycentric") return MorphMethod::Barycentric;
  if (name == "linear") return MorphMethod::Linear;
  throw InvalidArgumentError("unknown morph method '" + name + "' (choose rigid, barycentric or linear)");
}

std::string morph_method_name(MorphMethod method) {
  switch (method) {
    case MorphMethod::Rigid: return "rigid";
    case MorphMethod::Barycentric: return "barycentric";
    case MorphMethod::Linear: return "linear";
  }
  throw InternalError("morph_method_name: unknown MorphMethod " + std::to_string(static_cast<int>(method)));
}

GuidedMorph prepare_rigid_morph(const StickFigure& source, const StickFigure& target,
                                const MorphStickFiguresOptions& options, MorphStickFiguresStats* stats) {
  if (options.method != MorphMethod::Rigid)
    throw InvalidArgumentError("prepare_rigid_morph is the rigid method's; method is " +
                               morph_method_name(options.method));
  check_morph_options(options);
  if (options.correspond != CorrespondenceMode::ByIndex)
    throw InvalidArgumentError("prepare_rigid_morph takes figures that correspond by index: match them with "
                               "correspond_figures first and pass its source and target");
  check_numeric_range(source, target, MorphMethod::Rigid);
  if (options.timing) options.timing->check_vertex_count(source.vertices.size());
  const CompatiblePair pair = CompatiblePair::check(source, target);
  FigureTriangulationOptions paper;
  paper.method = options.steiner.value_or(SteinerMethod::Improved);
  paper.enclosure_sides = options.enclosure_sides ? int(*options.enclosure_sides) : kDefaultEnclosureSides;
  MorphStickFiguresStats measured;
  GuidedMorph morph = prepare_rigid_morph_checked(pair, options, paper,
                                                  options.weights.value_or(WeightKind::MeanValue), measured);
  if (stats) *stats = measured;
  return morph;
}

namespace {

// Steps 2-5 on a checked pair, at the scale it is given in; options
// already checked. Rigid and barycentric only.
// A result with the options in effect, defaults filled in, and the parts.
MorphStickFiguresResult initial_result(const CompatiblePair& pair, const MorphStickFiguresOptions& options) {
  MorphStickFiguresResult result;
  result.triangulation_options.method = options.steiner.value_or(SteinerMethod::Improved);
  result.triangulation_options.enclosure_sides =
      options.enclosure_sides ? int(*options.enclosure_sides) : kDefaultEnclosureSides;
  result.morph_options.frames = int(options.frames);
  result.morph_options.weights = options.weights.value_or(WeightKind::MeanValue);
  result.morph_options.verify = options.verify.value_or(true);
  result.morph_options.frame_check = options.frame_check.value_or(FrameCheck::Certificate);
  result.stats.triangulation.parts = pair.parts();
  return result;
}

MorphStickFiguresResult morph_at_scale(const CompatiblePair& pair, const MorphStickFiguresOptions& options) {
  const StickFigure& source = pair.source();
  MorphStickFiguresResult result = initial_result(pair, options);
  MorphStickFiguresStats& stats = result.stats;

  if (options.method == MorphMethod::Rigid) {
    morph_rigidly(pair, options, result);
    return result;
  }

  // Steps 1-4. The options were checked above, and steps 1-3 build the
  // triangulation step 4 morphs, so an InvalidArgumentError from inside is
  // about data the engine made itself: a bug, not the caller's mistake.
  FigureTriangulation triangulation;
  MorphResult morphed;
  try {
    report_stage("triangulate");
    auto start = std::chrono::steady_clock::now();
    triangulation = triangulate_figures(pair, result.triangulation_options, &stats.triangulation);
    stats.triangulate_ms = milliseconds_since(start);
    report_stage("frames", result.morph_options.frames);
    start = std::chrono::steady_clock::now();
    morphed = morph_triangulation(triangulation, source, pair.source_decomposition(), result.morph_options);
    stats.morph_ms = milliseconds_since(start);
  } catch (const InvalidArgumentError& error) {
    throw InternalError(std::string("morph_stick_figures: the engine refused its own intermediate result: ") +
                        error.what());
  }
  stats.steiner_vertices = triangulation.steiner_vertices;
  stats.triangles = int(triangulation.triangles.size());
  stats.factorize_ms = morphed.stats.factorize_ms;
  stats.solve_ms = morphed.stats.solve_ms;
  stats.verify_ms = morphed.stats.verify_ms;
  stats.refined_frames = morphed.stats.refined_frames;
  stats.factorizations = morphed.stats.factorizations;

  // Step 5: the enclosure and the Steiner vertices were only scaffolding;
  // the figure's n vertices come first in every frame.
  const std::size_t n = source.vertices.size();
  result.frames.reserve(morphed.frames.size());
  for (const std::vector<Vec2>& frame : morphed.frames) {
    if (frame.size() < n)
      throw InternalError("morph_stick_figures: a morph frame holds " + std::to_string(frame.size()) +
                          " positions, fewer than the figure's " + std::to_string(n) + " vertices");
    result.frames.emplace_back(frame.begin(), frame.begin() + static_cast<std::ptrdiff_t>(n));
  }
  if (options.keep_node_frames) result.node_frames = std::move(morphed.frames);
  result.times = std::move(morphed.times);
  result.triangulation = std::move(triangulation);
  return result;
}

// Algorithm 3 on a pair that corresponds by index: the pair checked once
// (validation is the figures', Algorithm 1 and compatibility the
// CompatiblePair's), then morph_at_scale in the working scale
// (working_scale.h): pairs beyond the numeric stages' comfortable range
// are morphed multiplied by an exact power of two, and the results
// multiplied back. The straight-line morph has no numeric stage to
// protect: its frames are verified as they are.
MorphStickFiguresResult morph_corresponding(const CompatiblePair& pair, const MorphStickFiguresOptions& options) {
  const StickFigure& source = pair.source();
  const StickFigure& target = pair.target();
  if (options.method == MorphMethod::Linear) {
    // The paper's Figure 8d baseline needs compatible figures like the real
    // morph, so that both refuse the same pairs; its invalid frames are
    // reported, not refused.
    MorphStickFiguresResult result = initial_result(pair, options);
    MorphStickFiguresStats& stats = result.stats;
    report_stage("frames", result.morph_options.frames);
    const auto start = std::chrono::steady_clock::now();
    MorphResult linear = linear_morph(source, target, result.morph_options.frames, &stats.invalid_frames,
                                      &pair.source_decomposition());
    stats.morph_ms = milliseconds_since(start);
    stats.solve_ms = linear.stats.solve_ms;
    stats.verify_ms = linear.stats.verify_ms;
    result.times = std::move(linear.times);
    result.frames = std::move(linear.frames);
    return result;
  }
  check_numeric_range(source, target, options.method);
  const int exponent = working_scale_exponent(source, target);
  if (exponent == 0) return morph_at_scale(pair, options);
  MorphStickFiguresResult result = morph_at_scale(scaled_pair(pair, exponent), options);
  scale_result_back(result, pair, exponent);
  return result;
}

}  // namespace

MorphStickFiguresResult morph_stick_figures(const StickFigure& source, const StickFigure& target,
                                            const MorphStickFiguresOptions& options) {
  check_morph_options(options);
  if (options.timing) options.timing->check_vertex_count(source.vertices.size());
  report_stage("check");
  if (options.correspond == CorrespondenceMode::ByIndex)
    return morph_corresponding(CompatiblePair::check(source, target), options);
  report_stage("correspond");
  CorrespondenceOptions matching;
  matching.pins = options.pins;
  FigureCorrespondence correspondence = correspond_figures(source, target, matching);
  // The match ends with the check of the matched pair; it is not run again.
  // That pair must be the matched figures as returned, at their own scale.
  if (correspondence.pair && (correspondence.pair->source().vertices != correspondence.source.vertices ||
                              correspondence.pair->target().vertices != correspondence.target.vertices))
    throw InternalError("morph_stick_figures: the correspondence's checked pair is not its matched figures");
  // The delay weights are the source's; a dummy on a source edge takes
  // the weight interpolated along it.
  MorphStickFiguresOptions matched_options = options;
  if (options.timing)
    matched_options.timing = options.timing->on_matched_figure(correspondence.source_places, source.edges);
  MorphStickFiguresResult result = morph_corresponding(
      correspondence.pair ? *correspondence.pair : CompatiblePair::check(correspondence.source, correspondence.target),
      matched_options);
  result.stats.correspond_ms = correspondence.milliseconds;
  result.correspondence = std::move(correspondence);
  return result;
}

}  // namespace stickmorph
