// The rigid morph (issue 12): GuidedMorph, the convex-combination morph that
// follows the as-rigid-as-possible guide wherever the guide is valid (after
// Surazhsky & Gotsman's "Controllable morphing", the paper's [17]), run
// through the engine's entry morph_stick_figures with MorphMethod::Rigid and
// directly.
#include "catch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "figures.h"
#include "option_checks.h"
#include "motion_helpers.h"
#include "stickmorph/errors.h"
#include "stickmorph/frame_certificate.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/guided_morph.h"
#include "stickmorph/internal/morph_topology.h"
#include "stickmorph/io/figure_io.h"
#include "stickmorph/morph_stick_figures.h"
#include "stickmorph/rigid_guide.h"
#include "stickmorph/similarity_motion.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Pair {
  std::string name;
  StickFigure source, target;
};

Pair read_pair(const std::string& stem) {
  const std::string path = std::string(STICKMORPH_TEST_DATA) + "/" + stem;
  return {stem, read_figure_file(path + ".source.json"), read_figure_file(path + ".target.json")};
}

std::vector<Vec2> negated(const std::vector<Vec2>& points) {
  std::vector<Vec2> out;
  for (const Vec2& p : points) out.push_back({-p[0], -p[1]});
  return out;
}

StickFigure with_vertices(const StickFigure& f, std::vector<Vec2> vertices) {
  StickFigure g = f;
  g.vertices = std::move(vertices);
  return g;
}

// The signed angle from edge e's direction in a to its direction in b, in (-pi, pi].
double turn_between(const std::vector<Vec2>& a, const std::vector<Vec2>& b, const Edge& e) {
  const Vec2 u = vector_of(a, e), v = vector_of(b, e);
  return std::atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]);
}
// Edge e's total turn along the frames, unwrapped frame by frame.
double unwrapped_turn(const std::vector<std::vector<Vec2>>& frames, const Edge& e) {
  double total = 0;
  for (std::size_t f = 1; f < frames.size(); ++f) total += turn_between(frames[f - 1], frames[f], e);
  return total;
}




MorphStickFiguresResult morph_rigid(const StickFigure& source, const StickFigure& target, int frames,
                                    bool keep_node_frames = false) {
  MorphStickFiguresOptions options;
  options.method = MorphMethod::Rigid;
  options.frames = frames;
  options.keep_node_frames = keep_node_frames;
  return morph_stick_figures(source, target, options);
}

// Everything the engine promises about a rigid morph's frames, checked here
// independently: ends bit for bit, every frame a valid figure with the
// source's topology (verify_frame), every triangle of every node frame
// counter-clockwise, the guide counts adding up.
void check_rigid_result(const StickFigure& source, const StickFigure& target, const MorphStickFiguresResult& result,
                        int frames) {
  REQUIRE(int(result.frames.size()) == frames);
  REQUIRE(int(result.times.size()) == frames);
  REQUIRE(int(result.node_frames.size()) == frames);
  REQUIRE(result.triangulation.has_value());
  const FigureTriangulation& tri = *result.triangulation;
  const std::size_t n = source.vertices.size();
  CHECK(tri.figure_vertices == int(n));
  CHECK(result.frames.front() == source.vertices);
  CHECK(result.frames.back() == target.vertices);
  CHECK(std::vector<Vec2>(tri.source.begin(), tri.source.begin() + long(n)) == source.vertices);
  CHECK(std::vector<Vec2>(tri.target.begin(), tri.target.begin() + long(n)) == target.vertices);
  CHECK(result.node_frames.front() == tri.source);
  CHECK(result.node_frames.back() == tri.target);
  CHECK(internal::first_non_positive(tri, tri.source) < 0);
  CHECK(internal::first_non_positive(tri, tri.target) < 0);
  const Decomposition decomposition = decompose(source);
  for (int f = 0; f < frames; ++f) {
    CAPTURE(f);
    REQUIRE(int(result.node_frames[f].size()) == tri.node_count());
    CHECK(std::equal(result.frames[f].begin(), result.frames[f].end(), result.node_frames[f].begin()));
    CHECK_NOTHROW(verify_frame(source, decomposition, result.frames[f], f, result.times[f]));
    CHECK(internal::first_non_positive(tri, result.node_frames[f]) == -1);
    CHECK(result.times[f] == double(f) / (frames - 1));
  }
  const MorphStickFiguresStats& s = result.stats;
  CHECK(s.guide_exact_frames + s.guide_blended_frames + s.guide_barycentric_frames == frames - 2);
  CHECK(s.steiner_vertices == tri.steiner_vertices);
  CHECK(s.triangles == int(tri.triangles.size()));
}


