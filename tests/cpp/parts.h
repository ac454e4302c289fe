// Figures of several parts (issue 14) shared by the Catch2 tests.
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph::test {

/// One part: its points, and whether they close into a loop (one point is a
/// lone vertex).
struct PartSpec {
  std::vector<Vec2> points;
  bool closed = true;
};

/// The parts numbered one after the other.
inline StickFigure parts_figure(const std::vector<PartSpec>& parts) {
  std::vector<Vec2> vertices;
  std::vector<std::array<std::int64_t, 2>> edges;
  for (const PartSpec& part : parts) {
    const std::int64_t offset = std::int64_t(vertices.size()), n = std::int64_t(part.points.size());
    vertices.insert(vertices.end(), part.points.begin(), part.points.end());
    if (n < 2) continue;
    for (std::int64_t i = 0; i + 1 < n; ++i) edges.push_back({offset + i, offset + i + 1});
    if (part.closed && n > 2) edges.push_back({offset + n - 1, offset});
  }
  return make_stick_figure(std::move(vertices), edges);
}

/// n points of a circle of radius r round (cx, cy), counter-clockwise from
/// angle `phase`.
inline std::vector<Vec2> circle(double cx, double cy, double r, int n, double phase = 0.0) {
  std::vector<Vec2> points;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * 3.14159265358979323846 * i / n;
    points.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return points;
}

}  // namespace stickmorph::test
