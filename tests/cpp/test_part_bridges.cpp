// internal::bridge_parts and the figures of several parts through
// Algorithm 3 (issue 14): triangulate_figures, morph_stick_figures and
// correspond_figures on figures whose parts nest.
#include "catch.h"

#include "figures.h"
#include "parts.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_parts.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/internal/part_bridges.h"
#include "stickmorph/morph_stick_figures.h"

using namespace stickmorph;
using namespace stickmorph::internal;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A ring of radius 1 inside a ring of radius `outer` (parts 0 and 1), the
// inner one turned by `turn`.
StickFigure ring_in_ring(double outer, double turn = 0.0, int outer_count = 24, int inner_count = 16) {
  return parts_figure({{circle(0, 0, outer, outer_count)}, {circle(0, 0, 1, inner_count, turn)}});
}

// A dotted i: a stem of three vertices and a dot (a lone vertex).
StickFigure dotted_i(double lean = 0.0) {
  return parts_figure({{{{0, 0}, {lean, 1}, {2 * lean, 2}}, false}, {{{3 * lean, 3}}}});
}

void check_bridged(const BridgedFigures& bridged, const StickFigure& source, const StickFigure& target) {
  const int n = int(source.vertices.size());
  CHECK(figure_parts(bridged.source).count() == 1);
  CHECK(check_compatibility(bridged.source, bridged.target).compatible());
  CHECK(int(bridged.source.vertices.size()) == n + bridged.bends);
  CHECK(bridged.bridges == figure_parts(source).count() - 1);
  for (int v = 0; v < n; ++v) {
    CHECK(bridged.source.vertices[std::size_t(v)] == source.vertices[std::size_t(v)]);
    CHECK(bridged.target.vertices[std::size_t(v)] == target.vertices[std::size_t(v)]);
  }
  // The figure's edges first, in their order; then bends + bridges edges.
  for (std::size_t e = 0; e < source.edges.size(); ++e) CHECK(bridged.source.edges[e] == source.edges[e]);
  CHECK(bridged.source.edges.size() == source.edges.size() + std::size_t(bridged.bends + bridged.bridges));
}

// Every frame of a morph is checked by the one frame verifier.
void check_morph(const StickFigure& source, const StickFigure& target, MorphMethod method) {
  MorphStickFiguresOptions options;
  options.method = method;
  options.frames = 12;
  const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
  REQUIRE(result.frames.size() == 12);
  CHECK(result.frames.front() == source.vertices);
  CHECK(result.frames.back() == target.vertices);
  const Decomposition dec = decompose(source);
  for (std::size_t f = 0; f < result.frames.size(); ++f) {
    REQUIRE(result.frames[f].size() == source.vertices.size());
    CHECK_NOTHROW(verify_frame(source, dec, result.frames[f], int(f), result.times[f]));
  }
  CHECK(result.stats.triangulation.parts == figure_parts(source).count());
}

}  // namespace

TEST_CASE("bridge_parts joins a ring to the ring around it by a straight bridge", "[part_bridges]") {
  const StickFigure source = ring_in_ring(2), target = ring_in_ring(2.2, 0.2);
  const BridgedFigures bridged = bridge_parts(CompatiblePair::check(source, target));
  check_bridged(bridged, source, target);
  CHECK(bridged.bridges == 1);
  CHECK(bridged.bends == 0);
}

TEST_CASE("bridge_parts bends a bridge where no straight one is valid in both", "[part_bridges]") {
  // Close rings, the inner one half turned: from every inner vertex the
  // straight way to the outer vertex it faces in one figure is blocked by
  // the inner ring in the other.
  const StickFigure source = ring_in_ring(1.05), target = ring_in_ring(1.05, 0.9 * kPi);
  const BridgedFigures bridged = bridge_parts(CompatiblePair::check(source, target));
  check_bridged(bridged, source, target);
  CHECK(bridged.bends > 0);
}

TEST_CASE("bridge_parts joins lone vertices and nested parts into one tree", "[part_bridges]") {
  std::vector<PartSpec> dots;
  for (int i = 0; i < 5; ++i) dots.push_back({{{double(i), double(i % 2)}}});
  dots.push_back({circle(10, 0, 3, 12)});
  dots.push_back({{{10, 0}}});        // a dot inside the ring
  dots.push_back({circle(10, 0, 1, 6)});  // a ring round that dot, inside the first
  const StickFigure source = parts_figure(dots);
  StickFigure target = source;
  for (Vec2& p : target.vertices) p = {1.5 * p[0] + 0.1 * p[1], 1.2 * p[1] - 0.05 * p[0]};
  target = make_stick_figure(target.vertices, {});  // re-validated below with the edges
  std::vector<std::array<std::int64_t, 2>> edges;
  for (const Edge& e : source.edges) edges.push_back({e[0], e[1]});
  target = make_stick_figure(target.vertices, edges);
  const BridgedFigures bridged = bridge_parts(CompatiblePair::check(source, target));
  check_bridged(bridged, source, target);
  CHECK(bridged.bridges == 7);
}

