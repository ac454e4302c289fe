// MorphSolver (Algorithm 3, step 4; [8]): the morph's linear system solved
// repeatedly, at any time and in any order.
#include "catch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "stickmorph/errors.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/morph.h"
#include "stickmorph/morph_solver.h"

using namespace stickmorph;

namespace {

// Figure vertices 0 and 1 (an edge) inside the square enclosure 2..5
// (corners (+-2, +-2)), six triangles; the edge turns by 45 degrees from
// source to target.
FigureTriangulation edge_in_square() {
  FigureTriangulation tri;
  tri.figure_vertices = 2;
  tri.enclosure_vertices = 4;
  tri.steiner_vertices = 0;
  tri.source = {{-0.5, 0}, {0.5, 0}, {-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  tri.target = {{-0.5, 0.5}, {0.5, -0.5}, {-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  tri.triangles = {{2, 3, 1}, {2, 1, 0}, {3, 4, 1}, {4, 5, 0}, {4, 0, 1}, {5, 2, 0}};
  return tri;
}

// One figure vertex joined to the four corners of the square.
FigureTriangulation vertex_in_square(const Vec2& source, const Vec2& target) {
  FigureTriangulation tri;
  tri.figure_vertices = 1;
  tri.enclosure_vertices = 4;
  tri.source = {source, {-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  tri.target = {target, {-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  tri.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
  return tri;
}

void check_close(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double margin) {
  REQUIRE(a.size() == b.size());
  for (std::size_t v = 0; v < a.size(); ++v)
    for (int c = 0; c < 2; ++c) CHECK(a[v][c] == Approx(b[v][c]).margin(margin));
}

}  // namespace

TEST_CASE("MorphSolver: one interior node moves on the straight line", "[morph_solver]") {
  // With one unknown, x(t) = sum_j ((1 - t) w0_j + t w1_j) p_j, and each
  // weight set reproduces its own embedding: x(t) = (1 - t) p0 + t p1.
  const Vec2 p0{0.3, -0.2}, p1{-0.5, 0.9};
  for (WeightKind kind : {WeightKind::MeanValue, WeightKind::Uniform, WeightKind::Floater}) {
    MorphSolver solver(vertex_in_square(p0, p1), kind);
    CHECK(solver.unknowns() == 1);
    for (double t : {0.25, 0.0, 1.0, 0.6}) {
      const std::vector<Vec2> x = solver.solve(t);
      CHECK(x[0][0] == Approx((1 - t) * p0[0] + t * p1[0]).margin(1e-12));
      CHECK(x[0][1] == Approx((1 - t) * p0[1] + t * p1[1]).margin(1e-12));
      CHECK(x[3] == Vec2{2, 2});  // the enclosure stays put
    }
  }
}

TEST_CASE("MorphSolver: solve_directly is solve_morph_frame, bit for bit", "[morph_solver]") {
  const FigureTriangulation tri = edge_in_square();
  for (WeightKind kind : {WeightKind::MeanValue, WeightKind::Uniform, WeightKind::Floater}) {
    MorphSolver solver(tri, kind);
    for (double t : {0.3, 0.0, 1.0, 0.77}) {
      CHECK(solver.solve_directly(t) == solve_morph_frame(tri, t, kind));
      CHECK(solver.last_solve_factorized());
    }
    CHECK(solver.stats().factorizations == 4);
  }
}

TEST_CASE("MorphSolver: scrubbing in any order matches the direct solves", "[morph_solver]") {
  const FigureTriangulation tri = edge_in_square();
  MorphSolver solver(tri);
  // The first solve builds the moment space (factorizations at 0, 1/2 and
  // 1) and answers from it, not from a factorization at its own time; a
  // nearby time is projected as well.
  check_close(solver.solve(0.3), solve_morph_frame(tri, 0.3), 1e-9);
  CHECK_FALSE(solver.last_solve_factorized());
  CHECK(solver.stats().factorizations == 3);
  check_close(solver.solve(0.52), solve_morph_frame(tri, 0.52), 1e-9);
  CHECK_FALSE(solver.last_solve_factorized());
  CHECK(solver.stats().factorizations == 3);
  for (double t : {0.9, 0.1, 0.11, 1.0, 0.0, 0.5})
    check_close(solver.solve(t), solve_morph_frame(tri, t), 1e-9);
  check_close(solver.solve(0.0), tri.source, 1e-12);
  check_close(solver.solve(1.0), tri.target, 1e-12);
  // Refinement of the last solution stays at it.
  check_close(solver.refine(3), tri.target, 1e-12);
}

TEST_CASE("MorphSolver: morph_triangulation's frames are its solves in order", "[morph_solver]") {
  // Without a frame that fails verification, the morph's interior frames
  // are exactly the solver's solve(t_f), f = 1..N-2, in order.
  const FigureTriangulation tri = edge_in_square();
  StickFigure source = make_stick_figure({tri.source[0], tri.source[1]}, std::vector<std::array<std::int64_t, 2>>{{0, 1}});
  MorphOptions options;
  options.frames = 9;
  const MorphResult morph = morph_triangulation(tri, source, options);
  MorphSolver solver(tri);
  for (int f = 1; f + 1 < options.frames; ++f) CHECK(morph.frames[f] == solver.solve(morph.times[f]));
  CHECK(morph.stats.refined_frames == 0);
  CHECK(morph.stats.factorizations == solver.stats().factorizations);
}

TEST_CASE("MorphSolver: refuses times outside [0, 1] and refinement before a solve", "[morph_solver]") {
  MorphSolver solver(edge_in_square());
  CHECK_THROWS_AS(solver.solve(1.5), InvalidArgumentError);
  CHECK_THROWS_AS(solver.solve_directly(-0.1), InvalidArgumentError);
  CHECK_THROWS_AS(solver.refine(1), InvalidArgumentError);
  // A malformed triangulation is refused at construction, as by the morph.
  FigureTriangulation broken = edge_in_square();
  broken.triangles.pop_back();
  CHECK_THROWS_AS(MorphSolver(broken), InvalidArgumentError);
}

namespace {

// A polyline of 40 vertices on a sine wave, the target on another: a
// triangulation with a few dozen unknowns whose morph moves every node.
FigureTriangulation sine_polyline() {
  std::vector<Vec2> source, target;
  std::vector<std::array<std::int64_t, 2>> edges;
  for (int i = 0; i < 40; ++i) {
    source.push_back({double(i), 3 * std::sin(i * 0.3)});
    target.push_back({double(i), 2 * std::sin(i * 0.5 + 1)});
    if (i > 0) edges.push_back({i - 1, i});
  }
  return triangulate_figures(make_stick_figure(source, edges), make_stick_figure(target, edges));
}

double largest_difference(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double d = 0;
  for (std::size_t v = 0; v < a.size(); ++v)
    for (int c = 0; c < 2; ++c) d = std::max(d, std::abs(a[v][c] - b[v][c]));
  return d;
}

}  // namespace

TEST_CASE("MorphSolver: in order, frames come from the moment space and its factorizations serve", "[morph_solver]") {
  const FigureTriangulation tri = sine_polyline();
  MorphSolver solver(tri);
  REQUIRE(solver.unknowns() > 10);
  constexpr int kFrames = 50;
  for (int f = 1; f + 1 < kFrames; ++f) {
    const double t = double(f) / (kFrames - 1);
    const std::vector<Vec2> x = solver.solve(t);
    CHECK(largest_difference(x, solve_morph_frame(tri, t)) < 1e-8);
  }
  const MorphSolverStats& stats = solver.stats();
  CHECK(stats.solves == kFrames - 2);
  // The moment space's three factorizations serve the whole playback: it
  // spans this morph, all frames but one are projected without a
  // triangular solve (pinned: 47 of 48, that one in 5 GMRES steps).
  CHECK(stats.factorizations == 3);
  CHECK(stats.projected >= kFrames - 3);
  CHECK(stats.iterations <= 8);
}

TEST_CASE("MorphSolver: a scrub back and forth matches the direct solves", "[morph_solver]") {
  const FigureTriangulation tri = sine_polyline();
  MorphSolver solver(tri);
  // Far jumps: an extrapolation there is wild, the nearest remembered
  // solution (or a factorization) is used instead; repeated times too.
  for (double t : {0.5, 0.52, 0.54, 0.05, 0.97, 0.97, 0.3, 0.31, 0.0, 1.0, 0.62, 0.6, 0.58}) {
    const std::vector<Vec2> x = solver.solve(t);
    CHECK(largest_difference(x, solve_morph_frame(tri, t)) < 1e-8);
  }
  CHECK(solver.stats().solves == 13);
  // solve_directly is still the fresh factorization, bit for bit, and joins
  // the warm starts.
  CHECK(solver.solve_directly(0.4) == solve_morph_frame(tri, 0.4));
  CHECK(largest_difference(solver.solve(0.41), solve_morph_frame(tri, 0.41)) < 1e-8);
  CHECK_FALSE(solver.last_solve_factorized());
}

TEST_CASE("MorphSolver: two solvers given the same times agree bit for bit", "[morph_solver]") {
  // The contract of stickmorph.MorphSolver: solving morph()'s times in order
  // from a new solver gives morph()'s frames exactly. The warm starts depend
  // only on the times asked, so the same sequence gives the same results.
  const FigureTriangulation tri = sine_polyline();
  StickFigure source = make_stick_figure(
      std::vector<Vec2>(tri.source.begin(), tri.source.begin() + tri.figure_vertices),
      [&] {
        std::vector<std::array<std::int64_t, 2>> edges;
        for (int i = 1; i < tri.figure_vertices; ++i) edges.push_back({i - 1, i});
        return edges;
      }());
  MorphOptions options;
  options.frames = 30;
  const MorphResult morph = morph_triangulation(tri, source, options);
  MorphSolver solver(tri);
  for (int f = 1; f + 1 < options.frames; ++f) CHECK(morph.frames[f] == solver.solve(morph.times[f]));
  CHECK(morph.stats.factorizations == solver.stats().factorizations);
}

TEST_CASE("MorphSolver: a time asked again gives the same positions", "[morph_solver]") {
  const FigureTriangulation tri = sine_polyline();
  MorphSolver solver(tri);
  const std::vector<Vec2> first = solver.solve(0.5);
  CHECK(solver.solve(0.5) == first);
  const std::vector<Vec2> other = solver.solve(0.55);
  CHECK(solver.solve(0.5) == first);
  CHECK(solver.solve(0.55) == other);
  CHECK(solver.stats().solves == 5);
}
