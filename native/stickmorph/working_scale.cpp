#include "stickmorph/working_scale.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/frame_verification.h"

namespace stickmorph {
namespace {


// x * 2^exponent is exact: neither x nor the product is subnormal, and the
// product is finite (zero stays zero).
bool scales_exactly(double x, int exponent) {
  if (x == 0) return true;
  const double scaled = std::ldexp(x, exponent);
  return std::isnormal(x) && std::isnormal(scaled) && std::ldexp(scaled, -exponent) == x;
}

std::string ratio_text(double ratio) { return format_double(ratio); }

double largest_magnitude(const std::vector<Vec2>& points) {
  double largest = 0;
  for (const Vec2& p : points) largest = std::max({largest, std::abs(p[0]), std::abs(p[1])});
  return largest;
}

// The exponent for two point sets whose roles name them in the message.
int exponent_for(const std::vector<Vec2>& source, const std::vector<Vec2>& target, const char* what) {
  const double largest = std::max(largest_magnitude(source), largest_magnitude(target));
  if (largest == 0) return 0;
  const int magnitude = std::ilogb(largest);
  if (magnitude >= -kComfortableExponent && magnitude <= kComfortableExponent) return 0;
  if (magnitude < kSmallestMagnitudeExponent)
    throw NumericRangeError("the pair's largest coordinate, " + format_double(largest) +
                            ", is below the smallest magnitude the morph carries, 2^" +
                            std::to_string(kSmallestMagnitudeExponent) + " = " +
                            format_double(std::ldexp(1.0, kSmallestMagnitudeExponent)) +
                            " (positions the morph constructs near 0 would round to subnormal doubles)");
  const int exponent = -magnitude;
  for (const std::vector<Vec2>* points : {&source, &target})
    for (std::size_t v = 0; v < points->size(); ++v)
      for (int c = 0; c < 2; ++c)
        if (!scales_exactly((*points)[v][c], exponent))
          throw NumericRangeError(
              std::string(points == &source ? "source " : "target ") + what + " " + std::to_string(v) +
              " has coordinate " + (c == 0 ? "x" : "y") + " = " + format_double((*points)[v][c]) +
              ", too close to 0 for a pair whose largest coordinate is " + format_double(largest) +
              ": the morph's floating-point stages cannot carry both (nonzero coordinates must be normal "
              "doubles within a factor of 2^1022 of the largest; write 0 for a coordinate that is meant to be 0)");
  return exponent;
}

// A frame that scaling back rounded, verified as it will be written.
void reverify_frame(const StickFigure& source, const Decomposition& source_decomposition,
                    const std::vector<Vec2>& figure, int frame_index, double time) {
  try {
    verify_frame(source, source_decomposition, figure, frame_index, time);
  } catch (const VerificationError& error) {
    throw NumericRangeError(std::string(error.what()) +
                            " once written at the figures' own scale, where its coordinates round below the "
                            "smallest normal double");
  }
}

}  // namespace

bool scale_points(std::vector<Vec2>& points, int exponent) {
  bool exact = true;
  for (Vec2& p : points)
    for (double& c : p) {
      exact = exact && scales_exactly(c, exponent);
      c = std::ldexp(c, exponent);
    }
  return exact;
}

int working_scale_exponent(const std::vector<Vec2>& source, const std::vector<Vec2>& target) {
  return exponent_for(source, target, "node");
}

double figure_size(const StickFigure& figure) {
  Vec2 low = figure.vertices.front(), high = figure.vertices.front();
  for (const Vec2& p : figure.vertices)
    for (int c = 0; c < 2; ++c) {
      low[c] = std::min(low[c], p[c]);
      high[c] = std::max(high[c], p[c]);
    }
  // Halved before subtracting: the sides of a box from -1e100 to 1e100
  // stay finite (and sizes are only compared).
  return 2 * std::max(high[0] / 2 - low[0] / 2, high[1] / 2 - low[1] / 2);
}

int working_scale_exponent(const StickFigure& source, const StickFigure& target) {
  return exponent_for(source.vertices, target.vertices, "vertex");
}

StickFigure scaled_figure(const StickFigure& figure, int exponent) {
  StickFigure scaled = figure;
  // Exact by working_scale_exponent's choice: the same plane graph.
  scale_points(scaled.vertices, exponent);
  return scaled;
}

void check_numeric_range(const StickFigure& source, const StickFigure& target, MorphMethod method) {
  if (method == MorphMethod::Linear) return;
  const bool barycentric = method == MorphMethod::Barycentric;
  const double limit = barycentric ? kMaxBarycentricSizeRatio : kMaxRigidSizeRatio;
  const double source_size = figure_size(source), target_size = figure_size(target);
  if (source_size == 0 || target_size == 0) return;  // a single point: nothing to resolve
  const double ratio = std::max(source_size / target_size, target_size / source_size);
  if (ratio <= limit) return;
  throw NumericRangeError(
      "the source (size " + format_double(source_size) + ") and the target (size " + format_double(target_size) +
      ") differ in size by a factor of " + ratio_text(ratio) + ", beyond the " +
      (barycentric ? "barycentric" : "rigid") + " method's limit of " + ratio_text(limit) +
      (barycentric ? " (in the common enclosure the smaller figure would be too small for its frames to be solved; "
                     "the rigid method takes ratios up to " + ratio_text(kMaxRigidSizeRatio) + ")"
                   : " (the target mapped back onto the source's scale would carry the rounding of the larger)"));
}

void scale_triangulation_back(FigureTriangulation& triangulation, const StickFigure& source, int exponent) {
  if (exponent == 0) return;
  bool exact = scale_points(triangulation.source, -exponent);
  exact = scale_points(triangulation.target, -exponent) && exact;
  if (exact) return;
  try {
    verify_figure_triangulation(triangulation, source);
  } catch (const VerificationError& error) {
    throw NumericRangeError(std::string("the compatible triangulation, once written at the figures' own scale, "
                                        "where its coordinates round below the smallest normal double: ") +
                            error.what());
  }
}

void scale_frame_back(std::vector<Vec2>& positions, int exponent, const StickFigure& source,
                      const Decomposition& source_decomposition, bool verify, int frame_index, double time) {
  if (exponent == 0) return;
  if (scale_points(positions, -exponent) || !verify) return;
  const std::vector<Vec2> figure(positions.begin(),
                                 positions.begin() + std::ptrdiff_t(std::min(positions.size(), source.vertices.size())));
  reverify_frame(source, source_decomposition, figure, frame_index, time);
}

CompatiblePair scaled_pair(const CompatiblePair& pair, int exponent, bool* exact) {
  CompatiblePair scaled = pair;
  // Exact by working_scale_exponent's choice: an angle sum of Algorithm 1
  // is the same for the scaled figure, and so is every orientation.
  const bool source_exact = scale_points(scaled.source_.vertices, exponent);
  const bool target_exact = scale_points(scaled.target_.vertices, exponent);
  if (exact) *exact = source_exact && target_exact;
  return scaled;
}

void scale_result_back(MorphStickFiguresResult& result, const CompatiblePair& pair, int exponent) {
  const StickFigure& source = pair.source();
  if (exponent == 0) return;
  const int back = -exponent;
  std::vector<bool> exact(result.frames.size(), true);
  for (std::size_t f = 0; f < result.frames.size(); ++f) exact[f] = scale_points(result.frames[f], back);
  for (std::vector<Vec2>& nodes : result.node_frames) scale_points(nodes, back);
  MorphStickFiguresStats& stats = result.stats;
  for (Vec2* center : {&stats.similarity.source_center, &stats.similarity.target_center})
    for (double& c : *center) c = std::ldexp(c, back);
  // What rounding touched is checked again as it will be written.
  if (std::find(exact.begin(), exact.end(), false) != exact.end()) {
    for (std::size_t f = 0; f < result.frames.size(); ++f)
      if (!exact[f]) reverify_frame(source, pair.source_decomposition(), result.frames[f], int(f), result.times[f]);
  }
  if (result.triangulation) scale_triangulation_back(*result.triangulation, source, exponent);
}

}  // namespace stickmorph
