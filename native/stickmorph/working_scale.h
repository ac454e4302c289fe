// The numeric range of a morph: which pairs the floating-point stages can
// carry, and the exact change of scale that brings every other pair the
// reader accepts into their comfortable range (docs/FORMAT.md, "Numeric
// range"; issue 26).
//
// The exact stages (validation, Algorithm 1's rotation system, every
// verification) decide on the given doubles at any magnitude. The numeric
// stages do not: Steiner positions, the enclosure, mean value weights and
// the linear solves square lengths and compare residuals, which underflow
// below about 1e-150 and overflow above 1e150, and an enclosure around a
// figure of size 1e99 leaves the reader's range. So the morph runs on both
// figures multiplied by one power of two 2^k that brings the pair's
// largest coordinate near 1, and multiplies its results by 2^-k.
//
// Why that is sound: multiplying doubles by a power of two is exact as long
// as nothing becomes subnormal, infinite or zero (IEEE 754), so the scaled
// figures are the same plane graphs with the same rotation systems (every
// orientation predicate has the same sign), and a result verified in the
// working scale is verified at the figures' own scale wherever scaling back
// was exact. Where it was not (a value so close to 0 that it becomes
// subnormal), the frame or triangulation is verified again as written.
//
// What no change of scale fixes is a ratio: a source and a target whose
// sizes differ by R place the smaller figure at 1/R of the common
// enclosure in the barycentric morph, and its solve cannot resolve it.
// Those pairs are refused before any work (NumericRangeError).
#pragma once

#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/morph_stick_figures.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// Pairs whose largest coordinate magnitude lies in [2^-kComfortableExponent,
/// 2^kComfortableExponent] are morphed at their own scale, bit for bit as
/// before; others in the working scale.
constexpr int kComfortableExponent = 64;

/// The largest ratio of the two figures' sizes (the larger side of each
/// bounding box) that each method accepts. The barycentric method places
/// both figures in one common enclosure, so the smaller spans 1/R of it and
/// its frames must be solved to that much more precision: on the 18 test
/// pairs every ratio up to 1e6 morphs (and 1e7 is where the first fail).
/// The rigid method factors the ratio out with its similarity, but the
/// target mapped back by it carries the rounding of the larger scale: every
/// pair morphs up to 1e16, the first fails at 1e18 (the polyline), so 1e12
/// keeps a margin of 1e4. The straight-line morph takes any ratio.
/// tests/python/test_numeric_range.py tests both sides of each limit.
constexpr double kMaxBarycentricSizeRatio = 1e6;
constexpr double kMaxRigidSizeRatio = 1e12;

/// The smallest largest-coordinate a pair may have: 2^-900, about 1.2e-271.
/// The morph's constructions put nodes at rounding noise from 0 (1e-16 of
/// the figure's size, and less); below this, multiplying them back would
/// make them subnormal, with too few digits left for the exact checks to
/// pass (a triangulation of letter A at 1e-300 was refused so).
constexpr int kSmallestMagnitudeExponent = -900;

/// The exponent k of the working scale 2^k for the pair: 0 when the pair is
/// in the comfortable range.
/// @throws NumericRangeError when the pair's largest coordinate is nonzero
///         and below 2^kSmallestMagnitudeExponent.
/// @throws NumericRangeError when the pair is not and scaling some nonzero
///         coordinate would not be exact: it is subnormal, or more than
///         2^1022 times smaller than the pair's largest coordinate.
int working_scale_exponent(const StickFigure& source, const StickFigure& target);

/// The same for any two point sets (a triangulation's source and target
/// nodes), with the same exception.
int working_scale_exponent(const std::vector<Vec2>& source, const std::vector<Vec2>& target);

/// Multiplies every coordinate by 2^exponent; returns whether every product
/// was exact.
bool scale_points(std::vector<Vec2>& points, int exponent);

/// The figure with every coordinate multiplied by 2^exponent, which
/// working_scale_exponent made exact: the same stick figure, not checked again.
StickFigure scaled_figure(const StickFigure& figure, int exponent);

/// The checked pair with both figures multiplied by 2^exponent, exactly (as
/// scaled_figure): the same plane graphs, so the decompositions and the
/// proof of compatibility carry over unchanged. Going back from the working
/// scale (a pair matched there) may round a coordinate near 0: `exact`, if
/// given, says whether every product was exact, and only then is the result
/// the same checked pair.
CompatiblePair scaled_pair(const CompatiblePair& pair, int exponent, bool* exact = nullptr);

/// The larger side of the figure's bounding box (0 for a single point).
double figure_size(const StickFigure& figure);

/// Refuses, before any work, a pair that `method` cannot morph for its
/// numbers alone.
/// @throws NumericRangeError naming both sizes, their ratio and the limit.
void check_numeric_range(const StickFigure& source, const StickFigure& target, MorphMethod method);

/// Multiplies the triangulation's node positions by 2^-exponent, and
/// verifies it again (verify_figure_triangulation) if that was not exact.
/// @throws NumericRangeError if it is then no longer valid.
void scale_triangulation_back(FigureTriangulation& triangulation, const StickFigure& source, int exponent);

/// A frame's positions (the figure's first) multiplied by 2^-exponent, and
/// verified again as written (verify_frame against `source`) if that was
/// not exact and `verify` is set.
/// @throws NumericRangeError if it is then no longer valid.
void scale_frame_back(std::vector<Vec2>& positions, int exponent, const StickFigure& source,
                      const Decomposition& source_decomposition, bool verify, int frame_index, double time);

/// Multiplies every position in `result` (frames, node frames, the
/// triangulation, the similarity's centres) by 2^-exponent, and verifies
/// again in exact arithmetic, as written, each frame and the triangulation
/// where that was not exact.
/// @throws NumericRangeError if such a frame or the triangulation is no
///         longer valid at the figures' own scale.
void scale_result_back(MorphStickFiguresResult& result, const CompatiblePair& pair, int exponent);

}  // namespace stickmorph
