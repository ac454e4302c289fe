// morph_stick_figures: Algorithm 3 end to end through the engine's one entry,
// and the option checks (argument_limits.h) every interface relies on. The
// rigid method (the default) has its own tests in test_guided_morph.cpp;
// here the methods side by side.
#include "catch.h"

#include <algorithm>
#include <cerrno>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "option_checks.h"
#include "stickmorph/argument_limits.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/morph.h"
#include "stickmorph/morph_stick_figures.h"

using namespace stickmorph;
using namespace stickmorph::test;

namespace {

struct Pair {
  StickFigure source, target;
};

Pair read_pair(const std::string& folder, const std::string& name) {
  const std::string stem = std::string(STICKMORPH_TEST_DATA) + "/pairs/" + folder + "/" + name;
  return {read_figure_file(stem + ".source.json"), read_figure_file(stem + ".target.json")};
}


}  // namespace

TEST_CASE("morph_stick_figures runs steps 1-5 as triangulate_figures and morph_triangulation do") {
  const Pair pair = read_pair("compatible", "letter_a");
  MorphStickFiguresOptions options;
  options.method = MorphMethod::Barycentric;
  options.frames = 7;
  options.keep_node_frames = true;
  const MorphStickFiguresResult result = morph_stick_figures(pair.source, pair.target, options);

  // The same computation by hand: the entry may not change a single bit.
  const FigureTriangulation triangulation = triangulate_figures(pair.source, pair.target);
  MorphOptions morph_options;
  morph_options.frames = 7;
  const MorphResult by_hand = morph_triangulation(triangulation, pair.source, morph_options);

  REQUIRE(result.triangulation.has_value());
  CHECK(result.triangulation->triangles == triangulation.triangles);
  CHECK(result.triangulation->source == triangulation.source);
  CHECK(result.times == by_hand.times);
  CHECK(result.node_frames == by_hand.frames);
  const std::size_t n = pair.source.vertices.size();
  REQUIRE(result.frames.size() == 7);
  for (std::size_t f = 0; f < result.frames.size(); ++f) {
    // Step 5: only the figure's vertices.
    REQUIRE(result.frames[f].size() == n);
    CHECK(std::vector<Vec2>(by_hand.frames[f].begin(), by_hand.frames[f].begin() + long(n)) == result.frames[f]);
  }
  CHECK(result.frames.front() == pair.source.vertices);
  CHECK(result.frames.back() == pair.target.vertices);

  CHECK(result.stats.steiner_vertices == triangulation.steiner_vertices);
  CHECK(result.stats.triangles == int(triangulation.triangles.size()));
  CHECK(result.stats.invalid_frames.empty());
  // Nothing of the rigid method's.
  CHECK_FALSE(result.stats.similarity_factored);
  CHECK(result.stats.similarity.is_identity());
  CHECK(result.stats.guide_exact_frames + result.stats.guide_blended_frames + result.stats.guide_barycentric_frames ==
        0);
  CHECK(result.stats.triangulate_ms > 0);
  CHECK(result.stats.morph_ms >= result.stats.solve_ms);
  CHECK(result.stats.triangulation.interior_faces > 0);
  CHECK(result.triangulation_options.method == SteinerMethod::Improved);
  CHECK(result.triangulation_options.enclosure_sides == kDefaultEnclosureSides);
  CHECK(result.morph_options.weights == WeightKind::MeanValue);
  CHECK(result.morph_options.verify);
}

TEST_CASE("morph_stick_figures keeps node frames only when asked") {
  const Pair pair = read_pair("compatible", "polyline");
  for (const MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric}) {
    CAPTURE(morph_method_name(method));
    MorphStickFiguresOptions options;
    options.method = method;
    options.frames = 3;
    CHECK(morph_stick_figures(pair.source, pair.target, options).node_frames.empty());
    options.keep_node_frames = true;
    const MorphStickFiguresResult result = morph_stick_figures(pair.source, pair.target, options);
    REQUIRE(result.node_frames.size() == 3);
    REQUIRE(result.triangulation.has_value());
    for (std::size_t f = 0; f < 3; ++f) {
      CHECK(int(result.node_frames[f].size()) == result.triangulation->node_count());
      CHECK(std::equal(result.frames[f].begin(), result.frames[f].end(), result.node_frames[f].begin()));
    }
  }
}

