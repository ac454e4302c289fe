// internal::reflected_figure and correspond_connected
// (connected_correspondence.h): one connected figure matched to another.
#include "catch.h"

#include "stickmorph/compatibility.h"
#include "stickmorph/internal/connected_correspondence.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {
StickFigure y_shape() {
  return make_stick_figure({{0, 0}, {0, 1}, {0, 2}, {-2, -1}, {3, -1}}, {{0, 1}, {1, 2}, {0, 3}, {0, 4}}, "y");
}
}  // namespace

TEST_CASE("reflected_figure is the figure mirrored in the y axis, still valid", "[connected_correspondence]") {
  const StickFigure f = y_shape();
  const StickFigure m = reflected_figure(f);
  REQUIRE(is_valid(m));
  CHECK(m.edges == f.edges);
  CHECK(m.name == "y");
  for (std::size_t v = 0; v < f.vertices.size(); ++v) CHECK(m.vertices[v] == Vec2{-f.vertices[v][0], f.vertices[v][1]});
  CHECK(reflected_figure(m).vertices == f.vertices);
}

TEST_CASE("correspond_connected matches a figure with itself vertex for vertex", "[connected_correspondence]") {
  const StickFigure f = y_shape();
  const FigureCorrespondence c = correspond_connected(f, f, {});
  CHECK(c.source.vertices == f.vertices);
  CHECK(c.target.vertices == f.vertices);
  for (std::size_t v = 0; v < f.vertices.size(); ++v) CHECK(c.target_places[v].vertex == int(v));
  CHECK(c.residual == Approx(0).margin(1e-12));
  CHECK(is_valid(c, f, f));
}
