// Corner anchors of the arc-length map (corner_anchors.h; Surazhsky &
// Gotsman 2001, section 6).
#include "stickmorph/internal/corner_anchors.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace stickmorph::internal {

namespace {

// Corners (a turn of at least this many radians at a vertex) are matched to
// corners of the same sense within this share of the stroke, and become
// anchors of the arc-length map: the same letter drawn in two fonts has its
// corners at slightly different arc lengths, and a corner that lands on the
// other drawing's straight edge would round off while its partner corner
// grows beside it. A pair of corners up to kMaxCornerPairs candidates per
// stroke; beyond, arc length alone (the dynamic programme is quadratic).
constexpr double kCornerTurn = 0.7;  // 40 degrees
constexpr double kCornerWindow = 0.08;
constexpr std::size_t kMaxCornerPairs = 4'000'000;

}  // namespace

double turn_at(const StickFigure& figure, const Track& track, std::size_t k) {
  const std::size_t n = track.vertices.size();
  if (!track.closed && (k == 0 || k + 1 == n)) return 0;
  const Vec2& a = figure.vertices[std::size_t(track.vertices[(k + n - 1) % n])];
  const Vec2& b = figure.vertices[std::size_t(track.vertices[k])];
  const Vec2& c = figure.vertices[std::size_t(track.vertices[(k + 1) % n])];
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - b[0], vy = c[1] - b[1];
  return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

void anchor_corners(const StickFigure& source, const Track& s, const StickFigure& target, const Track& t,
                    ChainMatch& match) {
  ParameterMap& map = match.map;
  const bool closed = s.closed;
  const double u0 = closed ? map.u[0] : 0.0, w0 = closed ? map.w[0] : 0.0;
  // Both sides in the common order: x along the source from the map's
  // first anchor, y along the target's run from its image.
  auto x_of = [&](double u) { return closed ? u - u0 - std::floor(u - u0) : u; };
  auto y_of = [&](double w) {  // w: stored target parameter
    const double run = run_parameter(w, match.reversed);
    return closed ? run - w0 - std::floor(run - w0) : run;
  };
  struct Corner {
    double x, y, turn;  // y: the target's own run coordinate (source side: 0)
    double mapped;      // target corners: x of their image under the map
  };
  std::vector<Corner> from_source, from_target;
  for (std::size_t k = 0; k < s.vertices.size(); ++k) {
    const double turn = turn_at(source, s, k);
    if (std::abs(turn) >= kCornerTurn) from_source.push_back({x_of(vertex_parameter(s, k)), 0, turn, 0});
  }
  for (std::size_t k = 0; k < t.vertices.size(); ++k) {
    const double turn = (match.reversed ? -1 : 1) * turn_at(target, t, k);
    if (std::abs(turn) < kCornerTurn) continue;
    const double w = vertex_parameter(t, k);
    from_target.push_back({0, y_of(w), turn, x_of(map.to_source(run_parameter(w, match.reversed)))});
  }
  if (from_source.empty() || from_target.empty() || from_source.size() * from_target.size() > kMaxCornerPairs) return;
  auto by_x = [](const Corner& a, const Corner& b) { return a.x < b.x; };
  auto by_y = [](const Corner& a, const Corner& b) { return a.y < b.y; };
  std::sort(from_source.begin(), from_source.end(), by_x);
  std::sort(from_target.begin(), from_target.end(), by_y);
  const std::size_t ns = from_source.size(), nt = from_target.size();
  auto score = [&](std::size_t i, std::size_t j) {
    const Corner& a = from_source[i];
    const Corner& b = from_target[j];
    if ((a.turn > 0) != (b.turn > 0)) return 0.0;
    const double gap = std::abs(a.x - b.mapped) / kCornerWindow;
    if (gap >= 1) return 0.0;
    return (1 - gap * gap) * std::min(std::abs(a.turn), std::abs(b.turn)) /
           std::max(std::abs(a.turn), std::abs(b.turn));
  };
  // best[i][j]: the best sum over the first i source and j target corners.
  std::vector<double> best((ns + 1) * (nt + 1), 0.0);
  auto at = [&](std::size_t i, std::size_t j) -> double& { return best[i * (nt + 1) + j]; };
  for (std::size_t i = 1; i <= ns; ++i)
    for (std::size_t j = 1; j <= nt; ++j) {
      const double pair = score(i - 1, j - 1);
      at(i, j) = std::max({at(i - 1, j), at(i, j - 1), pair > 0 ? at(i - 1, j - 1) + pair : 0.0});
    }
  std::vector<std::pair<double, double>> corners;  // (x, y), increasing
  for (std::size_t i = ns, j = nt; i > 0 && j > 0;) {
    const double pair = score(i - 1, j - 1);
    if (pair > 0 && at(i, j) == at(i - 1, j - 1) + pair) {
      corners.emplace_back(from_source[i - 1].x, from_target[j - 1].y);
      --i, --j;
    } else if (at(i, j) == at(i - 1, j)) {
      --i;
    } else {
      --j;
    }
  }
  std::reverse(corners.begin(), corners.end());
  // The anchors there are, in the same coordinates; a loop's first anchor
  // is (0, 0) and its last the first one turn on, (1, 1).
  std::vector<std::pair<double, double>> fixed;
  for (std::size_t k = 0; k < map.u.size(); ++k)
    fixed.emplace_back(x_of(map.u[k]), closed ? map.w[k] - w0 : map.w[k]);
  if (closed) fixed.emplace_back(1.0, 1.0);
  std::vector<std::pair<double, double>> merged = fixed;
  for (const auto& [x, y] : corners) {
    const auto next = std::upper_bound(fixed.begin(), fixed.end(), std::pair{x, -1.0},
                                       [](const auto& a, const auto& b) { return a.first < b.first; });
    if (next == fixed.begin() || next == fixed.end()) continue;
    const auto& before = *(next - 1);
    // Strictly between its neighbouring fixed anchors in both coordinates;
    // a corner that is itself a pinned vertex is already an anchor.
    if (x > before.first && x < next->first && y > before.second && y < next->second) merged.emplace_back(x, y);
  }
  std::sort(merged.begin(), merged.end());
  if (closed) merged.pop_back();
  ParameterMap result;
  result.closed = closed;
  for (const auto& [x, y] : merged) {
    result.u.push_back(closed ? u0 + x : x);
    result.w.push_back(closed ? w0 + y : y);
  }
  map = std::move(result);
}

}  // namespace stickmorph::internal
