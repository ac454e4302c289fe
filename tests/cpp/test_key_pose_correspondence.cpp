// correspond_key_poses and morph_key_poses with CorrespondenceMode::Auto
// (issue 28): keys drawn separately, matched onto one common figure.
#include "catch.h"

#include <algorithm>
#include <vector>

#include "figures.h"
#include "stickmorph/errors.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/key_pose_correspondence.h"
#include "stickmorph/key_pose_morph.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

// Key `k` of the walk, drawn as a user would draw it on its own: edge e
// split into `splits[e % splits.size()]` pieces, the vertices numbered
// backwards (the last drawn first) and the edges listed backwards.
StickFigure redrawn_walk_key(int k, const std::vector<int>& splits) {
  const StickFigure standing = stick_man_standing();
  const std::vector<Vec2> pose = stick_man_walk_pose(k);
  std::vector<Vec2> points = pose;
  std::vector<std::array<int, 2>> edges;
  for (std::size_t e = 0; e < standing.edges.size(); ++e) {
    const int a = standing.edges[e][0], b = standing.edges[e][1];
    const int pieces = splits[e % splits.size()];
    int previous = a;
    for (int p = 1; p < pieces; ++p) {
      const double f = double(p) / pieces;
      points.push_back({pose[a][0] + f * (pose[b][0] - pose[a][0]), pose[a][1] + f * (pose[b][1] - pose[a][1])});
      edges.push_back({previous, int(points.size()) - 1});
      previous = int(points.size()) - 1;
    }
    edges.push_back({previous, b});
  }
  const int n = int(points.size());
  std::vector<Vec2> renumbered(points.rbegin(), points.rend());
  RawEdges raw;
  for (auto it = edges.rbegin(); it != edges.rend(); ++it) raw.push_back({n - 1 - (*it)[0], n - 1 - (*it)[1]});
  return figure(renumbered, raw);
}

std::vector<StickFigure> three_drawings() {
  return {redrawn_walk_key(0, {1}), redrawn_walk_key(1, {2, 1, 3}), redrawn_walk_key(2, {1, 4})};
}

}  // namespace

TEST_CASE("correspond_key_poses: three keys drawn separately share one common figure") {
  const std::vector<StickFigure> keys = three_drawings();
  REQUIRE(keys[0].vertices.size() != keys[1].vertices.size());
  REQUIRE(keys[1].vertices.size() != keys[2].vertices.size());
  const KeyPoseCorrespondence c = correspond_key_poses(keys);
  REQUIRE(is_valid(c, keys));
  REQUIRE(c.matches.size() == 2);
  const std::size_t m = c.keys[0].vertices.size();
  for (const StickFigure& key : keys) REQUIRE(m >= key.vertices.size());
  // Key 1's vertices first, in order.
  for (std::size_t i = 0; i < keys[0].vertices.size(); ++i) REQUIRE(c.keys[0].vertices[i] == keys[0].vertices[i]);
  // The same joints matched: the matched keys' joints are the walk's joints
  // of each pose (the redrawing only renumbered and subdivided them).
  const std::vector<Vec2> pose0 = stick_man_walk_pose(0);
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const std::vector<Vec2> pose = stick_man_walk_pose(int(k));
    for (std::size_t joint = 0; joint < pose0.size(); ++joint) {
      const auto at = std::find(c.keys[0].vertices.begin(), c.keys[0].vertices.end(), pose0[joint]);
      REQUIRE(at != c.keys[0].vertices.end());
      const std::size_t i = std::size_t(at - c.keys[0].vertices.begin());
      INFO("key " << k + 1 << ", joint " << joint);
      REQUIRE(std::abs(c.keys[k].vertices[i][0] - pose[joint][0]) < 1e-12);
      REQUIRE(std::abs(c.keys[k].vertices[i][1] - pose[joint][1]) < 1e-12);
    }
  }
}

