// correspond_figures (issue 13; Surazhsky & Gotsman 2001, section 6's dummy
// vertices): two figures drawn separately, with other vertex counts,
// numbering and subdivision, matched as skeletons (plane maps keeping the
// rotation system and the exterior face) and chains resampled by arc length.
// Every matching here is checked with is_valid and check_compatibility; the
// node images and dummy counts are pinned where the geometry decides them.
#include "catch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "figures.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/morph_stick_figures.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A figure with its vertices renumbered and its edges shuffled and some
/// turned round; new_of_old[v] is the new index of old vertex v.
struct Renumbered {
  StickFigure figure;
  std::vector<int> new_of_old;
};

Renumbered renumbered(const StickFigure& f, std::uint32_t seed) {
  std::mt19937 rng(seed);
  const int n = int(f.vertices.size());
  Renumbered r;
  r.new_of_old.resize(std::size_t(n));
  std::iota(r.new_of_old.begin(), r.new_of_old.end(), 0);
  // Fisher-Yates on the raw output: the same permutation on every library.
  for (int i = n - 1; i > 0; --i) std::swap(r.new_of_old[std::size_t(i)], r.new_of_old[rng() % std::uint32_t(i + 1)]);
  std::vector<Vec2> vertices(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v) vertices[std::size_t(r.new_of_old[std::size_t(v)])] = f.vertices[std::size_t(v)];
  RawEdges edges;
  for (const Edge& e : f.edges) {
    std::int64_t a = r.new_of_old[std::size_t(e[0])], b = r.new_of_old[std::size_t(e[1])];
    if (rng() % 2) std::swap(a, b);
    edges.push_back({a, b});
  }
  for (std::size_t i = edges.size(); i > 1; --i) std::swap(edges[i - 1], edges[rng() % i]);
  r.figure = figure(std::move(vertices), edges);
  return r;
}

/// `f` with points[e] extra vertices on edge e, at even spacing when
/// `uneven` is false, else at seeded uneven fractions. The original vertices
/// keep their indices; the new ones follow, edge by edge.
StickFigure subdivided(const StickFigure& f, const std::vector<int>& points, bool uneven = false,
                       std::uint32_t seed = 1) {
  std::mt19937 rng(seed);
  std::vector<Vec2> vertices = f.vertices;
  RawEdges edges;
  for (std::size_t e = 0; e < f.edges.size(); ++e) {
    const int k = points[e];
    std::vector<double> fractions;
    for (int i = 1; i <= k; ++i) fractions.push_back(double(i) / (k + 1));
    if (uneven && k > 0) {
      // Cumulative random gaps in [1, 3): well separated, but not even.
      std::vector<double> gaps;
      double total = 0;
      for (int i = 0; i <= k; ++i) total += gaps.emplace_back(1.0 + 2.0 * double(rng()) / 4294967296.0);
      double run = 0;
      for (int i = 0; i < k; ++i) fractions[std::size_t(i)] = (run += gaps[std::size_t(i)]) / total;
    }
    std::int64_t previous = f.edges[e][0];
    const Vec2& a = f.vertices[std::size_t(f.edges[e][0])];
    const Vec2& b = f.vertices[std::size_t(f.edges[e][1])];
    for (double t : fractions) {
      vertices.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
      const std::int64_t v = std::int64_t(vertices.size()) - 1;
      edges.push_back({previous, v});
      previous = v;
    }
    edges.push_back({previous, f.edges[e][1]});
  }
  return figure(std::move(vertices), edges);
}

StickFigure reflected(const StickFigure& f) {
  StickFigure g = f;
  for (Vec2& p : g.vertices) p[0] = -p[0];
  return g;
}

int source_dummies(const FigureCorrespondence& c) {
  return int(std::count_if(c.source_places.begin(), c.source_places.end(),
                           [](const MatchedPlace& p) { return p.vertex < 0; }));
}
int target_dummies(const FigureCorrespondence& c) {
  return int(std::count_if(c.target_places.begin(), c.target_places.end(),
                           [](const MatchedPlace& p) { return p.vertex < 0; }));
}

/// The matched target vertex of source vertex v (-1: a dummy on the target).
int partner(const FigureCorrespondence& c, int v) { return c.target_places[std::size_t(v)].vertex; }

/// is_valid, compatible, the documented layout, and the counts that follow
/// from it: source vertices first in order, then one source dummy per target
/// vertex without a source partner, in target order.
void check_matching(const FigureCorrespondence& c, const StickFigure& s, const StickFigure& t) {
  REQUIRE(is_valid(c, s, t));
  const CompatibilityReport report = check_compatibility(c.source, c.target);
  INFO(report.reason);
  REQUIRE(report.compatible());
  const int m = int(c.source.vertices.size());
  const int ns = int(s.vertices.size()), nt = int(t.vertices.size());
  REQUIRE(m >= std::max(ns, nt));
  for (int v = 0; v < ns; ++v) REQUIRE(c.source_places[std::size_t(v)].vertex == v);
  int previous = -1;
  for (int i = ns; i < m; ++i) {
    REQUIRE(c.source_places[std::size_t(i)].vertex < 0);
    REQUIRE(c.target_places[std::size_t(i)].vertex > previous);  // in target order, never a dummy on both
    previous = c.target_places[std::size_t(i)].vertex;
  }
  CHECK(source_dummies(c) == m - ns);
  CHECK(target_dummies(c) == m - nt);
  CHECK(c.residual >= 0);
  CHECK(c.residual <= 1);
  CHECK(c.candidates >= 1);
  CHECK(c.milliseconds >= 0);
}

template <class F>
IncompatibleFiguresError incompatible(F&& run) {
  try {
    run();
  } catch (const IncompatibleFiguresError& error) {
    return error;
  }
  FAIL("no IncompatibleFiguresError");
  throw;  // not reached
}

// A stick man (figures.h): a junction of degree 4 (chest, vertex 1) and one of
// degree 3 (pelvis, 0), five ends, bent arms and legs as chains.
const StickFigure kMan = stick_man_standing();

