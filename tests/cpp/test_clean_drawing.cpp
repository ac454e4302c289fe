// clean_drawing (drawing_cleaning.h, issue 32): strokes that cross, touch,
// stop short and repeat points become a valid stick figure, every change
// reported; bad drawings are errors naming the stroke; a cleaned figure
// cleans to itself.
#include "catch.h"

#include <cmath>
#include <cstdint>
#include <vector>

#include "stickmorph/drawing_cleaning.h"
#include "stickmorph/errors.h"

using namespace stickmorph;
using Catch::Matchers::Contains;

namespace {

using Strokes = std::vector<std::vector<Vec2>>;

CleanedDrawing clean(const Strokes& strokes, std::vector<bool> cyclic = {}, std::optional<double> tolerance = {}) {
  const Drawing drawing = drawing_from_strokes(strokes, std::move(cyclic));
  DrawingCleaningOptions options;
  options.tolerance = tolerance;
  CleanedDrawing cleaned = clean_drawing(drawing, options);
  validate_cleaning(cleaned, drawing);  // every result, as the brief asks
  return cleaned;
}

int count(const CleanedDrawing& cleaned, DrawingChangeKind kind) {
  int n = 0;
  for (const DrawingChange& change : cleaned.changes) n += change.kind == kind;
  return n;
}

// Cleaning the cleaned figure again, as a figure: nothing changes.
void require_cleans_to_itself(const CleanedDrawing& cleaned) {
  std::vector<std::array<std::int64_t, 2>> edges;
  for (const Edge& e : cleaned.figure.edges) edges.push_back({e[0], e[1]});
  const Drawing again = drawing_from_figure(cleaned.figure.vertices, edges);
  DrawingCleaningOptions options;
  options.tolerance = cleaned.tolerance;
  const CleanedDrawing twice = clean_drawing(again, options);
  validate_cleaning(twice, again);
  CHECK(twice.changes.empty());
  CHECK(twice.figure.vertices == cleaned.figure.vertices);
  CHECK(twice.figure.edges == cleaned.figure.edges);
}

// A small deterministic generator (the same numbers on every platform,
// unlike std::uniform_real_distribution).
struct Lcg {
  std::uint64_t state;
  double next() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53);
  }
};

}  // namespace

TEST_CASE("clean_drawing: two crossing strokes share their crossing", "[clean_drawing]") {
  const CleanedDrawing cleaned = clean({{{0, 0}, {10, 10}}, {{0, 10}, {10, 0}}});
  REQUIRE(cleaned.figure.vertices.size() == 5);
  CHECK(cleaned.figure.vertices[4] == Vec2{5, 5});
  CHECK(cleaned.figure.edges.size() == 4);
  CHECK(cleaned.stroke_vertices[0] == std::vector<int>{0, 4, 1});
  CHECK(cleaned.stroke_vertices[1] == std::vector<int>{2, 4, 3});
  CHECK(cleaned.junctions_made == 1);
  REQUIRE(cleaned.changes.size() == 1);
  CHECK(cleaned.changes[0].kind == DrawingChangeKind::Crossing);
  CHECK(cleaned.changes[0].stroke == 0);
  CHECK(cleaned.changes[0].other_stroke == 1);
  CHECK(cleaned.summary() == "1 junction made");
  require_cleans_to_itself(cleaned);
}

TEST_CASE("clean_drawing: an end that stops short snaps onto the stroke", "[clean_drawing]") {
  // Tolerance 1% of the diagonal (about 0.14); the arm stops 0.1 below the body.
  const CleanedDrawing cleaned = clean({{{0, 0}, {10, 0}}, {{4, -10}, {4, -0.1}}});
  CHECK(cleaned.ends_snapped == 1);
  REQUIRE(count(cleaned, DrawingChangeKind::Snap) == 1);
  const DrawingChange& snap = cleaned.changes[0];
  CHECK(snap.stroke == 1);
  CHECK(snap.point == 1);
  CHECK(snap.other_stroke == 0);
  CHECK(snap.at == Vec2{4, 0});
  CHECK(snap.distance == Approx(0.1));
  // The body now passes through the arm's end: a T-junction.
  CHECK(cleaned.stroke_vertices[0] == std::vector<int>{0, 3, 1});
  CHECK(cleaned.stroke_vertices[1] == std::vector<int>{2, 3});
  require_cleans_to_itself(cleaned);
}

TEST_CASE("clean_drawing: an end near a stroke's vertex snaps onto the vertex", "[clean_drawing]") {
  // No new vertex a hair from an existing one (a sliver for the triangulation).
  const CleanedDrawing cleaned = clean({{{0, 0}, {5, 0}, {10, 0}}, {{5.02, -10}, {5.02, -0.1}}});
  REQUIRE(cleaned.ends_snapped == 1);
  CHECK(cleaned.figure.vertices.size() == 4);
  CHECK(cleaned.changes[0].at == Vec2{5, 0});
  CHECK(cleaned.stroke_vertices[1] == std::vector<int>{3, 1});
}

