// The as-rigid-as-possible trajectory of a stick figure; see rigid_guide.h.
#include "stickmorph/rigid_guide.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "stickmorph/errors.h"
#include "stickmorph/internal/geometry.h"

namespace stickmorph {
namespace {

using internal::kPi;

// Into (-pi, pi].
double wrap_angle(double a) {
  a = std::fmod(a + kPi, 2 * kPi);
  if (a <= 0) a += 2 * kPi;
  return a - kPi;
}

// Samples of the cumulative motion table: fine enough that the inverse,
// piecewise linear, is within a fraction of a percent of even for any frame
// count an animation uses, and cheap (one triangular solve per sample).
constexpr int kMotionSamples = 200;

double ease(double t, Easing easing) {
  if (easing == Easing::InOut) return t * t * (3 - 2 * t);
  return t;
}

// The counter-clockwise angle from direction a to direction b, in [0, 2 pi).
double ccw_angle(const Vec2& a, const Vec2& b) {
  double angle = std::atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]);
  if (angle < 0) angle += 2 * kPi;
  return angle;
}

// Every edge's turn from source to target, made consistent between
// neighbours (Baxter, Barla & Anjyo 2008, "Rigid shape interpolation using
// normal equations", for rotations of adjacent elements): at every joint,
// two edges consecutive round a vertex (the same order in both figures,
// which are compatible) keep their counter-clockwise angle in (0, 360°)
// and interpolate it linearly, so turn_f - turn_e = angle1 - angle0 with
// no multiple of a full turn left to choose. That never folds two edges of
// a joint onto each other (the joint-angle metric of docs/MOTION.md is 0
// on a tree). The constraints determine the turns of a connected figure up
// to one whole number of full turns (around every face they add up to the
// same total in both figures); that number is chosen so that the mean turn
// is nearest the whole figure's rotation `whole` (with its extra turns).
std::vector<double> consistent_turns(const std::vector<Vec2>& source, const std::vector<Vec2>& target,
                                     const std::vector<Edge>& edges, const std::vector<double>& change,
                                     double whole) {
  const int n = int(source.size()), m = int(edges.size());
  // Incident edges per vertex, counter-clockwise in the source.
  std::vector<std::vector<int>> incident(n);
  for (int e = 0; e < m; ++e) {
    incident[edges[e][0]].push_back(e);
    incident[edges[e][1]].push_back(e);
  }
  auto away = [&](const std::vector<Vec2>& p, int v, int e) {
    const int u = edges[e][0] == v ? edges[e][1] : edges[e][0];
    return Vec2{p[u][0] - p[v][0], p[u][1] - p[v][1]};
  };
  // Constraint graph: (neighbour edge, offset) with turn[f] = turn[e] + offset.
  std::vector<std::vector<std::pair<int, double>>> links(m);
  for (int v = 0; v < n; ++v) {
    std::vector<int>& around = incident[v];
    if (around.size() < 2) continue;
    std::sort(around.begin(), around.end(), [&](int a, int b) {
      const Vec2 da = away(source, v, a), db = away(source, v, b);
      return std::atan2(da[1], da[0]) < std::atan2(db[1], db[0]);
    });
    for (std::size_t k = 0; k < around.size(); ++k) {
      const int e = around[k], f = around[(k + 1) % around.size()];
      const double offset = ccw_angle(away(target, v, e), away(target, v, f)) -
                            ccw_angle(away(source, v, e), away(source, v, f));
      links[e].push_back({f, offset});
      links[f].push_back({e, -offset});
    }
  }
  std::vector<double> turn(m, 0.0);
  std::vector<char> seen(m, 0);
  for (int root = 0; root < m; ++root) {
    if (seen[root]) continue;
    // One connected part: propagate from its first edge, then shift by the
    // whole number of turns that brings its mean nearest `whole`.
    std::vector<int> part{root};
    seen[root] = 1;
    turn[root] = change[root];
    for (std::size_t i = 0; i < part.size(); ++i)
      for (const auto& [f, offset] : links[part[i]])
        if (!seen[f]) {
          seen[f] = 1;
          turn[f] = turn[part[i]] + offset;
          part.push_back(f);
        }
    double mean = 0;
    for (int e : part) mean += turn[e];
    mean /= double(part.size());
    const double shift = 2 * kPi * std::round((whole - mean) / (2 * kPi));
    for (int e : part) turn[e] += shift;
  }
  return turn;
}

}  // namespace

Easing parse_easing(const std::string& name) {
  if (name == "none") return Easing::None;
  if (name == "in-out") return Easing::InOut;
  throw InvalidArgumentError("unknown easing '" + name + "' (choose none or in-out)");
}

std::string easing_name(Easing easing) {
  switch (easing) {
    case Easing::None: return "none";
    case Easing::InOut: return "in-out";
  }
  throw InternalError("easing_name: unknown Easing");
}