// The compatible triangulation and guide morph_stick_figures builds for
// method Rigid, built by hand from the public pieces.
struct RigidParts {
  SimilarityMotion similarity;
  FigureTriangulation normalised;
};

RigidParts rigid_parts(const StickFigure& source, const StickFigure& target) {
  RigidParts parts;
  parts.similarity = fit_similarity(source.vertices, target.vertices);
  std::vector<Vec2> back;
  for (const Vec2& p : target.vertices) back.push_back(parts.similarity.unapply(1.0, p));
  RawEdges edges;
  for (const Edge& e : target.edges) edges.push_back({e[0], e[1]});
  const StickFigure normalised_target = make_stick_figure(std::move(back), edges, target.name);
  REQUIRE(check_compatibility(source, normalised_target).compatible());
  parts.normalised = triangulate_figures(source, normalised_target);
  return parts;
}

}  // namespace

TEST_CASE("the rigid morph of a figure into itself turned by 180 degrees just turns", "[guided_morph]") {
  constexpr int N = 13;
  for (const StickFigure& source : {stick_man_walking(), grid_triangulation(3), polygon(regular(7, 2.0, 0.3))}) {
    // The exact half turn about the origin: the centroid c goes to -c.
    const StickFigure target = with_vertices(source, negated(source.vertices));
    const MorphStickFiguresResult result = morph_rigid(source, target, N, true);
    check_rigid_result(source, target, result, N);
    CHECK(result.stats.similarity_factored);
    CHECK(result.stats.similarity.angle == kPi);
    // Compatibility needs no Steiner vertex (the normalised pair is one
    // figure); those there are compatible refinement's, for the angles.
    CHECK(result.stats.steiner_vertices == result.stats.triangulation.refinement_steiner);
    CHECK(result.stats.guide_exact_frames == N - 2);

    const Vec2 c = mean(source.vertices);
    const double r = rms_radius(source.vertices);
    for (int k = 0; k < N; ++k) {
      CAPTURE(k);
      const std::vector<Vec2>& frame = result.frames[k];
      const double t = result.times[k];
      // Rigid: every edge keeps its length, the figure its size ...
      for (const Edge& e : source.edges)
        CHECK(length_of(frame, e) == Approx(length_of(source.vertices, e)).margin(1e-9));
      CHECK(rms_radius(frame) == Approx(r).epsilon(1e-12));
      // ... its centroid goes straight through the origin ...
      const Vec2 m = mean(frame);
      CHECK(m[0] == Approx((1 - 2 * t) * c[0]).margin(1e-9));
      CHECK(m[1] == Approx((1 - 2 * t) * c[1]).margin(1e-9));
      // ... and it turns at constant speed (a rigid turn is even in u):
      // every edge by 180 * t degrees.
      if (k < N - 1)
        for (const Edge& e : source.edges)
          CHECK(turn_between(source.vertices, frame, e) == Approx(kPi * t).margin(1e-9));
    }
    for (const Edge& e : source.edges) CHECK(unwrapped_turn(result.frames, e) == Approx(kPi).margin(1e-9));
  }
}

TEST_CASE("the rigid morph keeps the size of a half turn that the barycentric morph squashes", "[guided_morph]") {
  // Issue 12's measurement: [8] alone, inside one fixed enclosure, shrinks
  // a figure turning by 180 degrees and turns it short; the rigid morph
  // factors the turn out.
  constexpr int N = 21;
  const StickFigure source = stick_man_walking();
  const StickFigure target = with_vertices(source, negated(source.vertices));
  const double r = rms_radius(source.vertices);
  double rigid_smallest = r, barycentric_smallest = r;
  MorphStickFiguresOptions options;
  options.frames = N;
  options.method = MorphMethod::Barycentric;
  for (const std::vector<Vec2>& frame : morph_stick_figures(source, target, options).frames)
    barycentric_smallest = std::min(barycentric_smallest, rms_radius(frame));
  options.method = MorphMethod::Rigid;
  for (const std::vector<Vec2>& frame : morph_stick_figures(source, target, options).frames)
    rigid_smallest = std::min(rigid_smallest, rms_radius(frame));
  CHECK(rigid_smallest == Approx(r).epsilon(1e-12));
  CHECK(barycentric_smallest < 0.8 * r);  // 0.64 at the time of writing
}

TEST_CASE("the rigid morph's easing slows the half turn in and out", "[guided_morph]") {
  constexpr int N = 11;
  const StickFigure source = stick_man_walking();
  const StickFigure target = with_vertices(source, negated(source.vertices));
  MorphStickFiguresOptions options;
  options.frames = N;
  options.easing = Easing::InOut;
  const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
  REQUIRE(int(result.frames.size()) == N);
  // The turn is even in u, so the eased turn is 180 degrees times the smoothstep of t.
  for (int k = 1; k + 1 < N; ++k) {
    const double t = result.times[k];
    CHECK(turn_between(source.vertices, result.frames[k], source.edges[0]) ==
          Approx(kPi * t * t * (3 - 2 * t)).margin(1e-9));
  }
}

