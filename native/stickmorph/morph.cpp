#include "stickmorph/morph.h"

#include <Eigen/Dense>
#include <Eigen/SparseLU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "stickmorph/decomposition.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/frame_verification.h"

namespace stickmorph {
namespace {

using Clock = std::chrono::steady_clock;
using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major, as SparseLU wants
using LongVector = Eigen::Matrix<long double, Eigen::Dynamic, 2>;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void check_frame_count(int frames) {
  if (frames < 2 || frames > kMaxMorphFrames)
    throw InvalidArgumentError("the number of frames must be between 2 and " + std::to_string(kMaxMorphFrames) +
                               ", got " + std::to_string(frames));
}

// t_f = f / (N - 1); the division makes the last time exactly 1.
std::vector<double> frame_times(int frames) {
  std::vector<double> times(frames);
  for (int f = 0; f < frames; ++f) times[f] = double(f) / double(frames - 1);
  return times;
}

// a x b, accurate to about one ulp (Kahan's fma trick), so that a thin but
// positive corner does not come out with a zero or negative sine.
double cross(const Vec2& a, const Vec2& b) {
  const double w = a[1] * b[0];
  const double e = std::fma(-a[1], b[0], w);
  const double f = std::fma(a[0], b[1], -w);
  return f + e;
}

double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }

// ---------------------------------------------------------------------------
// The triangulation's combinatorics.

std::string node_text(const FigureTriangulation& tri, int node) {
  const int n = tri.figure_vertices, k = tri.enclosure_vertices;
  std::string text = "node " + std::to_string(node);
  if (node < n) return text + " (figure vertex " + std::to_string(node) + ")";
  if (node < n + k) return text + " (enclosure vertex " + std::to_string(node - n) + ")";
  return text + " (Steiner vertex " + std::to_string(node - n - k) + ")";
}

std::string triangle_text(const FigureTriangulation& tri, int t) {
  const auto& tr = tri.triangles[t];
  return "triangle " + std::to_string(t) + " (" + std::to_string(tr[0]) + ", " + std::to_string(tr[1]) + ", " +
         std::to_string(tr[2]) + ")";
}

[[noreturn]] void malformed(const std::string& what) {
  throw InvalidArgumentError("invalid triangulation for the morph: " + what);
}

/// What the morph needs to know about the triangulation, established once.
struct Topology {
  int nodes = 0;
  /// For every interior (non-enclosure) node: its neighbours in
  /// counter-clockwise order, a closed cycle. Empty for enclosure nodes.
  std::vector<std::vector<int>> ring;
  std::vector<int> unknown;         ///< node -> row of the linear system, or -1 (enclosure)
  std::vector<int> interior_nodes;  ///< row -> node
};

bool is_enclosure(const FigureTriangulation& tri, int node) {
  return node >= tri.figure_vertices && node < tri.figure_vertices + tri.enclosure_vertices;
}

// Checks that the triangles form a disk bounded by the enclosure, with a
// closed fan around every other node, and returns those fans.
//
// Why this plus positive orientation suffices for an embedding (used for
// every frame): with the boundary mapped to the fixed convex enclosure
// traversed once counter-clockwise, a generic point inside is covered by
// exactly (winding number =) 1 positively oriented triangle and a point
// outside by none. So no two triangles overlap and the angles around every
// interior node sum to one turn: the frame is a triangulation with the
// same connectivity (Floater & Gotsman 1999, section 2).
Topology build_topology(const FigureTriangulation& tri) {
  const int n = tri.figure_vertices, k = tri.enclosure_vertices, s = tri.steiner_vertices;
  if (n < 1 || k < 3 || s < 0)
    malformed("it needs at least 1 figure vertex and 3 enclosure vertices, got n = " + std::to_string(n) +
              ", k = " + std::to_string(k) + ", s = " + std::to_string(s));
  const int N = tri.node_count();
  if (int(tri.source.size()) != N || int(tri.target.size()) != N)
    malformed("it has " + std::to_string(N) + " nodes but " + std::to_string(tri.source.size()) +
              " source and " + std::to_string(tri.target.size()) + " target positions");
  for (int side = 0; side < 2; ++side)
    for (int v = 0; v < N; ++v) {
      const Vec2& p = side ? tri.target[v] : tri.source[v];
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || std::abs(p[0]) > kMaxCoordinateMagnitude ||
          std::abs(p[1]) > kMaxCoordinateMagnitude)
        malformed(node_text(tri, v) + " has a non-finite or too large position in the " +
                  (side ? "target" : "source"));
    }