TEST_CASE("morph_stick_figures's default method is rigid") {
  CHECK(MorphStickFiguresOptions{}.method == MorphMethod::Rigid);
  const Pair pair = read_pair("compatible", "letter_a");
  MorphStickFiguresOptions options;
  options.frames = 5;
  const MorphStickFiguresResult by_default = morph_stick_figures(pair.source, pair.target, options);
  options.method = MorphMethod::Rigid;
  const MorphStickFiguresResult rigid = morph_stick_figures(pair.source, pair.target, options);
  CHECK(by_default.frames == rigid.frames);
  CHECK(by_default.stats.similarity_factored);
  CHECK(by_default.stats.guide_exact_frames + by_default.stats.guide_blended_frames +
            by_default.stats.guide_barycentric_frames ==
        3);
  options.method = MorphMethod::Barycentric;
  CHECK(morph_stick_figures(pair.source, pair.target, options).frames != rigid.frames);
}

TEST_CASE("morph_stick_figures: every method starts and ends exactly on the figures") {
  const Pair pair = read_pair("compatible", "letter_b");
  for (const MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric, MorphMethod::Linear}) {
    CAPTURE(morph_method_name(method));
    MorphStickFiguresOptions options;
    options.method = method;
    options.frames = 6;
    const MorphStickFiguresResult result = morph_stick_figures(pair.source, pair.target, options);
    REQUIRE(result.frames.size() == 6);
    CHECK(result.times.front() == 0);
    CHECK(result.times.back() == 1);
    CHECK(result.frames.front() == pair.source.vertices);
    CHECK(result.frames.back() == pair.target.vertices);
    CHECK(result.triangulation.has_value() == (method != MorphMethod::Linear));
    for (const std::vector<Vec2>& frame : result.frames) CHECK(frame.size() == pair.source.vertices.size());
  }
}

TEST_CASE("morph_stick_figures passes the chosen options on") {
  const Pair pair = read_pair("compatible", "letter_a");
  for (const MorphMethod method : {MorphMethod::Barycentric, MorphMethod::Rigid}) {
    CAPTURE(morph_method_name(method));
    MorphStickFiguresOptions options;
    options.method = method;
    options.frames = 4;
    options.steiner = SteinerMethod::Sg2001;
    options.weights = WeightKind::Floater;
    options.enclosure_sides = 9;
    options.verify = false;
    const MorphStickFiguresResult result = morph_stick_figures(pair.source, pair.target, options);
    REQUIRE(result.triangulation.has_value());
    CHECK(result.triangulation->enclosure_vertices == 9);
    CHECK(result.triangulation_options.method == SteinerMethod::Sg2001);
    CHECK(result.triangulation_options.enclosure_sides == 9);
    CHECK(result.morph_options.weights == WeightKind::Floater);
    CHECK(result.morph_options.frames == 4);
    CHECK_FALSE(result.morph_options.verify);
    CHECK(result.stats.verify_ms == 0);
  }
}

TEST_CASE("morph_stick_figures with the linear method is linear_morph") {
  const Pair pair = read_pair("compatible", "letter_a");
  MorphStickFiguresOptions options;
  options.method = MorphMethod::Linear;
  options.frames = 9;
  const MorphStickFiguresResult result = morph_stick_figures(pair.source, pair.target, options);
  std::vector<int> invalid;
  const MorphResult by_hand = linear_morph(pair.source, pair.target, 9, &invalid);
  CHECK(result.frames == by_hand.frames);
  CHECK(result.times == by_hand.times);
  CHECK(result.stats.invalid_frames == invalid);
  CHECK_FALSE(result.triangulation.has_value());
  CHECK(result.node_frames.empty());
  CHECK(result.stats.steiner_vertices == 0);
  CHECK(result.stats.triangulate_ms == 0);
}

