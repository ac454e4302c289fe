// KeyPoseGuide (issue 28): the as-rigid-as-possible trajectory through key
// poses, one C1 spline through every key.
#include "catch.h"

#include <cmath>
#include <vector>

#include "figures.h"
#include "motion_helpers.h"
#include "stickmorph/errors.h"
#include "stickmorph/key_pose_guide.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180;

const std::vector<Edge>& stick_man_edges() {
  static const std::vector<Edge> edges = stick_man_standing().edges;
  return edges;
}

// The guide's velocity just before and just after time t (difference
// quotients over dt), as whole-figure vectors.
std::pair<std::vector<Vec2>, std::vector<Vec2>> velocities_at(const KeyPoseGuide& guide, double t, double dt) {
  const std::vector<Vec2> before = guide.at(t - dt), here = guide.at(t), after = guide.at(t + dt);
  std::vector<Vec2> v_minus(here.size()), v_plus(here.size());
  for (std::size_t v = 0; v < here.size(); ++v)
    for (int c = 0; c < 2; ++c) {
      v_minus[v][c] = (here[v][c] - before[v][c]) / dt;
      v_plus[v][c] = (after[v][c] - here[v][c]) / dt;
    }
  return {v_minus, v_plus};
}

}  // namespace

TEST_CASE("the key-pose guide shows every key at its time", "[key_pose_guide]") {
  const auto keys = stick_man_walk(5);
  const std::vector<double> times = {0, 0.2, 0.45, 0.7, 1};
  const KeyPoseGuide guide(keys, stick_man_edges(), times);
  for (std::size_t k = 0; k < keys.size(); ++k) check_close(guide.at(times[k]), keys[k], 1e-12);
  REQUIRE(guide.knot_times() == times);
  CHECK(guide.segment_at(0) == 0);
  CHECK(guide.segment_at(0.2) == 1);
  CHECK(guide.segment_at(0.69) == 2);
  CHECK(guide.segment_at(1) == 3);
}

TEST_CASE("the key-pose guide shows the keys of a figure with a cycle and of two parts", "[key_pose_guide]") {
  // A square with a tail, and a separate stroke: the least-squares fit of a
  // key's own edges is that key, cycle or not, and each part sits on its
  // own centroid.
  const StickFigure base = figure({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1.5, 1.5}, {3, 0}, {4, 0.5}},
                                  {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {2, 4}, {5, 6}});
  const std::vector<std::vector<Vec2>> keys = {base.vertices, moved(base, 0.4, 1.2, 1, -0.5).vertices,
                                               moved(base, 1.1, 0.9, 2, 0.5).vertices};
  const KeyPoseGuide guide(keys, base.edges, {0, 0.5, 1});
  check_close(guide.at(0), keys[0], 1e-12);
  check_close(guide.at(0.5), keys[1], 1e-12);
  check_close(guide.at(1), keys[2], 1e-12);
}

TEST_CASE("the key-pose guide's velocity is continuous at interior keys", "[key_pose_guide]") {
  const auto keys = stick_man_walk(4);
  const std::vector<double> times = {0, 0.3, 0.55, 1};  // uneven: the tangents weigh the spacing
  const KeyPoseGuide guide(keys, stick_man_edges(), times);
  for (int k = 1; k <= 2; ++k) {
    const auto [v_minus, v_plus] = velocities_at(guide, times[std::size_t(k)], 1e-6);
    std::vector<Vec2> jump(v_minus.size());
    for (std::size_t v = 0; v < jump.size(); ++v) jump[v] = {v_plus[v][0] - v_minus[v][0], v_plus[v][1] - v_minus[v][1]};
    INFO("key " << k + 1);
    CHECK(frame_norm(v_plus) > 1);          // it moves through the key ...
    CHECK(frame_norm(jump) < 1e-4 * frame_norm(v_plus));  // ... without a change of velocity
  }
}

