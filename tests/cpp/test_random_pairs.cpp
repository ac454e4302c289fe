// Property tests at scale: random compatible pairs of every kind and
// placement (random_pairs.h) through the whole pipeline, every frame
// verified exactly. The long mode is stickmorph_random_pairs.
#include "catch.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>

#include "random_pairs.h"
#include "stickmorph/figure_io.h"

using namespace stickmorph;
using namespace stickmorph::test;

namespace {

constexpr int kFrames = 16;
// 7 kinds times 96 seeds: 672 pairs, each placement class (seed % 6) 16 times
// per kind.
constexpr std::uint64_t kFirstSeed = 1000;
constexpr int kSeedsPerKind = 96;

bool same_figure(const StickFigure& a, const StickFigure& b) {
  return a.vertices == b.vertices && a.edges == b.edges;
}

StickFigure translated(const StickFigure& f, double dx, double dy) { return moved(f, 0.0, 1.0, dx, dy); }

}  // namespace

TEST_CASE("generate_pair: a pair is a function of (seed, kind)", "[random_pairs]") {
  for (PairKind kind : kAllPairKinds) {
    INFO(pair_kind_name(kind));
    const RandomPair a = generate_pair(7, kind), b = generate_pair(7, kind), c = generate_pair(8, kind);
    CHECK(same_figure(a.source, b.source));
    CHECK(same_figure(a.target, b.target));
    CHECK(a.redraws == b.redraws);
    CHECK(a.description == b.description);
    CHECK_FALSE(same_figure(a.source, c.source));
  }
  CHECK(parse_pair_kind("near_touching") == PairKind::NearTouching);
  CHECK_FALSE(parse_pair_kind("triangle").has_value());
}

TEST_CASE("random compatible pairs of every kind and placement morph with every frame verified",
          "[random_pairs][property]") {
  const auto start = std::chrono::steady_clock::now();
  int pairs = 0, total_redraws = 0, max_redraws = 0;
  std::map<std::pair<int, int>, int> per_kind_and_placement;
  std::map<PairKind, int> with_dangling, with_cut_vertex, with_many_faces;
  for (PairKind kind : kAllPairKinds) {
    for (int i = 0; i < kSeedsPerKind; ++i) {
      const std::uint64_t seed = kFirstSeed + std::uint64_t(i);
      const RandomPair pair = generate_pair(seed, kind);
      INFO(pair.description);
      // The generator's own guarantee, checked again with the library.
      REQUIRE(is_valid(pair.source));
      REQUIRE(is_valid(pair.target));
      REQUIRE(check_compatibility(pair.source, pair.target).compatible());
      CHECK(morph_and_verify(pair.source, pair.target, kFrames) == "");
      ++pairs;
      total_redraws += pair.redraws;
      max_redraws = std::max(max_redraws, pair.redraws);
      ++per_kind_and_placement[{int(kind), int(seed % kPlacementCount)}];
      const FigureFeatures features = features_of(pair.source);
      with_dangling[kind] += features.dangling_vertices > 0;
      with_cut_vertex[kind] += features.cut_vertices > 0;
      with_many_faces[kind] += features.interior_faces >= 5;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("random pairs: %d pairs, %d redraws in total (at most %d for one pair), %.1f s\n", pairs,
              total_redraws, max_redraws, seconds);
  CHECK(pairs >= 300);
  CHECK(per_kind_and_placement.size() == kAllPairKinds.size() * kPlacementCount);
  // Redraws are rare (rounding in a Tutte solve or a placement); a jump
  // means a generator that mostly makes invalid or incompatible figures.
  CHECK(total_redraws <= pairs / 4);
  // The kinds produce the structures they are named for.
  CHECK(with_many_faces[PairKind::Sparse] >= kSeedsPerKind / 2);
  CHECK(with_dangling[PairKind::Dangling] >= kSeedsPerKind / 2);
  CHECK(with_cut_vertex[PairKind::Dangling] >= kSeedsPerKind / 2);
  CHECK(with_dangling[PairKind::Tree] >= kSeedsPerKind / 2);
  CHECK(with_many_faces[PairKind::Polygon] == 0);
}

TEST_CASE("pairs rescaled to 1e-6 and 1e6 and moved far from the origin still morph", "[random_pairs]") {
  // Unit-placement pairs (seed % 6 == 0) of the kinds without deliberate
  // near-degeneracy, so that rounding in the rescaling cannot invalidate them.
  for (PairKind kind : {PairKind::Polyline, PairKind::Polygon, PairKind::Tree, PairKind::Sparse, PairKind::Dangling}) {
    for (std::uint64_t seed : {std::uint64_t(6), std::uint64_t(12)}) {
      const RandomPair pair = generate_pair(seed, kind);
      REQUIRE(placement_of(seed).scale == 1.0);
      REQUIRE(placement_of(seed).offset_in_sizes == 0.0);
      const double size = std::max(random_pairs_detail::figure_size(pair.source.vertices),
                                   random_pairs_detail::figure_size(pair.target.vertices));
      struct Variant {
        const char* name;
        StickFigure source, target;
      };
      const std::vector<Variant> variants = {
          {"scale 1e-6", moved(pair.source, 0, 1e-6, 0, 0), moved(pair.target, 0, 1e-6, 0, 0)},
          {"scale 1e6", moved(pair.source, 0, 1e6, 0, 0), moved(pair.target, 0, 1e6, 0, 0)},
          {"moved 1e6 sizes", translated(pair.source, 1e6 * size, -0.7e6 * size),
           translated(pair.target, 1e6 * size, -0.7e6 * size)},
          {"scale 1e-6, moved 1e6 sizes", moved(pair.source, 0, 1e-6, 1e6 * size * 1e-6, 2e6 * size * 1e-6),
           moved(pair.target, 0, 1e-6, 1e6 * size * 1e-6, 2e6 * size * 1e-6)},
      };
      for (const Variant& v : variants) {
        INFO(pair.description << ", " << v.name);
        REQUIRE(is_valid(v.source));
        REQUIRE(is_valid(v.target));
        REQUIRE(check_compatibility(v.source, v.target).compatible());
        CHECK(morph_and_verify(v.source, v.target, kFrames) == "");
      }
    }
  }
}

TEST_CASE("save_regression_pair: files read back exactly and name seed, kind and error", "[random_pairs]") {
  const RandomPair pair = generate_pair(5, PairKind::NearCollinear);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "stickmorph_random_pairs_test";
  std::filesystem::create_directories(dir);
  const std::string stem = save_regression_pair(dir.string(), pair, "VerificationError: frame 3 \"quoted\"");
  CHECK(stem == dir.string() + "/random_near_collinear_seed5");
  const StickFigure source = read_figure_file(stem + ".source.json");
  const StickFigure target = read_figure_file(stem + ".target.json");
  CHECK(same_figure(source, pair.source));
  CHECK(same_figure(target, pair.target));
  CHECK(source.name.find("seed 5 kind near_collinear") != std::string::npos);
  CHECK(source.name.find("VerificationError: frame 3 \"quoted\"") != std::string::npos);
  std::filesystem::remove_all(dir);
}