TEST_CASE("morph_stick_figures refuses incompatible figures with every method") {
  const Pair pair = read_pair("incompatible", "mirror_image");
  for (const MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric, MorphMethod::Linear}) {
    MorphStickFiguresOptions options;
    options.method = method;
    options.frames = 3;
    CHECK_THROWS_AS(morph_stick_figures(pair.source, pair.target, options), IncompatibleFiguresError);
  }
}

TEST_CASE("check_morph_options refuses pins without correspond = Auto, in the caller's spelling") {
  MorphStickFiguresOptions options;
  options.pins = {{0, 0}};
  CHECK(refusal(options) ==
        "pins need correspond='auto' (with the index correspondence every vertex is already paired)");
  options.spelling = OptionSpelling::CommandLine;
  CHECK(refusal(options) ==
        "option --pin needs --correspond auto (with the index correspondence every vertex is already paired)");
  options.correspond = CorrespondenceMode::Auto;
  CHECK(refusal(options).empty());
  // prepare_rigid_morph builds a solver for one corresponding pair: it
  // takes the matched pair, never the matching.
  const StickFigure dot = make_stick_figure({{0, 0}}, {});
  CHECK_THROWS_WITH(prepare_rigid_morph(dot, dot, options),
                    stickmorph_test::Contains("match them with correspond_figures first"));
}

TEST_CASE("check_morph_options refuses what the linear method would ignore, in the caller's spelling") {
  MorphStickFiguresOptions linear;
  linear.method = MorphMethod::Linear;
  CHECK(refusal(linear).empty());

  MorphStickFiguresOptions options = linear;
  options.steiner = SteinerMethod::Aronov;
  CHECK(refusal(options) ==
        "steiner has no effect with method='linear' (the straight-line morph uses no triangulation)");
  options.spelling = OptionSpelling::CommandLine;
  CHECK(refusal(options) ==
        "option --steiner has no effect with --method linear (the straight-line morph uses no triangulation)");

  options = linear;
  options.weights = WeightKind::Uniform;
  CHECK(refusal(options).rfind("weights has no effect", 0) == 0);
  options = linear;
  options.enclosure_sides = 6;  // even the default, once asked for
  CHECK(refusal(options).rfind("enclosure_sides has no effect", 0) == 0);
  options = linear;
  options.verify = true;
  CHECK(refusal(options).rfind("verify has no effect", 0) == 0);
  options.spelling = OptionSpelling::CommandLine;
  CHECK(refusal(options).rfind("option --no-verify has no effect", 0) == 0);
  options = linear;
  options.keep_node_frames = true;
  CHECK(refusal(options).find("node frames do not exist") != std::string::npos);

  // The barycentric and rigid methods take every one of them.
  for (const MorphMethod method : {MorphMethod::Barycentric, MorphMethod::Rigid}) {
    MorphStickFiguresOptions all;
    all.method = method;
    all.steiner = SteinerMethod::Aronov;
    all.weights = WeightKind::Uniform;
    all.enclosure_sides = 6;
    all.verify = true;
    all.keep_node_frames = true;
    CHECK(refusal(all).empty());
  }
}

TEST_CASE("check_morph_options checks the counts against argument_limits.h") {
  MorphStickFiguresOptions options;
  options.frames = kMinMorphFrames - 1;
  CHECK(refusal(options) == "frames must be at least 2, got 1");
  options.spelling = OptionSpelling::CommandLine;
  CHECK(refusal(options) == "option --frames must be at least 2, got 1");
  options.frames = kMaxMorphFrames + 1LL;
  CHECK(refusal(options) == "option --frames must be at most 100000, got 100001");
  options.frames = kMaxMorphFrames;
  CHECK(refusal(options).empty());

  options.enclosure_sides = kMaxEnclosureSides + 1LL;
  CHECK(refusal(options) == "option --enclosure-sides must be at most 1000, got 1001");
  options.enclosure_sides = 1LL << 40;  // beyond int, reported as given
  CHECK(refusal(options) == "option --enclosure-sides must be at most 1000, got 1099511627776");
  options.enclosure_sides = kMinEnclosureSides;
  CHECK(refusal(options).empty());
}