/// T: junction 0 at the origin, ends 1 (left), 2 (right), 3 (down, longer).
StickFigure t_shape() { return figure({{0, 0}, {-1, 0}, {1.2, 0}, {0, -2}}, {{0, 1}, {0, 2}, {0, 3}}); }

/// X: junction 0, four ends.
StickFigure x_shape() { return figure({{0, 0}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}}, {{0, 1}, {0, 2}, {0, 3}, {0, 4}}); }

/// A "P": stem 0 (end) - 1 - 2 (junction), and the bowl 2-3-4-5-6-7-2.
StickFigure p_shape() {
  return figure({{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 4}, {1.5, 3}, {1, 2}},
                {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 2}});
}

/// A chiral tree: centre 0 (degree 3) with, counter-clockwise, a degree-3
/// junction 1 (two ends), a degree-4 junction 2 (three ends) and an end 3.
/// Its mirror image sees these in the order 1, 3, 2: no orientation-
/// preserving isomorphism, since every node's image is forced.
StickFigure chiral_tree() {
  return figure({{0, 0}, {2, 0}, {-1, 1.7}, {-0.8, -1.5},  // centre, J3, J4, end
                 {3, 0.8}, {3, -0.8},                     // ends of J3
                 {-1.2, 2.9}, {-2.1, 2.0}, {-0.2, 2.6}},  // ends of J4
                {{0, 1}, {0, 2}, {0, 3}, {1, 4}, {1, 5}, {2, 6}, {2, 7}, {2, 8}});
}

/// A plus sign: centre 0, arms ending at 1 (east), 2 (north), 3 (west), 4 (south).
StickFigure plus_sign() { return figure({{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}}, {{0, 1}, {0, 2}, {0, 3}, {0, 4}}); }

const std::vector<Vec2> kSquare = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

}  // namespace

// --------------------------------------------------------------- same drawing

TEST_CASE("an identical figure renumbered and moved matches vertex for vertex, with no dummy",
          "[correspond_figures]") {
  const Renumbered target = renumbered(moved(kMan, 0.7, 1.8, 5, -3), 17);
  const FigureCorrespondence c = correspond_figures(kMan, target.figure);
  check_matching(c, kMan, target.figure);
  CHECK(c.source.vertices.size() == kMan.vertices.size());
  CHECK(source_dummies(c) == 0);
  CHECK(target_dummies(c) == 0);
  for (int v = 0; v < int(kMan.vertices.size()); ++v) CHECK(partner(c, v) == target.new_of_old[std::size_t(v)]);
  CHECK(c.skeleton_nodes == 7);   // two junctions and five ends
  CHECK(c.skeleton_chains == 6);  // spine, head, two arms, two legs
  CHECK(c.candidates == 1);       // the pelvis's three darts: only one sends the spine to the chest
  CHECK(c.residual == Approx(0).margin(1e-9));
  CHECK(c.rotation_degrees == Approx(0.7 * 180 / kPi).margin(1e-6));
  // The matched target is the target's own drawing, vertex by vertex.
  for (int v = 0; v < int(kMan.vertices.size()); ++v)
    CHECK(c.target.vertices[std::size_t(v)] == target.figure.vertices[std::size_t(target.new_of_old[std::size_t(v)])]);
  CHECK(c.source.vertices == kMan.vertices);
}

TEST_CASE("an asymmetric figure turned by a large angle still matches itself exactly", "[correspond_figures]") {
  // Each figure against itself turned: the identity is an exact fit
  // (residual 0); every other matching distorts the drawing visibly (radii
  // or arm lengths differ by 20-30%).
  //
  // A regression test: an additive rotation charge (19441e2) once let a
  // wrong matching with a small rotation beat the exact one (the
  // quadrilateral turned by 120 degrees matched vertex to neighbour). The
  // charge now multiplies the residual, so an exact fit always wins.
  struct Case {
    const char* name;
    StickFigure figure;
    double degrees;
  };
  const std::vector<Case> cases = {
      {"quadrilateral with radii 1, 0.8, 0.9, 0.7", polygon({{1, 0}, {0, 0.8}, {-0.9, 0}, {0, -0.7}}), 120},
      {"irregular pentagon", polygon({{1, 0}, {0.3, 0.9}, {-0.8, 0.6}, {-0.7, -0.7}, {0.3, -0.85}}), 60},
      {"plus sign with arms 1, 0.9, 1, 0.8",
       figure({{0, 0}, {1, 0}, {0, 0.9}, {-1, 0}, {0, -0.8}}, {{0, 1}, {0, 2}, {0, 3}, {0, 4}}), 135},
  };
  for (const Case& c : cases) {
    INFO(c.name << " turned by " << c.degrees << " degrees");
    const Renumbered turned = renumbered(moved(c.figure, c.degrees * kPi / 180, 1.0, 0, 0), 3);
    const FigureCorrespondence m = correspond_figures(c.figure, turned.figure);
    check_matching(m, c.figure, turned.figure);
    CHECK(m.source.vertices.size() == c.figure.vertices.size());
    for (int v = 0; v < int(c.figure.vertices.size()); ++v) CHECK(partner(m, v) == turned.new_of_old[std::size_t(v)]);
    CHECK(m.residual == Approx(0).margin(1e-9));
    CHECK(m.rotation_degrees == Approx(c.degrees).margin(1e-4));
  }
}

TEST_CASE("a random plane graph with faces matches its renumbered, rotated copy exactly", "[correspond_figures]") {
  std::mt19937 rng(4242);
  for (int round = 0; round < 6; ++round) {
    const StickFigure s = random_plane_graph(rng, 12 + 3 * round, 0.5);
    const Renumbered t = renumbered(moved(s, -0.4 + 0.3 * round, 0.6, -2, 7), 100 + std::uint32_t(round));
    INFO("round " << round);
    const FigureCorrespondence c = correspond_figures(s, t.figure);
    check_matching(c, s, t.figure);
    CHECK(source_dummies(c) == 0);
    for (int v = 0; v < int(s.vertices.size()); ++v) CHECK(partner(c, v) == t.new_of_old[std::size_t(v)]);
  }
}