TEST_CASE("the rigid morph of a pure similarity pair is the similarity, without Steiner vertices for compatibility",
          "[guided_morph]") {
  constexpr int N = 9;
  for (const StickFigure& source : {read_pair("pairs/compatible/letter_a").source, stick_man_standing()}) {
    const StickFigure target = moved(source, 0.9, 1.5, 3, -2);
    const MorphStickFiguresResult result = morph_rigid(source, target, N, true);
    check_rigid_result(source, target, result, N);
    // Compatibility needs no Steiner vertex (the normalised pair is one
    // figure); those there are compatible refinement's, for the angles.
    CHECK(result.stats.steiner_vertices == result.stats.triangulation.refinement_steiner);
    CHECK(result.stats.similarity_factored);
    CHECK(result.stats.similarity.angle == Approx(0.9).margin(1e-12));
    CHECK(result.stats.similarity.scale == Approx(1.5).margin(1e-12));
    CHECK(result.stats.guide_exact_frames == N - 2);
    // The guide the morph follows, and its even-speed parameters.
    const RigidGuide guide(source, target.vertices, result.stats.similarity);
    for (int k = 0; k < N; ++k) {
      CAPTURE(k);
      const std::vector<Vec2>& frame = result.frames[k];
      const double u = guide.parameter_at(result.times[k]);
      // Every frame is a similarity image of the source: the figure only
      // turns, grows and moves ...
      const SimilarityMotion fit = fit_similarity(source.vertices, frame);
      check_close(fit.apply(1.0, source.vertices), frame, 1e-9);
      // ... by the interpolated rotation and translation ...
      CHECK(fit.angle == Approx(u * 0.9).margin(1e-9));
      const Vec2 m = mean(frame);
      CHECK(m[0] ==
            Approx((1 - u) * result.stats.similarity.source_center[0] + u * result.stats.similarity.target_center[0])
                .margin(1e-9));
      CHECK(m[1] ==
            Approx((1 - u) * result.stats.similarity.source_center[1] + u * result.stats.similarity.target_center[1])
                .margin(1e-9));
      // ... and the scale of the guide, whose edge lengths change linearly
      // (forward kinematics): 1 + 0.5 u, not SimilarityMotion's geometric
      // 1.5^u (2% apart at u = 0.5; both are similarities, so the motion is
      // rigid either way). The frame is the guide's.
      CHECK(fit.scale == Approx(1 + 0.5 * u).epsilon(1e-9));
      check_close(frame, guide.at(u), 1e-9);
    }
  }
}

TEST_CASE("the rigid morph's frames are all valid, with exact ends, on a few pairs", "[guided_morph]") {
  constexpr int N = 17;
  std::vector<Pair> pairs = {read_pair("pairs/compatible/letter_a"),
                             read_pair("pairs/compatible/letter_b"),
                             read_pair("pairs/compatible/wheel"),
                             read_pair("pairs/compatible/tree_junction"),
                             read_pair("pairs/compatible/square_with_spikes"),
                             read_pair("paper/s_to_u"),
                             read_pair("polygon_pairs/comb_star"),
                             read_pair("polygon_pairs/fig7_hand_bird")};
  pairs.push_back({"stick man", stick_man_standing(), stick_man_walking()});
  for (const Pair& pair : pairs) {
    CAPTURE(pair.name);
    const MorphStickFiguresResult result = morph_rigid(pair.source, pair.target, N, true);
    check_rigid_result(pair.source, pair.target, result, N);
    CHECK(result.stats.similarity_factored);
    CHECK(result.stats.guide_barycentric_frames == 0);
    // The triangulation in output space: its target enclosure is the
    // source's moved by the similarity (section 6's rotated enclosure).
    const FigureTriangulation& tri = *result.triangulation;
    for (int i = 0; i < tri.enclosure_vertices; ++i) {
      const int v = tri.figure_vertices + i;
      const Vec2 expected = result.stats.similarity.apply(1.0, tri.source[v]);
      CHECK(tri.target[v][0] == Approx(expected[0]).margin(1e-9));
      CHECK(tri.target[v][1] == Approx(expected[1]).margin(1e-9));
    }
  }
}

