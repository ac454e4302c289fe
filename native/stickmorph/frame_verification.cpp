#include "stickmorph/frame_verification.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "stickmorph/compatibility.h"

namespace stickmorph {
namespace {

void check_length(const StickFigure& source, const std::vector<Vec2>& positions) {
  if (positions.size() != source.vertices.size())
    throw InvalidArgumentError("a frame of the figure needs " + std::to_string(source.vertices.size()) +
                               " vertex positions, got " + std::to_string(positions.size()));
}

// The frame as a figure with the source's edges, or the reason it is none.
// make_stick_figure is the engine's exact plane-graph test; reusing it keeps
// one definition of "valid stick figure" (paper, section 1).
std::string frame_defect(const StickFigure& source, const Decomposition& source_decomposition,
                         const std::vector<Vec2>& positions) {
  std::vector<std::array<std::int64_t, 2>> edges;
  edges.reserve(source.edges.size());
  for (const Edge& e : source.edges) edges.push_back({e[0], e[1]});
  StickFigure frame;
  try {
    frame = make_stick_figure(positions, edges);
  } catch (const InvalidFigureError& error) {
    return error.what();
  }
  // Section 2.1: same cyclic sequences and the same exterior sequence. In the
  // report's wording the frame plays the target.
  const CompatibilityReport report =
      check_compatibility(source, source_decomposition, frame, decompose(frame));
  if (!report.compatible()) return "not compatible with the source (the frame is the target): " + report.reason;
  return {};
}

}  // namespace

std::string frame_label(int frame_index, double time) {
  // Four significant digits name the time well enough for a reader; the
  // index is the exact reference.
  char text[32];
  if (std::isfinite(time)) std::snprintf(text, sizeof text, "%.4g", time);
  if (frame_index < 0) return std::string("t = ") + (std::isfinite(time) ? text : "?");
  std::string label = "frame " + std::to_string(frame_index);
  if (std::isfinite(time)) label += std::string(" (t = ") + text + ")";
  return label;
}

void verify_frame(const StickFigure& source, const Decomposition& source_decomposition,
                  const std::vector<Vec2>& positions, int frame_index, double time) {
  check_length(source, positions);
  const std::string defect = frame_defect(source, source_decomposition, positions);
  if (!defect.empty()) throw VerificationError(frame_label(frame_index, time) + ": " + defect);
}

void verify_frame(const StickFigure& source, const std::vector<Vec2>& positions, int frame_index,
                  double time) {
  check_length(source, positions);
  verify_frame(source, decompose(source), positions, frame_index, time);
}

bool is_frame_valid(const StickFigure& source, const Decomposition& source_decomposition,
                    const std::vector<Vec2>& positions) {
  check_length(source, positions);
  return frame_defect(source, source_decomposition, positions).empty();
}

bool is_frame_valid(const StickFigure& source, const std::vector<Vec2>& positions) {
  check_length(source, positions);
  return is_frame_valid(source, decompose(source), positions);
}

}  // namespace stickmorph