TEST_CASE("a reflected figure whose mirror is the same plane map is matched, not refused", "[correspond_figures]") {
  // The stick man reflected: his left and right limbs swap, and the plane
  // map (chest: spine, head, arm, arm) is the same.
  const StickFigure mirror = reflected(kMan);
  const FigureCorrespondence c = correspond_figures(kMan, mirror);
  check_matching(c, kMan, mirror);
  CHECK(source_dummies(c) == 0);
  CHECK(partner(c, 0) == 0);  // pelvis
  CHECK(partner(c, 1) == 1);  // chest
  CHECK(partner(c, 2) == 2);  // head
  // A theta graph (two junctions joined by three strokes) reflected is its
  // own plane map too.
  const StickFigure theta = figure({{0, 0}, {4, 0}, {1, 2}, {3, 1.5}, {2, 0.3}, {2, -1.5}},
                                   {{0, 2}, {2, 3}, {3, 1}, {0, 4}, {4, 1}, {0, 5}, {5, 1}});
  const StickFigure theta_mirror = moved(reflected(theta), 2.0, 1.0, 0, 0);
  const FigureCorrespondence ct = correspond_figures(theta, theta_mirror);
  check_matching(ct, theta, theta_mirror);
  CHECK(ct.skeleton_nodes == 2);
  CHECK(ct.skeleton_chains == 3);
}

// ---------------------------------------------------------------- subdivision

TEST_CASE("a square against the same square subdivided: corners to corners, dummies on their edges",
          "[correspond_figures]") {
  const StickFigure square = polygon(kSquare);
  // 1, 2, 0, 3 extra vertices on edges 0-1, 1-2, 2-3, 3-0.
  const StickFigure fine = subdivided(square, {1, 2, 0, 3});
  REQUIRE(fine.vertices.size() == 10);
  const FigureCorrespondence c = correspond_figures(square, fine);
  check_matching(c, square, fine);
  CHECK(c.skeleton_nodes == 0);
  CHECK(c.skeleton_chains == 1);
  for (int v = 0; v < 4; ++v) CHECK(partner(c, v) == v);
  CHECK(c.source.vertices.size() == 10);
  CHECK(source_dummies(c) == 6);
  CHECK(target_dummies(c) == 0);
  // The dummy of target vertex 4..9 is on the source edge it subdivides, at
  // the same point (the drawings coincide).
  const std::vector<int> edge_of = {0, 1, 1, 3, 3, 3};
  for (int i = 4; i < 10; ++i) {
    INFO("matched vertex " << i);
    const MatchedPlace& place = c.source_places[std::size_t(i)];
    CHECK(c.target_places[std::size_t(i)].vertex == i);
    CHECK(place.edge == edge_of[std::size_t(i - 4)]);
    CHECK(c.source.vertices[std::size_t(i)][0] == Approx(fine.vertices[std::size_t(i)][0]).margin(1e-9));
    CHECK(c.source.vertices[std::size_t(i)][1] == Approx(fine.vertices[std::size_t(i)][1]).margin(1e-9));
  }
  CHECK(c.residual == Approx(0).margin(1e-9));
  // A loop's shift is refined by golden-section search: to about 1e-8 turn.
  CHECK(c.rotation_degrees == Approx(0).margin(1e-4));
}

TEST_CASE("a square against a renumbered, turned, subdivided copy starting at another corner",
          "[correspond_figures]") {
  const StickFigure square = polygon(kSquare);
  // Turned by 30 degrees (less than the square's 45-degree ambiguity), so
  // each corner's partner is its own image.
  const Renumbered target = renumbered(moved(subdivided(square, {2, 1, 3, 1}, true, 9), kPi / 6, 2.0, 1, 1), 5);
  const FigureCorrespondence c = correspond_figures(square, target.figure);
  check_matching(c, square, target.figure);
  for (int v = 0; v < 4; ++v) CHECK(partner(c, v) == target.new_of_old[std::size_t(v)]);
  CHECK(source_dummies(c) == 7);
  CHECK(target_dummies(c) == 0);
  CHECK(c.rotation_degrees == Approx(30).margin(1e-4));
}

TEST_CASE("a T against a subdivided, moved T: junction and ends matched, dummies elsewhere", "[correspond_figures]") {
  const StickFigure t = t_shape();
  const Renumbered fine = renumbered(moved(subdivided(t, {2, 0, 4}, true, 3), -0.5, 0.7, 3, 3), 11);
  const FigureCorrespondence c = correspond_figures(t, fine.figure);
  check_matching(c, t, fine.figure);
  CHECK(c.skeleton_nodes == 4);
  CHECK(c.skeleton_chains == 3);
  CHECK(c.candidates == 3);  // the junction's three darts
  for (int v = 0; v < 4; ++v) CHECK(partner(c, v) == fine.new_of_old[std::size_t(v)]);
  CHECK(source_dummies(c) == 6);
  CHECK(target_dummies(c) == 0);
  // The other way round: the T's vertices are the dummies on the target side.
  const FigureCorrespondence back = correspond_figures(fine.figure, t);
  check_matching(back, fine.figure, t);
  for (int v = 0; v < 4; ++v) CHECK(partner(back, fine.new_of_old[std::size_t(v)]) == v);
  CHECK(source_dummies(back) == 0);
  CHECK(target_dummies(back) == 6);
}

TEST_CASE("an open polyline numbered the other way round is matched end to end, the direction found",
          "[correspond_figures]") {
  // A hook: asymmetric, so only one direction fits.
  const std::vector<Vec2> hook = {{0, 0}, {3, 0}, {4, 1}, {4, 2}, {3, 2.5}};
  const StickFigure s = polyline(hook);
  const std::vector<Vec2> reversed_points(hook.rbegin(), hook.rend());
  const StickFigure t = moved(polyline(reversed_points), 1.0, 1.5, -1, 0);
  const FigureCorrespondence c = correspond_figures(s, t);
  check_matching(c, s, t);
  CHECK(c.candidates == 2);  // either end first
  for (int v = 0; v < 5; ++v) CHECK(partner(c, v) == 4 - v);
  CHECK(source_dummies(c) == 0);
  CHECK(c.residual == Approx(0).margin(1e-9));
  // Subdivided differently on both sides, the ends still meet their partners.
  const StickFigure s2 = subdivided(s, {3, 0, 1, 0}, true, 7);
  const StickFigure t2 = subdivided(t, {0, 2, 0, 5}, true, 8);
  const FigureCorrespondence c2 = correspond_figures(s2, t2);
  check_matching(c2, s2, t2);
  CHECK(partner(c2, 0) == 4);
  CHECK(partner(c2, 4) == 0);
  // Vertices 1-3 are on both drawings, at the same arc length: merged.
  for (int v = 1; v < 4; ++v) CHECK(partner(c2, v) == 4 - v);
}