TEST_CASE("clean_drawing: an overshoot within the tolerance is pulled back, a longer one keeps its stub", "[clean_drawing]") {
  const CleanedDrawing short_one = clean({{{0, 0}, {10, 0}}, {{4, -10}, {4, 0.1}}});
  CHECK(short_one.ends_snapped == 1);
  CHECK(short_one.junctions_made == 0);
  REQUIRE(short_one.figure.vertices.size() == 4);
  CHECK(short_one.figure.vertices[3] == Vec2{4, 0});  // a T, as meant
  require_cleans_to_itself(short_one);
  const CleanedDrawing long_one = clean({{{0, 0}, {10, 0}}, {{4, -10}, {4, 0.5}}});
  CHECK(long_one.ends_snapped == 0);
  CHECK(long_one.junctions_made == 1);
  REQUIRE(long_one.figure.vertices.size() == 5);
  CHECK(long_one.figure.vertices[3] == Vec2{4, 0.5});  // the stub's end, as drawn
  require_cleans_to_itself(long_one);
}

TEST_CASE("clean_drawing: a ring closed past its start closes once", "[clean_drawing]") {
  // 44 points around a circle of radius 5 over 400 degrees, jittered: the
  // last 40 degrees run along the first and cross them. The tail merges
  // into one junction; no little loops are left.
  Lcg random{7};
  std::vector<Vec2> ring;
  for (int i = 0; i < 44; ++i) {
    const double a = 1.5707963267948966 + 6.283185307179586 * i / 40;
    ring.push_back({5 * std::cos(a) + (random.next() - 0.5) * 0.04, 5 * std::sin(a) + (random.next() - 0.5) * 0.04});
  }
  const CleanedDrawing cleaned = clean({ring});
  CHECK(cleaned.junctions_made == 0);
  CHECK(cleaned.ends_snapped == 1);
  // One closed loop: every vertex has degree 2 (V == E).
  CHECK(cleaned.figure.vertices.size() == cleaned.figure.edges.size());
  require_cleans_to_itself(cleaned);
}

TEST_CASE("clean_drawing: a point on another stroke is a touch", "[clean_drawing]") {
  const CleanedDrawing cleaned = clean({{{0, 0}, {10, 0}}, {{3, 5}, {3, 0}, {6, 5}}}, {}, 0.0);
  CHECK(cleaned.junctions_made == 1);
  REQUIRE(count(cleaned, DrawingChangeKind::Touch) == 1);
  CHECK(cleaned.changes[0].stroke == 1);
  CHECK(cleaned.changes[0].point == 1);
  CHECK(cleaned.changes[0].other_stroke == 0);
  CHECK(cleaned.stroke_vertices[0] == std::vector<int>{0, 3, 1});
}

TEST_CASE("clean_drawing: duplicate points and zero-length edges merge", "[clean_drawing]") {
  const CleanedDrawing cleaned = clean({{{0, 0}, {1, 0}, {1, 0}, {2, 1}, {2, 1}, {2, 1}}});
  CHECK(cleaned.points_merged == 3);
  CHECK(cleaned.figure.vertices.size() == 3);
  CHECK(cleaned.figure.edges.size() == 2);
  CHECK(cleaned.stroke_vertices[0] == std::vector<int>{0, 1, 2});
  const std::vector<int> expected_map{0, 1, 1, 2, 2, 2};
  CHECK(cleaned.point_vertex == expected_map);
  for (const DrawingChange& change : cleaned.changes) {
    CHECK(change.kind == DrawingChangeKind::Merge);
    CHECK(change.distance == 0);
  }
}

TEST_CASE("clean_drawing: a stroke crossing itself and a closed stroke", "[clean_drawing]") {
  // A figure eight in one stroke, and a triangle given as a cyclic stroke.
  const CleanedDrawing eight = clean({{{0, 0}, {4, 4}, {4, 0}, {0, 4}}});
  CHECK(eight.junctions_made == 1);
  CHECK(eight.stroke_vertices[0] == std::vector<int>{0, 4, 1, 2, 4, 3});
  require_cleans_to_itself(eight);
  const CleanedDrawing triangle = clean({{{0, 0}, {4, 0}, {0, 4}}}, {true});
  CHECK(triangle.changes.empty());
  CHECK(triangle.figure.edges.size() == 3);
}

TEST_CASE("clean_drawing: tolerance 0 snaps nothing", "[clean_drawing]") {
  const CleanedDrawing cleaned = clean({{{0, 0}, {10, 0}}, {{4, -10}, {4, -0.1}}}, {}, 0.0);
  CHECK(cleaned.changes.empty());
  CHECK(cleaned.tolerance == 0);
}

