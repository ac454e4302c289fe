// internal::mean_value_weights, floater_weights, uniform_weights and
// node_weights: one interior node as a convex combination of its
// neighbours ([8], section 2.2 of the paper).
#include "catch.h"

#include <cmath>

#include "stickmorph/errors.h"
#include "stickmorph/internal/barycentric_weights.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {

// Neighbours' offsets of a node at the centre of a square star.
const std::vector<Vec2> kCross = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};

// sum_j w_j q_j: zero when the weights reproduce the node's position.
Vec2 reproduce(const std::vector<double>& w, const std::vector<Vec2>& q) {
  Vec2 sum{0, 0};
  for (std::size_t j = 0; j < q.size(); ++j) sum = {sum[0] + w[j] * q[j][0], sum[1] + w[j] * q[j][1]};
  return sum;
}

}  // namespace

TEST_CASE("all three kinds give 1/4 each at the centre of a square star", "[node_weights]") {
  // Exactly: tan(45 deg) = 1 in mean value coordinates, the exit triangle
  // splits evenly in Floater's, and a centroid gets 1/deg in the uniform kind.
  const std::vector<double> quarter(4, 0.25);
  CHECK(mean_value_weights(kCross) == quarter);
  CHECK(floater_weights(kCross) == quarter);
  CHECK(uniform_weights(kCross) == quarter);
}

TEST_CASE("mean value weights of a star with one far neighbour", "[node_weights]") {
  // Right angles throughout, so tan(a/2) = 1 and w_j ~ 2 / |q_j|:
  // 2, 2, 2, 1 over 7.
  const std::vector<Vec2> q = {{1, 0}, {0, 1}, {-1, 0}, {0, -2}};
  const std::vector<double> w = mean_value_weights(q);
  CHECK(w[0] == Approx(2.0 / 7));
  CHECK(w[1] == Approx(2.0 / 7));
  CHECK(w[2] == Approx(2.0 / 7));
  CHECK(w[3] == Approx(1.0 / 7));
  const Vec2 r = reproduce(w, q);
  CHECK(r[0] == Approx(0).margin(1e-15));
  CHECK(r[1] == Approx(0).margin(1e-15));
}

TEST_CASE("uniform weights off the centroid stay positive and reproduce the node", "[node_weights]") {
  // The node far towards neighbour 0: plain 1/deg would not reproduce it.
  const std::vector<Vec2> q = {{0.1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  const std::vector<double> w = uniform_weights(q);
  double sum = 0;
  for (double x : w) {
    CHECK(x > 0);
    sum += x;
  }
  CHECK(sum == Approx(1));
  const Vec2 r = reproduce(w, q);
  CHECK(r[0] == Approx(0).margin(1e-15));
  CHECK(r[1] == Approx(0).margin(1e-15));
  CHECK(w[0] > 0.25);  // the near neighbour weighs most
}

TEST_CASE("node_weights scales the offsets by a power of two and refuses a flat star", "[node_weights]") {
  // Node 0 at the centre of the square enclosure 1..4, at very different
  // scales: offsets are brought to about 1 before any square is taken, so
  // tiny and huge stars get the same (finite, positive) weights.
  for (double scale : {1.0, 1e-90, 1e90}) {
    FigureTriangulation tri;
    tri.figure_vertices = 1;
    tri.enclosure_vertices = 4;
    tri.source = {{0, 0}, {-scale, -scale}, {scale, -scale}, {scale, scale}, {-scale, scale}};
    tri.target = tri.source;
    tri.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
    const Topology topo = build_topology(tri);
    for (double w : node_weights(tri, topo, tri.source, 0, WeightKind::MeanValue)) CHECK(w == Approx(0.25));
    // Node 0 on the side 1-2: two triangles flat, no positive weights. The
    // morph only calls node_weights after the exact orientation test, so a
    // star reaching it this flat is one floating point cannot weigh: the
    // triangulation is refused (VerificationError), which lets the rigid
    // method fall back to another triangulation.
    std::vector<Vec2> flat = tri.source;
    flat[0] = {0, -scale};
    CHECK_THROWS_AS(node_weights(tri, topo, flat, 0, WeightKind::MeanValue), VerificationError);
  }
}

TEST_CASE("try_node_weights gives node_weights' weights into kept storage, false for a flat star", "[node_weights]") {
  // A fan of seven neighbours round node 0, irregular: the scratch form the
  // rigid morph calls every frame returns the same weights, bit for bit,
  // reusing its vectors, and reports the flat star instead of throwing.
  FigureTriangulation tri;
  tri.figure_vertices = 1;
  tri.enclosure_vertices = 7;
  tri.source = {{0.1, -0.05}};
  for (int k = 0; k < 7; ++k) {
    const double a = 2 * 3.14159265358979 * k / 7 + 0.1 * (k % 3);
    tri.source.push_back({(1 + 0.3 * (k % 2)) * std::cos(a), (1 + 0.3 * (k % 2)) * std::sin(a)});
  }
  tri.target = tri.source;
  for (int k = 0; k < 7; ++k) tri.triangles.push_back({0, 1 + k, 1 + (k + 1) % 7});
  const Topology topo = build_topology(tri);
  std::vector<Vec2> q;
  std::vector<double> w;
  for (WeightKind kind : {WeightKind::MeanValue, WeightKind::Floater, WeightKind::Uniform}) {
    REQUIRE(try_node_weights(topo, tri.source, 0, kind, q, w));
    CHECK(w == node_weights(tri, topo, tri.source, 0, kind));
    const Vec2 r = reproduce(w, std::vector<Vec2>(q.begin(), q.end()));
    CHECK(r[0] == Approx(0).margin(1e-15));
    CHECK(r[1] == Approx(0).margin(1e-15));
  }
  // Mean value weights with sqrt lengths agree with a hypot reference to
  // rounding.
  std::vector<double> reference(q.size());
  double sum = 0;
  for (std::size_t j = 0; j < q.size(); ++j) {
    const Vec2& p = q[(j + q.size() - 1) % q.size()];
    const Vec2& c = q[j];
    const Vec2& n = q[(j + 1) % q.size()];
    const double before = std::atan2(p[0] * c[1] - p[1] * c[0], p[0] * c[0] + p[1] * c[1]);
    const double after = std::atan2(c[0] * n[1] - c[1] * n[0], c[0] * n[0] + c[1] * n[1]);
    reference[j] = (std::tan(before / 2) + std::tan(after / 2)) / std::hypot(c[0], c[1]);
    sum += reference[j];
  }
  REQUIRE(try_node_weights(topo, tri.source, 0, WeightKind::MeanValue, q, w));
  for (std::size_t j = 0; j < q.size(); ++j) CHECK(w[j] == Approx(reference[j] / sum).epsilon(1e-14));
  std::vector<Vec2> flat = tri.source;
  flat[0] = {0.5 * (tri.source[1][0] + tri.source[2][0]), 0.5 * (tri.source[1][1] + tri.source[2][1])};
  CHECK_FALSE(try_node_weights(topo, flat, 0, WeightKind::MeanValue, q, w));
}