  // Every directed side of a triangle once: two triangles on the same side
  // of an edge would overlap.
  std::unordered_map<std::int64_t, int> side_of;
  side_of.reserve(tri.triangles.size() * 3);
  auto key = [N](int a, int b) { return std::int64_t(a) * N + b; };
  for (int t = 0; t < int(tri.triangles.size()); ++t) {
    const auto& tr = tri.triangles[t];
    for (int c = 0; c < 3; ++c)
      if (tr[c] < 0 || tr[c] >= N) malformed(triangle_text(tri, t) + " refers to a node out of range");
    if (tr[0] == tr[1] || tr[1] == tr[2] || tr[2] == tr[0]) malformed(triangle_text(tri, t) + " repeats a node");
    for (int c = 0; c < 3; ++c) {
      const auto [it, fresh] = side_of.emplace(key(tr[c], tr[(c + 1) % 3]), t);
      if (!fresh)
        malformed("the side " + std::to_string(tr[c]) + "->" + std::to_string(tr[(c + 1) % 3]) + " belongs to " +
                  triangle_text(tri, it->second) + " and " + triangle_text(tri, t) + " (they overlap)");
    }
  }
  // The boundary is the enclosure, counter-clockwise: each enclosure side
  // has a triangle on its left and none on its right; every other side has
  // triangles on both.
  for (int i = 0; i < k; ++i) {
    const int a = n + i, b = n + (i + 1) % k;
    if (!side_of.count(key(a, b)))
      malformed("the enclosure side " + std::to_string(a) + "->" + std::to_string(b) +
                " is not a side of any triangle");
    if (side_of.count(key(b, a)))
      malformed("a triangle lies outside the enclosure side " + std::to_string(a) + "-" + std::to_string(b));
  }
  for (const auto& [edge_key, t] : side_of) {
    const int a = int(edge_key / N), b = int(edge_key % N);
    const bool enclosure_side = is_enclosure(tri, a) && is_enclosure(tri, b) && (b - n) == (a - n + 1) % k;
    if (!enclosure_side && !side_of.count(key(b, a)))
      malformed("the edge " + std::to_string(a) + "-" + std::to_string(b) + " borders only " +
                triangle_text(tri, t) + " but is not an enclosure side (a hole or a second boundary)");
  }

  // Fans: at node v, triangle (v, b, c) leads from neighbour b to c
  // counter-clockwise.
  std::vector<std::vector<std::pair<int, int>>> turns(N);
  for (const auto& tr : tri.triangles)
    for (int c = 0; c < 3; ++c) turns[tr[c]].emplace_back(tr[(c + 1) % 3], tr[(c + 2) % 3]);

