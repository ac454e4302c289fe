// The rigid morph's set-up on a checked pair; see rigid_morph_setup.h.
#include "stickmorph/internal/rigid_morph_setup.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"

namespace stickmorph {
namespace internal {

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The target mapped back by the similarity at t = 1, as a stick figure, or
// nothing when rounding made it something else than a figure compatible
// with the source (possible only for a nearly degenerate figure). A pure
// similarity pair maps back onto the source up to rounding, and is then
// snapped onto it exactly, so that its morph needs no Steiner vertex and is
// the similarity itself.
std::optional<CompatiblePair> normalised_pair(const CompatiblePair& pair, const SimilarityMotion& similarity) {
  const StickFigure& source = pair.source();
  const StickFigure& target = pair.target();
  std::vector<Vec2> vertices;
  vertices.reserve(target.vertices.size());
  double radius = 0, largest_gap = 0;
  for (std::size_t v = 0; v < target.vertices.size(); ++v) {
    vertices.push_back(similarity.unapply(1.0, target.vertices[v]));
    radius = std::max({radius, std::abs(source.vertices[v][0] - similarity.source_center[0]),
                       std::abs(source.vertices[v][1] - similarity.source_center[1])});
    largest_gap = std::max({largest_gap, std::abs(vertices[v][0] - source.vertices[v][0]),
                            std::abs(vertices[v][1] - source.vertices[v][1])});
  }
  // Far below anything visible, far above the rounding of the map.
  constexpr double kSnap = 1e-9;
  if (largest_gap <= kSnap * radius) vertices = source.vertices;
  std::vector<std::array<std::int64_t, 2>> edges;
  for (const Edge& e : target.edges) edges.push_back({e[0], e[1]});
  try {
    // A third figure, decomposed once and checked against the source's
    // decomposition, which the pair already has.
    StickFigure figure = make_stick_figure(std::move(vertices), edges, target.name);
    Decomposition decomposition = decompose(figure);
    return CompatiblePair::check(source, pair.source_decomposition(), std::move(figure), std::move(decomposition));
  } catch (const InvalidFigureError&) {
    return std::nullopt;
  } catch (const IncompatibleFiguresError&) {
    return std::nullopt;
  }
}

}  // namespace

// Rounds of flips and Steiner moves on the rigid method's triangulation,
// and the Steiner vertices compatible refinement may add (a share of the
// figure's vertex count; FigureTriangulationOptions).
constexpr int kRigidImprovementRounds = 3;
constexpr double kRigidRefinementShare = 0.4;
// The departure from the guide (GuidedMorphStats::guide_departure) above
// which the unrefined triangulation is tried too: well inside the 0.005 of
// edge-length deviation within which issue 30 asks the morph to follow the
// as-rigid-as-possible motion.
constexpr double kMostGuideDeparture = 0.002;
// The lighter refinement shares tried, largest first, where the full one
// departs from the guide and the unrefined triangulation does not.
constexpr double kLighterRefinementShares[] = {0.2, 0.1};
// The shares tried for a locally timed guide whose morph departs from it,
// in order (the first that follows it is kept, else the least departure;
// issue 31's skeleton corpus: the morph at d = 0.5 left the guide far
// enough to miss the lag asked by 0.1 on 1 pair of 72 with the default
// share alone, on none with these).
constexpr double kTimedRefinementShares[] = {1.0, 0, 2.0, 0.2};
// Refinement and its ladder cost a triangulation and a set-up per attempt,
// seconds each at 10^4 vertices (the 10^4-vertex wavy line of
// bench/blender_bake.py: 11 s to its 250 frames instead of 3.9, its
// scrubbing families 10-50% slower) and far more at 10^5, where a bake
// already takes most of an hour. Larger figures keep the flips and moves.
constexpr std::size_t kMostVerticesForRefinement = 2000;

GuidedMorph prepare_guided_morph(const CompatiblePair& pair, const SimilarityMotion& similarity,
                                 const std::function<std::unique_ptr<const GuideTrajectory>()>& make_guide,
                                 const FigureTriangulationOptions& paper_options, WeightKind weights, Easing easing,
                                 MorphStickFiguresStats& stats) {
  // The user's pair is checked (its report, not the mapped-back one's).
  const StickFigure& source = pair.source();
  const StickFigure& target = pair.target();
  FigureTriangulation triangulation;
  std::optional<GuidedMorph> morph;
  try {
    auto start = std::chrono::steady_clock::now();
    const std::optional<CompatiblePair> normalised = normalised_pair(pair, similarity);
    // The enclosure holds the guide's whole way as the triangulation sees
    // it (mapped back by the similarity when that is factored out), not
    // only its two ends (FigureTriangulationOptions::enclosed_points).
    std::unique_ptr<const GuideTrajectory> guide = make_guide();
    auto guide_points = [&](bool mapped_back) {
      constexpr int kEnclosedSamples = 16;
      std::vector<Vec2> points;
      for (int j = 1; j < kEnclosedSamples; ++j) {
        const double u = double(j) / kEnclosedSamples;
        for (const Vec2& p : guide->at(u)) points.push_back(mapped_back ? similarity.unapply(u, p) : p);
      }
      return points;
    };
    FigureTriangulationOptions triangulation_options = paper_options;
    triangulation_options.enclosed_points = guide_points(normalised.has_value());
    // Issue 30: flips legal in both embeddings and Steiner vertices moved
    // for the smallest angle (compatible_improvement.h). A thin triangle
    // inverts under a small motion of the guide and forces blending; on
    // the motion corpus (bench/motion_corpus.py, 52 pairs and 78 letter
    // pairs) edge deviation P90 went from 0.020 to 0.010 and the letters'
    // smallest angle median from 1.3 to 2.3 degrees. The fallbacks keep
    // the paper's triangulation.
    triangulation_options.improvement_rounds = kRigidImprovementRounds;
    // And compatible refinement, up to kMostVerticesForRefinement figure
    // vertices: on the motion corpus and the letters the smallest angle
    // median rose from 2.3-2.7 to 8.2-8.7 degrees (P10 from 0.1-0.4 to
    // 1.8-2.1) for 0.39 Steiner vertices per figure vertex at the median.
    // It needs step 2 of guided_morph.h to place Steiner vertices rigidly
    // where that follows the guide better; where neither placement follows
    // it at every sample, lighter refinement is tried too (below).
    triangulation_options.refinement_share =
        source.vertices.size() <= kMostVerticesForRefinement ? kRigidRefinementShare : 0;
    // For the fallbacks below.
    const std::vector<Vec2> unmapped_points = guide_points(false);
    // The triangulation, each attempt verified exactly by triangulate_figures:
    // the mapped-back pair in the enclosure around the guide; else the pair
    // itself in it; else the paper's enclosure around the pair (where the
    // barycentric method's triangulation exists, the rigid method's does).
    // An attempt fails only where the spiderweb embedding of section 4
    // finds no valid embedding of a face in both figures, which depends on
    // the exact shapes; the last attempt's error is the one reported.
    auto triangulate_pair_itself = [&] {
      triangulation_options.enclosed_points = unmapped_points;
      try {
        triangulation = triangulate_figures(pair, triangulation_options, &stats.triangulation);
      } catch (const VerificationError&) {
        triangulation = triangulate_figures(pair, paper_options, &stats.triangulation);
      }
    };
    bool mapped_back = normalised.has_value();
    if (mapped_back) {
      try {
        triangulation = triangulate_figures(*normalised, triangulation_options, &stats.triangulation);
      } catch (const VerificationError&) {
        mapped_back = false;
      }
    }
    if (!mapped_back) triangulate_pair_itself();
    stats.triangulate_ms = milliseconds_since(start);

    start = std::chrono::steady_clock::now();
    auto make = [&](const SimilarityMotion& factored) {
      // The guide moves into the morph; a failed attempt needs a new one.
      if (!guide) guide = make_guide();
      morph.emplace(triangulation, source, pair.source_decomposition(), target.vertices, factored, std::move(guide),
                    weights, easing);
    };
    if (mapped_back) {
      try {
        make(similarity);
        stats.similarity_factored = true;
      } catch (const VerificationError&) {
        // The triangulation moved to the target by the similarity lost a
        // nearly flat triangle to rounding: triangulate the pair itself.
        const auto again = std::chrono::steady_clock::now();
        triangulate_pair_itself();
        stats.triangulate_ms += milliseconds_since(again);
      }
    }
    if (!morph) {
      try {
        make(SimilarityMotion{});
      } catch (const VerificationError&) {
        // Convex-combination weights of a nearly flat triangle that the
        // guide's enclosure made failed in floating point (node_weights):
        // the paper's own triangulation of the pair, the barycentric
        // method's, is the last resort.
        const auto again = std::chrono::steady_clock::now();
        triangulation = triangulate_figures(pair, paper_options, &stats.triangulation);
        stats.triangulate_ms += milliseconds_since(again);
        make(SimilarityMotion{});
      }
    }
    const bool factored = stats.similarity_factored;
    struct Attempt {
      FigureTriangulation triangulation;
      FigureTriangulationStats stats;
      std::optional<GuidedMorph> morph;
    };
    // The triangulation with that refinement share and its morph, or
    // nothing if either fails.
    auto attempt = [&](double share) -> std::optional<Attempt> {
      FigureTriangulationOptions other = triangulation_options;
      other.refinement_share = share;
      Attempt a;
      try {
        const auto again = std::chrono::steady_clock::now();
        a.triangulation = factored ? triangulate_figures(*normalised, other, &a.stats)
                                   : triangulate_figures(pair, other, &a.stats);
        stats.triangulate_ms += milliseconds_since(again);
        a.morph.emplace(a.triangulation, source, pair.source_decomposition(), target.vertices,
                        factored ? similarity : SimilarityMotion{}, make_guide(), weights, easing);
      } catch (const VerificationError&) {
        return std::nullopt;
      }
      return a;
    };
    auto departure = [](const std::optional<Attempt>& a) { return a->morph->stats().guide_departure; };
    auto keep = [&](std::optional<Attempt>& chosen) {
      morph.emplace(std::move(*chosen->morph));
      triangulation = std::move(chosen->triangulation);
      stats.triangulation = chosen->stats;
    };
    // Refinement's Steiner vertices can keep the guide from being followed
    // where the unrefined triangulation let it be (a letter 7 drawn into an
    // L: guide frames trusted at 3 samples of 15, against all 15 without).
    // Where the frames the refined morph makes at its samples depart from
    // the guide by more than kMostGuideDeparture in edge length, the same
    // triangulation without refinement is made too; if that one follows the
    // guide, the largest of kLighterRefinementShares that still does is
    // kept, else the unrefined one. Where even the unrefined one does not
    // follow the guide (the guide itself crosses, and every morph must
    // leave it), the refined one stands. Deciding by trust at the samples
    // instead (any sample short of full trust) took a lighter share on a
    // W drawn into an M whose refined morph departed by less than 0.002,
    // and that share, trusted at every sample, blended between them (edge
    // deviation 0.0081 against edge ARAP's 0, where the refined morph's was
    // within 0.005).
    //
    // A locally timed guide (local_timing.h, issue 31) moves parts of the
    // figure against each other in ways neither drawing shows: a triangle
    // of three figure vertices (a neck's base, its first joint and the
    // head) inverts when the neck's first bone turns ahead of the rest, and
    // no placement of Steiner vertices helps; a finer triangulation has no
    // such triangle. There every share of kTimedRefinementShares is tried
    // and the one whose morph departs least from the guide is kept (the
    // default on a tie). The plain guide's ladder above is unchanged, so
    // that overlap 0 (no local clock) is the plain morph bit for bit.
    const bool timed = morph->stats().local_timing;
    if (timed && source.vertices.size() <= kMostVerticesForRefinement &&
        morph->stats().guide_departure > kMostGuideDeparture) {
      std::optional<Attempt> best;
      for (double share : kTimedRefinementShares) {
        if (share == triangulation_options.refinement_share) continue;
        std::optional<Attempt> other = attempt(share);
        if (!other) continue;
        if (departure(other) < (best ? departure(best) : morph->stats().guide_departure)) best = std::move(other);
        if (best && departure(best) <= kMostGuideDeparture) break;
      }
      if (best) keep(best);
    } else if (stats.triangulation.refinement_steiner > 0 && morph->stats().guide_departure > kMostGuideDeparture) {
      auto follows = [&](const std::optional<Attempt>& a) { return a && departure(a) <= kMostGuideDeparture; };
      std::optional<Attempt> chosen = attempt(0);
      if (follows(chosen)) {
        for (double share : kLighterRefinementShares) {
          std::optional<Attempt> lighter = attempt(share);
          if (follows(lighter)) {
            chosen = std::move(lighter);
            break;
          }
        }
        keep(chosen);
      }
    }
    const double setup_ms = milliseconds_since(start);
    stats.factorize_ms = setup_ms;
    stats.steiner_vertices = triangulation.steiner_vertices;
    stats.triangles = int(triangulation.triangles.size());
    return std::move(*morph);
  } catch (const InvalidArgumentError& error) {
    throw InternalError(std::string("morph_stick_figures: the engine refused its own intermediate result: ") +
                        error.what());
  }
}

}  // namespace internal
}  // namespace stickmorph