TEST_CASE("check_count quotes the value as typed when one is given") {
  CHECK_THROWS_WITH(check_frames(std::numeric_limits<long long>::max(), OptionSpelling::Keyword,
                                 "99999999999999999999"),
                    "frames must be at most 100000, got 99999999999999999999");
  CHECK_THROWS_WITH(check_smoothing_rounds(-1, OptionSpelling::Keyword), "smoothing_rounds must be at least 0, got -1");
  CHECK(check_enclosure_sides(3, OptionSpelling::CommandLine) == 3);
}

TEST_CASE("the option-name table names every option once") {
  std::set<int> seen;
  std::set<std::string> keywords;
  for (const OptionName& row : option_names()) {
    CHECK(seen.insert(int(row.option)).second);
    CHECK(keywords.insert(row.keyword).second);
  }
  CHECK(seen.size() == std::size_t(Option::Timing) + 1);
  CHECK(describe_option(Option::Timing, OptionSpelling::CommandLine) == "option --timing");
  CHECK(describe_option(Option::Timing, OptionSpelling::Keyword) == "delay");
  CHECK(describe_option(Option::Correspond, OptionSpelling::CommandLine) == "option --correspond");
  CHECK(describe_option(Option::Pins, OptionSpelling::CommandLine) == "option --pin");
  CHECK(describe_option(Option::Pins, OptionSpelling::Keyword) == "pins");
  CHECK(describe_option(Option::Rotation, OptionSpelling::CommandLine) == "option --rotation");
  CHECK(describe_option(Option::Turns, OptionSpelling::Keyword) == "turns");
  CHECK(describe_option(Option::Easing, OptionSpelling::CommandLine) == "option --easing");
  CHECK(describe_option(Option::EnclosureSides, OptionSpelling::CommandLine) == "option --enclosure-sides");
  // No CLI flag: messages fall back to the keyword.
  CHECK(describe_option(Option::SmoothingRounds, OptionSpelling::CommandLine) == "smoothing_rounds");
}

TEST_CASE("morph_option_rules: every option of the morph once, each parsed back by its engine name") {
  std::set<int> seen;
  for (const MorphOptionRule& rule : morph_option_rules()) {
    CHECK(seen.insert(int(rule.option)).second);
    CHECK(&morph_option_rule(rule.option) == &rule);
    CHECK(rule.methods != 0);
    // A rule that does not apply to every method says why in its messages.
    CHECK((rule.methods == kAllMethods) == (*rule.refused_because == '\0'));
    if (rule.kind == OptionValueKind::Count) {
      CHECK(rule.least <= rule.default_count);
      CHECK(rule.default_count <= rule.most);
    }
    if (rule.kind == OptionValueKind::Name)
      CHECK(std::find(rule.choices.begin(), rule.choices.end(), rule.default_name) != rule.choices.end());
  }
  // Smoothing rounds belong to compatible_triangulation, not to the morph.
  CHECK(seen.size() == option_names().size() - 1);
  CHECK_THROWS_AS(morph_option_rule(Option::SmoothingRounds), InternalError);
  for (const std::string& name : morph_option_rule(Option::Steiner).choices) CHECK_NOTHROW(parse_steiner_method(name));
  for (const std::string& name : morph_option_rule(Option::Weights).choices) CHECK_NOTHROW(parse_weight_kind(name));
  for (const std::string& name : morph_option_rule(Option::Method).choices) CHECK_NOTHROW(parse_morph_method(name));
  CHECK(morph_option_rule(Option::Frames).most == kMaxMorphFrames);
  CHECK(morph_option_rule(Option::EnclosureSides).default_count == kDefaultEnclosureSides);
  CHECK(morph_option_rule(Option::Turns).least == -kMaxExtraTurns);
}