TEST_CASE("clean_drawing: bad drawings name the stroke", "[clean_drawing]") {
  const auto fails = [](const Strokes& strokes, DrawingDefect defect, const std::string& text, int stroke,
                        std::vector<bool> cyclic = {}) {
    try {
      clean_drawing(drawing_from_strokes(strokes, std::move(cyclic)));
      FAIL("no error");
    } catch (const InvalidDrawingError& error) {
      CHECK(error.defect() == defect);
      CHECK_THAT(error.what(), Contains(text));
      CHECK(error.stroke() == stroke);
    }
  };
  fails({}, DrawingDefect::NoStrokes, "the drawing has no strokes", -1);
  fails({{{0, 0}, {1, 1}}, {{3, 3}}}, DrawingDefect::TooFewPoints, "stroke 1 has a single point, at (3, 3)", 1);
  fails({{{0, 0}, {1, 1}}, {}}, DrawingDefect::TooFewPoints, "stroke 1 has no points", 1);
  fails({{{0, 0}, {0, 0}, {0, 0}}, {{1, 1}, {2, 2}}}, DrawingDefect::CollapsedStroke,
        "stroke 0 collapses to a single point at (0, 0)", 0);
  fails({{{0, 0}, {5, 0}}, {{2, 0}, {8, 0}}}, DrawingDefect::Overlap,
        "strokes 0 and 1 overlap along a length", 0);
  fails({{{0, 0}, {5, 0}, {5, 5}, {5, 1}}}, DrawingDefect::Retrace, "stroke 0 retraces itself", 0);
  fails({{{0, 0}, {5, 0}}}, DrawingDefect::Retrace, "stroke 0 retraces itself", 0, {true});
  // An end within the tolerance of a retrace must not split it into
  // something that passes (fuzz_clean_drawing's first finding).
  fails({{{12, 12}, {0, 0}, {12, 12}}, {{-0.1, 2}, {14, 12}}}, DrawingDefect::Retrace, "stroke 0 retraces itself", 0,
        {true, false});
  fails({{{0, 0}, {NAN, 0}}}, DrawingDefect::NonFiniteCoordinate, "point 1 of stroke 0 is not finite", 0);
  CHECK_THROWS_AS(clean_drawing(drawing_from_strokes({{{0, 0}, {1, 0}}}), DrawingCleaningOptions{-1.0}),
                  InvalidArgumentError);
  CHECK_THROWS_WITH(drawing_from_figure({{0, 0}, {1, 1}}, {{0, 5}}), Contains("edge 0 (0-5): vertex 5 does not exist"));
}

TEST_CASE("clean_drawing: a valid figure cleans to itself", "[clean_drawing]") {
  // A stick man: head ring, spine, arms and legs at the hip, already clean.
  const std::vector<Vec2> vertices{{0, 10}, {1, 11}, {0, 12}, {-1, 11}, {0, 5}, {-3, 7}, {3, 7}, {-2, 0}, {2, 0}};
  const std::vector<std::array<std::int64_t, 2>> edges{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4},
                                                        {4, 5}, {4, 6}, {4, 7}, {4, 8}};
  const Drawing drawing = drawing_from_figure(vertices, edges);
  const CleanedDrawing cleaned = clean_drawing(drawing);
  validate_cleaning(cleaned, drawing);
  CHECK(cleaned.changes.empty());
  CHECK(cleaned.figure.vertices == vertices);
  REQUIRE(cleaned.figure.edges.size() == edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e)
    CHECK(cleaned.figure.edges[e] == Edge{int(edges[e][0]), int(edges[e][1])});
}

TEST_CASE("clean_drawing: random scribbles clean into valid figures that clean to themselves", "[clean_drawing]") {
  // Jittered polylines in a box: many crossings, near misses, ends near
  // strokes. Each result is checked (validate_cleaning: exact validity and
  // every moved point reported) and cleaned again.
  Lcg random{32};
  int crossings = 0, snaps = 0, overlaps = 0;
  for (int drawing = 0; drawing < 60; ++drawing) {
    Strokes strokes;
    const int count = 2 + int(random.next() * 6);
    for (int s = 0; s < count; ++s) {
      std::vector<Vec2> stroke;
      Vec2 p{random.next() * 60, random.next() * 60};
      const double heading = random.next() * 6.283185307179586;
      const int points = 2 + int(random.next() * 40);
      for (int i = 0; i < points; ++i) {
        stroke.push_back(p);
        const double turn = heading + (random.next() - 0.5) * 0.8;
        p = {p[0] + 2.5 * std::cos(turn), p[1] + 2.5 * std::sin(turn)};
        if (random.next() < 0.05) stroke.push_back(stroke.back());  // a pen pause
      }
      strokes.push_back(stroke);
    }
    try {
      const CleanedDrawing cleaned = clean(strokes);
      crossings += cleaned.junctions_made;
      snaps += cleaned.ends_snapped;
      require_cleans_to_itself(cleaned);
    } catch (const InvalidDrawingError& error) {
      // Only a real overlap may refuse a random scribble.
      CHECK((error.defect() == DrawingDefect::Overlap || error.defect() == DrawingDefect::Retrace));
      ++overlaps;
    }
  }
  CHECK(crossings > 30);
  CHECK(snaps > 5);
  CHECK(overlaps <= 2);
}