  Topology topo;
  topo.nodes = N;
  topo.ring.assign(N, {});
  topo.unknown.assign(N, -1);
  for (int v = 0; v < N; ++v) {
    if (turns[v].empty()) malformed(node_text(tri, v) + " is in no triangle");
    std::unordered_map<int, int> next;
    for (const auto& [b, c] : turns[v]) next.emplace(b, c);
    if (is_enclosure(tri, v)) {
      // An open fan from the next enclosure vertex to the previous one.
      const int i = v - n;
      int at = n + (i + 1) % k;
      const int last = n + (i + k - 1) % k;
      std::size_t steps = 0;
      while (at != last && steps <= turns[v].size()) {
        auto it = next.find(at);
        if (it == next.end()) break;
        at = it->second;
        ++steps;
      }
      if (at != last || steps != turns[v].size())
        malformed("the triangles around " + node_text(tri, v) + " do not form one fan (the disk is pinched there)");
      continue;
    }
    std::vector<int> ring{turns[v].front().first};
    for (std::size_t step = 0; step < turns[v].size(); ++step) {
      auto it = next.find(ring.back());
      if (it == next.end()) malformed("the triangles around " + node_text(tri, v) + " leave a gap");
      ring.push_back(it->second);
    }
    // turns[v].size() steps must close the cycle exactly then, not before.
    ring.pop_back();
    const bool closed = next.at(ring.back()) == ring.front();
    std::vector<int> sorted = ring;
    std::sort(sorted.begin(), sorted.end());
    if (!closed || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      malformed("the triangles around " + node_text(tri, v) + " do not close into one fan");
    topo.unknown[v] = int(topo.interior_nodes.size());
    topo.interior_nodes.push_back(v);
    topo.ring[v] = std::move(ring);
  }
  return topo;
}

// Every triangle counter-clockwise in `positions` (exact), or the first
// that is not.
int first_non_positive(const FigureTriangulation& tri, const std::vector<Vec2>& positions) {
  for (int t = 0; t < int(tri.triangles.size()); ++t) {
    const auto& tr = tri.triangles[t];
    if (orientation(positions[tr[0]], positions[tr[1]], positions[tr[2]]) <= 0) return t;
  }
  return -1;
}

void require_positive(const FigureTriangulation& tri, const std::vector<Vec2>& positions, const char* which) {
  const int t = first_non_positive(tri, positions);
  if (t >= 0) malformed(triangle_text(tri, t) + " is not counter-clockwise in the " + which);
}

// Section 2.2: the boundary is common to both triangulations, convex, and
// stays fixed. Strict convexity (every other corner strictly left of every
// side, exact) also makes it a simple polygon.
void require_enclosure(const FigureTriangulation& tri) {
  const int n = tri.figure_vertices, k = tri.enclosure_vertices;
  for (int i = 0; i < k; ++i)
    if (tri.source[n + i] != tri.target[n + i])
      malformed(node_text(tri, n + i) + " moves: the enclosure must be the same in source and target");
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      if (j == i || j == (i + 1) % k) continue;
      if (orientation(tri.source[n + i], tri.source[n + (i + 1) % k], tri.source[n + j]) <= 0)
        malformed("the enclosure is not strictly convex and counter-clockwise: " + node_text(tri, n + j) +
                  " is not strictly left of the side " + std::to_string(n + i) + "-" +
                  std::to_string(n + (i + 1) % k));
    }
}

// ---------------------------------------------------------------------------
// Weights of one interior node from its neighbours' offsets q_j = p_j - p_i
// (counter-clockwise, scaled so that the largest coordinate is about 1: all
// three kinds are invariant under scaling, and the scaling keeps squares and
// products of tiny or huge coordinates finite and normal).

std::vector<double> mean_value_weights(const std::vector<Vec2>& q) {
  const std::size_t d = q.size();
  std::vector<double> len(d), tan_half(d), w(d);
  for (std::size_t j = 0; j < d; ++j) len[j] = std::hypot(q[j][0], q[j][1]);
  for (std::size_t j = 0; j < d; ++j) {
    // tan(a/2) of the angle a in (0, pi) between q_j and q_j+1, in whichever
    // of its two forms does not cancel: sin/(1+cos) or (1-cos)/sin.
    const Vec2& a = q[j];
    const Vec2& b = q[(j + 1) % d];
    const double c = cross(a, b), dt = dot(a, b), l = len[j] * len[(j + 1) % d];
    tan_half[j] = dt >= 0 ? c / (l + dt) : (l - dt) / c;
  }
  double sum = 0;
  for (std::size_t j = 0; j < d; ++j) {
    w[j] = (tan_half[(j + d - 1) % d] + tan_half[j]) / len[j];
    sum += w[j];
  }
  for (double& x : w) x /= sum;
  return w;
}

std::vector<double> floater_weights(const std::vector<Vec2>& q) {
  // Floater 1997, section 6: in the plane the geodesic polar map of the star
  // is the star itself, so p_i's barycentric coordinates are taken in the
  // actual neighbour positions.
  const std::size_t d = q.size();
  std::vector<double> len(d), w(d, 0.0);
  for (std::size_t j = 0; j < d; ++j) len[j] = std::hypot(q[j][0], q[j][1]);
  for (std::size_t l = 0; l < d; ++l) {
    // The ray from p_l through p_i leaves the star through the side
    // (p_r, p_r+1) whose cone around p_i contains -q_l. Picking the side
    // where -q_l is deepest inside (largest smaller sine) is robust when it
    // passes within rounding of a neighbour: either adjacent side is right.
    const Vec2 opposite{-q[l][0], -q[l][1]};
    std::size_t best = d;
    double best_depth = -2;
    for (std::size_t r = 0; r < d; ++r) {
      const std::size_t r1 = (r + 1) % d;
      if (r == l || r1 == l) continue;
      const double depth =
          std::min(cross(q[r], opposite) / (len[r] * len[l]), cross(opposite, q[r1]) / (len[l] * len[r1]));
      if (depth > best_depth) best_depth = depth, best = r;
    }
    const std::size_t r = best, r1 = (best + 1) % d;
    // Barycentric coordinates of the origin (p_i) in (q_l, q_r, q_r1).
    double mu_l = cross(q[r], q[r1]), mu_r = cross(q[r1], q[l]), mu_r1 = cross(q[l], q[r]);
    mu_r = std::max(mu_r, 0.0);  // only rounding makes these negative
    mu_r1 = std::max(mu_r1, 0.0);
    const double total = mu_l + mu_r + mu_r1;
    w[l] += mu_l / total;
    w[r] += mu_r / total;
    w[r1] += mu_r1 / total;
  }
  for (double& x : w) x /= double(d);
  return w;
}

