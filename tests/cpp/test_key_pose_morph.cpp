// morph_key_poses (issue 28): one valid, continuous motion through a
// sequence of key poses.
#include "catch.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "figures.h"
#include "motion_helpers.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/key_pose_morph.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

std::vector<StickFigure> walk_keys(int count) {
  const StickFigure standing = stick_man_standing();
  std::vector<StickFigure> keys;
  for (const std::vector<Vec2>& pose : stick_man_walk(count)) keys.push_back(figure(pose, raw_edges(standing.edges)));
  return keys;
}

double mean_step(const std::vector<std::vector<Vec2>>& frames) {
  double total = 0;
  for (std::size_t f = 1; f < frames.size(); ++f) total += frame_distance(frames[f - 1], frames[f]);
  return total / double(frames.size() - 1);
}

// Issue 28's smoothness number at frame f: |v+ - v-| over the mean step.
double jump_at(const std::vector<std::vector<Vec2>>& frames, int f) {
  std::vector<Vec2> jump(frames[0].size());
  for (std::size_t v = 0; v < jump.size(); ++v)
    for (int c = 0; c < 2; ++c)
      jump[v][c] = frames[f + 1][v][c] - 2 * frames[f][v][c] + frames[f - 1][v][c];
  return frame_norm(jump) / mean_step(frames);
}

void require_every_frame_valid(const std::vector<StickFigure>& keys, const KeyPoseMorphResult& result) {
  // The engine's frame verifier, independently of the certificate the
  // morph used: every frame a valid drawing of key 1's stick figure.
  for (std::size_t f = 0; f < result.frames.size(); ++f) {
    INFO("frame " << f);
    REQUIRE(is_frame_valid(keys[0], result.frames[f]));
  }
}

}  // namespace

TEST_CASE("a walk through four keys is valid, hits every key and does not jerk at them", "[key_pose_morph]") {
  const std::vector<StickFigure> keys = walk_keys(4);
  const KeyPoseMorphResult result = morph_key_poses(keys);
  REQUIRE(result.frames.size() == 3 * 49 + 1);
  REQUIRE(result.key_frames == std::vector<int>{0, 49, 98, 147});
  REQUIRE(result.segments.size() == 3);
  for (std::size_t k = 0; k < keys.size(); ++k) CHECK(result.frames[std::size_t(result.key_frames[k])] == keys[k].vertices);
  CHECK(result.times.front() == 0);
  CHECK(result.times.back() == 1);
  require_every_frame_valid(keys, result);
  // C1 through the interior keys: issue 28 asks for a median at most 0.25.
  for (int k : {1, 2}) {
    INFO("key " << k + 1);
    CHECK(jump_at(result.frames, result.key_frames[std::size_t(k)]) < 0.25);
  }
  for (const KeyPoseSegment& segment : result.segments) CHECK(segment.triangulation.triangles.size() > 0);
}

TEST_CASE("a held key stops the morph there", "[key_pose_morph]") {
  const std::vector<StickFigure> keys = walk_keys(3);
  KeyPoseMorphOptions options;
  options.hold = {false, true, false};
  const KeyPoseMorphResult result = morph_key_poses(keys, options);
  const int f = result.key_frames[1];
  const double step = mean_step(result.frames);
  CHECK(frame_distance(result.frames[std::size_t(f) - 1], result.frames[std::size_t(f)]) < 0.05 * step);
  CHECK(frame_distance(result.frames[std::size_t(f)], result.frames[std::size_t(f) + 1]) < 0.05 * step);
  require_every_frame_valid(keys, result);
}

TEST_CASE("a loop ends on the first key and passes through it smoothly", "[key_pose_morph]") {
  const std::vector<StickFigure> keys = walk_keys(3);
  KeyPoseMorphOptions options;
  options.loop = true;
  const KeyPoseMorphResult result = morph_key_poses(keys, options);
  REQUIRE(result.frames.size() == 3 * 49 + 1);
  CHECK(result.key_frames == std::vector<int>{0, 49, 98});
  CHECK(result.frames.back() == keys[0].vertices);
  REQUIRE(result.segments.size() == 3);
  CHECK(result.segments.back().to_key == 0);
  require_every_frame_valid(keys, result);
  for (int k : {1, 2}) CHECK(jump_at(result.frames, result.key_frames[std::size_t(k)]) < 0.25);
  // Across the loop's seam: the step into the last frame against the step
  // out of the first.
  std::vector<std::vector<Vec2>> seam = {result.frames[146], result.frames[147], result.frames[1]};
  std::vector<Vec2> jump(keys[0].vertices.size());
  for (std::size_t v = 0; v < jump.size(); ++v)
    for (int c = 0; c < 2; ++c) jump[v][c] = seam[2][v][c] - 2 * seam[1][v][c] + seam[0][v][c];
  CHECK(frame_norm(jump) < 0.25 * mean_step(result.frames));
}