TEST_CASE("a loop with a tail (a P) against a subdivided copy", "[correspond_figures]") {
  const StickFigure p = p_shape();
  const std::vector<int> extra = {1, 0, 2, 0, 1, 3, 0, 2};
  const Renumbered fine = renumbered(moved(subdivided(p, extra, true, 21), 0.3, 1.1, 0, 0), 23);
  const FigureCorrespondence c = correspond_figures(p, fine.figure);
  check_matching(c, p, fine.figure);
  CHECK(c.skeleton_nodes == 2);   // the stem's end and the junction
  CHECK(c.skeleton_chains == 2);  // the stem and the bowl
  for (int v = 0; v < 8; ++v) CHECK(partner(c, v) == fine.new_of_old[std::size_t(v)]);
  CHECK(source_dummies(c) == 9);
  CHECK(target_dummies(c) == 0);
  // And the other way round.
  const FigureCorrespondence back = correspond_figures(fine.figure, p);
  check_matching(back, fine.figure, p);
  for (int v = 0; v < 8; ++v) CHECK(partner(back, fine.new_of_old[std::size_t(v)]) == v);
}

TEST_CASE("a figure eight (two loops at one junction) against a subdivided copy", "[correspond_figures]") {
  // Junction 0 of degree 4; an upper loop 0-1-2-3 and a larger lower loop 0-4-5-6-7.
  const StickFigure eight = figure({{0, 0}, {1, 1}, {0, 2}, {-1, 1}, {-1.5, -1}, {-1, -2.5}, {1, -2.5}, {1.5, -1}},
                                   {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 0}});
  const Renumbered fine = renumbered(subdivided(eight, {1, 1, 1, 1, 0, 2, 0, 2, 0}), 31);
  const FigureCorrespondence c = correspond_figures(eight, fine.figure);
  check_matching(c, eight, fine.figure);
  CHECK(c.skeleton_nodes == 1);
  CHECK(c.skeleton_chains == 2);
  for (int v = 0; v < 8; ++v) CHECK(partner(c, v) == fine.new_of_old[std::size_t(v)]);
  CHECK(source_dummies(c) == 8);
}

TEST_CASE("an identical loop, turned, matches with no dummy vertex", "[correspond_figures]") {
  // A star-shaped heptagon with seeded radii, turned by 0.3 rad: every
  // vertex is on both drawings at the same arc length, so m must be 7.
  //
  // A regression test: the loop's common parameter runs from the source's
  // vertex 0 (order 0), and the target partner of that vertex lands at order
  // 1 - 4e-8 when the golden-section shift is a hair above the exact one. A
  // merge that did not look across the seam gave m = 8 at 0.3 rad: source
  // vertex 0 with a dummy on target edge 0 at fraction 3.9e-8 and target
  // vertex 0 with a dummy 3e-8 from source vertex 0 (fixed in 6cc2995).
  std::mt19937 rng(7030);
  std::vector<Vec2> corners;
  for (int i = 0; i < 7; ++i) {
    const double r = 0.6 + 0.4 * (double(rng()) / 4294967296.0), a = 2 * kPi * i / 7;
    corners.push_back({r * std::cos(a), r * std::sin(a)});
  }
  const StickFigure loop = polygon(corners);
  int failures = 0;
  for (const double angle : {0.0, 0.1, 0.2, 0.3}) {
    INFO("turned by " << angle);
    const StickFigure turned = moved(loop, angle, 1.0, 0, 0);
    const FigureCorrespondence c = correspond_figures(loop, turned);
    check_matching(c, loop, turned);
    CHECK(c.source.vertices.size() == 7);
    for (int v = 0; v < 7; ++v) CHECK(partner(c, v) == v);
    if (c.source.vertices.size() != 7) ++failures;
  }
  CHECK(failures == 0);
}

// ------------------------------------------------------------------- refusals

TEST_CASE("a loop with its tail outside against one with the tail inside: the exterior differs",
          "[correspond_figures]") {
  // The same plane map (a junction, an end, a loop); the tail is in the
  // exterior face of one and in the bounded face of the other.
  const std::vector<Vec2> box = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const RawEdges edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}};
  std::vector<Vec2> outside = box, inside = box;
  outside.push_back({-1, -1});
  inside.push_back({1, 1});
  const StickFigure balloon = figure(outside, edges), clock = figure(inside, edges);
  const IncompatibleFiguresError error = incompatible([&] { correspond_figures(balloon, clock); });
  CHECK(error.kind() == Incompatibility::ExteriorDiffers);
  CHECK_THAT(std::string(error.what()), Contains("another face outside"));
  // Each matches a turned, subdivided copy of itself.
  for (const StickFigure* f : {&balloon, &clock}) {
    const StickFigure copy = moved(subdivided(*f, {1, 0, 2, 0, 1}), 0.2, 1.0, 0, 0);
    const FigureCorrespondence c = correspond_figures(*f, copy);
    check_matching(c, *f, copy);
    for (int v = 0; v < 5; ++v) CHECK(partner(c, v) == v);
  }
}


TEST_CASE("a chiral tree against its mirror image is refused as a mirror image", "[correspond_figures]") {
  const StickFigure tree = chiral_tree();
  const StickFigure mirror = renumbered(moved(reflected(tree), 1.3, 0.9, 4, 0), 41).figure;
  const IncompatibleFiguresError error = incompatible([&] { correspond_figures(tree, mirror); });
  CHECK(error.kind() == Incompatibility::MirrorImage);
  CHECK_THAT(std::string(error.what()), Contains("mirror image"));
  // Turned, not reflected, it matches.
  const Renumbered turned = renumbered(moved(tree, 2.5, 0.9, 4, 0), 41);
  const FigureCorrespondence c = correspond_figures(tree, turned.figure);
  check_matching(c, tree, turned.figure);
  for (int v = 0; v < 9; ++v) CHECK(partner(c, v) == turned.new_of_old[std::size_t(v)]);
}