std::vector<double> uniform_weights(const std::vector<Vec2>& q) {
  // Least-squares nearest to u = 1/d subject to sum w = 1 and sum w q = 0:
  // w = u - A^T (A A^T)^-1 (A u - b) with A = [1; qx; qy], b = (1, 0, 0).
  const std::size_t d = q.size();
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  Eigen::Vector3d residual(0, 0, 0);  // A u - b: the first row is exactly 0
  for (const Vec2& p : q) {
    const Eigen::Vector3d a(1, p[0], p[1]);
    M += a * a.transpose();
    residual += a / double(d);
  }
  residual[0] = 0;
  const Eigen::Vector3d y = M.fullPivLu().solve(residual);
  std::vector<double> w(d);
  for (std::size_t j = 0; j < d; ++j) w[j] = 1.0 / double(d) - (y[0] + y[1] * q[j][0] + y[2] * q[j][1]);
  // Keep every weight at least half of min(1/d, its mean value weight) by
  // the smallest blend toward mean value coordinates (which satisfy the
  // same constraints and are positive), so that Tutte's theorem applies.
  const std::vector<double> m = mean_value_weights(q);
  double blend = 0;
  for (std::size_t j = 0; j < d; ++j) {
    const double floor = 0.5 * std::min(1.0 / double(d), m[j]);
    if (w[j] < floor) blend = std::max(blend, (floor - w[j]) / (m[j] - w[j]));
  }
  if (blend > 0)
    for (std::size_t j = 0; j < d; ++j) w[j] = (1 - blend) * w[j] + blend * m[j];
  return w;
}

// The weights of interior node v over topo.ring[v], positive and summing to
// one.
std::vector<double> node_weights(const FigureTriangulation& tri, const Topology& topo,
                                 const std::vector<Vec2>& positions, int v, WeightKind kind) {
  const std::vector<int>& ring = topo.ring[v];
  std::vector<Vec2> q(ring.size());
  double largest = 0;
  for (std::size_t j = 0; j < ring.size(); ++j) {
    q[j] = {positions[ring[j]][0] - positions[v][0], positions[ring[j]][1] - positions[v][1]};
    largest = std::max({largest, std::abs(q[j][0]), std::abs(q[j][1])});
  }
  // Scale by a power of two: exact, so the orientations stay as they are.
  const int exponent = std::ilogb(largest);
  for (Vec2& p : q) p = {std::ldexp(p[0], -exponent), std::ldexp(p[1], -exponent)};
  std::vector<double> w;
  switch (kind) {
    case WeightKind::MeanValue: w = mean_value_weights(q); break;
    case WeightKind::Uniform: w = uniform_weights(q); break;
    case WeightKind::Floater: w = floater_weights(q); break;
  }
  for (double x : w)
    if (!(x > 0) || !std::isfinite(x))
      // Not the caller's fault: every triangle passed the exact orientation
      // test (require_positive), and the weights of a valid triangle are positive in
      // exact arithmetic, so it is this computation that failed.
      throw InternalError("morph: the triangles around " + node_text(tri, v) +
                          " are too close to degenerate for convex-combination weights");
  return w;
}

// ---------------------------------------------------------------------------
// The linear systems of [8].