TEST_CASE("two keys turn every edge at a constant rate, as the pair guide does", "[key_pose_guide]") {
  const std::vector<std::vector<Vec2>> keys = {stick_man_standing().vertices, stick_man_walking().vertices};
  const KeyPoseGuide guide(keys, stick_man_edges(), {0, 1});
  // On a tree the fit is exact: every edge's angle at t is its angle at 0
  // plus t times its turn, and its length the geometric mean at t = 1/2.
  const std::vector<Vec2> quarter = guide.at(0.25), half = guide.at(0.5);
  for (const Edge& e : stick_man_edges()) {
    const double turn = wrap(angle_of(keys[1], e) - angle_of(keys[0], e));
    CHECK(wrap(angle_of(quarter, e) - angle_of(keys[0], e)) == Approx(0.25 * turn).margin(1e-9));
    CHECK(length_of(half, e) == Approx(std::sqrt(length_of(keys[0], e) * length_of(keys[1], e))).epsilon(1e-12));
  }
}

TEST_CASE("three keys give one parabola through them", "[key_pose_guide]") {
  // A single edge whose centroid moves along x through 0, 1, 4 at times 0,
  // 1/2, 1: the parabola x = 4 t^2, also between the keys and with a
  // continuous velocity, where chained straight segments would bend at 1.
  const std::vector<Edge> edges = {{0, 1}};
  auto key = [](double x) { return std::vector<Vec2>{{x - 0.5, 0}, {x + 0.5, 0}}; };
  const KeyPoseGuide guide({key(0), key(1), key(4)}, edges, {0, 0.5, 1});
  for (double t : {0.1, 0.25, 0.6, 0.9}) {
    const std::vector<Vec2> p = guide.at(t);
    CHECK((p[0][0] + p[1][0]) / 2 == Approx(4 * t * t).margin(1e-12));
    CHECK(p[1][0] - p[0][0] == Approx(1).margin(1e-12));
  }
}

TEST_CASE("a held key stops the motion there", "[key_pose_guide]") {
  const auto keys = stick_man_walk(3);
  KeyPoseGuideOptions options;
  options.hold = {false, true, false};
  const KeyPoseGuide guide(keys, stick_man_edges(), {0, 0.5, 1}, options);
  check_close(guide.at(0.5), keys[1], 1e-12);
  const auto [v_minus, v_plus] = velocities_at(guide, 0.5, 1e-6);
  CHECK(frame_norm(v_minus) < 1e-4);
  CHECK(frame_norm(v_plus) < 1e-4);
  const auto [w_minus, w_plus] = velocities_at(guide, 0.25, 1e-6);
  CHECK(frame_norm(w_plus) > 1);
}

TEST_CASE("a loop returns to the first key and joins itself smoothly", "[key_pose_guide]") {
  const auto keys = stick_man_walk(3);
  KeyPoseGuideOptions options;
  options.loop = true;
  const KeyPoseGuide guide(keys, stick_man_edges(), {0, 1.0 / 3, 2.0 / 3}, options);
  REQUIRE(guide.knot_times().size() == 4);
  check_close(guide.at(1), keys[0], 1e-12);
  check_close(guide.at(2.0 / 3), keys[2], 1e-12);
  // The velocity leaving key 1 at time 0 is the one arriving at time 1.
  const double dt = 1e-6;
  const std::vector<Vec2> start = guide.at(0), after = guide.at(dt), end = guide.at(1), before = guide.at(1 - dt);
  std::vector<Vec2> leave(start.size()), arrive(start.size()), jump(start.size());
  for (std::size_t v = 0; v < start.size(); ++v)
    for (int c = 0; c < 2; ++c) {
      leave[v][c] = (after[v][c] - start[v][c]) / dt;
      arrive[v][c] = (end[v][c] - before[v][c]) / dt;
      jump[v][c] = leave[v][c] - arrive[v][c];
    }
  CHECK(frame_norm(leave) > 1);
  CHECK(frame_norm(jump) < 1e-4 * frame_norm(leave));
}