TEST_CASE("correspond_key_poses: errors name the keys") {
  std::vector<StickFigure> keys = three_drawings();
  SECTION("a key of another topology") {
    keys[2] = polyline({{0, 0}, {1, 0}, {2, 1}});
    REQUIRE_THROWS_AS(correspond_key_poses(keys), IncompatibleFiguresError);
    REQUIRE_THROWS_WITH(correspond_key_poses(keys), Contains("key 2 and key 3: "));
  }
  SECTION("a pin naming a vertex key 1 lacks") {
    KeyPoseCorrespondenceOptions options;
    options.pins = {{{999, 0}}};
    REQUIRE_THROWS_AS(correspond_key_poses(keys, options), InvalidArgumentError);
    REQUIRE_THROWS_WITH(correspond_key_poses(keys, options), Contains("key 1 and key 2: "));
  }
  SECTION("more pin lists than pairs") {
    KeyPoseCorrespondenceOptions options;
    options.pins = {{}, {}, {}};
    REQUIRE_THROWS_AS(correspond_key_poses(keys, options), InvalidArgumentError);
  }
  SECTION("one key") {
    REQUIRE_THROWS_AS(correspond_key_poses({keys[0]}), InvalidArgumentError);
  }
}

TEST_CASE("correspond_key_poses: pins of the second pair are in keys 2 and 3's own numbers") {
  const std::vector<StickFigure> keys = three_drawings();
  const KeyPoseCorrespondence free = correspond_key_poses(keys);
  // Take the free match's partner of some key-2 vertex in key 3 and pin it:
  // the pinned match must agree with it.
  const std::size_t m = free.keys[0].vertices.size();
  std::size_t i = 0;
  while (i < m && (free.places[1][i].vertex < 0 || free.places[2][i].vertex < 0)) ++i;
  REQUIRE(i < m);
  KeyPoseCorrespondenceOptions options;
  options.pins = {{}, {{free.places[1][i].vertex, free.places[2][i].vertex}}};
  const KeyPoseCorrespondence pinned = correspond_key_poses(keys, options);
  REQUIRE(is_valid(pinned, keys));
  bool found = false;
  for (std::size_t j = 0; j < pinned.keys[0].vertices.size(); ++j)
    found = found || (pinned.places[1][j].vertex == free.places[1][i].vertex &&
                      pinned.places[2][j].vertex == free.places[2][i].vertex);
  REQUIRE(found);
}

TEST_CASE("morph_key_poses with correspond auto: every frame valid, keys exact, every key vertex a frame vertex") {
  const std::vector<StickFigure> keys = three_drawings();
  KeyPoseMorphOptions options;
  options.correspond = CorrespondenceMode::Auto;
  options.frames = 41;
  const KeyPoseMorphResult result = morph_key_poses(keys, options);
  REQUIRE(result.correspondence);
  const KeyPoseCorrespondence& c = *result.correspondence;
  REQUIRE(is_valid(c, keys));
  REQUIRE(result.frames.size() == 41);
  for (std::size_t f = 0; f < result.frames.size(); ++f) {
    INFO("frame " << f);
    REQUIRE(is_frame_valid(c.keys[0], result.frames[f]));
  }
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const std::vector<Vec2>& frame = result.frames[std::size_t(result.key_frames[k])];
    REQUIRE(frame == c.keys[k].vertices);
    for (std::size_t i = 0; i < frame.size(); ++i)
      if (c.places[k][i].vertex >= 0) REQUIRE(frame[i] == keys[k].vertices[std::size_t(c.places[k][i].vertex)]);
  }
}

TEST_CASE("morph_key_poses: pins need correspond auto") {
  std::vector<StickFigure> keys;
  for (int k = 0; k < 3; ++k) keys.push_back(redrawn_walk_key(k, {1}));
  KeyPoseMorphOptions options;
  options.pins = {{{0, 0}}};
  REQUIRE_THROWS_AS(morph_key_poses(keys, options), InvalidArgumentError);
  REQUIRE_THROWS_WITH(morph_key_poses(keys, options), Contains("correspond='auto'"));
}