TEST_CASE("the rigid morph of a tree whose guide is valid follows the guide exactly", "[guided_morph]") {
  constexpr int N = 21;
  const StickFigure source = stick_man_standing(), target = stick_man_walking();
  const MorphStickFiguresResult result = morph_rigid(source, target, N);
  CHECK(result.stats.guide_exact_frames == N - 2);
  const RigidGuide guide(source, target.vertices, result.stats.similarity);
  for (int k = 1; k + 1 < N; ++k) {
    CAPTURE(k);
    const std::vector<Vec2> g = guide.at(guide.parameter_at(result.times[k]));
    check_close(result.frames[k], g, 1e-9);
    // Forward kinematics: lengths linear in u.
    const double u = guide.parameter_at(result.times[k]);
    for (const Edge& e : source.edges)
      CHECK(length_of(result.frames[k], e) ==
            Approx((1 - u) * length_of(source.vertices, e) + u * length_of(target.vertices, e)).margin(1e-9));
  }
}

TEST_CASE("the rigid morph turns the way the rotation option says", "[guided_morph]") {
  constexpr int N = 41;
  const StickFigure source = stick_man_walking();
  // Turned by exactly -90 degrees: (x, y) -> (y, -x).
  std::vector<Vec2> turned;
  for (const Vec2& p : source.vertices) turned.push_back({p[1], -p[0]});
  const StickFigure target = with_vertices(source, turned);

  struct Case {
    std::optional<RotationDirection> rotation;
    std::optional<long long> turns;
    double degrees;
  };
  const Case cases[] = {
      {std::nullopt, std::nullopt, -90},
      {RotationDirection::Short, std::nullopt, -90},
      {RotationDirection::CounterClockwise, std::nullopt, 270},
      {RotationDirection::Clockwise, std::nullopt, -90},
      {std::nullopt, 1LL, 270},
      {RotationDirection::CounterClockwise, 1LL, 630},
      {RotationDirection::Clockwise, -1LL, -450},
  };
  for (const Case& c : cases) {
    CAPTURE(c.degrees);
    MorphStickFiguresOptions options;
    options.frames = N;
    options.rotation = c.rotation;
    options.turns = c.turns;
    const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
    CHECK(result.stats.similarity.angle == Approx(c.degrees * kPi / 180).margin(1e-12));
    // Compatibility needs no Steiner vertex (the normalised pair is one
    // figure); those there are compatible refinement's, for the angles.
    CHECK(result.stats.steiner_vertices == result.stats.triangulation.refinement_steiner);
    for (const Edge& e : source.edges) {
      CHECK(unwrapped_turn(result.frames, e) == Approx(c.degrees * kPi / 180).margin(1e-9));
      // Steadily one way, as a rigid turn: every step the same turn.
      for (int k = 1; k < N; ++k)
        CHECK(turn_between(result.frames[k - 1], result.frames[k], e) ==
              Approx(c.degrees * kPi / 180 / (N - 1)).margin(1e-9));
      // Lengths kept.
      for (int k = 0; k < N; ++k)
        CHECK(length_of(result.frames[k], e) == Approx(length_of(source.vertices, e)).margin(1e-9));
    }
  }
}

TEST_CASE("the rigid morph's direction also holds for a pair that is not a similarity", "[guided_morph]") {
  constexpr int N = 41;
  const StickFigure source = stick_man_standing();
  // The walking stick man turned a further -120 degrees: about -90 in all.
  const StickFigure target = moved(stick_man_walking(), -120 * kPi / 180, 1, 0, 0);
  for (RotationDirection direction : {RotationDirection::Short, RotationDirection::CounterClockwise}) {
    MorphStickFiguresOptions options;
    options.frames = N;
    options.rotation = direction;
    const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
    const double angle = result.stats.similarity.angle;
    CHECK((direction == RotationDirection::Short ? angle < 0 : angle > kPi));
    for (const Edge& e : source.edges) {
      // Every edge turns within half a turn of the whole figure's rotation.
      const double own = unwrapped_turn(result.frames, e);
      CHECK(std::abs(own - angle) < kPi);
      CHECK(std::abs(std::remainder(own - turn_between(source.vertices, target.vertices, e), 2 * kPi)) < 1e-9);
    }
  }
}

TEST_CASE("the rigid morph stays valid where its guide self-intersects", "[guided_morph]") {
  constexpr int N = 30;
  for (const std::string stem : {"polygon_pairs/glyph_s_u", "polygon_pairs/spiral_meander"}) {
    CAPTURE(stem);
    const Pair pair = read_pair(stem);
    const MorphStickFiguresResult result = morph_rigid(pair.source, pair.target, N, true);
    // The premise: the guide itself is not a valid figure in some frames.
    const RigidGuide guide(pair.source, pair.target.vertices, result.stats.similarity);
    int invalid_guide_frames = 0;
    for (int k = 1; k + 1 < N; ++k)
      if (!is_frame_valid(pair.source, guide.at(guide.parameter_at(result.times[k])))) ++invalid_guide_frames;
    CHECK(invalid_guide_frames > 0);
    // Yet every frame is valid, and the frames follow the guide where they can.
    check_rigid_result(pair.source, pair.target, result, N);
    CHECK(result.stats.guide_blended_frames >= invalid_guide_frames);
    CHECK(result.stats.guide_barycentric_frames == 0);
  }
}