TEST_CASE("triangulate_figures on parts: figure, enclosure, then the bends as Steiner vertices", "[part_bridges][triangulate_figures]") {
  const StickFigure source = ring_in_ring(1.05), target = ring_in_ring(1.05, 0.9 * kPi);
  FigureTriangulationStats stats;
  const FigureTriangulation tri = triangulate_figures(source, target, {}, &stats);
  CHECK(tri.figure_vertices == int(source.vertices.size()));
  CHECK(tri.enclosure_vertices == 6);
  CHECK(stats.parts == 2);
  CHECK(stats.bridges == 1);
  CHECK(stats.bridge_bends > 0);
  CHECK(tri.steiner_vertices >= stats.bridge_bends);
  for (int v = 0; v < tri.figure_vertices; ++v) {
    CHECK(tri.source[std::size_t(v)] == source.vertices[std::size_t(v)]);
    CHECK(tri.target[std::size_t(v)] == target.vertices[std::size_t(v)]);
  }
  CHECK_NOTHROW(verify_figure_triangulation(tri, source));
}

TEST_CASE("morph_stick_figures keeps every part in its face in every frame", "[part_bridges][morph_stick_figures]") {
  for (MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric}) {
    INFO(morph_method_name(method));
    check_morph(ring_in_ring(2), ring_in_ring(2.3, 1.2), method);
    check_morph(ring_in_ring(1.05), ring_in_ring(1.05, 0.9 * kPi), method);
    check_morph(dotted_i(), dotted_i(0.4), method);
  }
}

TEST_CASE("morph_stick_figures refuses parts that change face", "[part_bridges][morph_stick_figures]") {
  const StickFigure source = ring_in_ring(2);
  StickFigure target = source;
  for (std::size_t v = 24; v < target.vertices.size(); ++v) target.vertices[v][0] += 5;
  MorphStickFiguresOptions options;
  try {
    morph_stick_figures(source, target, options);
    FAIL("the morph was not refused");
  } catch (const IncompatibleFiguresError& error) {
    CHECK(error.kind() == Incompatibility::NestingDiffers);
    CHECK_THAT(error.what(), Contains("part 1 (vertices 24, 25,"));
  }
}

TEST_CASE("correspond_figures matches figures of several parts part to part", "[part_bridges][correspond_figures]") {
  // The source: an outer ring, an inner ring and a dot beside them. The
  // target: the same drawing resampled, its parts listed in another order.
  const StickFigure source =
      parts_figure({{circle(0, 0, 2, 12)}, {circle(0, 0, 1, 8)}, {{{3, 0}}}});
  const StickFigure target =
      parts_figure({{{{3.2, 0.1}}}, {circle(0.1, 0, 1.1, 11, 0.3)}, {circle(0.1, 0, 2.1, 17, 0.2)}});
  const FigureCorrespondence c = correspond_figures(source, target);
  CHECK(is_valid(c, source, target));
  const FigureParts source_parts = figure_parts(source), target_parts = figure_parts(target);
  // Matched vertex i is in one part in both drawings; source part p is
  // matched to target part 2 - p.
  for (std::size_t i = 0; i < c.source_places.size(); ++i) {
    const MatchedPlace& s = c.source_places[i];
    const MatchedPlace& t = c.target_places[i];
    const int sv = s.vertex >= 0 ? s.vertex : source.edges[std::size_t(s.edge)][0];
    const int tv = t.vertex >= 0 ? t.vertex : target.edges[std::size_t(t.edge)][0];
    CHECK(target_parts.part_of_vertex[std::size_t(tv)] == 2 - source_parts.part_of_vertex[std::size_t(sv)]);
  }
  CHECK(check_compatibility(c.source, c.target).compatible());

  MorphStickFiguresOptions options;
  options.correspond = CorrespondenceMode::Auto;
  options.frames = 8;
  const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
  const Decomposition dec = decompose(result.correspondence->source);
  for (std::size_t f = 0; f < result.frames.size(); ++f)
    CHECK_NOTHROW(verify_frame(result.correspondence->source, dec, result.frames[f], int(f), result.times[f]));
}

