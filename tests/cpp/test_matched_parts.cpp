// part_figure and assemble_matched_parts: a figure cut into its parts, and
// the matched parts put back together as one checked pair (issue 14).
#include "catch.h"

#include <algorithm>
#include <vector>

#include "parts.h"
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_parts.h"
#include "stickmorph/internal/matched_parts.h"

using namespace stickmorph;
using namespace stickmorph::internal;
using namespace stickmorph::test;

TEST_CASE("part_figure keeps the whole figure's coordinates, edge order and direction", "[matched_parts]") {
  // A ring (0-5), a dot (6), a stroke (7-9).
  const StickFigure whole = parts_figure({{circle(0, 0, 3, 6)}, {{{0, 0}}}, {{{5, 0}, {6, 1}, {7, 0}}, false}});
  const FigureParts parts = figure_parts(whole);
  REQUIRE(parts.count() == 3);
  const PartFigure stroke = part_figure(whole, parts, 2);
  CHECK(stroke.global_vertex == std::vector<int>{7, 8, 9});
  CHECK(stroke.global_edge == std::vector<int>{6, 7});
  CHECK(stroke.figure.edges == std::vector<Edge>{{0, 1}, {1, 2}});
  CHECK(stroke.figure.vertices[1] == whole.vertices[8]);
  const PartFigure dot = part_figure(whole, parts, 1);
  CHECK(dot.global_vertex == std::vector<int>{6});
  CHECK(dot.figure.edges.empty());
}

TEST_CASE("the matched parts make one pair, numbered as the source, checked once", "[matched_parts]") {
  // A ring holding a small ring, the target's rings drawn with other
  // vertex counts (so dummies are placed) and turned a little.
  const StickFigure source = parts_figure({{circle(0, 0, 3, 12)}, {circle(0.5, 0, 1, 6)}});
  const StickFigure target = parts_figure({{circle(0, 0, 3.2, 9, 0.1)}, {circle(0.4, 0.1, 1.1, 8, 0.2)}});
  const FigureCorrespondence c = correspond_figures(source, target, {});
  REQUIRE(c.pair.has_value());
  CHECK(c.pair->parts() == 2);
  CHECK(c.pair->source().vertices == c.source.vertices);
  CHECK(c.pair->target().vertices == c.target.vertices);
  // The source's 18 vertices keep their numbers and places.
  for (int v = 0; v < 18; ++v) {
    CHECK(c.source_places[std::size_t(v)].vertex == v);
    CHECK(c.source.vertices[std::size_t(v)] == source.vertices[std::size_t(v)]);
  }
  // Every target vertex is matched once.
  std::vector<int> seen(target.vertices.size(), 0);
  for (const MatchedPlace& place : c.target_places)
    if (place.vertex >= 0) ++seen[std::size_t(place.vertex)];
  CHECK(std::count(seen.begin(), seen.end(), 1) == int(target.vertices.size()));
  CHECK(is_valid(c, source, target));
}
