// CompatiblePair: the pair checked once at the boundary (issue 27). Algorithm
// 1 and the compatibility check of section 2.1 run once per figure in one
// morph call; the counters of internal/stage_counters.h count them.
#include "catch.h"

#include <string>
#include <vector>

#include "figures.h"
#include "parts.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/internal/stage_counters.h"
#include "stickmorph/morph_stick_figures.h"
#include "stickmorph/working_scale.h"

using namespace stickmorph;
using namespace stickmorph::test;

namespace {

struct Counts {
  long decompositions = 0, checks = 0;
};

Counts counts_now() {
  const internal::StageCounters& c = internal::stage_counters();
  return {c.decompositions.load(), c.compatibility_checks.load()};
}

// The stages' runs during f().
template <class F>
Counts counted(F&& f) {
  const Counts before = counts_now();
  f();
  const Counts after = counts_now();
  return {after.decompositions - before.decompositions, after.checks - before.checks};
}

StickFigure read_pair_figure(const std::string& name, const std::string& side) {
  return read_figure_file(std::string(STICKMORPH_TEST_DATA) + "/pairs/compatible/" + name + "." + side + ".json");
}

}  // namespace

TEST_CASE("CompatiblePair::check decomposes each figure once and checks the pair once") {
  const StickFigure source = read_pair_figure("letter_a", "source");
  const StickFigure target = read_pair_figure("letter_a", "target");
  std::optional<CompatiblePair> pair;
  const Counts c = counted([&] { pair.emplace(CompatiblePair::check(source, target)); });
  CHECK(c.decompositions == 2);
  CHECK(c.checks == 1);
  // The pair holds what proved it: Algorithm 1 of each figure as decompose says.
  const Decomposition again = decompose(source);
  CHECK(pair->source_decomposition().sequences.size() == again.sequences.size());
  CHECK(pair->source().vertices == source.vertices);
  CHECK(pair->target().vertices == target.vertices);
  CHECK(pair->parts() == 1);
}

TEST_CASE("CompatiblePair::check refuses an incompatible pair with the report's reason") {
  const std::string stem = std::string(STICKMORPH_TEST_DATA) + "/pairs/incompatible/mirror_image";
  const StickFigure source = read_figure_file(stem + ".source.json");
  const StickFigure target = read_figure_file(stem + ".target.json");
  const CompatibilityReport report = check_compatibility(source, target);
  REQUIRE_FALSE(report.compatible());
  try {
    (void)CompatiblePair::check(source, target);
    FAIL("an incompatible pair was accepted");
  } catch (const IncompatibleFiguresError& error) {
    CHECK(std::string(error.what()) == "incompatible figures: " + report.reason);
    CHECK(error.kind() == report.kind);
  }
}

TEST_CASE("One morph call runs Algorithm 1 and the compatibility check once per figure") {
  const StickFigure source = read_pair_figure("letter_a", "source");
  const StickFigure target = read_pair_figure("letter_a", "target");
  MorphStickFiguresOptions options;
  options.frames = 8;

  SECTION("barycentric: the source and the target") {
    options.method = MorphMethod::Barycentric;
    const Counts c = counted([&] { (void)morph_stick_figures(source, target, options); });
    CHECK(c.decompositions == 2);
    CHECK(c.checks == 1);
  }
  SECTION("linear: the source and the target, then the frame verifier on every frame") {
    // The linear method's frames are not triangulation morphs: no
    // certificate, each frame is rebuilt and checked (linear_morph's
    // invalid_frames), against the source's decomposition from the pair.
    options.method = MorphMethod::Linear;
    const Counts c = counted([&] { (void)morph_stick_figures(source, target, options); });
    CHECK(c.decompositions == 2 + options.frames);
    CHECK(c.checks == 1 + options.frames);
  }
  SECTION("rigid: the source, the target and the target mapped back by the similarity") {
    // The mapped-back target (morph_stick_figures.cpp, normalised_pair) is a
    // third figure, made by rounding: it is decomposed and checked against
    // the source's decomposition, which the pair already holds.
    MorphStickFiguresStats stats;
    const Counts c = counted([&] {
      const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
      stats = result.stats;
    });
    REQUIRE(stats.similarity_factored);
    CHECK(c.decompositions == 3);
    CHECK(c.checks == 2);
  }
  SECTION("exactly checked frames decompose only the frames") {
    // FrameCheck::Full is the frame verifier's own Algorithm 1 of every
    // frame (frame_verification.h), independent of the pair's; the interior
    // frames are the only extra decompositions.
    options.method = MorphMethod::Barycentric;
    options.frame_check = FrameCheck::Full;
    const Counts c = counted([&] { (void)morph_stick_figures(source, target, options); });
    CHECK(c.decompositions == 2 + options.frames);
    CHECK(c.checks == 1 + options.frames);
  }
  SECTION("matched (correspond auto): each drawing and the matched pair, checked once") {
    // The match decomposes each drawing for its skeleton and ends with the
    // check of the matched pair (FigureCorrespondence::pair), which the
    // morph uses as it is.
    options.method = MorphMethod::Barycentric;
    options.correspond = CorrespondenceMode::Auto;
    const Counts c = counted([&] { (void)morph_stick_figures(source, target, options); });
    CHECK(c.decompositions == 4);
    CHECK(c.checks == 1);
  }
  SECTION("in the working scale the scaled pair is not checked again") {
    const StickFigure big_source = scaled_figure(source, 400), big_target = scaled_figure(target, 400);
    REQUIRE(working_scale_exponent(big_source, big_target) != 0);
    options.method = MorphMethod::Barycentric;
    const Counts c = counted([&] { (void)morph_stick_figures(big_source, big_target, options); });
    CHECK(c.decompositions == 2);
    CHECK(c.checks == 1);
  }
}

TEST_CASE("A figure of several parts: the bridged pair is checked once, the inputs once") {
  const StickFigure source = parts_figure({{circle(0, 0, 2, 12)}, {circle(0, 0, 1, 6)}});
  const StickFigure target = parts_figure({{circle(0, 0, 2.5, 12, 0.1)}, {circle(0.2, 0, 1, 6, 0.2)}});
  MorphStickFiguresOptions options;
  options.method = MorphMethod::Barycentric;
  options.frames = 4;
  const Counts c = counted([&] { (void)morph_stick_figures(source, target, options); });
  // The inputs, then the bridged figures (part_bridges.h: new figures with
  // the bridges' edges), each pair once.
  CHECK(c.decompositions == 4);
  CHECK(c.checks == 2);
}

TEST_CASE("triangulate_figures on a checked pair runs no check of its own") {
  const StickFigure source = read_pair_figure("wheel", "source");
  const StickFigure target = read_pair_figure("wheel", "target");
  const CompatiblePair pair = CompatiblePair::check(source, target);
  const Counts c = counted([&] { (void)triangulate_figures(pair, FigureTriangulationOptions{}); });
  CHECK(c.decompositions == 0);
  CHECK(c.checks == 0);
}