TEST_CASE("GuidedMorph is what morph_stick_figures runs for method Rigid", "[guided_morph]") {
  // On pairs whose guide is valid throughout, every interior frame is the
  // guide frame whatever the triangulation, so the entry and GuidedMorph
  // built by hand from the public pieces agree on the figure.
  constexpr int N = 12;
  std::vector<Pair> pairs = {read_pair("pairs/compatible/letter_a"), read_pair("pairs/compatible/tree_junction")};
  pairs.push_back({"stick man", stick_man_standing(), stick_man_walking()});
  for (const Pair& pair : pairs) {
    CAPTURE(pair.name);
    const RigidParts parts = rigid_parts(pair.source, pair.target);
    GuidedMorph morph(parts.normalised, pair.source, decompose(pair.source), pair.target.vertices, parts.similarity,
                      RigidGuide(pair.source, pair.target.vertices, parts.similarity), WeightKind::MeanValue,
                      Easing::None);
    CHECK(morph.similarity().angle == parts.similarity.angle);
    GuidedMorphStats stats;
    const MorphResult by_hand = guided_morph(morph, N, true, &stats);
    const MorphStickFiguresResult result = morph_rigid(pair.source, pair.target, N);
    CHECK(stats.exact_frames == N - 2);
    CHECK(result.stats.guide_exact_frames == N - 2);
    CHECK(stats.exact_frames + stats.blended_frames + stats.barycentric_frames == N - 2);
    CHECK(result.times == by_hand.times);
    REQUIRE(int(by_hand.frames.size()) == N);
    const std::size_t n = pair.source.vertices.size();
    for (int f = 0; f < N; ++f)
      check_close(std::vector<Vec2>(by_hand.frames[f].begin(), by_hand.frames[f].begin() + long(n)), result.frames[f],
                  1e-9);
    CHECK(std::vector<Vec2>(by_hand.frames.back().begin(), by_hand.frames.back().begin() + long(n)) ==
          pair.target.vertices);
  }
}

TEST_CASE("GuidedMorph frames at the guide's even-speed parameter where it follows the guide", "[guided_morph]") {
  const StickFigure source = stick_man_standing(), target = stick_man_walking();
  const RigidParts parts = rigid_parts(source, target);
  for (Easing easing : {Easing::None, Easing::InOut}) {
    GuidedMorph morph(parts.normalised, source, decompose(source), target.vertices, parts.similarity,
                      RigidGuide(source, target.vertices, parts.similarity), WeightKind::MeanValue, easing);
    const RigidGuide guide(source, target.vertices, parts.similarity);
    for (double t : {0.1, 0.5, 0.8}) {
      const GuidedFrame frame = morph.frame(t, -1, true, "");
      CHECK(frame.fit == GuideFit::Exact);
      CHECK(frame.parameter == Approx(guide.parameter_at(t, easing)).margin(1e-12));
      check_close(std::vector<Vec2>(frame.positions.begin(), frame.positions.begin() + long(source.vertices.size())),
                  guide.at(frame.parameter), 1e-9);
    }
  }
}

