// internal::prepare_guided_morph (rigid_morph_setup.h), through the rigid
// method's entry: the triangulation it chooses (issue 30).
#include "catch.h"

#include <algorithm>
#include <string>
#include <vector>

#include "stickmorph/internal/geometry.h"
#include "stickmorph/io/figure_io.h"
#include "stickmorph/morph_stick_figures.h"

using namespace stickmorph;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct FigurePair {
  StickFigure source, target;
};

FigurePair read_pair(const std::string& stem) {
  const std::string path = std::string(STICKMORPH_TEST_DATA) + "/" + stem;
  return {read_figure_file(path + ".source.json"), read_figure_file(path + ".target.json")};
}

// The smallest angle, in degrees, over every triangle in both embeddings.
double smallest_angle_degrees(const FigureTriangulation& tri) {
  double least = 180;
  for (const std::vector<Vec2>* p : {&tri.source, &tri.target})
    for (const auto& t : tri.triangles)
      least = std::min(least, internal::triangle_min_angle((*p)[t[0]], (*p)[t[1]], (*p)[t[2]]) * 180 / kPi);
  return least;
}

MorphStickFiguresResult rigid_morph(const FigurePair& pair, int frames) {
  MorphStickFiguresOptions options;
  options.frames = frames;
  return morph_stick_figures(pair.source, pair.target, options);
}

}  // namespace

TEST_CASE("the rigid method's triangulation is refined for its angles and still follows the guide",
          "[rigid_morph_setup]") {
  constexpr int N = 12;
  // A letter L drawn into a V (bench/motion_corpus.py, seed 31).
  const MorphStickFiguresResult result = rigid_morph(read_pair("pairs/compatible/glyph_L_to_V"), N);
  REQUIRE(result.triangulation);
  INFO("Steiner " << result.stats.steiner_vertices << " refinement " << result.stats.triangulation.refinement_steiner
       << " smallest angle " << smallest_angle_degrees(*result.triangulation));
  CHECK(result.stats.triangulation.refinement_steiner > 0);
  // Pinned (8.5 degrees when written, 12 Steiner vertices for 30 figure
  // vertices); the paper's triangulation of this pair, the barycentric
  // method's, has a smallest angle of 0.13 degrees with none.
  CHECK(smallest_angle_degrees(*result.triangulation) > 8);
  CHECK(result.stats.steiner_vertices <= 12);
  CHECK(result.stats.guide_exact_frames == N - 2);
}

TEST_CASE("compatible refinement gives way where its Steiner vertices keep the guide from being followed",
          "[rigid_morph_setup]") {
  // A letter 7 drawn into an L (bench/motion_corpus.py, seed 5): refined,
  // the guide frames were trusted at 3 of 15 samples and no frame followed
  // the guide; refined by less, still not; unrefined, every frame does.
  constexpr int N = 30;
  const MorphStickFiguresResult result = rigid_morph(read_pair("pairs/compatible/glyph_7_to_L"), N);
  CHECK(result.stats.triangulation.refinement_steiner == 0);
  CHECK(result.stats.guide_exact_frames == N - 2);
}
