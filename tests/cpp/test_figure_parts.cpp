// figure_parts, part_nesting, and the nesting condition of compatibility
// (issue 14: figures of several parts, the paper's future work, section 6).
#include "catch.h"

#include "figures.h"
#include "parts.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/figure_parts.h"
#include "stickmorph/frame_verification.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

// Three concentric rings (parts 0, 1, 2), a dot at the centre (part 3) and
// a dot outside (part 4).
StickFigure bullseye(double inner_phase = 0.0) {
  return parts_figure({{circle(0, 0, 3, 12)}, {circle(0, 0, 2, 10)}, {circle(0, 0, 1, 8, inner_phase)},
                       {{{0.1, 0.0}}}, {{{5.0, 0.0}}}});
}

// A square split by its diagonal 0-2 into two triangles, and a dot at
// `dot` (part 1).
StickFigure split_square_with_dot(Vec2 dot) {
  return figure({{0, 0}, {4, 0}, {4, 4}, {0, 4}, dot}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}});
}

}  // namespace

TEST_CASE("figure_parts numbers the parts by their smallest vertex", "[figure_parts]") {
  // Vertices 0, 3 form one stroke, 1 is a dot, 2-4 another stroke.
  const StickFigure f = figure({{0, 0}, {5, 5}, {0, 2}, {1, 0}, {0, 3}}, {{0, 3}, {2, 4}});
  const FigureParts parts = figure_parts(f);
  REQUIRE(parts.count() == 3);
  CHECK(parts.part_of_vertex == std::vector<int>{0, 1, 2, 0, 2});
  CHECK(parts.vertices[0] == std::vector<int>{0, 3});
  CHECK(parts.vertices[1] == std::vector<int>{1});
  CHECK(parts.vertices[2] == std::vector<int>{2, 4});
  CHECK(describe_part(parts, 1) == "part 1 (vertex 1)");
  CHECK(describe_part(parts, 2) == "part 2 (vertices 2, 4)");
  CHECK(figure_parts(polygon(regular(5))).count() == 1);
  // The graph alone (no positions) gives the same parts.
  const FigureParts of_graph = figure_parts(5, f.edges);
  CHECK(of_graph.part_of_vertex == parts.part_of_vertex);
  CHECK(of_graph.vertices == parts.vertices);
  CHECK(figure_parts(0, {}).count() == 0);
}

TEST_CASE("decompose gives every part its own exterior sequence", "[figure_parts][decompose]") {
  const StickFigure f = bullseye();
  const Decomposition dec = decompose(f);
  REQUIRE(dec.exterior_of_part.size() == 5);
  CHECK(dec.exterior == dec.exterior_of_part[0]);
  CHECK(is_valid(dec, f));
  // Three rings: an inside and an outside each; two dots: one lone sequence each.
  CHECK(dec.sequences.size() == 8);
  int lone = 0;
  for (const CyclicSequence& seq : dec.sequences) lone += seq.darts.empty();
  CHECK(lone == 2);
}

TEST_CASE("part_nesting finds the faces that hold each part", "[figure_parts]") {
  const StickFigure f = bullseye();
  const Decomposition dec = decompose(f);
  const FigureParts parts = figure_parts(f);
  const PartNesting nesting = part_nesting(f, dec, parts);
  REQUIRE(is_valid(nesting, dec, parts));
  auto containers = [&](int part) {
    std::vector<int> result;
    for (const auto& entry : nesting.enclosing[std::size_t(part)]) result.push_back(entry.first);
    return result;
  };
  CHECK(containers(0).empty());
  CHECK(containers(1) == std::vector<int>{0});
  CHECK(containers(2) == std::vector<int>{0, 1});
  CHECK(containers(3) == std::vector<int>{0, 1, 2});
  CHECK(containers(4).empty());
  CHECK(nesting.parent_part == std::vector<int>{-1, 0, 1, 2, -1});
  for (int part = 1; part <= 3; ++part) {
    const CyclicSequence& face = dec.sequences[std::size_t(nesting.parent_sequence[std::size_t(part)])];
    CHECK_FALSE(face.exterior);
    CHECK(parts.part_of_vertex[std::size_t(face.vertices.front())] == part - 1);
  }
}

TEST_CASE("part_nesting tells the two triangles of a split square apart", "[figure_parts]") {
  const StickFigure below = split_square_with_dot({3, 1});
  const Decomposition dec = decompose(below);
  const PartNesting nesting = part_nesting(below, dec, figure_parts(below));
  REQUIRE(nesting.enclosing[1].size() == 1);
  const CyclicSequence& face = dec.sequences[std::size_t(nesting.enclosing[1][0].second)];
  std::vector<int> corners = face.vertices;
  std::sort(corners.begin(), corners.end());
  CHECK(corners == std::vector<int>{0, 1, 2});  // the triangle below the diagonal
}

TEST_CASE("check_compatibility compares the nesting of the parts", "[figure_parts][check_compatibility]") {
  SECTION("the same faces: compatible, however the inner parts turn") {
    CHECK(check_compatibility(bullseye(), bullseye(2.5)).compatible());
    CHECK(check_compatibility(split_square_with_dot({3, 1}), split_square_with_dot({3.5, 0.2})).compatible());
  }
  SECTION("a dot that crosses the diagonal changes face") {
    const CompatibilityReport report =
        check_compatibility(split_square_with_dot({3, 1}), split_square_with_dot({1, 3}));
    CHECK(report.kind == Incompatibility::NestingDiffers);
    CHECK_THAT(report.reason, Contains("the parts nest differently: part 1 (vertex 4) lies inside part 0, in its "
                                       "face bounded by 0 1 2 in the source, but inside part 0, in its face bounded "
                                       "by 0 2 3 in the target"));
    CHECK(report.vertices == std::vector<int>{4, 0});
  }
  SECTION("a dot that leaves the square") {
    const CompatibilityReport report =
        check_compatibility(split_square_with_dot({3, 1}), split_square_with_dot({6, 1}));
    CHECK(report.kind == Incompatibility::NestingDiffers);
    CHECK_THAT(report.reason, Contains("but outside part 0 in the target"));
  }
  SECTION("a ring that slips out of the ring around it") {
    StickFigure moved = bullseye();
    for (int v = 22; v < 30; ++v) moved.vertices[std::size_t(v)][0] += 10;  // the inner ring, part 2
    moved.vertices[30][0] += 10;                                            // and its dot
    const CompatibilityReport report = check_compatibility(bullseye(), moved);
    CHECK(report.kind == Incompatibility::NestingDiffers);
    CHECK_THAT(report.reason, Contains("part 2 (vertices 22, 23,"));
    CHECK_THAT(report.reason, Contains("outside part 0 in the target"));
  }
  SECTION("each part is still compared on the paper's terms first") {
    StickFigure mirrored = bullseye();
    for (Vec2& p : mirrored.vertices) p[1] = -p[1];
    CHECK(check_compatibility(bullseye(), mirrored).kind == Incompatibility::MirrorImage);
  }
}

TEST_CASE("verify_frame refuses a frame in which a part changed face", "[figure_parts][verify_frame]") {
  const StickFigure source = split_square_with_dot({3, 1});
  std::vector<Vec2> frame = source.vertices;
  CHECK(is_frame_valid(source, frame));
  frame[4] = {1, 3};
  CHECK_FALSE(is_frame_valid(source, frame));
  CHECK_THROWS_WITH(verify_frame(source, frame, 7, 0.5), Contains("frame 7 (t = 0.5)") && Contains("nest differently"));
}