/// (I - W_interior(t)) x = W_boundary(t) x_boundary for every t, with the
/// two endpoint matrices assembled on one sparsity pattern so that a frame
/// blends their value arrays and reuses one symbolic factorization.
///
/// Solver choice, measured (Release, g++ 12, one core; twisted polar webs of
/// radius 8 to 64, 50 frames, mean value weights; per interior frame; "err"
/// is the largest coordinate difference from the direct solve):
///   unknowns   SparseLU+COLAMD,     SparseLU with   BiCGSTAB warm start    exact checks
///              symbolic once        symbolic each   (Jacobi, tol 1e-13)    (verify)
///        113   0.125 ms             0.24 ms         0.036 ms, err 3e-13    0.61 ms
///        481   0.89 ms              1.37 ms         0.31 ms,  err 7e-12    2.8 ms
///       1985   5.4 ms               7.1 ms          2.9 ms,   err 5e-11    12 ms
///       8065   37 ms                47 ms           27 ms,    err 3e-10    53 ms
/// (BiCGSTAB with IncompleteLUT was slower than both LU variants; AMD and
/// natural orderings gave 1.1-4 times the fill of COLAMD and up to 11 times
/// the time.) On the long thin triangulations around polylines and trees
/// neither helps much: a numeric refactorization costs nearly a fresh LU
/// there, and diagonally preconditioned BiCGSTAB converges slowly (up to 7
/// times slower, benchmark_morph); BiCGSTAB preconditioned with a nearby
/// frame's LU needs two preconditioner solves per column and step, and costs
/// about what a factorization does. What is fast everywhere: iterative
/// refinement on the LU of a nearby frame (the anchor), from the previous
/// frame's solution, both coordinates per solve. Consecutive systems differ
/// only by the blend, so it converges in a step or two; when it needs more
/// than kAnchorIterations the frame is factorized and becomes the new
/// anchor. An iterative result is never trusted on its own: every frame is
/// verified exactly, and one that fails is solved directly at its own time
/// (the factorization that the long double refinement then reuses).
class MorphSystem {
 public:
  MorphSystem(const FigureTriangulation& tri, WeightKind kind) : tri_(tri), topo_(build_topology(tri)) {
    require_positive(tri, tri.source, "source");
    require_positive(tri, tri.target, "target");
    require_enclosure(tri);
    const int m = int(topo_.interior_nodes.size());
    for (int side = 0; side < 2; ++side) {
      const std::vector<Vec2>& positions = side ? tri.target : tri.source;
      std::vector<Eigen::Triplet<double>> triplets;
      LongVector rhs = LongVector::Zero(m, 2);
      for (int row = 0; row < m; ++row) {
        const int v = topo_.interior_nodes[row];
        const std::vector<double> w = node_weights(tri, topo_, positions, v, kind);
        triplets.emplace_back(row, row, 1.0);
        for (std::size_t j = 0; j < w.size(); ++j) {
          const int u = topo_.ring[v][j];
          if (topo_.unknown[u] >= 0) {
            triplets.emplace_back(row, topo_.unknown[u], -w[j]);
          } else {
            // The enclosure is the same in both embeddings and fixed.
            rhs(row, 0) += static_cast<long double>(w[j]) * tri.source[u][0];
            rhs(row, 1) += static_cast<long double>(w[j]) * tri.source[u][1];
          }
        }
      }
      SparseMatrix& A = side ? a1_ : a0_;
      A.resize(m, m);
      A.setFromTriplets(triplets.begin(), triplets.end());
      A.makeCompressed();
      (side ? b1_ : b0_) = rhs;
    }
    // Same rows, same neighbours: the compressed structures coincide.
    if (a0_.nonZeros() != a1_.nonZeros() ||
        !std::equal(a0_.innerIndexPtr(), a0_.innerIndexPtr() + a0_.nonZeros(), a1_.innerIndexPtr()) ||
        !std::equal(a0_.outerIndexPtr(), a0_.outerIndexPtr() + m + 1, a1_.outerIndexPtr()))
      throw InternalError("morph: the source and target systems have different sparsity patterns");
    a_ = a0_;
    lu_.analyzePattern(a_);
  }

  int unknowns() const { return int(topo_.interior_nodes.size()); }

  /// Blends the system to time t and factorizes it. False if singular
  /// (it never is for positive weights: I - W_interior is then an
  /// irreducibly diagonally dominant M-matrix).
  bool factorize(double t) {
    t_ = t;
    const double* v0 = a0_.valuePtr();
    const double* v1 = a1_.valuePtr();
    double* v = a_.valuePtr();
    for (Eigen::Index e = 0; e < a_.nonZeros(); ++e) v[e] = (1 - t) * v0[e] + t * v1[e];
    lu_.factorize(a_);
    return lu_.info() == Eigen::Success;
  }