TEST_CASE("GuidedMorph scrubs: any time, any order, exact ends", "[guided_morph]") {
  const Pair pair = read_pair("paper/s_to_u");
  const RigidParts parts = rigid_parts(pair.source, pair.target);
  GuidedMorph morph(parts.normalised, pair.source, decompose(pair.source), pair.target.vertices, parts.similarity,
                    RigidGuide(pair.source, pair.target.vertices, parts.similarity), WeightKind::MeanValue,
                    Easing::InOut);

  const FigureTriangulation& tri = morph.triangulation();
  CHECK(std::vector<Vec2>(tri.target.begin(), tri.target.begin() + tri.figure_vertices) == pair.target.vertices);
  CHECK(tri.source == parts.normalised.source);
  CHECK(tri.triangles == parts.normalised.triangles);
  const GuidedFrame first = morph.frame(0, 0, true, "scrub: ");
  CHECK(first.positions == tri.source);
  CHECK(first.parameter == 0);
  const GuidedFrame last = morph.frame(1, -1, true, "scrub: ");
  CHECK(last.positions == tri.target);
  CHECK(last.parameter == 1);

  const GuidedFrame a = morph.frame(0.7, -1, true, "scrub: ");
  const GuidedFrame b = morph.frame(0.2, -1, true, "scrub: ");
  const GuidedFrame again = morph.frame(0.7, -1, true, "scrub: ");
  // The systems are solved by iterating on the latest factorization from
  // the last solution (as MorphSolver does), so a time solved again after
  // another one agrees to the solvers' tolerance, not bit for bit.
  const double scale = rms_radius(pair.source.vertices) + rms_radius(pair.target.vertices);
  check_close(again.positions, a.positions, 1e-7 * scale);
  CHECK(again.fit == a.fit);
  CHECK(again.parameter == a.parameter);
  CHECK(b.parameter > 0);
  CHECK(b.parameter < a.parameter);
  CHECK(a.parameter < 1);
  CHECK(b.parameter < 0.2);  // eased: slow in
  for (const GuidedFrame* f : {&a, &b}) {
    CHECK(f->fit != GuideFit::Barycentric);
    CHECK(internal::first_non_positive(tri, f->positions) == -1);
    CHECK(is_frame_valid(pair.source,
                         std::vector<Vec2>(f->positions.begin(), f->positions.begin() + tri.figure_vertices)));
  }
  // Without the check the same frame comes out.
  check_close(morph.frame(0.7, -1, false, "scrub: ").positions, a.positions, 1e-7 * scale);

  CHECK_THROWS_AS(morph.frame(-0.1, -1, true, "scrub: "), InvalidArgumentError);
  CHECK_THROWS_AS(morph.frame(1.5, 3, true, "scrub: "), InvalidArgumentError);
  CHECK_THROWS_WITH(morph.frame(std::nan(""), -1, true, ""), Contains("must be in [0, 1]"));
  CHECK(morph.stats().verify_ms > 0);
}

TEST_CASE("GuidedMorph scrubs at random times after a playback: verified frames, the same for the same times",
          "[guided_morph]") {
  // Issue 29: a scrub iterates on the kept factorization nearest in time
  // and starts from the kept solutions nearest in time. Every frame is
  // still checked (FrameCheck::Full: the certificate and verify_frame), and
  // the result depends only on the times asked since construction: two
  // morphs given the same times agree bit for bit, in order and scrubbed.
  constexpr int N = 24;
  constexpr int kScrub = 40;
  int blended = 0;
  for (const Pair& pair : {read_pair("paper/s_to_u"), read_pair("polygon_pairs/comb_star")}) {
    CAPTURE(pair.name);
    const MorphStickFiguresOptions options;
    GuidedMorph first = prepare_rigid_morph(pair.source, pair.target, options);
    GuidedMorph second = prepare_rigid_morph(pair.source, pair.target, options);
    GuidedMorphStats stats;
    const MorphResult played = guided_morph(first, N, true, &stats, FrameCheck::Full);
    const MorphResult again = guided_morph(second, N, true, nullptr, FrameCheck::Full);
    CHECK(played.frames == again.frames);
    blended += stats.blended_frames;
    const int factorizations = first.stats().factorizations;

    std::mt19937 rng(29);
    std::vector<double> times;
    for (int k = 0; k < kScrub; ++k) times.push_back(double(rng()) / 4294967296.0);
    times.push_back(times[3]);  // a time asked again, after others
    const FigureTriangulation& tri = first.triangulation();
    const double scale = rms_radius(pair.source.vertices) + rms_radius(pair.target.vertices);
    for (std::size_t k = 0; k < times.size(); ++k) {
      CAPTURE(k, times[k]);
      GuidedFrame a, b;
      REQUIRE_NOTHROW(a = first.frame(times[k], -1, true, "scrub: ", FrameCheck::Full));
      REQUIRE_NOTHROW(b = second.frame(times[k], -1, true, "scrub: ", FrameCheck::Full));
      CHECK(a.positions == b.positions);
      CHECK(a.fit == b.fit);
      CHECK(internal::first_non_positive(tri, a.positions) == -1);
      CHECK(is_frame_valid(pair.source, std::vector<Vec2>(a.positions.begin(),
                                                          a.positions.begin() + tri.figure_vertices)));
      // The frame a fresh morph gives at that time first, to the solvers'
      // tolerance.
      GuidedMorph fresh = prepare_rigid_morph(pair.source, pair.target, options);
      check_close(a.positions, fresh.frame(times[k], -1, true, "fresh: ").positions, 1e-7 * scale);
    }
    CHECK(first.stats().factorizations == second.stats().factorizations);
    CHECK(first.stats().factorizations >= factorizations);
  }
  CHECK(blended > 0);  // the blended system, whose anchors a scrub chooses, was solved
}