struct RigidGuide::State {
  int n = 0;
  std::vector<Edge> edges;
  std::vector<double> angle0, turn, length0, length1;  // per edge
  // Connected parts: each has one fixed root (the lowest vertex), the
  // others are unknowns of one reduced Laplacian.
  std::vector<int> part;                  // vertex -> part
  std::vector<int> root;                  // part -> root vertex
  std::vector<int> unknown;               // vertex -> row, -1 for roots
  std::vector<int> part_size;             // part -> vertices
  std::vector<Vec2> center0, center1;     // part -> centroid in source, target
  std::vector<Vec2> source, target;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> laplacian;
  int unknowns = 0;
  std::vector<double> motion;  // cumulative RMS displacement at u = j / kMotionSamples
  double still_motion = 0;     // a total motion at or below this is rounding noise

  /// The figure at u whose edge e points along directions[e] (a unit
  /// vector): the least-squares positions for the edges at their lengths
  /// at u (the normal equations, one solve), each part's centroid on its
  /// straight line.
  std::vector<Vec2> positions(double u, const std::vector<Vec2>& directions) const;
};

RigidGuide::RigidGuide(const StickFigure& source, const std::vector<Vec2>& target_vertices,
                       const SimilarityMotion& similarity)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.n = int(source.vertices.size());
  if (int(target_vertices.size()) != s.n)
    throw InvalidArgumentError("RigidGuide: the source has " + std::to_string(s.n) + " vertices and the target " +
                               std::to_string(target_vertices.size()));
  s.source = source.vertices;
  s.target = target_vertices;
  s.edges = source.edges;
  const int m = int(s.edges.size());
  std::vector<double> change(m);  // a1 - a0 per edge, in (-pi, pi]
  for (int e = 0; e < m; ++e) {
    const Edge& edge = s.edges[e];
    const Vec2 d0{s.source[edge[1]][0] - s.source[edge[0]][0], s.source[edge[1]][1] - s.source[edge[0]][1]};
    const Vec2 d1{s.target[edge[1]][0] - s.target[edge[0]][0], s.target[edge[1]][1] - s.target[edge[0]][1]};
    const double a0 = std::atan2(d0[1], d0[0]), a1 = std::atan2(d1[1], d1[0]);
    s.angle0.push_back(a0);
    change[e] = wrap_angle(a1 - a0);
    s.length0.push_back(std::hypot(d0[0], d0[1]));
    s.length1.push_back(std::hypot(d1[0], d1[1]));
  }
  s.turn = consistent_turns(s.source, s.target, s.edges, change, similarity.angle);
  // Connected parts by union-find.
  std::vector<int> parent(s.n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Edge& e : s.edges) parent[find(e[0])] = find(e[1]);
  s.part.assign(s.n, -1);
  std::vector<int> part_of_root(s.n, -1);
  for (int v = 0; v < s.n; ++v) {
    const int r = find(v);
    if (part_of_root[r] < 0) {
      part_of_root[r] = int(s.root.size());
      s.root.push_back(v);  // the part's lowest vertex
      s.part_size.push_back(0);
      s.center0.push_back({0, 0});
      s.center1.push_back({0, 0});
    }
    const int p = part_of_root[r];
    s.part[v] = p;
    ++s.part_size[p];
    for (int c = 0; c < 2; ++c) {
      s.center0[p][c] += s.source[v][c];
      s.center1[p][c] += s.target[v][c];
    }
  }
  for (std::size_t p = 0; p < s.root.size(); ++p)
    for (int c = 0; c < 2; ++c) {
      s.center0[p][c] /= s.part_size[p];
      s.center1[p][c] /= s.part_size[p];
    }
  s.unknown.assign(s.n, -1);
  for (int v = 0; v < s.n; ++v)
    if (s.root[s.part[v]] != v) s.unknown[v] = s.unknowns++;
  // The normal equations of min sum_e |p_j - p_i - d_e|^2 with the roots
  // fixed: the graph Laplacian without the roots' rows and columns,
  // positive definite, the same for every u.
  std::vector<Eigen::Triplet<double>> triplets;
  for (const Edge& e : s.edges) {
    const int a = s.unknown[e[0]], b = s.unknown[e[1]];
    if (a >= 0) triplets.emplace_back(a, a, 1.0);
    if (b >= 0) triplets.emplace_back(b, b, 1.0);
    if (a >= 0 && b >= 0) {
      triplets.emplace_back(a, b, -1.0);
      triplets.emplace_back(b, a, -1.0);
    }
  }
  if (s.unknowns > 0) {
    Eigen::SparseMatrix<double> L(s.unknowns, s.unknowns);
    L.setFromTriplets(triplets.begin(), triplets.end());
    s.laplacian.compute(L);
    if (s.laplacian.info() != Eigen::Success)
      throw InternalError("RigidGuide: the figure's reduced Laplacian is not positive definite");
  }
  // The cumulative motion table for even speed. A figure that does not
  // move still shows rounding noise of the size's order times the unit
  // roundoff per sample; far below any motion an animation shows.
  double size = 0;
  for (int v = 0; v < s.n; ++v)
    size = std::max({size, std::abs(s.source[v][0]), std::abs(s.source[v][1]), std::abs(s.target[v][0]),
                     std::abs(s.target[v][1])});
  s.still_motion = 1e-10 * size;
  s.motion.assign(kMotionSamples + 1, 0.0);
  // The edges' directions at the samples by a rotation of each per step
  // rather than a cosine and a sine each: those were 7% of a rigid morph
  // of 10^3 vertices (prepare_rigid_morph and 48 frames, thinned, perf;
  // prepare_rigid_morph went from 53 to 49 ms), and 200 rotations leave a
  // direction within about 1e-13 of at()'s, far below what the table's
  // timing resolves.
  std::vector<Vec2> directions(static_cast<std::size_t>(m)), step(static_cast<std::size_t>(m));
  for (int e = 0; e < m; ++e) {
    directions[e] = {std::cos(s.angle0[e]), std::sin(s.angle0[e])};
    const double a = s.turn[e] / kMotionSamples;
    step[e] = {std::cos(a), std::sin(a)};
  }
  std::vector<Vec2> previous = s.source;
  for (int j = 1; j <= kMotionSamples; ++j) {
    for (int e = 0; e < m; ++e) {
      const Vec2 d = directions[e];
      directions[e] = {d[0] * step[e][0] - d[1] * step[e][1], d[1] * step[e][0] + d[0] * step[e][1]};
    }
    const std::vector<Vec2> here = s.positions(double(j) / kMotionSamples, directions);
    long double sum = 0;
    for (int v = 0; v < s.n; ++v) {
      const long double dx = here[v][0] - previous[v][0], dy = here[v][1] - previous[v][1];
      sum += dx * dx + dy * dy;
    }
    s.motion[j] = s.motion[j - 1] + std::sqrt(double(sum / std::max(s.n, 1)));
    previous = here;
  }
}

