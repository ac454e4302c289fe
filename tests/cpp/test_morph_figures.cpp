// End to end: Algorithm 3 (triangulate_figures) and the Floater-Gotsman morph
// (morph_triangulation) on whole stick figures, every frame verified.
#include "catch.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>
#include <random>

#include "figures.h"
#include "polygons.h"
#include "random_pairs.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/morph.h"

using namespace stickmorph;
using namespace stickmorph::test;

namespace {

// Morphs with the default options and checks every frame again, apart from
// the morph's own check (morph_and_verify in random_pairs.h: the
// triangulation re-verified, endpoints exact, every triangle
// counter-clockwise and every frame a stick figure with the source's cyclic
// sequences).
void check_morph(const StickFigure& s, const StickFigure& t, int frames = 12) {
  REQUIRE(check_compatibility(s, t).compatible());
  CHECK(morph_and_verify(s, t, frames) == "");
}

// The pairs of a regressions directory: (source path, target path).
std::vector<std::pair<std::string, std::string>> regression_pairs(const std::string& dir) {
  std::vector<std::pair<std::string, std::string>> pairs;
  const std::string suffix = ".source.json";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string path = entry.path().string();
    if (path.size() < suffix.size() || path.compare(path.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    pairs.push_back({path, path.substr(0, path.size() - suffix.size()) + ".target.json"});
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace

TEST_CASE("the paper's cases morph with every frame valid", "[morph_figures]") {
  SECTION("S to U (Figure 8c)") {
    check_morph(polyline({{3, 5}, {2, 6}, {1, 6}, {0, 5}, {0, 4}, {1, 3}, {2, 3}, {3, 2}, {3, 1}, {2, 0}, {1, 0}, {0, 1}}),
                polyline({{0, 6}, {0, 4.5}, {0, 3}, {0, 1.5}, {0.5, 0.5}, {1.5, 0}, {2.5, 0}, {3.5, 0.5}, {4, 1.5}, {4, 3}, {4, 4.5}, {4, 6}}));
  }
  SECTION("a triangulation with a common convex boundary (Figure 3)") {
    const StickFigure s = grid_triangulation(5);
    StickFigure t = s;
    for (Vec2& p : t.vertices)
      if (p[0] > 0 && p[0] < 4 && p[1] > 0 && p[1] < 4) p = {p[0] + 0.3 * (p[1] - 2), p[1] - 0.2 * (p[0] - 2)};
    check_morph(s, t);
  }
  SECTION("a polygon pair (Figure 4)") {
    std::mt19937 rng(4);
    check_morph(polygon(star_polygon(rng, 12, 0.5)), polygon(two_opt_polygon(rng, 12)));
  }
  SECTION("a figure with several faces (Figure 5)") {
    const RawEdges edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 4}, {3, 5}};
    check_morph(figure({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {3, 1.5}, {-2, 5}}, edges),
                figure({{0, 0}, {5, 1}, {3, 5}, {-1, 3}, {3.5, 2}, {-3, 1}}, edges));
  }
}

TEST_CASE("trees, dangling edges, single edges and collinear polylines morph", "[morph_figures]") {
  const StickFigure tree = figure({{0, 0}, {1, 0}, {0, 1}, {-1, -1}, {2, 1}, {2, -1}}, {{0, 1}, {0, 2}, {0, 3}, {1, 4}, {1, 5}});
  check_morph(tree, moved(tree, 2.5, 1.7, 3, -1));
  const RawEdges spike = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {1, 4}};
  check_morph(figure({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 3}}, spike), figure({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {3.5, 3.5}}, spike));
  check_morph(figure({{0, 0}, {1, 0}}, {{0, 1}}), figure({{0, 0}, {-1, 0.1}}, {{0, 1}}));
  check_morph(figure({{2, 3}}, {}), figure({{-5, 7}}, {}));
  check_morph(polyline({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}}), polyline({{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}}));
}

TEST_CASE("figures far apart and at very different scales morph", "[morph_figures]") {
  std::mt19937 rng(9);
  const StickFigure f = random_plane_graph(rng, 14, 0.5);
  check_morph(f, moved(f, 1.0, 1.0, 1e4, -3e4));
  check_morph(f, moved(f, -0.5, 1e-3, 0.2, 0.1));
}

TEST_CASE("random compatible stick figures morph with every frame verified", "[morph_figures][property]") {
  std::mt19937 rng(77);
  int tested = 0;
  for (int round = 0; tested < 25 && round < 300; ++round)
    if (const auto pair = random_compatible_pair(rng, round, 6, 25)) {
      ++tested;
      check_morph(pair->first, pair->second, 8);
    }
  CHECK(tested == 25);
}

TEST_CASE("regression pairs in tests/data/regressions morph with every frame verified", "[morph_figures]") {
  // Each pair once failed; see the name field of its source file.
  const auto pairs = regression_pairs(std::string(STICKMORPH_TEST_DATA) + "/regressions");
  for (const auto& [source, target] : pairs) {
    INFO(source);
    check_morph(read_figure_file(source), read_figure_file(target));
  }
  CHECK(pairs.size() >= 1);
}
