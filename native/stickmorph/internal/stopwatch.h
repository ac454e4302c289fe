// Wall-clock milliseconds for the per-stage timings that the engine reports
// (FigureTriangulationStats, MorphStats, MorphSolverStats; BENCHMARKS.md).
// Timings never influence a result.
#pragma once

#include <chrono>

namespace stickmorph::internal {

using Clock = std::chrono::steady_clock;

/// Milliseconds since `start`.
inline double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace stickmorph::internal