TEST_CASE("a loop against a tree is refused: the topologies differ, the message says loop", "[correspond_figures]") {
  const StickFigure square = polygon(kSquare);
  const StickFigure path = polyline(kSquare);
  const IncompatibleFiguresError error = incompatible([&] { correspond_figures(square, path); });
  CHECK(error.kind() == Incompatibility::TopologyDiffers);
  CHECK_THAT(std::string(error.what()), Contains("loop"));
  CHECK_THAT(std::string(error.what()), Contains("the source has 1 loop"));
  const IncompatibleFiguresError back = incompatible([&] { correspond_figures(path, square); });
  CHECK(back.kind() == Incompatibility::TopologyDiffers);
  CHECK_THAT(std::string(back.what()), Contains("loop"));
  // A P (one loop, with a tail) against a plain loop: the same cycle count,
  // but a junction and an end against none.
  const IncompatibleFiguresError tail = incompatible([&] { correspond_figures(p_shape(), square); });
  CHECK(tail.kind() == Incompatibility::TopologyDiffers);
  CHECK_THAT(std::string(tail.what()), Contains("one closed loop"));
}

TEST_CASE("a T against an X is refused, naming the junction degrees", "[correspond_figures]") {
  const IncompatibleFiguresError error = incompatible([&] { correspond_figures(t_shape(), x_shape()); });
  CHECK(error.kind() == Incompatibility::TopologyDiffers);
  CHECK_THAT(std::string(error.what()),
             Contains("the source has 3 ends and a junction of degree 3, the target 4 ends and a junction of degree 4"));
}

TEST_CASE("two trees with the same degrees but another arrangement are refused", "[correspond_figures]") {
  // Both have junctions of degree 3, 3 and 4 and six ends; in the chiral
  // tree the degree-4 junction hangs off a degree-3 one, here it is between
  // the two, each of which carries two ends.
  const StickFigure other = figure({{0, 0}, {2, 0}, {-2, 0}, {0, 1.5}, {0, -1.5},  // J4, J3, J3, ends of J4
                                    {3, 1}, {3, -1}, {-3, 1}, {-3, -1}},            // ends of the J3s
                                   {{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 5}, {1, 6}, {2, 7}, {2, 8}});
  const IncompatibleFiguresError error = incompatible([&] { correspond_figures(chiral_tree(), other); });
  CHECK(error.kind() == Incompatibility::TopologyDiffers);
  CHECK_THAT(std::string(error.what()), Contains("another arrangement"));
}

TEST_CASE("two single vertices match; a single vertex against an edge does not", "[correspond_figures]") {
  const StickFigure a = figure({{1, 2}}, {});
  const StickFigure b = figure({{-5, 3}}, {});
  const FigureCorrespondence c = correspond_figures(a, b);
  check_matching(c, a, b);
  CHECK(c.source.vertices.size() == 1);
  CHECK(partner(c, 0) == 0);
  CHECK(c.target.vertices[0] == Vec2{-5, 3});
  const StickFigure edge = figure({{0, 0}, {1, 0}}, {{0, 1}});
  for (const auto& [one, other] : {std::pair{&a, &edge}, std::pair{&edge, &a}}) {
    // Copies for the lambda: C++17 does not let it capture structured bindings (clang refuses).
    const StickFigure* s = one;
    const StickFigure* t = other;
    const IncompatibleFiguresError error = incompatible([&] { correspond_figures(*s, *t); });
    CHECK(error.kind() == Incompatibility::TopologyDiffers);
    CHECK_THAT(std::string(error.what()), Contains("a single vertex"));
    CHECK_THAT(std::string(error.what()), Contains("2 ends and no junction"));
  }
  // Two single edges: either way round fits, the smaller rotation wins.
  const StickFigure other = figure({{5, 5}, {6, 7}}, {{0, 1}});
  const FigureCorrespondence ce = correspond_figures(edge, other);
  check_matching(ce, edge, other);
  CHECK(partner(ce, 0) == 0);
  CHECK(partner(ce, 1) == 1);
  CHECK(ce.rotation_degrees == Approx(std::atan2(2.0, 1.0) * 180 / kPi).margin(1e-6));
}

// ----------------------------------------------------------------------- pins

TEST_CASE("a pin turns the match of a symmetric plus sign by a quarter", "[correspond_figures]") {
  const StickFigure plus = plus_sign();
  const FigureCorrespondence plain = correspond_figures(plus, plus);
  check_matching(plain, plus, plus);
  CHECK(plain.candidates == 4);  // four equal fits: the smallest rotation wins
  for (int v = 0; v < 5; ++v) CHECK(partner(plain, v) == v);
  CHECK(plain.rotation_degrees == Approx(0).margin(1e-6));
  // East to north: every arm turns a quarter counter-clockwise.
  const FigureCorrespondence c = correspond_figures(plus, plus, {{{1, 2}}});
  check_matching(c, plus, plus);
  CHECK(c.candidates == 1);
  CHECK(partner(c, 0) == 0);
  CHECK(partner(c, 1) == 2);
  CHECK(partner(c, 2) == 3);
  CHECK(partner(c, 3) == 4);
  CHECK(partner(c, 4) == 1);
  CHECK(c.rotation_degrees == Approx(90).margin(1e-6));
  // East to south, pinned through the centre as well.
  const FigureCorrespondence d = correspond_figures(plus, plus, {{{0, 0}, {1, 4}}});
  check_matching(d, plus, plus);
  CHECK(partner(d, 1) == 4);
  CHECK(partner(d, 2) == 1);
  CHECK(d.rotation_degrees == Approx(-90).margin(1e-6));
}

