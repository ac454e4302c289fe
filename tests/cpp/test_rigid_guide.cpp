// RigidGuide (issue 12): the as-rigid-as-possible trajectory of a stick
// figure on its own edges, its even-speed time table and easing.
#include "catch.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "figures.h"
#include "motion_helpers.h"
#include "stickmorph/errors.h"
#include "stickmorph/internal/motion_timing.h"
#include "stickmorph/rigid_guide.h"
#include "stickmorph/similarity_motion.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

constexpr double kPi = 3.14159265358979323846;




// Root mean square of the vertex displacements from a to b.
double rms_step(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double sum = 0;
  for (std::size_t v = 0; v < a.size(); ++v)
    sum += (b[v][0] - a[v][0]) * (b[v][0] - a[v][0]) + (b[v][1] - a[v][1]) * (b[v][1] - a[v][1]);
  return std::sqrt(sum / a.size());
}


RigidGuide guide_between(const StickFigure& source, const std::vector<Vec2>& target,
                         RotationDirection direction = RotationDirection::Short, int turns = 0) {
  return RigidGuide(source, target, fit_similarity(source.vertices, target, direction, turns));
}

std::vector<Vec2> negated(const std::vector<Vec2>& points) {
  std::vector<Vec2> out;
  for (const Vec2& p : points) out.push_back({-p[0], -p[1]});
  return out;
}

// An irregular heptagon away from the origin (a cycle: the guide's
// least-squares fit has closure to spread).
StickFigure heptagon() { return polygon({{1, 0}, {4, 0.5}, {5, 2}, {4.5, 4}, {2.5, 5}, {0.5, 3.5}, {1.5, 2}}); }

}  // namespace

TEST_CASE("RigidGuide on a tree: forward kinematics, lengths and joint angles linear", "[rigid_guide]") {
  const StickFigure source = stick_man_standing();
  const StickFigure target = stick_man_walking();
  REQUIRE(check_compatibility(source, target).compatible());
  const RigidGuide guide = guide_between(source, target.vertices);

  check_close(guide.at(0), source.vertices, 1e-12);
  check_close(guide.at(1), target.vertices, 1e-12);

  const Vec2 c0 = mean(source.vertices), c1 = mean(target.vertices);
  for (double u : {0.0, 0.1, 0.3, 0.5, 0.77, 1.0}) {
    const std::vector<Vec2> p = guide.at(u);
    REQUIRE(p.size() == source.vertices.size());
    for (const Edge& e : source.edges) {
      const double l0 = length_of(source.vertices, e), l1 = length_of(target.vertices, e);
      CHECK(length_of(p, e) == Approx((1 - u) * l0 + u * l1).margin(1e-12));
    }
    // The angle at every joint (between an edge and the edge it hangs off)
    // is interpolated linearly, the short way.
    for (int i = 0; i < 10; ++i) {
      const int r = kStickManReference[i];
      if (r < 0) continue;
      const Edge& e = source.edges[i];
      const Edge& f = source.edges[r];
      const double rel0 = wrap(angle_of(source.vertices, e) - angle_of(source.vertices, f));
      const double rel1 = wrap(angle_of(target.vertices, e) - angle_of(target.vertices, f));
      const double rel = wrap(angle_of(p, e) - angle_of(p, f));
      CHECK(wrap(rel - rel0 - u * wrap(rel1 - rel0)) == Approx(0).margin(1e-12));
    }
    // The centroid moves on a straight line.
    const Vec2 c = mean(p);
    CHECK(c[0] == Approx((1 - u) * c0[0] + u * c1[0]).margin(1e-12));
    CHECK(c[1] == Approx((1 - u) * c0[1] + u * c1[1]).margin(1e-12));
  }
  // Lengths are linear, so not the straight-line morph: the two differ.
  const std::vector<Vec2> half = guide.at(0.5);
  double largest = 0;
  for (std::size_t v = 0; v < half.size(); ++v)
    largest = std::max(largest, std::hypot(half[v][0] - 0.5 * (source.vertices[v][0] + target.vertices[v][0]),
                                           half[v][1] - 0.5 * (source.vertices[v][1] + target.vertices[v][1])));
  CHECK(largest > 0.05);
}

