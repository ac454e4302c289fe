// Local timing (local_timing.h, issue 31): the checked weights and overlap,
// the local clocks, and the rigid morph and the key-pose sequence run on
// them: the lagging limb half-turns later by the overlap, every frame valid,
// the ends exact, overlap 0 the plain morph bit for bit.
#include "catch.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "figures.h"
#include "motion_helpers.h"
#include "stickmorph/errors.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/key_pose_morph.h"
#include "stickmorph/local_timing.h"
#include "stickmorph/morph_stick_figures.h"

using namespace stickmorph;
using namespace stickmorph::test;
using Catch::Matchers::Contains;

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec2 turned(Vec2 p, Vec2 center, double degrees) {
  const double a = degrees * kPi / 180, c = std::cos(a), s = std::sin(a);
  const double x = p[0] - center[0], y = p[1] - center[1];
  return {center[0] + c * x - s * y, center[1] + s * x + c * y};
}

// A stick figure (hips 0, chest 1, neck 2, head 3, legs 4-7, left arm 8-9,
// right arm 10-12, the forearm 10-11-12 from the elbow 10) and the same
// figure with its body bent by `bend` degrees about the hips while the right
// forearm turns `wave` degrees about the elbow: the issue's "body bends
// while the limb turns about its junction".
const std::vector<Vec2> kStanding = {{0, 0},    {0, 1},      {0, 1.5},   {0, 2.0},   {-0.3, -0.8},
                                     {-0.4, -1.6}, {0.3, -0.8}, {0.4, -1.6}, {-0.6, 1.1}, {-1.1, 0.9},
                                     {0.6, 1.1},  {0.9, 1.1},  {1.2, 1.1}};
const RawEdges kBones = {{0, 1}, {1, 2}, {2, 3}, {0, 4}, {4, 5}, {0, 6}, {6, 7},
                         {1, 8}, {8, 9}, {1, 10}, {10, 11}, {11, 12}};
const std::vector<int> kForearm = {11, 12};  // weight 1; the elbow 10 is the junction

StickFigure waving(double bend, double wave) {
  std::vector<Vec2> p = kStanding;
  for (int v : {1, 2, 3, 8, 9, 10, 11, 12}) p[v] = turned(kStanding[v], {0, 0}, bend);
  for (int v : {2, 3}) p[v] = turned(p[v], p[1], bend);
  for (int v : {6, 7}) p[v] = turned(kStanding[v], {0, 0}, -bend * 0.6);
  for (int v : {11, 12}) p[v] = turned(p[v], p[10], wave);
  return figure(p, kBones);
}

std::vector<double> forearm_delay() {
  std::vector<double> delay(kStanding.size(), 0.0);
  for (int v : kForearm) delay[v] = 1;
  return delay;
}

// The time at which edge e has made half of its turn from frames[0] to the
// last frame (linear between frames).
double half_turn_time(const std::vector<std::vector<Vec2>>& frames, const std::vector<double>& times, const Edge& e) {
  std::vector<double> angle{0};
  for (std::size_t f = 1; f < frames.size(); ++f)
    angle.push_back(angle.back() + wrap(angle_of(frames[f], e) - angle_of(frames[f - 1], e)));
  const double half = angle.back() / 2;
  for (std::size_t f = 1; f < frames.size(); ++f)
    if ((angle[f] - half) * (angle.back() > 0 ? 1 : -1) >= 0)
      return times[f - 1] + (half - angle[f - 1]) / (angle[f] - angle[f - 1]) * (times[f] - times[f - 1]);
  return 1;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t m = values.size() / 2;
  return values.size() % 2 ? values[m] : 0.5 * (values[m - 1] + values[m]);
}

// Median half-turn time of the forearm's edge with both ends weighted
// (11-12) minus that of the body's turning edges; the elbow's edge (10-11)
// is between weights and half-turns at the middle.
double measured_lag(const MorphStickFiguresResult& result, const StickFigure& source) {
  std::vector<double> limb, others;
  for (const Edge& e : source.edges) {
    const double total = std::abs(angle_of(result.frames.back(), e) - angle_of(result.frames.front(), e));
    if (std::min(total, 2 * kPi - total) < 5 * kPi / 180) continue;  // too little turn to time
    const bool in_limb = std::count(kForearm.begin(), kForearm.end(), e[0]) && std::count(kForearm.begin(), kForearm.end(), e[1]);
    const bool touches_limb = std::count(kForearm.begin(), kForearm.end(), e[0]) || std::count(kForearm.begin(), kForearm.end(), e[1]);
    if (in_limb)
      limb.push_back(half_turn_time(result.frames, result.times, e));
    else if (!touches_limb)
      others.push_back(half_turn_time(result.frames, result.times, e));
  }
  REQUIRE(!limb.empty());
  REQUIRE(!others.empty());
  return median(limb) - median(others);
}

}  // namespace