TEST_CASE("a pin inside a stroke chooses the rotation of a subdivided plus sign", "[correspond_figures]") {
  // Every arm with one midpoint (vertices 5..8 on arms 1..4).
  const StickFigure plus = subdivided(plus_sign(), {1, 1, 1, 1});
  // The east arm's midpoint (5) to the west arm's (7): a half turn.
  const FigureCorrespondence c = correspond_figures(plus, plus, {{{5, 7}}});
  check_matching(c, plus, plus);
  CHECK(partner(c, 1) == 3);
  CHECK(partner(c, 2) == 4);
  CHECK(partner(c, 5) == 7);
  CHECK(partner(c, 6) == 8);
  CHECK(source_dummies(c) == 0);
  CHECK(std::abs(c.rotation_degrees) == Approx(180).margin(1e-6));
}

TEST_CASE("pins are checked: kinds, ranges, repeats", "[correspond_figures]") {
  const StickFigure plus = subdivided(plus_sign(), {1, 1, 1, 1});
  auto refused = [&](std::vector<VertexPin> pins, const std::string& text) {
    INFO(text);
    CHECK_THROWS_AS(correspond_figures(plus, plus, {pins}), InvalidArgumentError);
    CHECK_THROWS_WITH(correspond_figures(plus, plus, {pins}), Contains(text));
  };
  refused({{0, 5}}, "pin 0:5 joins a vertex of degree 4 to one of degree 2");
  refused({{5, 0}}, "pin 5:0 joins a vertex of degree 2 to one of degree 4");
  refused({{1, 0}}, "pin 1:0 joins a vertex of degree 1 to one of degree 4");
  refused({{9, 1}}, "the source has no vertex 9 (it has 9 vertices)");
  refused({{1, 9}}, "the target has no vertex 9");
  refused({{-1, 1}}, "the source has no vertex -1");
  refused({{1, 2}, {1, 3}}, "source vertex 1 is pinned twice");
  refused({{1, 2}, {3, 2}}, "target vertex 2 is pinned twice");
  refused({{1, 2}, {1, 2}}, "pinned twice");
}

TEST_CASE("contradictory pins are refused as unsatisfiable", "[correspond_figures]") {
  const StickFigure plus = subdivided(plus_sign(), {1, 1, 1, 1});
  // East to north asks for a quarter turn, north to south for a half turn.
  const IncompatibleFiguresError nodes = incompatible([&] { correspond_figures(plus, plus, {{{1, 2}, {2, 4}}}); });
  CHECK(nodes.kind() == Incompatibility::PinsUnsatisfiable);
  CHECK_THAT(std::string(nodes.what()), Contains("no matching respects every pin"));
  // A node pin and a pin inside a stroke that disagree.
  const IncompatibleFiguresError mixed = incompatible([&] { correspond_figures(plus, plus, {{{1, 1}, {5, 6}}}); });
  CHECK(mixed.kind() == Incompatibility::PinsUnsatisfiable);
  // The end and the inside of a polyline in opposite directions.
  const StickFigure path = subdivided(polyline({{0, 0}, {4, 0}}), {3});  // 0, 2, 3, 4, 1 along the line
  const IncompatibleFiguresError order =
      incompatible([&] { correspond_figures(path, path, {{{0, 0}, {2, 4}, {4, 2}}}); });
  CHECK(order.kind() == Incompatibility::PinsUnsatisfiable);
  CHECK_THAT(std::string(order.what()), Contains("out of order"));
  // Without the end pinned the same pins reverse the line.
  const FigureCorrespondence reversed = correspond_figures(path, path, {{{2, 4}, {4, 2}}});
  check_matching(reversed, path, path);
  CHECK(partner(reversed, 0) == 1);
  CHECK(partner(reversed, 3) == 3);
}

TEST_CASE("a node pin that no matching satisfies is refused as unsatisfiable, whatever the figures",
          "[correspond_figures]") {
  // Each pair below is a figure and itself, which match without the pin.
  //
  // A regression test: the search once seeded at the first pin's target
  // node only, so a pin no isomorphism allows made the figures look
  // unmatchable (a mirror image, another arrangement, another exterior).
  // Now every isomorphism is tried and the pins only filter.
  struct Case {
    const char* name;
    StickFigure figure;
    std::vector<VertexPin> pins;
  };
  const StickFigure k4 = figure({{0, 0}, {4, 0}, {2, 3.5}, {2, 1.2}}, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}});
  const std::vector<Case> cases = {
      {"stick man, head to left hand", kMan, {{2, 4}}},
      {"chiral tree, the centre's end to an end of the degree-3 junction", chiral_tree(), {{3, 4}}},
      {"chiral tree, the centre to the degree-3 junction", chiral_tree(), {{0, 1}}},
      {"K4, the centre to a corner of the outer triangle", k4, {{3, 0}}},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    REQUIRE_NOTHROW(correspond_figures(c.figure, c.figure));
    const IncompatibleFiguresError error = incompatible([&] { correspond_figures(c.figure, c.figure, {c.pins}); });
    CHECK(error.kind() == Incompatibility::PinsUnsatisfiable);
    CHECK_THAT(std::string(error.what()), Contains("no matching respects every pin"));
  }
  // A second node pin that breaks the match is reported right already.
  const IncompatibleFiguresError second = incompatible([&] { correspond_figures(kMan, kMan, {{{2, 2}, {4, 8}}}); });
  CHECK(second.kind() == Incompatibility::PinsUnsatisfiable);
  CHECK_THAT(std::string(second.what()), Contains("it would send source vertex 4 to target vertex 4, not 8"));
}

TEST_CASE("pins on two loops: kept when in the same counter-clockwise order, refused otherwise",
          "[correspond_figures]") {
  // An octagon: vertices 0..7 counter-clockwise.
  const StickFigure octagon = polygon(regular(8));
  // Two pins are always in the same cyclic order: 0 -> 2 and 4 -> 1 is a
  // valid (if uneven) matching.
  const FigureCorrespondence two = correspond_figures(octagon, octagon, {{{0, 2}, {4, 1}}});
  check_matching(two, octagon, octagon);
  CHECK(partner(two, 0) == 2);
  CHECK(partner(two, 4) == 1);
  CHECK(two.candidates == 1);
  // Three pins in the reverse cyclic order: 0, 2, 4 to 0, 6, 4 (clockwise).
  const IncompatibleFiguresError three =
      incompatible([&] { correspond_figures(octagon, octagon, {{{0, 0}, {2, 6}, {4, 4}}}); });
  CHECK(three.kind() == Incompatibility::PinsUnsatisfiable);
  CHECK_THAT(std::string(three.what()), Contains("counter-clockwise order"));
  // In the same order, turned by a quarter: the pins decide.
  const FigureCorrespondence turned = correspond_figures(octagon, octagon, {{{0, 2}, {2, 4}, {4, 6}}});
  check_matching(turned, octagon, octagon);
  for (int v = 0; v < 8; ++v) CHECK(partner(turned, v) == (v + 2) % 8);
  CHECK(turned.rotation_degrees == Approx(90).margin(1e-4));
}

