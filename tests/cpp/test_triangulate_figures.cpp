#include "catch.h"

#include "figures.h"
#include "polygons.h"
#include "stickmorph/argument_limits.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/figure_triangulation.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

const SteinerMethod kMethods[] = {SteinerMethod::Aronov, SteinerMethod::Sg2001, SteinerMethod::Improved};

// Triangulates with every method and checks the result against the FORMAT.md
// layout and the exact verifier; returns the Steiner counts.
std::array<int, 3> check_all_methods(const StickFigure& s, const StickFigure& t, int sides = 6) {
  REQUIRE(check_compatibility(s, t).compatible());
  std::array<int, 3> counts{};
  for (int m = 0; m < 3; ++m) {
    FigureTriangulationOptions options;
    options.method = kMethods[m];
    options.enclosure_sides = sides;
    FigureTriangulationStats stats;
    INFO("method " << steiner_method_name(kMethods[m]));
    const FigureTriangulation tri = triangulate_figures(s, t, options, &stats);
    CHECK_NOTHROW(verify_figure_triangulation(tri, s));
    CHECK(tri.figure_vertices == int(s.vertices.size()));
    CHECK(tri.enclosure_vertices == sides);
    CHECK(tri.node_count() == int(tri.source.size()));
    // Figure vertices keep their positions; the enclosure is the same in both.
    for (int v = 0; v < tri.figure_vertices; ++v) {
      CHECK(tri.source[v] == s.vertices[v]);
      CHECK(tri.target[v] == t.vertices[v]);
    }
    for (int j = 0; j < sides; ++j) CHECK(tri.source[tri.figure_vertices + j] == tri.target[tri.figure_vertices + j]);
    // A triangulated disk with k boundary vertices: T = 2 * (nodes) - k - 2.
    CHECK(int(tri.triangles.size()) == 2 * tri.node_count() - sides - 2);
    CHECK(stats.min_angle > 0);
    counts[m] = tri.steiner_vertices;
  }
  return counts;
}

}  // namespace

TEST_CASE("S to U as 12-vertex polylines (Figure 8c)", "[triangulate_figures]") {
  const StickFigure s = polyline({{3, 5}, {2, 6}, {1, 6}, {0, 5}, {0, 4}, {1, 3}, {2, 3}, {3, 2}, {3, 1}, {2, 0}, {1, 0}, {0, 1}});
  const StickFigure u = polyline({{0, 6}, {0, 4.5}, {0, 3}, {0, 1.5}, {0.5, 0.5}, {1.5, 0}, {2.5, 0}, {3.5, 0.5}, {4, 1.5}, {4, 3}, {4, 4.5}, {4, 6}});
  const auto counts = check_all_methods(s, u);
  CHECK(counts[2] < counts[1]);
  CHECK(counts[1] < counts[0]);
}

TEST_CASE("a triangulation pair with a common convex boundary (Figure 3)", "[triangulate_figures]") {
  const StickFigure s = grid_triangulation(5);
  StickFigure t = s;
  // Shear the interior vertices; the boundary stays.
  for (Vec2& p : t.vertices)
    if (p[0] > 0 && p[0] < 4 && p[1] > 0 && p[1] < 4) p = {p[0] + 0.3 * (p[1] - 2), p[1] - 0.2 * (p[0] - 2)};
  for (int m = 0; m < 3; ++m) {
    FigureTriangulationOptions options;
    options.method = kMethods[m];
    FigureTriangulationStats stats;
    triangulate_figures(s, t, options, &stats);
    // All interior faces are triangles already.
    if (kMethods[m] == SteinerMethod::Improved) CHECK(stats.interior_steiner == 0);
    CHECK(stats.interior_faces == 32);
  }
  check_all_methods(s, t);
}

TEST_CASE("a polygon pair (Figure 4) and a figure with several faces (Figure 5)", "[triangulate_figures]") {
  std::mt19937 rng(4);
  check_all_methods(polygon(star_polygon(rng, 12, 0.5)), polygon(two_opt_polygon(rng, 12)));
  // Two faces sharing an edge, plus a dangling edge inside one and a tail outside.
  const RawEdges edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 4}, {3, 5}};
  const StickFigure s = figure({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {3, 1.5}, {-2, 5}}, edges);
  const StickFigure t = figure({{0, 0}, {5, 1}, {3, 5}, {-1, 3}, {3.5, 2}, {-3, 1}}, edges);
  check_all_methods(s, t);
}