TEST_CASE("GuidedMorph without a similarity morphs the pair itself", "[guided_morph]") {
  // What morph_stick_figures falls back to when the mapped-back target
  // lost a triangle to rounding: the pair's own triangulation, the guide
  // still turning the figure.
  constexpr int N = 9;
  const Pair pair = read_pair("pairs/compatible/letter_a");
  const FigureTriangulation tri = triangulate_figures(pair.source, pair.target);
  const SimilarityMotion similarity = fit_similarity(pair.source.vertices, pair.target.vertices);
  GuidedMorph morph(tri, pair.source, decompose(pair.source), pair.target.vertices, SimilarityMotion{},
                    RigidGuide(pair.source, pair.target.vertices, similarity), WeightKind::MeanValue, Easing::None);
  CHECK(morph.similarity().is_identity());
  CHECK(morph.triangulation().target == tri.target);
  GuidedMorphStats stats;
  const MorphResult result = guided_morph(morph, N, true, &stats);
  REQUIRE(int(result.frames.size()) == N);
  CHECK(result.frames.front() == tri.source);
  CHECK(result.frames.back() == tri.target);
  CHECK(stats.exact_frames + stats.blended_frames + stats.barycentric_frames == N - 2);
  const Decomposition decomposition = decompose(pair.source);
  for (int f = 0; f < N; ++f) {
    CHECK(internal::first_non_positive(tri, result.frames[f]) == -1);
    CHECK(is_frame_valid(pair.source, decomposition,
                         std::vector<Vec2>(result.frames[f].begin(), result.frames[f].begin() + tri.figure_vertices)));
  }
}

TEST_CASE("GuidedMorph refuses a target of the wrong size", "[guided_morph]") {
  const Pair pair = read_pair("pairs/compatible/letter_a");
  const RigidParts parts = rigid_parts(pair.source, pair.target);
  std::vector<Vec2> short_target = pair.target.vertices;
  short_target.pop_back();
  CHECK_THROWS_AS(
      GuidedMorph(parts.normalised, pair.source, decompose(pair.source), short_target, parts.similarity,
                  RigidGuide(pair.source, pair.target.vertices, parts.similarity), WeightKind::MeanValue, Easing::None),
      InvalidArgumentError);
}

TEST_CASE("the rigid method's options are refused with the other methods, naming the option", "[guided_morph]") {
  MorphStickFiguresOptions rigid;
  rigid.rotation = RotationDirection::CounterClockwise;
  rigid.turns = -3;
  rigid.easing = Easing::InOut;
  rigid.keep_node_frames = true;
  CHECK(rigid.method == MorphMethod::Rigid);  // the default
  CHECK(refusal(rigid).empty());

  const std::string why = " (only the rigid method factors out a rotation and follows a guide)";
  for (const MorphMethod method : {MorphMethod::Barycentric, MorphMethod::Linear}) {
    const std::string name = morph_method_name(method);
    MorphStickFiguresOptions options;
    options.method = method;
    CHECK(refusal(options).empty());
    options.rotation = RotationDirection::Short;  // even the default, once asked for
    CHECK(refusal(options) == "rotation has no effect with method='" + name + "'" + why);
    options.spelling = OptionSpelling::CommandLine;
    CHECK(refusal(options) == "option --rotation has no effect with --method " + name + why);
    options = {};
    options.method = method;
    options.turns = 0;
    CHECK(refusal(options) == "turns has no effect with method='" + name + "'" + why);
    options = {};
    options.method = method;
    options.easing = Easing::None;
    options.spelling = OptionSpelling::CommandLine;
    CHECK(refusal(options) == "option --easing has no effect with --method " + name + why);
    // The entry itself refuses them before any work.
    CHECK_THROWS_AS(morph_stick_figures(stick_man_standing(), stick_man_walking(), options), InvalidArgumentError);
  }
}

TEST_CASE("the rigid method refuses too many turns", "[guided_morph]") {
  MorphStickFiguresOptions options;
  options.turns = kMaxExtraTurns + 1LL;
  CHECK(refusal(options) == "turns must be at most 100, got 101");
  options.turns = -kMaxExtraTurns - 1LL;
  options.spelling = OptionSpelling::CommandLine;
  CHECK(refusal(options) == "option --turns must be at least -100, got -101");
  options.turns = 1LL << 40;
  CHECK(refusal(options) == "option --turns must be at most 100, got 1099511627776");
  CHECK_THROWS_AS(morph_stick_figures(stick_man_standing(), stick_man_walking(), options), InvalidArgumentError);
  options.turns = kMaxExtraTurns;
  CHECK(refusal(options).empty());
  options.turns = -kMaxExtraTurns;
  CHECK(refusal(options).empty());
}