// ----------------------------------------------------------------------- size

namespace {

/// A spanning tree of a k by k grid (Kruskal over the grid edges in a seeded
/// order): a plane tree with junctions of degree 3 and 4, ends and bends.
StickFigure grid_tree(int k, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<Vec2> points;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) points.push_back({double(j), double(i) + 0.01 * j});  // no collinear rows
  std::vector<std::array<int, 2>> all;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      if (j + 1 < k) all.push_back({i * k + j, i * k + j + 1});
      if (i + 1 < k) all.push_back({i * k + j, (i + 1) * k + j});
    }
  for (std::size_t i = all.size(); i > 1; --i) std::swap(all[i - 1], all[rng() % i]);
  std::vector<int> parent(std::size_t(k * k));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int v) {
    while (parent[std::size_t(v)] != v) v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
    return v;
  };
  RawEdges edges;
  for (const auto& [a, b] : all)
    if (root(a) != root(b)) {
      parent[std::size_t(root(a))] = root(b);
      edges.push_back({a, b});
    }
  return figure(std::move(points), edges);
}

std::vector<int> seeded_counts(std::size_t edges, int most, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<int> counts;
  for (std::size_t e = 0; e < edges; ++e) counts.push_back(int(rng() % std::uint32_t(most + 1)));
  return counts;
}

}  // namespace

TEST_CASE("a 1000-vertex subdivided tree against a renumbered copy subdivided otherwise", "[correspond_figures]") {
  const StickFigure tree = grid_tree(16, 77);  // 256 vertices, 255 edges
  const StickFigure s = subdivided(tree, seeded_counts(tree.edges.size(), 5, 1), true, 2);
  const Renumbered t = renumbered(moved(subdivided(tree, seeded_counts(tree.edges.size(), 5, 3), true, 4), 0.4, 3.0,
                                        -10, 20),
                                  5);
  REQUIRE(s.vertices.size() > 800);
  REQUIRE(t.figure.vertices.size() > 800);
  const FigureCorrespondence c = correspond_figures(s, t.figure);
  check_matching(c, s, t.figure);
  // Every vertex of the tree itself is on both drawings: matched to itself.
  for (int v = 0; v < int(tree.vertices.size()); ++v) CHECK(partner(c, v) == t.new_of_old[std::size_t(v)]);
  CHECK(c.residual == Approx(0).margin(1e-9));
  CHECK(c.rotation_degrees == Approx(0.4 * 180 / kPi).margin(1e-6));
  CHECK(c.milliseconds < 5000);  // the issue asks for under a second; generous on a shared machine
}

TEST_CASE("a 1000-vertex triangulated grid (all junctions) against a renumbered, subdivided copy",
          "[correspond_figures]") {
  const StickFigure grid = grid_triangulation(12);  // 144 vertices, 397 edges
  const StickFigure s = subdivided(grid, seeded_counts(grid.edges.size(), 4, 6), true, 7);
  const Renumbered t = renumbered(moved(subdivided(grid, seeded_counts(grid.edges.size(), 4, 8)), 0.5, 1.0, 0, 0), 9);
  REQUIRE(s.vertices.size() > 800);
  REQUIRE(t.figure.vertices.size() > 800);
  const FigureCorrespondence c = correspond_figures(s, t.figure);
  check_matching(c, s, t.figure);
  // The grid is symmetric under a half turn; turned by 0.5 rad, the true
  // match is the smaller rotation.
  for (int v = 0; v < int(grid.vertices.size()); ++v) CHECK(partner(c, v) == t.new_of_old[std::size_t(v)]);
  CHECK(c.rotation_degrees == Approx(0.5 * 180 / kPi).margin(1e-6));
  CHECK(c.milliseconds < 5000);
}

// ---------------------------------------------------------------------- morph

TEST_CASE("morph_stick_figures with correspond = Auto morphs the matched figure", "[correspond_figures]") {
  const StickFigure square = polygon(kSquare);
  const StickFigure t = t_shape();
  const std::vector<std::pair<StickFigure, StickFigure>> pairs = {
      {t, renumbered(moved(subdivided(t, {2, 0, 4}, true, 3), -0.5, 0.7, 3, 3), 11).figure},
      {square, renumbered(moved(subdivided(square, {2, 1, 3, 1}, true, 9), kPi / 6, 2.0, 1, 1), 5).figure},
      {p_shape(), renumbered(subdivided(p_shape(), {1, 0, 2, 0, 1, 3, 0, 2}, true, 21), 23).figure},
      {kMan, reflected(stick_man_walking())},
  };
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    INFO("pair " << k);
    const auto& [s, g] = pairs[k];
    MorphStickFiguresOptions options;
    options.correspond = CorrespondenceMode::Auto;
    options.frames = 5;
    const MorphStickFiguresResult result = morph_stick_figures(s, g, options);
    REQUIRE(result.correspondence.has_value());
    const FigureCorrespondence& c = *result.correspondence;
    check_matching(c, s, g);
    const std::size_t m = c.source.vertices.size();
    REQUIRE(result.frames.size() == 5);
    for (const std::vector<Vec2>& frame : result.frames) CHECK(frame.size() == m);
    CHECK(result.frames.front() == c.source.vertices);
    CHECK(result.frames.back() == c.target.vertices);
    CHECK(result.stats.correspond_ms == c.milliseconds);
    // The same matching as correspond_figures on its own.
    const FigureCorrespondence alone = correspond_figures(s, g);
    CHECK(alone.source.vertices == c.source.vertices);
    CHECK(alone.target.vertices == c.target.vertices);
    CHECK(alone.source.edges == c.source.edges);
  }
  // With a pin, the pinned pair is one matched vertex of the morph.
  MorphStickFiguresOptions pinned;
  pinned.correspond = CorrespondenceMode::Auto;
  pinned.frames = 3;
  pinned.pins = {{1, 2}};
  const MorphStickFiguresResult turned = morph_stick_figures(plus_sign(), plus_sign(), pinned);
  REQUIRE(turned.correspondence.has_value());
  CHECK(turned.correspondence->target_places[1].vertex == 2);
  CHECK(turned.frames.back()[1] == Vec2{0, 1});
  // Pins without Auto are refused before any work.
  MorphStickFiguresOptions by_index;
  by_index.pins = {{1, 2}};
  CHECK_THROWS_AS(morph_stick_figures(plus_sign(), plus_sign(), by_index), InvalidArgumentError);
}