TEST_CASE("trees, single edges, single vertices and collinear polylines", "[triangulate_figures]") {
  const StickFigure tree = figure({{0, 0}, {1, 0}, {0, 1}, {-1, -1}, {2, 1}, {2, -1}}, {{0, 1}, {0, 2}, {0, 3}, {1, 4}, {1, 5}});
  check_all_methods(tree, moved(tree, 2.5, 1.7, 3, -1));
  const StickFigure edge = figure({{0, 0}, {1, 0}}, {{0, 1}});
  check_all_methods(edge, figure({{0, 0}, {-1, 0.1}}, {{0, 1}}));
  const StickFigure point = figure({{2, 3}}, {});
  check_all_methods(point, figure({{-5, 7}}, {}));
  const StickFigure line = polyline({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}});
  check_all_methods(line, polyline({{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}}));
  check_all_methods(line, polyline({{4, 0}, {3, 0}, {2, 0}, {1, 0}, {0, 0}}), 3);
}

TEST_CASE("the target's edges listed in another order and direction", "[triangulate_figures]") {
  // Found by fuzz_morph_pair (tests/data/fuzz/regressions/morph_pair): the
  // annulus cut took corner c of the source's exterior sequence to be corner
  // c of the target's, but Algorithm 1 starts each walk at a dart that
  // depends on the edge order, so in the target the cut left from another
  // corner and crossed the figure ("polygon is not weakly simple").
  const StickFigure star = figure({{0, 0}, {20, 0}, {0, 20}, {-20, 0}, {0, -20}, {14, 14}},
                                  {{1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}});
  const StickFigure moved_star = figure({{0, 0}, {20, 3.75}, {-3.75, 20}, {-20, -3.75}, {3.75, -20}, {12.125, 15.875}},
                                        {{0, 5}, {0, 4}, {0, 3}, {0, 2}, {0, 1}});
  for (int sides : {3, 5, 6}) {
    INFO("enclosure sides " << sides);
    check_all_methods(star, moved_star, sides);
  }
}

TEST_CASE("figures far apart and at very different scales", "[triangulate_figures]") {
  std::mt19937 rng(9);
  const StickFigure f = random_plane_graph(rng, 14, 0.5);
  check_all_methods(f, moved(f, 1.0, 1.0, 1e4, -3e4));
  check_all_methods(f, moved(f, -0.5, 1e-3, 0.2, 0.1));
  // A thousand times smaller and far away. (Size ratios beyond about 1e4
  // combined with such distances exhaust double precision in the annulus,
  // and the engine reports that instead of returning an invalid result.)
  check_all_methods(moved(f, 0, 1e3, 0, 0), moved(f, 3.0, 1.0, 1e4, 1e4));
}

TEST_CASE("random compatible stick figures", "[triangulate_figures][property]") {
  std::mt19937 rng(42);
  int tested = 0;
  for (int round = 0; tested < 30 && round < 300; ++round)
    if (const auto pair = random_compatible_pair(rng, round, 6, 20)) {
      ++tested;
      check_all_methods(pair->first, pair->second);
    }
  CHECK(tested == 30);
}

TEST_CASE("bad requests", "[triangulate_figures]") {
  const StickFigure star = figure({{0, 0}, {1, 0}, {0, 1}, {-1, 0}}, {{0, 1}, {0, 2}, {0, 3}});
  const StickFigure swapped = figure({{0, 0}, {-1, 0}, {0, 1}, {1, 0}}, {{0, 1}, {0, 2}, {0, 3}});
  CHECK_THROWS_AS(triangulate_figures(star, swapped), IncompatibleFiguresError);
  FigureTriangulationOptions options;
  options.enclosure_sides = 2;
  CHECK_THROWS_WITH(triangulate_figures(star, star, options), Contains("enclosure_sides must be at least 3"));
  // The annulus work grows quadratically in the sides; a huge count would
  // hang the caller, so the engine itself refuses it.
  options.enclosure_sides = kMaxEnclosureSides + 1;
  CHECK_THROWS_AS(triangulate_figures(star, star, options), InvalidArgumentError);
  CHECK_THROWS_WITH(triangulate_figures(star, star, options), Contains("enclosure_sides must be at most 1000"));
  options.enclosure_sides = kMaxEnclosureSides;
  CHECK_NOTHROW(verify_figure_triangulation(triangulate_figures(star, star, options), star));
}
