#include "stickmorph/morph_stick_figures.h"

#include <chrono>
#include <utility>

#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"

namespace stickmorph {
namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// "--method linear" or "method='linear'", as the caller would have written it.
std::string describe_linear(OptionSpelling spelling) {
  return spelling == OptionSpelling::CommandLine ? "--method linear" : "method='linear'";
}

}  // namespace

MorphMethod parse_morph_method(const std::string& name) {
  if (name == "barycentric") return MorphMethod::Barycentric;
  if (name == "linear") return MorphMethod::Linear;
  throw InvalidArgumentError("unknown morph method '" + name + "' (choose barycentric or linear)");
}

std::string morph_method_name(MorphMethod method) {
  switch (method) {
    case MorphMethod::Barycentric: return "barycentric";
    case MorphMethod::Linear: return "linear";
  }
  throw InternalError("morph_method_name: unknown MorphMethod " + std::to_string(static_cast<int>(method)));
}

void check_morph_options(const MorphStickFiguresOptions& options) {
  check_frames(options.frames, options.spelling);
  if (options.method == MorphMethod::Linear) {
    // The order of the CLI's historical checks, so that the first refused
    // option named is the same as before.
    const std::pair<Option, bool> unused[] = {
        {Option::Verify, options.verify.has_value()},
        {Option::Weights, options.weights.has_value()},
        {Option::Steiner, options.steiner.has_value()},
        {Option::EnclosureSides, options.enclosure_sides.has_value()},
    };
    for (const auto& [option, given] : unused)
      if (given)
        throw InvalidArgumentError(describe_option(option, options.spelling) + " has no effect with " +
                                   describe_linear(options.spelling) +
                                   " (the straight-line morph uses no triangulation)");
    if (options.keep_node_frames)
      throw InvalidArgumentError("node frames do not exist with " + describe_linear(options.spelling) +
                                 " (the straight-line morph uses no triangulation)");
  }
  if (options.enclosure_sides) check_enclosure_sides(*options.enclosure_sides, options.spelling);
}

MorphStickFiguresResult morph_stick_figures(const StickFigure& source, const StickFigure& target,
                                            const MorphStickFiguresOptions& options) {
  check_morph_options(options);
  MorphStickFiguresResult result;
  result.triangulation_options.method = options.steiner.value_or(SteinerMethod::Improved);
  result.triangulation_options.enclosure_sides =
      options.enclosure_sides ? int(*options.enclosure_sides) : kDefaultEnclosureSides;
  result.morph_options.frames = int(options.frames);
  result.morph_options.weights = options.weights.value_or(WeightKind::MeanValue);
  result.morph_options.verify = options.verify.value_or(true);
  MorphStickFiguresStats& stats = result.stats;

  if (options.method == MorphMethod::Linear) {
    // The paper's Figure 8d baseline needs compatible figures like the real
    // morph, so that both refuse the same pairs; its invalid frames are
    // reported, not refused.
    require_compatible(source, target);
    const auto start = std::chrono::steady_clock::now();
    MorphResult linear = linear_morph(source, target, result.morph_options.frames, &stats.invalid_frames);
    stats.morph_ms = milliseconds_since(start);
    stats.solve_ms = linear.stats.solve_ms;
    stats.verify_ms = linear.stats.verify_ms;
    result.times = std::move(linear.times);
    result.frames = std::move(linear.frames);
    return result;
  }

  // Steps 1-4. The options were checked above, and steps 1-3 build the
  // triangulation step 4 morphs, so an InvalidArgumentError from inside is
  // about data the engine made itself: a bug, not the caller's mistake.
  FigureTriangulation triangulation;
  MorphResult morphed;
  try {
    auto start = std::chrono::steady_clock::now();
    triangulation = triangulate_figures(source, target, result.triangulation_options, &stats.triangulation);
    stats.triangulate_ms = milliseconds_since(start);
    start = std::chrono::steady_clock::now();
    morphed = morph_triangulation(triangulation, source, result.morph_options);
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

}  // namespace stickmorph