namespace {

// fuzz_correspond_pair's stroke (two findings below): a source polyline of
// two edges near 1e39, and a target stroke of length ~1e39 whose last
// edges, near (1.06e37, 0), are 1e20 to 1e23 long.
struct StrokePair {
  StickFigure source, target;
};

StrokePair crowded_stroke_pair() {
  StickFigure source = make_stick_figure(
      {{5.231841391409429e+39, 2.1267647932558654e+38}, {4.253529586511731e+37, 0.0},
       {2.084229497390748e+39, 1.9566236097953962e+39}},
      {{1, 0}, {2, 1}});
  StickFigure target = make_stick_figure(
      {{1.3079603478523572e+39, 5.3169119831396635e+37}, {1.0633823966279327e+37, 0.0},
       {5.21057374347687e+38, 4.8915590244884904e+38}, {1.568178709424072e+37, 2.068837347525161e+35},
       {4.585171458275706e+37, 1.4433561728064644e+36}, {1.0653465846154662e+37, 8.049950768580393e+32},
       {1.063390039382748e+37, 3.1322765636499586e+30}, {1.0633824263662784e+37, 1.2187846551167155e+28},
       {1.063382396743646e+37, 4.742352743644808e+25}, {1.063382396628383e+37, 1.845273441106929e+23},
       {1.0633823966279344e+37, 718005230002696093696.0}},
      {{1, 10}, {2, 1}, {3, 4}, {4, 0}, {5, 3}, {6, 5}, {7, 6}, {8, 7}, {9, 8}, {10, 9}});
  return {std::move(source), std::move(target)};
}

}  // namespace

TEST_CASE("a dummy lands on the edge between its neighbours where edges are shorter than the arc's rounding",
          "[correspond_figures]") {
  // fuzz_correspond_pair's finding: a target stroke of length ~1e39 whose
  // last edges, near (1.06e37, 0), are 1e20 to 1e23 long, below the
  // rounding of the arc length there, so that several vertices share one
  // arc value. The source's middle vertex falls between target vertices 9
  // and 10; by its parameter alone it was put on edge (2, 1), past vertex
  // 1, and the matched edges no longer subdivided the target.
  const auto [source, target] = crowded_stroke_pair();
  const FigureCorrespondence c = correspond_figures(source, target);
  CHECK(is_valid(c, source, target));
  CHECK(check_compatibility(c.source, c.target).compatible());
  // Source vertex 1's image: a dummy on target edge 9, (10, 9).
  REQUIRE(c.target_places.size() > 1);
  CHECK(c.target_places[1].vertex == -1);
  CHECK(c.target_places[1].edge == 9);
}

TEST_CASE("a pair matched in the working scale is morphed and written at its own scale", "[correspond_figures]") {
  // fuzz_correspond_pair's finding (tests/data/fuzz/regressions/
  // correspond_pair/working_scale_pair_not_scaled_back.bin): figures near
  // 1e39 are matched in the working scale (working_scale.h), and the checked
  // pair the match handed to the morph stayed there, so every frame came
  // out 2^-130 times the figures.
  const auto [source, target] = crowded_stroke_pair();
  const FigureCorrespondence matched = correspond_figures(source, target);
  REQUIRE(matched.pair);
  CHECK(matched.pair->source().vertices == matched.source.vertices);
  CHECK(matched.pair->target().vertices == matched.target.vertices);
  MorphStickFiguresOptions options;
  options.frames = 5;
  options.correspond = CorrespondenceMode::Auto;
  const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
  REQUIRE(result.frames.size() == 5);
  CHECK(result.frames.front() == matched.source.vertices);
  CHECK(result.frames.back() == matched.target.vertices);
  // The similarity's centres are reported at the figures' scale too.
  CHECK(result.stats.similarity.source_center[0] > 1e38);
}

TEST_CASE("a matchable pair beyond the rigid method's size ratio is refused with NumericRangeError",
          "[correspond_figures]") {
  // fuzz_correspond_pair's finding (tests/data/fuzz/regressions/correspond_pair/
  // morph_size_ratio_beyond_rigid_limit.bin): two dots about 1e-32 apart
  // against two 0.0078 apart, pinned. The matching succeeds; the rigid
  // morph refuses the size ratio (8e29 > kMaxRigidSizeRatio) before any
  // work, with the documented NumericRangeError, not a crash.
  const StickFigure source = make_stick_figure({{1.4791141972893971e-30, 0.0}, {1.488977384825e-30, 0.0}}, {});
  const StickFigure target = make_stick_figure({{0.0078125, 0.0}, {0.0078125, 0.0078125}}, {});
  CorrespondenceOptions matching;
  matching.pins = {{0, 0}};
  const FigureCorrespondence c = correspond_figures(source, target, matching);
  REQUIRE(is_valid(c, source, target));
  MorphStickFiguresOptions options;
  options.frames = 3;
  options.correspond = CorrespondenceMode::Auto;
  options.pins = {{0, 0}};
  REQUIRE_THROWS_AS(morph_stick_figures(source, target, options), NumericRangeError);
  REQUIRE_THROWS_WITH(morph_stick_figures(source, target, options), Contains("beyond the rigid method's limit"));
}