TEST_CASE("RigidGuide turns a figure turned by 180 degrees rigidly, all edges the same way", "[rigid_guide]") {
  for (const StickFigure& source : {heptagon(), stick_man_walking(), grid_triangulation(3)}) {
    // The exact half turn about the origin: the centroid goes from c to -c.
    const std::vector<Vec2> target = negated(source.vertices);
    const SimilarityMotion similarity = fit_similarity(source.vertices, target);
    REQUIRE(similarity.angle == kPi);
    const RigidGuide guide(source, target, similarity);
    const Vec2 c = mean(source.vertices);
    for (double u : {0.25, 0.5, 0.75}) {
      const std::vector<Vec2> p = guide.at(u);
      // Rigid: every edge keeps its length ...
      for (const Edge& e : source.edges) CHECK(length_of(p, e) == Approx(length_of(source.vertices, e)).margin(1e-12));
      // ... and the figure is the source turned by u * 180 degrees about
      // its centroid, which is at (1 - 2u) c.
      const double a = u * kPi;
      std::vector<Vec2> expected;
      for (const Vec2& x : source.vertices) {
        const double dx = x[0] - c[0], dy = x[1] - c[1];
        expected.push_back({(1 - 2 * u) * c[0] + std::cos(a) * dx - std::sin(a) * dy,
                            (1 - 2 * u) * c[1] + std::sin(a) * dx + std::cos(a) * dy});
      }
      check_close(p, expected, 1e-12);
    }
  }
}

TEST_CASE("RigidGuide keeps the similarity's whole turns on every edge", "[rigid_guide]") {
  const StickFigure source = heptagon();
  const std::vector<Vec2> target = negated(source.vertices);
  // 180 + 360 degrees: at u = 0.5 the figure has turned by 270 degrees.
  const RigidGuide guide = guide_between(source, target, RotationDirection::Short, 1);
  const std::vector<Vec2> p = guide.at(0.5);
  const Vec2 c = mean(source.vertices);
  std::vector<Vec2> expected;
  for (const Vec2& x : source.vertices) expected.push_back({x[1] - c[1], -(x[0] - c[0])});  // R(270)
  check_close(p, expected, 1e-12);
  check_close(guide.at(1), target, 1e-12);
  // Clockwise: -180 degrees, so at u = 0.5 the turn is -90.
  const std::vector<Vec2> q = guide_between(source, target, RotationDirection::Clockwise).at(0.5);
  expected.clear();
  for (const Vec2& x : source.vertices) expected.push_back({x[1] - c[1], -(x[0] - c[0])});  // R(-90) = R(270)
  check_close(q, expected, 1e-12);
  const std::vector<Vec2> r = guide_between(source, target, RotationDirection::Clockwise).at(0.25);
  const std::vector<Vec2> s = guide.at(0.25);  // +135 vs -45 degrees: different
  CHECK(rms_step(r, s) > 1);
}

TEST_CASE("RigidGuide's time table: ends exact, increasing, evened as much as the speed needs", "[rigid_guide]") {
  // One edge that grows tenfold while it turns by 150 degrees: its free end
  // moves ever faster in u.
  const StickFigure source = polyline({{0, 0}, {1, 0}});
  const double a = 150 * kPi / 180;
  const std::vector<Vec2> target = {{0, 0}, {10 * std::cos(a), 10 * std::sin(a)}};
  const RigidGuide guide = guide_between(source, target);

  CHECK(guide.parameter_at(0) == 0);
  CHECK(guide.parameter_at(1) == 1);
  CHECK(guide.parameter_at(0, Easing::InOut) == 0);
  CHECK(guide.parameter_at(1, Easing::InOut) == 1);
  double previous = 0;
  for (int i = 1; i <= 1000; ++i) {
    const double u = guide.parameter_at(i / 1000.0);
    CHECK(u > previous);
    CHECK(u <= 1);
    previous = u;
  }
  // Slow at first (the edge is short), so the parameter runs ahead of time,
  // but not as far as full evening would take it (0.596: the cumulative
  // motion halved).
  CHECK(guide.parameter_at(0.5) > 0.51);
  CHECK(guide.parameter_at(0.5) < 0.59);

  constexpr int N = 30;
  std::vector<double> steps_u, steps_t;
  for (int k = 0; k + 1 < N; ++k) {
    steps_u.push_back(rms_step(guide.at(double(k) / (N - 1)), guide.at(double(k + 1) / (N - 1))));
    steps_t.push_back(rms_step(guide.at(guide.parameter_at(double(k) / (N - 1))),
                               guide.at(guide.parameter_at(double(k + 1) / (N - 1)))));
  }
  // Uneven in u (the last step about twice the first) ...
  CHECK(*std::max_element(steps_u.begin(), steps_u.end()) > 1.8 * *std::min_element(steps_u.begin(), steps_u.end()));
  // ... and in time no step more than kMostUnevenSpeed times the mean, to
  // within 1%, and evened no more than that needs.
  double mean_step = 0;
  for (double s : steps_t) mean_step += s / steps_t.size();
  const double largest = *std::max_element(steps_t.begin(), steps_t.end());
  CHECK(largest <= internal::kMostUnevenSpeed * 1.01 * mean_step);
  CHECK(largest >= (internal::kMostUnevenSpeed - 0.05) * mean_step);
}