TEST_CASE("option_applies: the triangulation's options not to linear, the rotation's only to rigid") {
  for (const Option option : {Option::Steiner, Option::Weights, Option::EnclosureSides, Option::Verify,
                              Option::FrameCheck}) {
    CHECK(option_applies(option, MorphMethod::Rigid));
    CHECK(option_applies(option, MorphMethod::Barycentric));
    CHECK_FALSE(option_applies(option, MorphMethod::Linear));
  }
  for (const Option option : {Option::Rotation, Option::Turns, Option::Easing, Option::Timing}) {
    CHECK(option_applies(option, MorphMethod::Rigid));
    CHECK_FALSE(option_applies(option, MorphMethod::Barycentric));
    CHECK_FALSE(option_applies(option, MorphMethod::Linear));
  }
  for (const Option option : {Option::Frames, Option::Method, Option::Correspond, Option::Pins})
    for (const MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric, MorphMethod::Linear})
      CHECK(option_applies(option, method));
}

TEST_CASE("check_morph_options refuses every option given with a method outside its rule") {
  // Derived from the table, so that the rule and the check cannot drift.
  for (const MorphOptionRule& rule : morph_option_rules())
    for (const MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric, MorphMethod::Linear}) {
      MorphStickFiguresOptions options;
      options.method = method;
      switch (rule.option) {
        case Option::Verify: options.verify = true; break;
        case Option::FrameCheck: options.frame_check = FrameCheck::Certificate; break;
        case Option::Weights: options.weights = WeightKind::MeanValue; break;
        case Option::Steiner: options.steiner = SteinerMethod::Improved; break;
        case Option::EnclosureSides: options.enclosure_sides = kDefaultEnclosureSides; break;
        case Option::Rotation: options.rotation = RotationDirection::Short; break;
        case Option::Turns: options.turns = 0; break;
        case Option::Easing: options.easing = Easing::None; break;
        default: continue;  // always in effect
      }
      const std::string message = refusal(options);
      if (option_applies(rule.option, method)) {
        CHECK(message.empty());
      } else {
        CHECK(message == describe_option(rule.option, OptionSpelling::Keyword) + " has no effect with method='" +
                             morph_method_name(method) + "' (" + rule.refused_because + ")");
      }
    }
}

TEST_CASE("check_count_option checks a count's range only where the option applies") {
  CHECK_THROWS_WITH(check_count_option(Option::EnclosureSides, 2, MorphMethod::Barycentric, OptionSpelling::Keyword),
                    "enclosure_sides must be at least 3, got 2");
  CHECK_THROWS_WITH(check_count_option(Option::EnclosureSides, std::numeric_limits<long long>::max(),
                                       MorphMethod::Rigid, OptionSpelling::Keyword, "1" + std::string(30, '0')),
                    "enclosure_sides must be at most 1000, got 1" + std::string(30, '0'));
  CHECK_THROWS_WITH(check_count_option(Option::Turns, 101, MorphMethod::Rigid, OptionSpelling::CommandLine),
                    "option --turns must be at most 100, got 101");
  // Out of its methods the value does not matter: check_morph_options
  // refuses the option by name.
  CHECK_NOTHROW(check_count_option(Option::EnclosureSides, 2, MorphMethod::Linear, OptionSpelling::Keyword));
  CHECK_NOTHROW(check_count_option(Option::Turns, 101, MorphMethod::Barycentric, OptionSpelling::Keyword));
  CHECK_THROWS_AS(check_count_option(Option::Steiner, 1, MorphMethod::Rigid, OptionSpelling::Keyword), InternalError);
}

TEST_CASE("check_pins_need_auto names the command when given one") {
  const std::vector<VertexPin> pins = {{0, 0}};
  CHECK_NOTHROW(check_pins_need_auto(CorrespondenceMode::ByIndex, {}, OptionSpelling::CommandLine));
  CHECK_NOTHROW(check_pins_need_auto(CorrespondenceMode::Auto, pins, OptionSpelling::CommandLine));
  CHECK_THROWS_WITH(check_pins_need_auto(CorrespondenceMode::ByIndex, pins, OptionSpelling::CommandLine, "check: "),
                    "check: option --pin needs --correspond auto (with the index correspondence every vertex is "
                    "already paired)");
  CHECK_THROWS_WITH(check_pins_need_auto(CorrespondenceMode::ByIndex, pins, OptionSpelling::Keyword),
                    "pins need correspond='auto' (with the index correspondence every vertex is already paired)");
}

