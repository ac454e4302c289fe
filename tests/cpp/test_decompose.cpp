#include "catch.h"

#include <algorithm>

#include "figures.h"
#include "stickmorph/decomposition.h"

using namespace stickmorph;
using namespace stickmorph::test;

namespace {

const double kPi = 3.14159265358979323846;

std::vector<Vec2> corners_of(const StickFigure& f, const CyclicSequence& s) {
  std::vector<Vec2> corners;
  for (int v : s.vertices) corners.push_back(f.vertices[v]);
  return corners;
}

// Checks the invariants every decomposition must satisfy, and cross-checks
// the angle-sum rule against the exact signed area: interior sequences run
// counter-clockwise (positive area), the exterior one encloses no area on
// its left (zero for a tree, negative otherwise).
void check_decomposition(const StickFigure& f, const Decomposition& d) {
  REQUIRE(is_valid(d, f));
  for (const CyclicSequence& s : d.sequences) {
    const double n = double(s.vertices.size());
    const int area = signed_area_sign(corners_of(f, s));
    if (s.exterior) {
      CHECK(s.angle_sum == Approx(kPi * (n + 2)));
      CHECK(area <= 0);
    } else {
      CHECK(s.angle_sum == Approx(kPi * (n - 2)));
      CHECK(area > 0);
    }
  }
}

// The cyclic sequence as a list starting from its smallest vertex.
std::vector<int> canonical(std::vector<int> cycle) {
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  return cycle;
}

std::size_t interior_count(const Decomposition& d) {
  return std::count_if(d.sequences.begin(), d.sequences.end(),
                       [](const CyclicSequence& s) { return !s.exterior; });
}

}  // namespace

TEST_CASE("rotation_system orders edges counter-clockwise exactly", "[decompose]") {
  // A star: centre 0, leaves at 90, 0, 270, 180 degrees (edge order scrambled).
  const StickFigure star = figure({{0, 0}, {0, 1}, {1, 0}, {0, -1}, {-1, 0}}, {{0, 1}, {2, 0}, {0, 3}, {4, 0}});
  const RotationSystem rs = rotation_system(star);
  std::vector<int> heads;
  for (int d : rs.outgoing_ccw[0]) heads.push_back(dart_head(star, d));
  CHECK(heads == std::vector<int>{2, 1, 4, 3});
  for (int d = 0; d < 8; ++d) CHECK(rs.outgoing_ccw[rs.tail[d]][rs.position[d]] == d);
}

TEST_CASE("a polyline has one exterior sequence", "[decompose]") {
  const StickFigure f = polyline({{0, 0}, {1, 0}, {2, 1}, {3, 0}, {4, 0}});
  const Decomposition d = decompose(f);
  check_decomposition(f, d);
  REQUIRE(d.sequences.size() == 1);
  CHECK(d.sequences[0].exterior);
  CHECK(d.sequences[0].vertices.size() == 8);  // every edge walked twice
  CHECK(d.sequences[0].angle_sum == Approx(kPi * 10));
}

TEST_CASE("a single edge and a single vertex", "[decompose]") {
  const StickFigure edge = figure({{0, 0}, {1, 0}}, {{0, 1}});
  const Decomposition d = decompose(edge);
  check_decomposition(edge, d);
  REQUIRE(d.sequences.size() == 1);
  CHECK(d.sequences[0].angle_sum == Approx(4 * kPi));  // two 2*pi tips

  const StickFigure point = figure({{2, 2}}, {});
  const Decomposition p = decompose(point);
  CHECK(is_valid(p, point));
  REQUIRE(p.sequences.size() == 1);
  CHECK(p.sequences[0].exterior);
  CHECK(p.sequences[0].vertices == std::vector<int>{0});
}