TEST_CASE("RigidGuide's time table: a figure that only turns keeps time, the rigid interpolation exactly",
          "[rigid_guide]") {
  // Issue 30: where the guide's own speed is even enough, every edge's
  // angle changes at constant speed in time (and its length linearly).
  const StickFigure source = stick_man_standing();
  const double a = 100 * kPi / 180;
  std::vector<Vec2> target;
  for (const Vec2& x : source.vertices)
    target.push_back({3 + std::cos(a) * x[0] - std::sin(a) * x[1], 1 + std::sin(a) * x[0] + std::cos(a) * x[1]});
  const RigidGuide guide = guide_between(source, target);
  for (int k = 0; k <= 10; ++k) CHECK(guide.parameter_at(k / 10.0) == k / 10.0);
}

TEST_CASE("RigidGuide's easing: slow in and slow out on top of even speed", "[rigid_guide]") {
  const StickFigure source = stick_man_standing();
  const RigidGuide guide = guide_between(source, stick_man_walking().vertices);
  constexpr int N = 30;
  std::vector<double> steps;
  for (int k = 0; k + 1 < N; ++k)
    steps.push_back(rms_step(guide.at(guide.parameter_at(double(k) / (N - 1), Easing::InOut)),
                             guide.at(guide.parameter_at(double(k + 1) / (N - 1), Easing::InOut))));
  double total = 0;
  for (double s : steps) total += s;
  const double middle = steps[N / 2 - 1];
  CHECK(steps.front() < 0.1 * middle);
  CHECK(steps.back() < 0.1 * middle);
  // Each step the smoothstep's share of the motion, to within 2%.
  auto smoothstep = [](double t) { return t * t * (3 - 2 * t); };
  for (int k = 0; k + 1 < N; ++k) {
    const double share = smoothstep(double(k + 1) / (N - 1)) - smoothstep(double(k) / (N - 1));
    CHECK(steps[k] / total == Approx(share).epsilon(0.02));
  }
  // The eased parameter at half time is the even one (smoothstep(0.5) = 0.5).
  CHECK(guide.parameter_at(0.5, Easing::InOut) == Approx(guide.parameter_at(0.5)).margin(1e-12));
}

TEST_CASE("RigidGuide of a figure that does not move stays put", "[rigid_guide]") {
  const StickFigure source = heptagon();
  const RigidGuide guide = guide_between(source, source.vertices);
  for (double u : {0.0, 0.2, 0.5, 0.9, 1.0}) check_close(guide.at(u), source.vertices, 1e-12);
}

// A still guide's motion table holds only rounding noise (at(u) differs from
// the source by ~1e-16); inverting it would warp the time for nothing.
TEST_CASE("RigidGuide of a figure that does not move keeps the time", "[rigid_guide]") {
  const StickFigure source = heptagon();
  const RigidGuide guide = guide_between(source, source.vertices);
  for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) CHECK(guide.parameter_at(t) == t);
}

TEST_CASE("RigidGuide refuses mismatched input and times outside [0, 1]", "[rigid_guide]") {
  const StickFigure source = heptagon();
  const std::vector<Vec2> short_target = {{0, 0}, {1, 1}};
  CHECK_THROWS_AS(RigidGuide(source, short_target, SimilarityMotion{}), InvalidArgumentError);
  CHECK_THROWS_WITH(RigidGuide(source, short_target, SimilarityMotion{}),
                    Contains("the source has 7 vertices and the target 2"));
  const RigidGuide guide = guide_between(source, negated(source.vertices));
  CHECK_THROWS_AS(guide.parameter_at(-0.01), InvalidArgumentError);
  CHECK_THROWS_AS(guide.parameter_at(1.5), InvalidArgumentError);
  CHECK_THROWS_AS(guide.parameter_at(std::nan("")), InvalidArgumentError);
}

TEST_CASE("RigidGuide moves: the moved-from object is replaced by the moved-to one", "[rigid_guide]") {
  const StickFigure source = heptagon();
  RigidGuide a = guide_between(source, negated(source.vertices));
  const std::vector<Vec2> half = a.at(0.5);
  RigidGuide b = std::move(a);
  CHECK(b.at(0.5) == half);
  RigidGuide c = guide_between(source, source.vertices);
  c = std::move(b);
  CHECK(c.at(0.5) == half);
}

TEST_CASE("parse_easing and easing_name round trip", "[rigid_guide]") {
  CHECK(parse_easing("none") == Easing::None);
  CHECK(parse_easing("in-out") == Easing::InOut);
  for (Easing e : {Easing::None, Easing::InOut}) CHECK(parse_easing(easing_name(e)) == e);
  CHECK(easing_name(Easing::InOut) == "in-out");
  CHECK_THROWS_AS(parse_easing("in_out"), InvalidArgumentError);
  CHECK_THROWS_WITH(parse_easing("bounce"), "unknown easing 'bounce' (choose none or in-out)");
}