  /// Solves the system blended to time t by iterative refinement on the last
  /// factorization (the anchor), starting from `guess`: x += LU^-1 (b - A x),
  /// both coordinates in one pass. Consecutive systems differ only by the
  /// blend, so the anchor's inverse is close to this system's and each step
  /// gains several digits. False if the residual does not drop below the
  /// tolerance within kAnchorIterations steps: the anchor is too far, and the
  /// caller factorizes at t instead.
  bool iterate(double t, const Eigen::MatrixX2d& guess, Eigen::MatrixX2d& x) {
    t_ = t;
    const double* v0 = a0_.valuePtr();
    const double* v1 = a1_.valuePtr();
    double* v = a_.valuePtr();
    for (Eigen::Index e = 0; e < a_.nonZeros(); ++e) v[e] = (1 - t) * v0[e] + t * v1[e];
    const Eigen::MatrixX2d b = rhs().cast<double>();
    // Positions to about ten digits: far finer than any animation needs, and
    // every frame is verified exactly whatever the residual.
    const double tolerance = 1e-10 * std::max(b.norm(), 1e-300);
    x = guess;
    for (int step = 0; step < kAnchorIterations; ++step) {
      const Eigen::MatrixX2d residual = b - a_ * x;
      if (!residual.allFinite()) return false;
      if (residual.norm() <= tolerance) return true;
      x += lu_.solve(residual);
    }
    return (b - a_ * x).norm() <= tolerance && x.allFinite();
  }
  /// Steps after which an anchor counts as too far from the frame.
  static constexpr int kAnchorIterations = 8;

  /// Interior coordinates in the source embedding: the first warm start.
  Eigen::MatrixX2d source_coordinates() const {
    Eigen::MatrixX2d x(unknowns(), 2);
    for (int row = 0; row < unknowns(); ++row) {
      x(row, 0) = tri_.source[topo_.interior_nodes[row]][0];
      x(row, 1) = tri_.source[topo_.interior_nodes[row]][1];
    }
    return x;
  }

  /// Solves the factorized system; x holds the interior coordinates.
  Eigen::MatrixX2d solve() const {
    const Eigen::MatrixX2d b = rhs().cast<double>();
    return lu_.solve(b);
  }

  /// Iterative refinement: residuals of the blended system computed in long
  /// double from the endpoint values (so the blend itself is not rounded to
  /// double), corrections solved with the double factorization.
  Eigen::MatrixX2d refine(const Eigen::MatrixX2d& start, int rounds) const {
    const long double t = t_;
    LongVector x = start.cast<long double>();
    const LongVector b = rhs();
    for (int round = 0; round < rounds; ++round) {
      LongVector r = b;
      for (int col = 0; col < a0_.outerSize(); ++col)
        for (Eigen::Index e = a0_.outerIndexPtr()[col]; e < a0_.outerIndexPtr()[col + 1]; ++e) {
          const int row = a0_.innerIndexPtr()[e];
          const long double a = (1 - t) * a0_.valuePtr()[e] + t * a1_.valuePtr()[e];
          r(row, 0) -= a * x(col, 0);
          r(row, 1) -= a * x(col, 1);
        }
      const Eigen::MatrixX2d correction = lu_.solve(Eigen::MatrixX2d(r.cast<double>()));
      if (!correction.allFinite()) break;
      x += correction.cast<long double>();
    }
    return x.cast<double>();
  }

  /// All node positions with the interior coordinates x.
  std::vector<Vec2> positions(const Eigen::MatrixX2d& x) const {
    std::vector<Vec2> p = tri_.source;  // enclosure nodes stay put
    for (int row = 0; row < unknowns(); ++row) p[topo_.interior_nodes[row]] = {x(row, 0), x(row, 1)};
    return p;
  }

 private:
  LongVector rhs() const {
    const long double t = t_;
    return (1 - t) * b0_ + t * b1_;
  }

  const FigureTriangulation& tri_;
  Topology topo_;
  SparseMatrix a0_, a1_, a_;
  LongVector b0_, b1_;
  double t_ = 0;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
};

