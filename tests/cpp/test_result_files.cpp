#include "catch.h"

#include <limits>
#include <string>
#include <vector>

#include "figures.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/io/json.h"
#include "stickmorph/io/result_files.h"
#include "stickmorph/morph.h"

using namespace stickmorph;
using stickmorph_test::Contains;

namespace {

// The caret of FORMAT.md's example: source [[0, 0], [1, 2], [2, 0]], target
// the same with the tip at [1, 1].
struct Caret {
  StickFigure source = test::polyline({{0, 0}, {1, 2}, {2, 0}});
  StickFigure target = test::polyline({{0, 0}, {1, 1}, {2, 0}});
  FigureTriangulation triangulation = triangulate_figures(source, target, {});
};

std::vector<std::string> keys(const JsonValue& object) {
  std::vector<std::string> names;
  for (const JsonMember& member : object.as_object()) names.push_back(member.key);
  return names;
}

}  // namespace

TEST_CASE("the triangulation file holds the triangulation object, nodes in FORMAT.md's order", "[result_files]") {
  const Caret caret;
  const std::string text = triangulation_file_json(caret.triangulation);
  CHECK(text.back() == '\n');
  const JsonValue file = parse_json(text);
  CHECK(keys(file) == std::vector<std::string>{"figure_vertices", "enclosure_vertices", "steiner_vertices", "source",
                                               "target", "triangles"});
  CHECK(file.find("figure_vertices")->as_number() == 3);
  const std::size_t nodes = 3 + caret.triangulation.enclosure_vertices + caret.triangulation.steiner_vertices;
  REQUIRE(file.find("target")->as_array().size() == nodes);
  // The first n nodes are the figure's own vertices, exactly.
  CHECK(file.find("target")->as_array()[1].as_array()[1].as_number() == 1.0);
  CHECK(file.find("triangles")->as_array().size() == caret.triangulation.triangles.size());
  // Counts and indices are integers, coordinates floats (FORMAT.md).
  CHECK_THAT(text, Contains("\"figure_vertices\": 3,"));
  CHECK_THAT(text, Contains("[0.0, 0.0]"));
}

TEST_CASE("the morph file of the barycentric morph", "[result_files]") {
  const Caret caret;
  MorphOptions options;
  options.frames = 3;
  const MorphResult result = morph_triangulation(caret.triangulation, caret.source, options);
  MorphProvenance how;
  how.triangulation = &caret.triangulation;
  how.options = options;
  how.stats = &result.stats;
  how.triangulate_ms = 0.25;
  const JsonValue file = parse_json(morph_file_json(caret.source, result.times, result.frames, how));
  CHECK(keys(file) == std::vector<std::string>{"edges", "times", "frames", "triangulation", "stats"});
  const auto& frames = file.find("frames")->as_array();
  REQUIRE(frames.size() == 3);
  // Only the figure's vertices, although the morph's frames hold every node.
  CHECK(result.frames[1].size() > 3);
  CHECK(frames[1].as_array().size() == 3);
  CHECK(frames[2].as_array()[1].as_array()[1].as_number() == 1.0);
  CHECK(file.find("triangulation")->is_object());
  const JsonValue& stats = *file.find("stats");
  CHECK(keys(stats) == std::vector<std::string>{"steiner_vertices", "triangles", "parts", "bridge_vertices", "milliseconds", "method",
                                                "steiner_method", "enclosure_sides", "weights", "verified",
                                                "refined_frames", "factorizations"});
  CHECK(keys(*stats.find("milliseconds")) ==
        std::vector<std::string>{"triangulate", "morph", "factorize", "solve", "verify"});
  CHECK(stats.find("milliseconds")->find("triangulate")->as_number() == 0.25);
  CHECK(stats.find("method")->as_string() == "barycentric");
  CHECK(stats.find("verified")->as_bool());
  CHECK(stats.find("triangles")->as_number() == double(caret.triangulation.triangles.size()));
}

TEST_CASE("the morph file of the straight-line baseline has no triangulation", "[result_files]") {
  const Caret caret;
  std::vector<int> invalid;
  const MorphResult result = linear_morph(caret.source, caret.target, 4, &invalid);
  MorphProvenance how;
  how.method = "linear";
  how.invalid_frames = &invalid;
  how.morph_ms = 1.5;
  const JsonValue file = parse_json(morph_file_json(caret.source, result.times, result.frames, how));
  CHECK(file.find("triangulation")->is_null());
  CHECK(file.find("times")->as_array().size() == 4);
  const JsonValue& stats = *file.find("stats");
  CHECK(keys(stats) ==
        std::vector<std::string>{"steiner_vertices", "triangles", "parts", "bridge_vertices", "milliseconds", "method",
                                 "invalid_frames"});
  CHECK(stats.find("steiner_vertices")->as_number() == 0);
  CHECK(keys(*stats.find("milliseconds")) == std::vector<std::string>{"triangulate", "morph"});
  CHECK(stats.find("invalid_frames")->as_array().empty());
}

TEST_CASE("the morph file refuses numbers JSON cannot hold", "[result_files]") {
  const Caret caret;
  MorphResult result = linear_morph(caret.source, caret.target, 2);
  result.frames[1][0][0] = std::numeric_limits<double>::infinity();
  MorphProvenance how;
  how.method = "linear";
  CHECK_THROWS_AS(morph_file_json(caret.source, result.times, result.frames, how), InvalidArgumentError);
}