TEST_CASE("parse_morph_method knows the three methods") {
  CHECK(parse_morph_method("rigid") == MorphMethod::Rigid);
  CHECK(parse_morph_method("barycentric") == MorphMethod::Barycentric);
  CHECK(parse_morph_method("linear") == MorphMethod::Linear);
  for (const MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric, MorphMethod::Linear})
    CHECK(parse_morph_method(morph_method_name(method)) == method);
  CHECK_THROWS_AS(parse_morph_method("arap"), InvalidArgumentError);
  CHECK_THROWS_WITH(parse_morph_method("spline"),
                    "unknown morph method 'spline' (choose rigid, barycentric or linear)");
}

TEST_CASE("the pipeline's errors carry what callers need without parsing messages") {
  SECTION("a file that cannot be read is a FileError with errno, not a JsonError") {
    const std::string missing = std::string(STICKMORPH_TEST_DATA) + "/no_such_figure.json";
    try {
      read_figure_file(missing);
      FAIL("read a missing file");
    } catch (const FileError& e) {
      CHECK(e.error_number() == ENOENT);
      CHECK(e.path() == missing);
      CHECK(std::string(e.what()) == missing + ": cannot read file: No such file or directory");
    }
    try {
      read_figure_file(STICKMORPH_TEST_DATA);
      FAIL("read a directory");
    } catch (const FileError& e) {
      CHECK(e.error_number() == EISDIR);
    }
  }
  SECTION("incompatible figures carry the report's kind and vertices") {
    const Pair pair = read_pair("incompatible", "junction_rotation");
    const CompatibilityReport report = check_compatibility(pair.source, pair.target);
    REQUIRE_FALSE(report.compatible());
    for (const MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric, MorphMethod::Linear}) {
      MorphStickFiguresOptions options;
      options.method = method;
      try {
        morph_stick_figures(pair.source, pair.target, options);
        FAIL("morphed incompatible figures");
      } catch (const IncompatibleFiguresError& e) {
        CHECK(e.kind() == Incompatibility::RotationDiffers);
        CHECK(e.kind() == report.kind);
        CHECK(e.vertices() == report.vertices);
        CHECK(std::string(e.what()) == "incompatible figures: " + report.reason);
      }
    }
  }
}

TEST_CASE("the rigid method falls back to the paper's triangulation where the guide's has a star too flat to weigh") {
  // A pinned zigzag matched onto a crowded copy (found by fuzz_correspond_pair,
  // tests/data/fuzz/regressions/correspond_pair): the guide's enclosure gave a
  // triangulation whose mean value weights fail in floating point at figure
  // vertex 0; the barycentric method's triangulation of the same pair morphs.
  const StickFigure source = make_stick_figure(
      {{0.0, 0.0}, {10.0, 20.0}, {20.0, 0.0}, {30.0, 20.0}, {40.0, 0.0}, {50.0, 20.0},
       {9.75015461757851, 19.50030923515702}, {13.333333333333332, 13.333333333333336},
       {16.666666666666668, 6.666666666666665}, {47.29895519069767, 14.597910381395335},
       {15.006485084306096, 9.987029831387808}},
      {{0, 6}, {6, 1}, {1, 7}, {7, 10}, {10, 8}, {8, 2}, {2, 3}, {3, 4}, {4, 9}, {9, 5}});
  const StickFigure target = make_stick_figure(
      {{320.015625, 40.0}, {322.5, 45.0}, {330.0, 40.0}, {330.9015324861232, 41.80306497224631},
       {331.8030649722463, 43.606129944492615}, {333.0, 45.0}, {322.44163424124514, 45.13326848249027},
       {325.0, 40.0}, {327.5, 45.0}, {332.46108949416345, 44.92217898832685},
       {326.2548638132296, 42.509727626459146}},
      {{0, 6}, {6, 1}, {1, 7}, {7, 10}, {10, 8}, {8, 2}, {2, 3}, {3, 4}, {4, 9}, {9, 5}});
  MorphStickFiguresOptions options;
  options.frames = 5;
  const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
  REQUIRE(result.frames.size() == 5);
  CHECK(result.frames.front() == source.vertices);
  CHECK(result.frames.back() == target.vertices);
}