void require_source_matches(const FigureTriangulation& tri, const StickFigure& source) {
  if (int(source.vertices.size()) != tri.figure_vertices)
    throw InvalidArgumentError("the figure has " + std::to_string(source.vertices.size()) +
                               " vertices, the triangulation " + std::to_string(tri.figure_vertices) +
                               " figure vertices");
  for (int v = 0; v < tri.figure_vertices; ++v)
    if (source.vertices[v] != tri.source[v])
      throw InvalidArgumentError("vertex " + std::to_string(v) +
                                 " of the figure is not at its position in the triangulation's source");
}

// The frame's defect, or empty: (1) every triangle counter-clockwise,
// (2) the figure a stick figure compatible with the source.
std::string frame_defect(const FigureTriangulation& tri, const StickFigure& source,
                         const Decomposition& source_decomposition, const std::vector<Vec2>& positions,
                         int frame, double time) {
  const int t = first_non_positive(tri, positions);
  if (t >= 0)
    return frame_label(frame, time) + ": " + triangle_text(tri, t) + " is not counter-clockwise";
  const std::vector<Vec2> figure(positions.begin(), positions.begin() + tri.figure_vertices);
  try {
    verify_frame(source, source_decomposition, figure, frame, time);
  } catch (const VerificationError& error) {
    return error.what();
  }
  return {};
}

}  // namespace

WeightKind parse_weight_kind(const std::string& name) {
  if (name == "mvc") return WeightKind::MeanValue;
  if (name == "uniform") return WeightKind::Uniform;
  if (name == "floater") return WeightKind::Floater;
  throw InvalidArgumentError("unknown weight kind '" + name + "' (choose mvc, uniform or floater)");
}

std::string weight_kind_name(WeightKind kind) {
  switch (kind) {
    case WeightKind::MeanValue: return "mvc";
    case WeightKind::Uniform: return "uniform";
    case WeightKind::Floater: return "floater";
  }
  throw InternalError("weight_kind_name: unknown WeightKind");
}

