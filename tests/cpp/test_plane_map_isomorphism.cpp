// internal::extend_isomorphism, exterior_dart, make_candidate and
// search_isomorphisms (plane_map_isomorphism.h): skeletons matched as plane
// maps.
#include "catch.h"

#include "stickmorph/internal/plane_map_isomorphism.h"

using namespace stickmorph;
using namespace stickmorph::internal;

namespace {
// A plus: centre 0 and four arms of equal length.
StickFigure plus() {
  return make_stick_figure({{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}}, {{0, 1}, {0, 2}, {0, 3}, {0, 4}});
}
// A T whose stem has a bend: arms of different lengths.
StickFigure bent_t() {
  return make_stick_figure({{0, 0}, {2, 0}, {-1, 0}, {0, -1}, {1, -2}}, {{0, 1}, {0, 2}, {0, 3}, {3, 4}});
}
}  // namespace

TEST_CASE("extend_isomorphism sends a seed dart's image round the skeleton", "[plane_map_isomorphism]") {
  const StickFigure f = plus();
  const Skeleton s = make_skeleton(f);
  const int seed = s.decomposition.rotation.outgoing_ccw[0][0];
  const std::optional<std::vector<int>> identity = extend_isomorphism(s, s, seed, seed);
  REQUIRE(identity);
  for (int dart = 0; dart < s.dart_count(); ++dart)
    if (s.leaves_node(dart)) CHECK((*identity)[std::size_t(dart)] == dart);
  // A dart leaving an end cannot be the image of one leaving the centre.
  const int from_end = s.decomposition.rotation.outgoing_ccw[1][0];
  CHECK_FALSE(extend_isomorphism(s, s, seed, from_end));
  CHECK(s.leaves_node(exterior_dart(s)));
}

TEST_CASE("search_isomorphisms finds every rotation of a symmetric skeleton", "[plane_map_isomorphism]") {
  const StickFigure f = plus();
  const Skeleton s = make_skeleton(f);
  const IsomorphismSearch search = search_isomorphisms(s, s, {}, {}, true);
  CHECK(search.any_isomorphism);
  CHECK(search.any_exterior);
  CHECK(search.images.size() == 4);
  CHECK(search.fits.size() == 4);
  CHECK(search.pin_conflict.empty());
}

TEST_CASE("search_isomorphisms filters by the pins", "[plane_map_isomorphism]") {
  const StickFigure f = plus();
  const Skeleton s = make_skeleton(f);
  const IsomorphismSearch search = search_isomorphisms(s, s, {{1, 2}}, {}, true);
  CHECK(search.images.size() == 1);
  const IsomorphismSearch none = search_isomorphisms(s, s, {{1, 0}}, {}, false);
  CHECK(none.images.empty());
  CHECK(none.any_exterior);
  CHECK_FALSE(none.pin_conflict.empty());
}

TEST_CASE("make_candidate pairs the chains as the isomorphism does", "[plane_map_isomorphism]") {
  const StickFigure f = bent_t();
  const Skeleton s = make_skeleton(f);
  const IsomorphismSearch search = search_isomorphisms(s, s, {}, {}, true);
  // The skeleton alone does not see the arms' lengths: three rotations; the
  // fit tells them apart, and the identity fits best.
  REQUIRE(search.images.size() == 3);
  const std::size_t best = best_fit(search.fits);
  CHECK(search.fits[best].residual == Approx(0).margin(1e-12));
  const std::optional<std::vector<int>> map = extend_isomorphism(s, s, search.seed, search.images[best]);
  REQUIRE(map);
  std::string broken;
  const std::optional<Candidate> candidate = make_candidate(s, s, *map, {}, {}, broken);
  REQUIRE(candidate);
  CHECK(candidate->chains.size() == s.chains.size());
  for (int v : {0, 1, 2, 4}) CHECK(candidate->node_image[std::size_t(v)] == v);
  CHECK(candidate->node_image[3] == -1);
  CHECK(broken.empty());
}