TEST_CASE("the rigid method is the default and reports its similarity", "[guided_morph]") {
  const MorphStickFiguresOptions defaults;
  CHECK(defaults.method == MorphMethod::Rigid);
  const StickFigure source = stick_man_standing(), target = stick_man_walking();
  MorphStickFiguresOptions options;
  options.frames = 5;
  const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
  CHECK(result.stats.similarity_factored);
  const SimilarityMotion fit = fit_similarity(source.vertices, target.vertices);
  CHECK(result.stats.similarity.angle == fit.angle);
  CHECK(result.stats.similarity.scale == fit.scale);
  CHECK(result.stats.similarity.source_center == fit.source_center);
  CHECK(result.stats.similarity.target_center == fit.target_center);
  CHECK(result.node_frames.empty());  // only when asked
  REQUIRE(result.triangulation.has_value());
  CHECK(result.stats.triangulate_ms > 0);
  CHECK(result.stats.morph_ms > 0);
}
// A pair whose source and mapped-back target cannot be triangulated (the
// spiderweb of section 4 finds no embedding of the exterior face in both):
// the rigid method falls back to the pair itself, as the barycentric
// method triangulates it (145 Steiner vertices).
TEST_CASE("the rigid morph handles a regression pair whose normalised target does not triangulate",
          "[guided_morph]") {
  constexpr int N = 10;
  const Pair pair = read_pair("regressions/random_near_touching_seed381076493457");
  MorphStickFiguresOptions options;
  options.frames = N;
  options.method = MorphMethod::Barycentric;
  REQUIRE_NOTHROW(morph_stick_figures(pair.source, pair.target, options));
  MorphStickFiguresResult result;
  REQUIRE_NOTHROW(result = morph_rigid(pair.source, pair.target, N, true));
  check_rigid_result(pair.source, pair.target, result, N);
}

TEST_CASE("a rigid frame that rounding flipped is refined in long double before any fallback", "[guided_morph]") {
  // The 10^4-vertex sine wave wound into a spiral (the benchmark's spiral
  // family): in some of its interior frames the blended frame squeezes
  // the innermost turns until neighbouring figure vertices lie about 1e-8
  // apart, 1e-11 of the coordinates, and a triangle beside them comes out
  // of the solve inverted. Refined in long double (GuidedMorph::frame)
  // those frames are valid with the figure where the blended solve put it;
  // before, the barycentric fallback was the only repair and failed there
  // too, so the morph was refused. Every frame is checked here again by
  // the certificate, independently of the morph's own check.
  const int n = 10000;
  std::vector<Vec2> source, target;
  std::vector<std::array<long, 2>> edges;
  for (int i = 0; i < n; ++i) {
    const double angle = std::sqrt(double(i + 1));
    source.push_back({0.5 * i, 3 * std::sin(i * 0.3)});
    target.push_back({angle * std::cos(angle), angle * std::sin(angle)});
    if (i > 0) edges.push_back({i - 1, i});
  }
  const StickFigure from = make_stick_figure(source, edges), to = make_stick_figure(target, edges);
  // The paper's triangulation (no improvement rounds) in an enclosure round
  // the guide, with no similarity factored out: the rigid method's own
  // triangulation is flipped and smoothed for its angles (issue 30) and no
  // longer has a triangle that thin here.
  const CompatiblePair pair = CompatiblePair::check(from, to);
  const SimilarityMotion identity;
  RigidGuide guide(from, to.vertices, identity);
  FigureTriangulationOptions paper;
  for (int j = 1; j < 16; ++j)
    for (const Vec2& p : guide.at(j / 16.0)) paper.enclosed_points.push_back(p);
  const FigureTriangulation triangulation = triangulate_figures(pair, paper);
  GuidedMorph morph(triangulation, from, pair.source_decomposition(), to.vertices, identity, std::move(guide),
                    WeightKind::MeanValue, Easing::None);
  int refined = 0;
  // Frames at f / 40. With issue 30's timing (time kept where the guide's
  // speed allows) the frames near t = 0.28 (14 of 49 or of 50, 13 of 48)
  // are refused: the blended frame there stays inverted after refinement
  // in long double and untangling, and the barycentric fallback of this
  // paper triangulation fails too. A limit of this stress case, left open;
  // the rigid method's own triangulation (improvement rounds) passes 200
  // frames of the same pair.
  constexpr int frames = 40;
  for (int f = 1; f < frames; ++f) {
    const GuidedFrame frame = morph.frame(f / double(frames), f, true, "");
    refined += frame.refined;
    CHECK(frame.fit != GuideFit::Barycentric);
    REQUIRE(certificate_defect(morph.triangulation(), frame.positions).empty());
  }
  CHECK(refined >= 1);
}