Eigen::SparseMatrix<double, Eigen::RowMajor> barycentric_weights(const FigureTriangulation& triangulation,
                                                                 const std::vector<Vec2>& positions,
                                                                 WeightKind kind) {
  const Topology topo = build_topology(triangulation);
  if (int(positions.size()) != topo.nodes)
    throw InvalidArgumentError("barycentric_weights needs " + std::to_string(topo.nodes) + " positions, got " +
                               std::to_string(positions.size()));
  require_positive(triangulation, positions, "given positions");
  std::vector<Eigen::Triplet<double>> triplets;
  for (int v : topo.interior_nodes) {
    const std::vector<double> w = node_weights(triangulation, topo, positions, v, kind);
    for (std::size_t j = 0; j < w.size(); ++j) triplets.emplace_back(v, topo.ring[v][j], w[j]);
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> W(topo.nodes, topo.nodes);
  W.setFromTriplets(triplets.begin(), triplets.end());
  return W;
}

std::vector<Vec2> solve_morph_frame(const FigureTriangulation& triangulation, double t, WeightKind kind) {
  if (!(t >= 0 && t <= 1)) throw InvalidArgumentError("the morph time must be in [0, 1]");
  MorphSystem system(triangulation, kind);
  if (!system.factorize(t)) throw VerificationError("the morph system at t = " + format_double(t) + " is singular");
  return system.positions(system.solve());
}

MorphResult morph_triangulation(const FigureTriangulation& triangulation, const StickFigure& source,
                                const MorphOptions& options) {
  check_frame_count(options.frames);
  MorphResult result;
  result.times = frame_times(options.frames);
  auto start = Clock::now();
  MorphSystem system(triangulation, options.weights);
  require_source_matches(triangulation, source);
  result.stats.factorize_ms += ms_since(start);

  const Decomposition source_decomposition = decompose(source);
  // Refinement rounds for a frame that fails: each round gains roughly the
  // extra precision of long double until the result is correctly rounded;
  // beyond three it no longer changes.
  constexpr int kRefinementRounds = 3;
  const int last = options.frames - 1;
  result.frames.reserve(options.frames);
  Eigen::MatrixX2d guess = system.source_coordinates();
  Eigen::MatrixX2d x;
  bool direct = false;
  bool anchored = false;        // a factorization exists to iterate on
  bool anchor_too_far = false;  // the last iteration did not converge
  // The direct factorization of frame f's system, into x.
  auto solve_directly = [&](int f, double t) {
    auto begin = Clock::now();
    if (!system.factorize(t)) throw VerificationError(frame_label(f, t) + ": the morph's linear system is singular");
    result.stats.factorize_ms += ms_since(begin);
    begin = Clock::now();
    x = system.solve();
    result.stats.solve_ms += ms_since(begin);
    ++result.stats.factorizations;
    direct = true;
  };
  for (int f = 0; f <= last; ++f) {
    const double t = result.times[f];
    std::vector<Vec2> positions;
    direct = false;
    if (f == 0 || f == last) {
      // The endpoints are the inputs themselves. The solve reproduces them
      // only up to rounding amplified by the condition number of
      // I - W_interior (the source is the fixed point of W0 in exact
      // arithmetic), while the contract (FORMAT.md) promises frames[0] is
      // the source and the last frame the target, bit for bit.
      positions = f == 0 ? triangulation.source : triangulation.target;
    } else {
      // The first interior frame is factorized; later frames iterate on the
      // latest factorization and refactorize only when it is too far.
      // Right after an iteration that did not converge, frames are too far
      // apart for the anchor: factorize without trying.
      direct = !anchored || anchor_too_far;
      if (!direct) {
        start = Clock::now();
        direct = !system.iterate(t, guess, x);
        result.stats.solve_ms += ms_since(start);
        anchor_too_far = direct;
      } else {
        anchor_too_far = false;
      }
      if (direct) solve_directly(f, t);
      anchored = true;
      positions = system.positions(x);
      guess = x;
    }
    if (options.verify) {
      start = Clock::now();
      std::string defect = frame_defect(triangulation, source, source_decomposition, positions, f, t);
      result.stats.verify_ms += ms_since(start);
      if (!defect.empty() && f != 0 && f != last && !direct) {
        // The iteration's residual can flip a nearly flat triangle: solve
        // this frame directly.
        solve_directly(f, t);
        positions = system.positions(x);
        start = Clock::now();
        defect = frame_defect(triangulation, source, source_decomposition, positions, f, t);
        result.stats.verify_ms += ms_since(start);
      }
      if (!defect.empty() && f != 0 && f != last) {
        // Rounding in the solve can flip a nearly flat triangle that is
        // positive in exact arithmetic (the theorem of [8] holds exactly).
        start = Clock::now();
        positions = system.positions(system.refine(x, kRefinementRounds));
        result.stats.solve_ms += ms_since(start);
        ++result.stats.refined_frames;
        start = Clock::now();
        defect = frame_defect(triangulation, source, source_decomposition, positions, f, t);
        result.stats.verify_ms += ms_since(start);
        if (!defect.empty()) defect += " (after refinement in long double)";
      }
      if (!defect.empty()) throw VerificationError("morph: " + defect);
    }
    result.frames.push_back(std::move(positions));
  }
  return result;
}

MorphResult linear_morph(const StickFigure& source, const StickFigure& target, int frames,
                         std::vector<int>* invalid_frames) {
  check_frame_count(frames);
  if (source.vertices.size() != target.vertices.size())
    throw InvalidArgumentError("the source has " + std::to_string(source.vertices.size()) +
                               " vertices and the target " + std::to_string(target.vertices.size()));
  MorphResult result;
  result.times = frame_times(frames);
  const std::size_t n = source.vertices.size();
  auto start = Clock::now();
  result.frames.reserve(frames);
  for (int f = 0; f < frames; ++f) {
    const double t = result.times[f];
    if (f == 0) {
      result.frames.push_back(source.vertices);
    } else if (f == frames - 1) {
      result.frames.push_back(target.vertices);
    } else {
      std::vector<Vec2> p(n);
      for (std::size_t v = 0; v < n; ++v)
        for (int c = 0; c < 2; ++c) p[v][c] = (1 - t) * source.vertices[v][c] + t * target.vertices[v][c];
      result.frames.push_back(std::move(p));
    }
  }
  result.stats.solve_ms = ms_since(start);
  if (invalid_frames) {
    start = Clock::now();
    invalid_frames->clear();
    const Decomposition source_decomposition = decompose(source);
    for (int f = 0; f < frames; ++f)
      if (!is_frame_valid(source, source_decomposition, result.frames[f])) invalid_frames->push_back(f);
    result.stats.verify_ms = ms_since(start);
  }
  return result;
}

}  // namespace stickmorph