TEST_CASE("turns add up along the sequence", "[key_pose_guide]") {
  // The stick man turned by 100 degrees from key to key: four keys make
  // 300 degrees, and halfway through the last segment the figure is turned
  // by about 250 degrees (the spline through equal steps is the straight
  // line), not back by the short way from key 1.
  const StickFigure man = stick_man_standing();
  std::vector<std::vector<Vec2>> keys;
  for (int k = 0; k < 4; ++k) keys.push_back(moved(man, k * 100 * kDegree, 1, 0, 0).vertices);
  const KeyPoseGuide guide(keys, man.edges, {0, 1.0 / 3, 2.0 / 3, 1});
  const double spine = angle_of(man.vertices, man.edges[0]);
  CHECK(wrap(angle_of(guide.at(5.0 / 6), man.edges[0]) - spine - 250 * kDegree) == Approx(0).margin(1e-9));
  // Per segment, the long way round: the first segment clockwise by 260.
  KeyPoseGuideOptions options;
  options.rotation = {RotationDirection::Clockwise, RotationDirection::Short, RotationDirection::Short};
  const KeyPoseGuide long_way(keys, man.edges, {0, 1.0 / 3, 2.0 / 3, 1}, options);
  const double early = wrap(angle_of(long_way.at(0.05), man.edges[0]) - spine);
  CHECK(early < 0);  // it starts turning clockwise
}

TEST_CASE("the key-pose guide refuses bad input, naming the key or the time", "[key_pose_guide]") {
  const auto keys = stick_man_walk(3);
  const std::vector<Edge>& edges = stick_man_edges();
  CHECK_THROWS_WITH(KeyPoseGuide({keys[0]}, edges, {0}), Contains("at least two keys, got 1"));
  auto short_key = keys;
  short_key[2].pop_back();
  CHECK_THROWS_WITH(KeyPoseGuide(short_key, edges, {0, 0.5, 1}), Contains("key 3 has 10 vertices, key 1 has 11"));
  auto collapsed = keys;
  collapsed[1][1] = collapsed[1][0];
  CHECK_THROWS_WITH(KeyPoseGuide(collapsed, edges, {0, 0.5, 1}), Contains("edge 0 (0, 1) has length zero in key 2"));
  CHECK_THROWS_WITH(KeyPoseGuide(keys, edges, {0, 1}), Contains("3 keys, 2 times"));
  CHECK_THROWS_WITH(KeyPoseGuide(keys, edges, {0.1, 0.5, 1}), Contains("first key's time must be 0"));
  CHECK_THROWS_WITH(KeyPoseGuide(keys, edges, {0, 0.5, 0.5}), Contains("key 3's is not after key 2's"));
  CHECK_THROWS_WITH(KeyPoseGuide(keys, edges, {0, 0.5, 0.9}), Contains("the last key's time must be 1"));
  KeyPoseGuideOptions loop;
  loop.loop = true;
  CHECK_THROWS_WITH(KeyPoseGuide(keys, edges, {0, 0.5, 1}, loop), Contains("below 1"));
  KeyPoseGuideOptions hold;
  hold.hold = {true};
  CHECK_THROWS_WITH(KeyPoseGuide(keys, edges, {0, 0.5, 1}, hold), Contains("one entry per key"));
  KeyPoseGuideOptions turns;
  turns.turns = {1, 0, 0};
  CHECK_THROWS_WITH(KeyPoseGuide(keys, edges, {0, 0.5, 1}, turns), Contains("2 segments, 3 entries"));
  const KeyPoseGuide guide(keys, edges, {0, 0.5, 1});
  CHECK_THROWS_AS(guide.at(1.5), InvalidArgumentError);
  CHECK_THROWS_AS(guide.at(std::nan("")), InvalidArgumentError);
}