TEST_CASE("local_time starts weight-w parts at d w and ends them at 1 - d + d w", "[local_timing]") {
  CHECK(local_time(0.3, 0.7, 0) == 0.3);
  CHECK(local_time(0.0, 1.0, 0.5) == 0);
  CHECK(local_time(1.0, 0.0, 0.5) == 1);
  CHECK(local_time(1.0, 1.0, 0.5) == 1);
  CHECK(local_time(0.25, 0.0, 0.5) == Approx(0.5));
  CHECK(local_time(0.5, 1.0, 0.5) == 0);
  CHECK(local_time(0.75, 1.0, 0.5) == Approx(0.5));
  CHECK(local_time(0.9, 0.0, 0.5) == 1);
}

TEST_CASE("LocalTiming names the entry that is out of range", "[local_timing]") {
  CHECK_THROWS_WITH(LocalTiming({0, 1.5, 0}, 0.3), "delay[1] is 1.5, outside [0, 1]");
  CHECK_THROWS_WITH(LocalTiming({0, -0.25}, 0.3), "delay[1] is -0.25, outside [0, 1]");
  CHECK_THROWS_WITH(LocalTiming({0, std::nan("")}, 0.3), Contains("delay[1] is nan"));
  CHECK_THROWS_WITH(LocalTiming({0, 1}, 1), "overlap is 1, outside [0, 1)");
  CHECK_THROWS_WITH(LocalTiming({0, 1}, -0.1), "overlap is -0.1, outside [0, 1)");
  CHECK_THROWS_AS(LocalTiming({0, 1}, 1), InvalidArgumentError);
  const LocalTiming timing({0, 1, 0.5}, 0.3);
  CHECK_FALSE(timing.is_plain());
  CHECK(LocalTiming({0, 1}, 0).is_plain());
  CHECK_NOTHROW(timing.check_vertex_count(3));
  CHECK_THROWS_WITH(timing.check_vertex_count(4), "delay has 3 entries for 4 vertices of the source");
}

TEST_CASE("LocalTiming on a matched figure interpolates a dummy's weight along its edge", "[local_timing]") {
  const LocalTiming timing({0, 1, 0.5}, 0.4);
  std::vector<MatchedPlace> places(4);
  places[0].vertex = 2;
  places[1].vertex = 0;
  places[2].vertex = 1;
  places[3].edge = 0;  // edge (0, 1), a quarter of the way from 0
  places[3].fraction = 0.25;
  const LocalTiming matched = timing.on_matched_figure(places, {{0, 1}, {1, 2}});
  CHECK(matched.delay() == std::vector<double>{0.5, 0, 1, 0.25});
  CHECK(matched.overlap() == 0.4);
}

TEST_CASE("LocalClock: an edge at its ends' mean local time; a part placed by its leading vertices",
          "[local_timing]") {
  // A path 0 - 1 - 2, vertex 2 lagging: at u = 0.5 with d = 0.5 the first
  // edge is done, the second half way (mean of 1 and 0).
  const LocalTiming timing({0, 0, 1}, 0.5);
  const std::vector<Vec2> first{{0, 0}, {1, 0}, {2, 0}}, last{{5, 0}, {6, 0}, {6, 1}};
  const LocalClock clock(timing, {{0, 1}, {1, 2}}, {0, 0, 0}, 1, first, last);
  const std::vector<double> times = clock.edge_times(0.5);
  CHECK(times[0] == 1);
  CHECK(times[1] == 0.5);
  // The leading vertices 0 and 1 (lead 1; vertex 2 lead 0) are at their
  // targets at u = 0.5: the part is moved so their centroid is (5.5, 0).
  std::vector<Vec2> positions{{0, 0}, {1, 0}, {1.5, 0.5}};
  clock.place_parts(0.5, positions);
  CHECK(positions[0][0] == Approx(5));
  CHECK(positions[1][0] == Approx(6));
  CHECK(positions[2][0] == Approx(6.5));
  CHECK(positions[2][1] == Approx(0.5));
}

TEST_CASE("A lagging forearm half-turns later than the bending body by the overlap", "[local_timing][morph]") {
  // The body bends: the source stands, the target bends and waves.
  const StickFigure target = waving(-15, 100);
  const StickFigure standing = figure(kStanding, kBones);
  for (double overlap : {0.3, 0.5}) {
    MorphStickFiguresOptions options;
    options.frames = 61;
    options.timing = LocalTiming(forearm_delay(), overlap);
    const MorphStickFiguresResult result = morph_stick_figures(standing, target, options);
    CHECK(measured_lag(result, standing) == Approx(overlap).margin(0.05));
    CHECK(result.frames.front() == standing.vertices);
    CHECK(result.frames.back() == target.vertices);
    for (std::size_t f = 0; f < result.frames.size(); ++f) CHECK(is_frame_valid(standing, result.frames[f]));
  }
}