TEST_CASE("correspond_figures on parts says what cannot be matched", "[part_bridges][correspond_figures]") {
  const StickFigure source = parts_figure({{circle(0, 0, 2, 12)}, {{{3, 0}}}});
  SECTION("another number of parts") {
    const StickFigure target = parts_figure({{circle(0, 0, 2, 12)}, {{{3, 0}}}, {{{4, 0}}}});
    CHECK_THROWS_WITH(correspond_figures(source, target), Contains("the source has 2 parts and the target 3"));
  }
  SECTION("a part of another shape") {
    const StickFigure target = parts_figure({{circle(0, 0, 2, 12)}, {{{3, 0}, {3.5, 0}}, false}});
    try {
      correspond_figures(source, target);
      FAIL("matched");
    } catch (const IncompatibleFiguresError& error) {
      CHECK(error.kind() == Incompatibility::TopologyDiffers);
      CHECK_THAT(error.what(), Contains("part 1 (vertex 12) of the source (a lone vertex"));
    }
  }
  SECTION("a dot that moves into the ring") {
    const StickFigure target = parts_figure({{circle(0, 0, 2, 12)}, {{{0.5, 0}}}});
    // Nesting depth differs: the dot is inside the ring only in the target.
    CHECK_THROWS_AS(correspond_figures(source, target), IncompatibleFiguresError);
  }
  SECTION("pins that pair one part with two") {
    const StickFigure rings = parts_figure({{circle(0, 0, 2, 12)}, {circle(5, 0, 1, 6)}});
    CorrespondenceOptions options;
    options.pins = {{0, 0}, {1, 12}};  // ring 0's vertices to ring 0 and to ring 1
    try {
      correspond_figures(rings, rings, options);
      FAIL("matched");
    } catch (const IncompatibleFiguresError& error) {
      CHECK(error.kind() == Incompatibility::PinsUnsatisfiable);
    }
  }
}

TEST_CASE("bridges round a lone vertex keep their order in both figures", "[part_bridges]") {
  // Found by bench/parts_stress.py: five dots, three bridged to vertex 1.
  // Its wedges between bridges were once taken the wrong way round, and the
  // bridged figures then had other cyclic orders at vertex 1.
  const StickFigure source = figure({{327, -528}, {0, 0}, {8, -100}, {-1, 0}, {-4, 2}}, {});
  const StickFigure target = figure({{850, 729}, {0, 0}, {197, 47}, {-1, 7}, {5, 1}}, {});
  const BridgedFigures bridged = bridge_parts(CompatiblePair::check(source, target));
  check_bridged(bridged, source, target);
  check_morph(source, target, MorphMethod::Rigid);
}

TEST_CASE("correspond_figures pairs parts by what they hold, not only by place", "[part_bridges][correspond_figures]") {
  // Found by the parts fuzzer: an empty hexagon and a square holding a
  // triangle swap places. By place the square would go to the hexagon and
  // its triangle would have nowhere to go.
  const StickFigure source = parts_figure(
      {{circle(0, 0, 1.4, 6)}, {{{9, -1}, {11, -1}, {11, 1}, {9, 1}}}, {{{9.5, -0.5}, {10.5, -0.5}, {10, 0.5}}}});
  const StickFigure target = parts_figure(
      {{circle(10, 0, 1.4, 6)}, {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}}, {{{-0.5, -0.5}, {0.5, -0.5}, {0, 0.5}}}});
  const FigureCorrespondence c = correspond_figures(source, target);
  CHECK(is_valid(c, source, target));
  const FigureParts target_parts = figure_parts(target);
  // Source vertex 6 (a corner of the square) is matched into the target's square, part 1.
  for (std::size_t i = 0; i < c.source_places.size(); ++i)
    if (c.source_places[i].vertex == 6) {
      REQUIRE(c.target_places[i].vertex >= 0);
      CHECK(target_parts.part_of_vertex[std::size_t(c.target_places[i].vertex)] == 1);
    }
}

TEST_CASE("correspond_figures checks the pins before it compares the parts", "[part_bridges][correspond_figures]") {
  const StickFigure source = polyline({{0, 0}, {1, 0}});
  const StickFigure target = figure({{0, 0}, {1, 0}}, {});
  CorrespondenceOptions options;
  options.pins = {{0, 5}};
  CHECK_THROWS_AS(correspond_figures(source, target, options), InvalidArgumentError);
}