RigidGuide::~RigidGuide() = default;
RigidGuide::RigidGuide(RigidGuide&&) noexcept = default;
RigidGuide& RigidGuide::operator=(RigidGuide&&) noexcept = default;

std::vector<Vec2> RigidGuide::at(double u) const {
  const State& s = *state_;
  std::vector<Vec2> directions(s.edges.size());
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    const double a = s.angle0[e] + u * s.turn[e];
    directions[e] = {std::cos(a), std::sin(a)};
  }
  return s.positions(u, directions);
}

std::vector<Vec2> RigidGuide::State::positions(double u, const std::vector<Vec2>& directions) const {
  const State& s = *this;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(s.unknowns, 2);
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    const double length = (1 - u) * s.length0[e] + u * s.length1[e];
    const double dx = length * directions[e][0], dy = length * directions[e][1];
    const int i = s.unknown[s.edges[e][0]], j = s.unknown[s.edges[e][1]];
    // d/dp of |p_j - p_i - d|^2 / 2: L p = B^T d.
    if (j >= 0) {
      rhs(j, 0) += dx;
      rhs(j, 1) += dy;
    }
    if (i >= 0) {
      rhs(i, 0) -= dx;
      rhs(i, 1) -= dy;
    }
  }
  Eigen::MatrixX2d x;
  if (s.unknowns > 0) x = s.laplacian.solve(rhs);
  std::vector<Vec2> p(s.n, Vec2{0, 0});
  for (int v = 0; v < s.n; ++v)
    if (s.unknown[v] >= 0) p[v] = {x(s.unknown[v], 0), x(s.unknown[v], 1)};
  // Each part's centroid moves on a straight line.
  std::vector<Vec2> mean(s.root.size(), Vec2{0, 0});
  for (int v = 0; v < s.n; ++v)
    for (int c = 0; c < 2; ++c) mean[s.part[v]][c] += p[v][c];
  for (int v = 0; v < s.n; ++v) {
    const int q = s.part[v];
    for (int c = 0; c < 2; ++c)
      p[v][c] += (1 - u) * s.center0[q][c] + u * s.center1[q][c] - mean[q][c] / s.part_size[q];
  }
  return p;
}

double RigidGuide::parameter_at(double t, Easing easing) const {
  if (!(t >= 0 && t <= 1)) throw InvalidArgumentError("the morph time must be in [0, 1]");
  if (t == 0 || t == 1) return t;
  const State& s = *state_;
  const double total = s.motion.back();
  const double eased = ease(t, easing);
  // Nothing moves (the table then holds only rounding noise): any
  // parametrisation is even, so keep the (eased) time.
  if (!(total > s.still_motion)) return eased;
  const double goal = eased * total;
  // The first sample at or beyond the goal; linear in between.
  const auto it = std::lower_bound(s.motion.begin(), s.motion.end(), goal);
  const int j = std::clamp(int(it - s.motion.begin()), 1, kMotionSamples);
  const double lo = s.motion[j - 1], hi = s.motion[j];
  const double f = hi > lo ? (goal - lo) / (hi - lo) : 0.0;
  return std::clamp((j - 1 + f) / kMotionSamples, 0.0, 1.0);
}

}  // namespace stickmorph