TEST_CASE("a polygon has one interior and one exterior sequence", "[decompose]") {
  for (bool clockwise_input : {false, true}) {
    std::vector<Vec2> corners = regular(6);
    if (clockwise_input) std::reverse(corners.begin(), corners.end());
    const StickFigure f = polygon(corners);
    const Decomposition d = decompose(f);
    check_decomposition(f, d);
    REQUIRE(d.sequences.size() == 2);
    CHECK(interior_count(d) == 1);
    const CyclicSequence& inside = d.sequences[1 - d.exterior];
    // The interior runs counter-clockwise whatever the input order.
    const std::vector<int> ccw = clockwise_input ? std::vector<int>{0, 5, 4, 3, 2, 1}
                                                 : std::vector<int>{0, 1, 2, 3, 4, 5};
    CHECK(canonical(inside.vertices) == ccw);
    CHECK(inside.angle_sum == Approx(4 * kPi));
    CHECK(d.sequences[d.exterior].angle_sum == Approx(8 * kPi));
  }
}

TEST_CASE("a triangulation with t triangles has t interior sequences", "[decompose]") {
  const StickFigure f = grid_triangulation(5);
  const Decomposition d = decompose(f);
  check_decomposition(f, d);
  CHECK(interior_count(d) == 32);
  CHECK(d.sequences.size() == 33);
  for (const CyclicSequence& s : d.sequences)
    if (!s.exterior) CHECK(s.vertices.size() == 3);
  CHECK(d.sequences[d.exterior].vertices.size() == 16);
}

TEST_CASE("a tree is one exterior sequence with 2*pi angles at its leaves", "[decompose]") {
  const StickFigure tree = figure({{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}, {2, 1}, {2, -1}},
                                  {{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 5}, {1, 6}});
  const Decomposition d = decompose(tree);
  check_decomposition(tree, d);
  REQUIRE(d.sequences.size() == 1);
  CHECK(d.sequences[0].vertices.size() == 12);
  CHECK(std::count(d.sequences[0].vertices.begin(), d.sequences[0].vertices.end(), 0) == 4);
}

TEST_CASE("a dangling edge inside a face puts a 2*pi angle in the interior", "[decompose]") {
  // Unit square with an edge from corner 0 to the centre.
  const StickFigure f = figure({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}});
  const Decomposition d = decompose(f);
  check_decomposition(f, d);
  REQUIRE(d.sequences.size() == 2);
  const CyclicSequence& inside = d.sequences[1 - d.exterior];
  CHECK(inside.vertices.size() == 6);
  CHECK(std::count(inside.vertices.begin(), inside.vertices.end(), 0) == 2);
  CHECK(inside.angle_sum == Approx(4 * kPi));
}

TEST_CASE("a cut vertex is visited twice by the exterior", "[decompose]") {
  // Two triangles sharing vertex 0 (a bow tie).
  const StickFigure f = figure({{0, 0}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}},
                               {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {3, 4}, {4, 0}});
  const Decomposition d = decompose(f);
  check_decomposition(f, d);
  CHECK(interior_count(d) == 2);
  const std::vector<int>& outside = d.sequences[d.exterior].vertices;
  CHECK(outside.size() == 6);
  CHECK(std::count(outside.begin(), outside.end(), 0) == 2);
}

TEST_CASE("near-degenerate corners keep their class", "[decompose]") {
  // A needle triangle whose apex angle is about 1e-12 rad, and a polygon
  // with a reflex corner of 2*pi minus about 1e-12.
  const StickFigure needle = polygon({{0, 0}, {1, 0}, {1e12, 1}});
  check_decomposition(needle, decompose(needle));
  const StickFigure notch = polygon({{0, 0}, {1e12, 0}, {1e12, 1}, {1, 1e-12}, {0, 1}});
  check_decomposition(notch, decompose(notch));
}

TEST_CASE("random plane graphs decompose consistently", "[decompose]") {
  std::mt19937 rng(2001);
  for (int round = 0; round < 60; ++round) {
    const StickFigure f = random_plane_graph(rng, 8 + round % 30, 0.2 + 0.02 * (round % 40));
    const Decomposition d = decompose(f);
    check_decomposition(f, d);
  }
}