TEST_CASE("key frames given by the caller are where the keys land", "[key_pose_morph]") {
  const std::vector<StickFigure> keys = walk_keys(3);
  KeyPoseMorphOptions options;
  options.frames = 31;
  options.keys_at = {0, 8, 30};
  const KeyPoseMorphResult result = morph_key_poses(keys, options);
  REQUIRE(result.frames.size() == 31);
  CHECK(result.frames[8] == keys[1].vertices);
  CHECK(result.segments[0].last_frame == 8);
  CHECK(result.segments[1].first_frame == 8);
}

TEST_CASE("two keys make one segment, ends exact", "[key_pose_morph]") {
  const std::vector<StickFigure> keys = walk_keys(2);
  const KeyPoseMorphResult result = morph_key_poses(keys);
  REQUIRE(result.frames.size() == 50);
  CHECK(result.frames.front() == keys[0].vertices);
  CHECK(result.frames.back() == keys[1].vertices);
  require_every_frame_valid(keys, result);
}

TEST_CASE("morph_key_poses refuses bad sequences, naming the key", "[key_pose_morph]") {
  const std::vector<StickFigure> keys = walk_keys(3);
  CHECK_THROWS_WITH(morph_key_poses({keys[0]}), Contains("at least two keys, got 1"));
  // Key 3 mirrored: a valid drawing, but every junction's order of edges
  // is reversed, so it is not compatible with key 2.
  std::vector<StickFigure> mirrored = keys;
  std::vector<Vec2> flipped = keys[2].vertices;
  for (Vec2& p : flipped) p[0] = -p[0];
  mirrored[2] = figure(flipped, raw_edges(keys[2].edges));
  try {
    morph_key_poses(mirrored);
    FAIL("morphed a sequence with an incompatible key");
  } catch (const IncompatibleFiguresError& error) {
    CHECK_THAT(std::string(error.what()), Contains("key 2 and key 3: "));
    CHECK(!error.vertices().empty());
  }
  std::vector<StickFigure> fewer = keys;
  fewer[1] = figure({{0, 0}, {1, 0}}, {{0, 1}});
  CHECK_THROWS_WITH(morph_key_poses(fewer), Contains("key 2 has 2 vertices, key 1 has 11"));
  KeyPoseMorphOptions options;
  options.frames = 30;
  options.keys_at = {0, 15, 15};
  CHECK_THROWS_WITH(morph_key_poses(keys, options), Contains("key 3 at 15 is not after key 2 at 15"));
  options.keys_at = {0, 15, 28};
  CHECK_THROWS_WITH(morph_key_poses(keys, options), Contains("key 3 must be at frame 29"));
  options.keys_at = {0, 15};
  CHECK_THROWS_WITH(morph_key_poses(keys, options), Contains("3 keys, 2 frames"));
  options.keys_at.clear();
  options.frames = 2;
  CHECK_THROWS_WITH(morph_key_poses(keys, options), Contains("frames must be between 3"));
  KeyPoseMorphOptions turns;
  turns.turns = {1};
  CHECK_THROWS_WITH(morph_key_poses(keys, turns), Contains("2 segments, 1 entries"));
}

TEST_CASE("KeyPoseMorphSolver: any frame in any order is morph_key_poses' frame, any time a valid figure",
          "[key_pose_morph]") {
  const std::vector<StickFigure> keys = walk_keys(3);
  KeyPoseMorphOptions options;
  options.frames = 31;
  options.loop = true;
  const KeyPoseMorphResult result = morph_key_poses(keys, options);
  KeyPoseMorphSolver solver(keys, options);
  REQUIRE(solver.frame_count() == 31);
  REQUIRE(solver.key_frames() == result.key_frames);
  // Scrubbing backwards and jumping about: the same frames, bit for bit.
  for (int f : {30, 17, 3, 29, 0, 10, 11, 20, 9})
    REQUIRE(solver.frame(f) == result.frames[std::size_t(f)]);
  // At the keys' times the keys exactly, between frames valid figures.
  for (std::size_t k = 0; k < keys.size(); ++k)
    REQUIRE(solver.solve(double(result.key_frames[k]) / 30.0) == keys[k].vertices);
  REQUIRE(solver.solve(1.0) == keys[0].vertices);
  for (double time : {0.0123, 0.5001, 0.777, 0.999})
    REQUIRE(is_frame_valid(keys[0], solver.solve(time)));
  CHECK_THROWS_WITH(solver.solve(1.5), Contains("time must be between 0 and 1"));
  CHECK_THROWS_WITH(solver.frame(31), Contains("frame must be between 0 and 30"));
}

TEST_CASE("an eased segment starts from rest and comes to rest: its keys held", "[key_pose_morph]") {
  const std::vector<StickFigure> keys = walk_keys(4);
  KeyPoseMorphOptions eased;
  eased.easing = {Easing::None, Easing::InOut, Easing::None};
  KeyPoseMorphOptions held;
  held.hold = {false, true, true, false};
  REQUIRE(morph_key_poses(keys, eased).frames == morph_key_poses(keys, held).frames);
  eased.easing = {Easing::InOut};
  CHECK_THROWS_WITH(morph_key_poses(keys, eased), Contains("easing: one entry per segment: 3 segments, 1 entries"));
}
