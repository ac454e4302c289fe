// Convex-combination weights of one interior node; see barycentric_weights.h.
#include "stickmorph/internal/barycentric_weights.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

#include "stickmorph/errors.h"

namespace stickmorph::internal {
namespace {

// a x b, accurate to about one ulp (Kahan's fma trick), so that a thin but
// positive corner does not come out with a zero or negative sine.
double cross(const Vec2& a, const Vec2& b) {
  const double w = a[1] * b[0];
  const double e = std::fma(-a[1], b[0], w);
  const double f = std::fma(a[0], b[1], -w);
  return f + e;
}

double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }

// |p| for the offsets of a star scaled to a largest coordinate of about 1:
// the square root of the sum of squares, which is within about an ulp of
// std::hypot and several times faster (hypot was a tenth of a blended
// rigid frame, perf at 10^3 vertices), and hypot itself only where a square
// would leave the normal range.
double length(const Vec2& p) {
  const double squared = p[0] * p[0] + p[1] * p[1];
  constexpr double kNormal = std::numeric_limits<double>::min();
  if (squared >= kNormal && squared <= std::numeric_limits<double>::max()) return std::sqrt(squared);
  return std::hypot(p[0], p[1]);
}

}  // namespace

void mean_value_weights(const std::vector<Vec2>& q, std::vector<double>& w) {
  const std::size_t d = q.size();
  w.resize(d);
  if (d == 0) return;
  // tan(a/2) of the angle a in (0, pi) between q_j and q_j+1, in whichever
  // of its two forms does not cancel: sin/(1+cos) or (1-cos)/sin.
  auto tan_half = [&](std::size_t j, double len_j, double len_next) {
    const Vec2& a = q[j];
    const Vec2& b = q[(j + 1) % d];
    const double c = cross(a, b), dt = dot(a, b), l = len_j * len_next;
    return dt >= 0 ? c / (l + dt) : (l - dt) / c;
  };
  // w holds the lengths until each is replaced by its weight, so the first
  // length is kept aside for the last corner.
  for (std::size_t j = 0; j < d; ++j) w[j] = length(q[j]);
  const double first_length = w[0];
  double previous = tan_half(d - 1, w[d - 1], first_length);  // the corner before q_0
  double sum = 0;
  for (std::size_t j = 0; j < d; ++j) {
    const double len_j = w[j];
    const double next_length = j + 1 < d ? w[j + 1] : first_length;
    const double current = tan_half(j, len_j, next_length);
    w[j] = (previous + current) / len_j;
    sum += w[j];
    previous = current;
  }
  for (double& x : w) x /= sum;
}

std::vector<double> mean_value_weights(const std::vector<Vec2>& q) {
  std::vector<double> w;
  mean_value_weights(q, w);
  return w;
}

std::vector<double> floater_weights(const std::vector<Vec2>& q) {
  // Floater 1997, section 6: in the plane the geodesic polar map of the star
  // is the star itself, so p_i's barycentric coordinates are taken in the
  // actual neighbour positions.
  const std::size_t d = q.size();
  std::vector<double> len(d), w(d, 0.0);
  for (std::size_t j = 0; j < d; ++j) len[j] = length(q[j]);
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

bool try_node_weights(const Topology& topo, const std::vector<Vec2>& positions, int v, WeightKind kind,
                      std::vector<Vec2>& q, std::vector<double>& w) {
  const std::vector<int>& ring = topo.ring[v];
  q.resize(ring.size());
  double largest = 0;
  for (std::size_t j = 0; j < ring.size(); ++j) {
    q[j] = {positions[ring[j]][0] - positions[v][0], positions[ring[j]][1] - positions[v][1]};
    largest = std::max({largest, std::abs(q[j][0]), std::abs(q[j][1])});
  }
  // Scale by a power of two: exact, so the orientations stay as they are
  // (a product with 2^-e is exact as ldexp is, and rounds a subnormal
  // result the same way; ldexp was 3% of a blended rigid frame).
  const int exponent = std::ilogb(largest);
  if (exponent > -1000 && exponent < 1000) {
    const double scale = std::ldexp(1.0, -exponent);
    for (Vec2& p : q) p = {p[0] * scale, p[1] * scale};
  } else {
    for (Vec2& p : q) p = {std::ldexp(p[0], -exponent), std::ldexp(p[1], -exponent)};
  }
  switch (kind) {
    case WeightKind::MeanValue: mean_value_weights(q, w); break;
    case WeightKind::Uniform: w = uniform_weights(q); break;
    case WeightKind::Floater: w = floater_weights(q); break;
  }
  for (double x : w)
    if (!(x > 0) || !std::isfinite(x)) return false;
  return true;
}

// The weights of interior node v over topo.ring[v], positive and summing to
// one.
std::vector<double> node_weights(const FigureTriangulation& tri, const Topology& topo,
                                 const std::vector<Vec2>& positions, int v, WeightKind kind) {
  std::vector<Vec2> q;
  std::vector<double> w;
  if (!try_node_weights(topo, positions, v, kind, q, w))
    // Not the caller's fault: every triangle passed the exact orientation
    // test (require_positive), and the weights of a valid triangle are
    // positive in exact arithmetic, so it is this floating-point
    // computation that failed on a nearly flat triangle. A triangulation
    // the engine cannot morph, like a frame it cannot verify: the callers
    // that have another triangulation to try (the rigid method's
    // fallbacks) catch it, the others report it.
    throw VerificationError("morph: the triangles around " + node_text(tri, v) +
                            " are too close to degenerate for convex-combination weights");
  return w;
}

}  // namespace stickmorph::internal