TEST_CASE("Overlap 0 is the plain morph bit for bit", "[local_timing][morph]") {
  const StickFigure standing = figure(kStanding, kBones), target = waving(-15, 100);
  MorphStickFiguresOptions plain;
  plain.frames = 31;
  MorphStickFiguresOptions timed = plain;
  timed.timing = LocalTiming(forearm_delay(), 0);
  CHECK(morph_stick_figures(standing, target, timed).frames == morph_stick_figures(standing, target, plain).frames);
}

TEST_CASE("Local timing is refused with another method and with the wrong length", "[local_timing][morph]") {
  const StickFigure standing = figure(kStanding, kBones), target = waving(-15, 100);
  MorphStickFiguresOptions options;
  options.method = MorphMethod::Barycentric;
  options.timing = LocalTiming(forearm_delay(), 0.3);
  CHECK_THROWS_WITH(morph_stick_figures(standing, target, options), Contains("delay has no effect with method='barycentric'"));
  options.method = MorphMethod::Rigid;
  options.timing = LocalTiming({0, 1}, 0.3);
  CHECK_THROWS_WITH(morph_stick_figures(standing, target, options), "delay has 2 entries for 13 vertices of the source");
}

TEST_CASE("Local timing with correspond auto: a dummy lags as its edge's ends do", "[local_timing][morph]") {
  // The target's forearm drawn with one vertex less (11 dropped): 11 becomes
  // a dummy on the target; the source keeps its weights.
  const StickFigure standing = figure(kStanding, kBones);
  const StickFigure waved = waving(-15, 100);
  std::vector<Vec2> p = waved.vertices;
  p.erase(p.begin() + 11);
  const StickFigure target = figure(p, {{0, 1}, {1, 2}, {2, 3}, {0, 4}, {4, 5}, {0, 6}, {6, 7}, {1, 8}, {8, 9},
                                        {1, 10}, {10, 11}});
  MorphStickFiguresOptions options;
  options.frames = 41;
  options.correspond = CorrespondenceMode::Auto;
  options.timing = LocalTiming(forearm_delay(), 0.5);
  const MorphStickFiguresResult result = morph_stick_figures(standing, target, options);
  REQUIRE(result.correspondence);
  const StickFigure& matched = result.correspondence->source;
  for (const auto& frame : result.frames) CHECK(is_frame_valid(matched, frame));
  // The hand (source vertex 12) turns late: at t = 0.4 its edge from the
  // elbow has turned less than the body has bent in full.
  const Edge hand{10, 12};
  const double start = angle_of(result.frames.front(), hand), end = angle_of(result.frames.back(), hand);
  const double at_04 = angle_of(result.frames[16], hand);
  CHECK(std::abs(wrap(at_04 - start)) < 0.35 * std::abs(wrap(end - start)));
}

TEST_CASE("Key poses on local clocks: every key exact, the limb lagging in every segment", "[local_timing][key_poses]") {
  const StickFigure standing = figure(kStanding, kBones);
  const std::vector<StickFigure> keys{standing, waving(-15, 100), waving(-5, 20)};
  KeyPoseMorphOptions options;
  options.frames = 61;
  options.timing = LocalTiming(forearm_delay(), 0.4);
  const KeyPoseMorphResult result = morph_key_poses(keys, options);
  for (std::size_t k = 0; k < keys.size(); ++k) CHECK(result.frames[result.key_frames[k]] == keys[k].vertices);
  for (const auto& frame : result.frames) CHECK(is_frame_valid(standing, frame));
  // In the first segment (frames 0-30) the forearm's own edge is still at
  // its start a third of the way in, while the body has moved.
  const Edge forearm{11, 12}, spine{0, 1};
  const std::vector<Vec2>& third = result.frames[10];
  CHECK(std::abs(wrap(angle_of(third, forearm) - angle_of(result.frames[0], forearm))) < 0.02);
  CHECK(std::abs(wrap(angle_of(third, spine) - angle_of(result.frames[0], spine))) > 0.05);
  // Overlap 0: the plain sequence.
  KeyPoseMorphOptions plain;
  plain.frames = 61;
  KeyPoseMorphOptions zero = plain;
  zero.timing = LocalTiming(forearm_delay(), 0);
  CHECK(morph_key_poses(keys, zero).frames == morph_key_poses(keys, plain).frames);
  options.timing = LocalTiming({0, 1}, 0.4);
  CHECK_THROWS_WITH(morph_key_poses(keys, options), "delay has 2 entries for 13 vertices of key 1");
}
