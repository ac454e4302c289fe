// Steiner vertices placed as rigidly as possible; see
// rigid_steiner_placement.h.
#include "stickmorph/internal/rigid_steiner_placement.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <string>
#include <utility>

#include "stickmorph/errors.h"

namespace stickmorph {
namespace internal {
namespace {

using Matrix2 = std::array<double, 4>;  // row major: a b / c d

constexpr double kTwoPi = 6.283185307179586;

// theta + 2 pi k nearest `reference`.
double nearest_turn(double theta, double reference) {
  return theta + kTwoPi * std::round((reference - theta) / kTwoPi);
}

// Every triangle's angle shifted by whole turns: nearest the mean turn of
// its figure edges, else nearest a neighbour's chosen angle, breadth first.
void choose_whole_turns(const FigureTriangulation& tri, const std::vector<Edge>& edges,
                        const std::vector<double>& turns, std::vector<double>& theta) {
  const std::size_t m = tri.triangles.size();
  auto key = [](int a, int b) { return std::pair<int, int>(std::min(a, b), std::max(a, b)); };
  std::map<std::pair<int, int>, double> edge_turn;
  for (std::size_t e = 0; e < edges.size(); ++e) edge_turn[key(edges[e][0], edges[e][1])] = turns[e];
  std::map<std::pair<int, int>, std::vector<int>> sides;
  std::vector<char> chosen(m, 0);
  std::deque<int> queue;
  for (std::size_t t = 0; t < m; ++t) {
    const auto& tr = tri.triangles[t];
    double sum = 0;
    int count = 0;
    for (int i = 0; i < 3; ++i) {
      const auto side = key(tr[i], tr[(i + 1) % 3]);
      sides[side].push_back(int(t));
      const auto it = edge_turn.find(side);
      if (it == edge_turn.end()) continue;
      sum += it->second;
      ++count;
    }
    if (count == 0) continue;
    theta[t] = nearest_turn(theta[t], sum / count);
    chosen[t] = 1;
    queue.push_back(int(t));
  }
  if (queue.empty() && m > 0) {  // a figure without edges: the principal angles, spread from one
    chosen[0] = 1;
    queue.push_back(0);
  }
  while (!queue.empty()) {
    const int t = queue.front();
    queue.pop_front();
    const auto& tr = tri.triangles[std::size_t(t)];
    for (int i = 0; i < 3; ++i)
      for (int other : sides[key(tr[i], tr[(i + 1) % 3])]) {
        if (chosen[std::size_t(other)]) continue;
        theta[std::size_t(other)] = nearest_turn(theta[std::size_t(other)], theta[std::size_t(t)]);
        chosen[std::size_t(other)] = 1;
        queue.push_back(other);
      }
  }
}

}  // namespace

struct RigidSteinerPlacement::State {
  int first_steiner = 0;
  int steiner = 0;
  // Per triangle: its source area and the gradients of its three hat
  // functions on the source (2-vectors), and its source-to-target map's
  // rotation angle and stretch (polar decomposition A = R(theta) S).
  std::vector<std::array<int, 3>> triangles;
  std::vector<double> area;
  std::vector<std::array<Vec2, 3>> gradient;
  std::vector<double> theta;
  std::vector<Matrix2> stretch;
  Eigen::SparseMatrix<double> known_coupling;  // Steiner rows by all nodes, known columns only
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor;
  bool factorized = false;
};

RigidSteinerPlacement::RigidSteinerPlacement(const FigureTriangulation& tri, const std::vector<Edge>& edges,
                                             const std::vector<double>& turns)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.first_steiner = tri.figure_vertices + tri.enclosure_vertices;
  s.steiner = tri.steiner_vertices;
  if (s.steiner == 0) return;
  s.triangles = tri.triangles;
  const std::size_t m = tri.triangles.size();
  s.area.resize(m);
  s.gradient.resize(m);
  s.theta.resize(m);
  s.stretch.resize(m);
  std::vector<Eigen::Triplet<double>> unknown_part, known_part;
  for (std::size_t t = 0; t < m; ++t) {
    const auto& tr = tri.triangles[t];
    const Vec2 &p0 = tri.source[tr[0]], &p1 = tri.source[tr[1]], &p2 = tri.source[tr[2]];
    const Vec2 &q0 = tri.target[tr[0]], &q1 = tri.target[tr[1]], &q2 = tri.target[tr[2]];
    // Edge matrices E = [p1 - p0, p2 - p0] (columns), F likewise.
    const double e00 = p1[0] - p0[0], e01 = p2[0] - p0[0], e10 = p1[1] - p0[1], e11 = p2[1] - p0[1];
    const double det = e00 * e11 - e01 * e10;  // twice the area, > 0
    s.area[t] = 0.5 * det;
    // Rows of E^-1 are the gradients of the hat functions of nodes 1 and 2;
    // node 0's is minus their sum.
    const Vec2 g1{e11 / det, -e01 / det}, g2{-e10 / det, e00 / det};
    s.gradient[t] = {Vec2{-g1[0] - g2[0], -g1[1] - g2[1]}, g1, g2};
    // A = F E^-1.
    const double f00 = q1[0] - q0[0], f01 = q2[0] - q0[0], f10 = q1[1] - q0[1], f11 = q2[1] - q0[1];
    const double a = f00 * g1[0] + f01 * g2[0], b = f00 * g1[1] + f01 * g2[1];
    const double c = f10 * g1[0] + f11 * g2[0], d = f10 * g1[1] + f11 * g2[1];
    // Polar decomposition of a 2x2 map with positive determinant: the
    // rotation's angle is atan2(c - b, a + d), and S = R^T A is symmetric.
    const double th = std::atan2(c - b, a + d);
    const double cs = std::cos(th), sn = std::sin(th);
    s.theta[t] = th;  // its whole turns below
    s.stretch[t] = {cs * a + sn * c, cs * b + sn * d, -sn * a + cs * c, -sn * b + cs * d};
    for (int i = 0; i < 3; ++i) {
      if (tr[i] < s.first_steiner) continue;
      const int row = tr[i] - s.first_steiner;
      for (int j = 0; j < 3; ++j) {
        const double k = s.area[t] * (s.gradient[t][i][0] * s.gradient[t][j][0] +
                                      s.gradient[t][i][1] * s.gradient[t][j][1]);
        if (tr[j] >= s.first_steiner)
          unknown_part.emplace_back(row, tr[j] - s.first_steiner, k);
        else
          known_part.emplace_back(row, tr[j], k);
      }
    }
  }
  choose_whole_turns(tri, edges, turns, s.theta);
  Eigen::SparseMatrix<double> system(s.steiner, s.steiner);
  system.setFromTriplets(unknown_part.begin(), unknown_part.end());
  s.known_coupling.resize(s.steiner, tri.node_count());
  s.known_coupling.setFromTriplets(known_part.begin(), known_part.end());
  s.factor.compute(system);
  s.factorized = s.factor.info() == Eigen::Success;
}

RigidSteinerPlacement::~RigidSteinerPlacement() = default;
RigidSteinerPlacement::RigidSteinerPlacement(RigidSteinerPlacement&&) noexcept = default;
RigidSteinerPlacement& RigidSteinerPlacement::operator=(RigidSteinerPlacement&&) noexcept = default;

bool RigidSteinerPlacement::place(double u, std::vector<Vec2>& positions) const {
  return place_at([u](std::size_t) { return u; }, positions);
}

bool RigidSteinerPlacement::place(const std::vector<double>& node_times, std::vector<Vec2>& positions) const {
  if (node_times.size() != positions.size())
    throw InternalError("RigidSteinerPlacement::place: " + std::to_string(node_times.size()) + " node times for " +
                        std::to_string(positions.size()) + " nodes");
  const State& s = *state_;
  return place_at(
      [&](std::size_t t) {
        const auto& tr = s.triangles[t];
        return (node_times[std::size_t(tr[0])] + node_times[std::size_t(tr[1])] + node_times[std::size_t(tr[2])]) / 3;
      },
      positions);
}

template <class TriangleTime>
bool RigidSteinerPlacement::place_at(const TriangleTime& time_of, std::vector<Vec2>& positions) const {
  const State& s = *state_;
  if (s.steiner == 0) return true;
  if (!s.factorized) return false;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(s.steiner, 2);
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tr = s.triangles[t];
    const double u = time_of(t);
    // A_t(u) = R(u theta) ((1 - u) I + u S).
    const Matrix2& st = s.stretch[t];
    const double m00 = (1 - u) + u * st[0], m01 = u * st[1], m10 = u * st[2], m11 = (1 - u) + u * st[3];
    const double cs = std::cos(u * s.theta[t]), sn = std::sin(u * s.theta[t]);
    const double a = cs * m00 - sn * m10, b = cs * m01 - sn * m11;
    const double c = sn * m00 + cs * m10, d = sn * m01 + cs * m11;
    // The normal equations' right-hand side: area times the hat function's
    // gradient against each row of A_t(u).
    for (int i = 0; i < 3; ++i) {
      if (tr[i] < s.first_steiner) continue;
      const Vec2& g = s.gradient[t][i];
      const int row = tr[i] - s.first_steiner;
      rhs(row, 0) += s.area[t] * (g[0] * a + g[1] * b);
      rhs(row, 1) += s.area[t] * (g[0] * c + g[1] * d);
    }
  }
  Eigen::MatrixX2d known(positions.size(), 2);
  for (std::size_t v = 0; v < positions.size(); ++v) known.row(Eigen::Index(v)) << positions[v][0], positions[v][1];
  rhs -= s.known_coupling * known;
  const Eigen::MatrixX2d x = s.factor.solve(rhs);
  if (s.factor.info() != Eigen::Success || !x.allFinite()) return false;
  for (int r = 0; r < s.steiner; ++r) positions[std::size_t(s.first_steiner + r)] = {x(r, 0), x(r, 1)};
  return true;
}

}  // namespace internal
}  // namespace stickmorph
