// The rigid morph following an as-rigid-as-possible guide; see guided_morph.h.
#include "stickmorph/guided_morph.h"

#include <Eigen/Dense>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <limits>
#include <optional>
#include <utility>

#include "stickmorph/cancellation.h"
#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/frame_certificate.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/internal/barycentric_weights.h"
#include "stickmorph/internal/convex_combination_system.h"
#include "stickmorph/internal/edge_turns.h"
#include "stickmorph/internal/morph_topology.h"
#include "stickmorph/internal/motion_timing.h"
#include "stickmorph/internal/preconditioned_gmres.h"
#include "stickmorph/internal/rigid_steiner_placement.h"
#include "stickmorph/internal/stopwatch.h"
#include "stickmorph/morph_solver.h"

namespace stickmorph {
namespace {

using namespace internal;
using SparseMatrix = Eigen::SparseMatrix<double>;

// Times at which the guide's trust is sampled for smoothing (trust_at), and
// the time over which a vertex's trust may rise from 0 to 1: a fifth of the
// morph, several frames at any frame rate an animation uses, so a hand-over
// is spread over several frames instead of one.
constexpr int kTrustSamples = 16;
constexpr double kTrustRamp = 0.2;

// Sample j of kTrustSamples + 1 along the guide's motion: denser near the
// ends (Chebyshev spacing), where a morph that leaves the guide has to come
// back to the exact source and target and may do it quickly; the timing
// by the morph's own motion is piecewise linear between samples.
// Rounds of long double refinement of a frame that rounding flipped, as
// morph.cpp's for the barycentric frame.
constexpr int kRefinementRounds = 3;

double sample_time(int j) {
  if (j <= 0) return 0;
  if (j >= kTrustSamples) return 1;
  return 0.5 - 0.5 * std::cos(3.14159265358979323846 * j / kTrustSamples);
}

double smoothstep01(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

// The defect of a frame in output space, or empty. The enclosure is no
// longer fixed (the similarity moved it), but the certificate
// (frame_certificate.h) checks it in every frame: a strictly convex polygon
// winding once, every triangle counter-clockwise, which proves the frame an
// embedding with the source's topology. FrameCheck::Full adds the
// independent rebuild of the figure (verify_frame).
std::string output_defect(const FigureTriangulation& tri, const StickFigure& source,
                          const Decomposition& source_decomposition, const std::vector<Vec2>& p, int frame,
                          double time, FrameCheck check) {
  const std::string defect = certificate_defect(tri, p);
  if (!defect.empty()) return frame_label(frame, time) + ": " + defect;
  if (check == FrameCheck::Certificate) return {};
  const std::vector<Vec2> figure(p.begin(), p.begin() + tri.figure_vertices);
  try {
    verify_frame(source, source_decomposition, figure, frame, time);
  } catch (const VerificationError& error) {
    return error.what();
  }
  return {};
}

}  // namespace

// How far the guide turns every figure edge from u = 0 to 1 in the
// normalised space (the similarity taken out): each edge's direction
// followed through kTurnSamples samples, every step taken the short way.
// The guide turns an edge at constant speed by at most half a turn beyond
// the similarity's whole rotation, which is taken out here, so a step of
// 1/64 turns it by far less than half a turn.
static std::vector<double> normalised_turns(const FigureTriangulation& tri, const StickFigure& source,
                                            const SimilarityMotion& similarity, const GuideTrajectory& guide) {
  constexpr int kTurnSamples = 64;
  const std::size_t m = source.edges.size();
  std::vector<double> turns(m, 0.0), previous(m);
  auto directions = [&](const std::vector<Vec2>& p, std::vector<double>& angle) {
    for (std::size_t e = 0; e < m; ++e) {
      const Vec2 &a = p[std::size_t(source.edges[e][0])], &b = p[std::size_t(source.edges[e][1])];
      angle[e] = std::atan2(b[1] - a[1], b[0] - a[0]);
    }
  };
  directions(tri.source, previous);
  std::vector<double> here(m);
  for (int j = 1; j <= kTurnSamples; ++j) {
    const double u = double(j) / kTurnSamples;
    directions(j == kTurnSamples ? tri.target : similarity.unapply(u, guide.at(u)), here);
    for (std::size_t e = 0; e < m; ++e) turns[e] += wrap_angle(here[e] - previous[e]);
    previous.swap(here);
  }
  return turns;
}

struct GuidedMorph::State {
  State(const FigureTriangulation& normalised, const StickFigure& source_figure,
        const Decomposition& source_decomposition, const SimilarityMotion& motion,
        std::unique_ptr<const GuideTrajectory> trajectory, WeightKind kind, Easing easing_kind)
      : tri(normalised),
        source(source_figure),
        decomposition(source_decomposition),
        similarity(motion),
        guide(std::move(trajectory)),
        weight_kind(kind),
        easing(easing_kind),
        topo(build_topology(tri)),
        // The blended frame is the solution of [17]'s system, to the ten
        // digits of MorphSolver.
        // The Steiner vertices of the guide frame placed by weights only set
        // the figure vertices' trust and weights (any positive weights give a
        // valid frame), and a guide frame that is output is checked exactly
        // like any other: nine digits are plenty, and keep a frame scrubbed
        // in any order within about 1e-9 of the same frame solved in order.
        steiner_system(topo, steiner_rows(tri), 1e-9),
        placement(tri, source.edges, normalised_turns(tri, source, similarity, *guide)),
        full_system(topo, topo.interior_nodes, 1e-10) {
    std::size_t largest = 0;
    for (const std::vector<int>& ring : topo.ring) largest = std::max(largest, ring.size());
    corner_scratch.resize(largest);
  }

  const FigureTriangulation tri;  // normalised
  FigureTriangulation output;     // output space
  const StickFigure source;
  const Decomposition decomposition;
  const SimilarityMotion similarity;
  const std::unique_ptr<const GuideTrajectory> guide;
  const WeightKind weight_kind;
  const Easing easing;
  const Topology topo;
  std::vector<std::vector<double>> w0, w1;  // per node, over topo.ring (interior nodes only)
  std::vector<std::vector<double>> wt;      // the blend at the current u
  static std::vector<int> steiner_rows(const FigureTriangulation& tri) {
    std::vector<int> rows;
    for (int v = tri.figure_vertices + tri.enclosure_vertices; v < tri.node_count(); ++v) rows.push_back(v);
    return rows;
  }

  // Step 2's two placements of the guide frame's Steiner vertices, and
  // which one this morph uses (sample_guide chooses).
  ConvexCombinationSystem steiner_system;  // by the blended weights W(u)
  RigidSteinerPlacement placement;         // as rigidly as possible
  bool rigid_placement = false;
  // The nodes whose stars decide trust: the figure's vertices, and with
  // rigid_placement the Steiner vertices too (placed by W(u) alone they are
  // convex combinations of their neighbours, valid when the figure
  // vertices' stars are, by Tutte's theorem).
  std::vector<int> judged;
  ConvexCombinationSystem full_system;
  std::vector<double> full_trust_margin;  // per interior node, see trust()
  mutable std::vector<double> corner_scratch;  // star_margin's, one per neighbour of the largest ring
  // guided_frame's: the blended weights of every figure vertex, and the
  // offsets and mean value weights of one star.
  std::vector<std::vector<double>> mixed;
  std::vector<Vec2> offset_scratch;
  std::vector<double> weight_scratch;
  // sample_guide(): the sampled parameters u_j, trust() of every figure
  // vertex there (for smoothing it over time, trust_at), and the morph's own
  // cumulative motion there if it leaves the guide (else empty).
  std::vector<double> sample_u;
  std::vector<std::vector<float>> trust_samples;
  std::vector<char> sampled_below_one;  // per node: some trust_samples below 1 (empty: not known yet)
  std::optional<MotionTiming> own_timing;  // the morph's own motion at the samples (none: it follows the guide)
  std::optional<MorphSolver> fallback;  // [8] itself, made on first need
  GuidedMorphStats stats;

  // stats.factorizations after solves: both systems' and the fallback's.
  void count_factorizations() {
    stats.factorizations = steiner_system.factorizations() + full_system.factorizations() +
                           (fallback ? fallback->stats().factorizations : 0);
  }

  // Local timing (issue 31; local_timing.h): where the guide runs its
  // vertices on their own clocks, every node has a local time too, so that
  // the Steiner vertices about a lagging limb lag with it: a figure vertex
  // its guide's, an enclosure node u itself, a Steiner node the least of its
  // neighbours' nearer the figure (breadth first from the figure, fixed at
  // construction: steiner_time_order and steiner_time_sources): a Steiner
  // vertex lags as much as the most lagging part beside it, so that the
  // scaffolding about a lagging limb stays where the limb still is (the
  // mean instead let Steiner vertices beside a hand follow the bending
  // body into the hand's way; on issue 31's skeleton corpora at d = 0.5,
  // with the timed refinement of internal/rigid_morph_setup.cpp, the
  // largest miss of the lag was 0.067 and 0.071 with the least, 0.072 and
  // 0.082 with the mean, docs/MOTION.md). The blended
  // weights of [8] are then taken at each node's own time, row by row, as
  // [17] allows (any positive convex-combination weights keep the morph a
  // valid triangulation), and the rigid placement interpolates each
  // triangle at its corners' mean time. Empty where the guide has no local
  // clocks: then every node runs on u and the code below is what it always
  // was.
  std::vector<int> steiner_time_order;
  std::vector<std::vector<int>> steiner_time_sources;  // per entry of steiner_time_order
  std::vector<double> node_times;                       // at the latest set_node_times

  void order_steiner_times() {
    const int n = tri.figure_vertices, first_steiner = tri.figure_vertices + tri.enclosure_vertices;
    std::vector<char> assigned(std::size_t(tri.node_count()), 0);
    std::deque<int> queue;
    for (int v = 0; v < n; ++v) {
      assigned[std::size_t(v)] = 1;
      queue.push_back(v);
    }
    while (!queue.empty()) {
      const int v = queue.front();
      queue.pop_front();
      for (int w : topo.ring[std::size_t(v)]) {
        if (w < first_steiner || assigned[std::size_t(w)]) continue;
        std::vector<int> sources;
        for (int x : topo.ring[std::size_t(w)])
          if (assigned[std::size_t(x)] && (x < n || x >= first_steiner)) sources.push_back(x);
        assigned[std::size_t(w)] = 1;
        steiner_time_order.push_back(w);
        steiner_time_sources.push_back(std::move(sources));
        queue.push_back(w);
      }
    }
    // Steiner nodes the figure does not reach (none in a connected
    // triangulation) keep u.
  }

  bool timed = false;  // the guide has local clocks (set at construction)

  void set_node_times(double u) {
    const std::vector<double> figure_times = guide->vertex_times(u);
    node_times.assign(std::size_t(tri.node_count()), u);
    std::copy(figure_times.begin(), figure_times.end(), node_times.begin());
    for (std::size_t k = 0; k < steiner_time_order.size(); ++k) {
      const std::vector<int>& sources = steiner_time_sources[k];
      if (sources.empty()) continue;
      double least = 1;
      for (int x : sources) least = std::min(least, node_times[std::size_t(x)]);
      node_times[std::size_t(steiner_time_order[k])] = least;
    }
  }

  void blend_weights(double u) {
    if (timed) {
      set_node_times(u);
      for (int v : topo.interior_nodes) {
        const double tau = node_times[std::size_t(v)];
        for (std::size_t j = 0; j < wt[v].size(); ++j) wt[v][j] = (1 - tau) * w0[v][j] + tau * w1[v][j];
      }
      return;
    }
    for (int v : topo.interior_nodes)
      for (std::size_t j = 0; j < wt[v].size(); ++j) wt[v][j] = (1 - u) * w0[v][j] + u * w1[v][j];
  }

  // Step 1: the source's nodes with the figure's vertices where the guide
  // puts them at u, mapped back into the normalised space (where the
  // enclosure is fixed); step 2 then places the Steiner vertices.
  std::vector<Vec2> figure_held_at(double u) const {
    const std::vector<Vec2> figure = similarity.unapply(u, guide->at(u));
    std::vector<Vec2> g = tri.source;
    std::copy(figure.begin(), figure.end(), g.begin());
    return g;
  }

  // Step 2's rigid placement of g's Steiner vertices at u, each triangle on
  // its corners' local times where the guide has local clocks.
  bool place_rigidly(double u, std::vector<Vec2>& g) {
    if (!timed) return placement.place(u, g);
    set_node_times(u);
    return placement.place(node_times, g);
  }

  // Steps 1-2: the guide frame in normalised space, its Steiner vertices
  // placed by W(u) or (rigid) as rigidly as possible.
  std::vector<Vec2> guide_frame(double u) { return guide_frame(u, rigid_placement); }
  std::vector<Vec2> guide_frame(double u, bool rigid) {
    std::vector<Vec2> g = figure_held_at(u);
    if (rigid) {
      if (!place_rigidly(u, g))
        throw VerificationError("the rigid morph's Steiner placement at u = " + format_double(u) + " failed");
      return g;
    }
    // The Steiner nodes' values in g are not a warm start: the system
    // iterates from its own (warm_start).
    if (!steiner_system.solve(u, [&](int v) -> const std::vector<double>& { return wt[v]; }, g))
      throw VerificationError("the rigid morph's Steiner system at u = " + format_double(u) + " is singular");
    return g;
  }

  // The mean over the figure's edges of how much longer or shorter each is
  // in p than in the guide frame g, over the longer of its source and
  // target lengths (both normalised): the edge-length deviation a frame adds
  // to the guide's own.
  double edge_length_departure(const std::vector<Vec2>& p, const std::vector<Vec2>& g) const {
    if (source.edges.empty()) return 0;
    double sum = 0;
    for (const Edge& e : source.edges) {
      const auto length = [&](const std::vector<Vec2>& x) {
        return std::hypot(x[e[1]][0] - x[e[0]][0], x[e[1]][1] - x[e[0]][1]);
      };
      const double longest = std::max(length(tri.source), length(tri.target));
      if (longest > 0) sum += std::abs(length(p) - length(g)) / longest;
    }
    return sum / double(source.edges.size());
  }

  // The nodes whose trust counts with that placement.
  std::vector<int> judged_nodes(bool rigid) const {
    std::vector<int> nodes;
    for (int v : topo.interior_nodes)
      if (v < tri.figure_vertices || rigid) nodes.push_back(v);
    return nodes;
  }

  // The sine of the smallest corner angle at v of its star in p, or 0 if
  // the star is not valid there (a corner not strictly positive, or
  // positive corners winding more than once).
  //
  // This runs for every figure vertex in every frame, and was most of an
  // exact frame at 10^3 vertices (perf over the frames of tree: the atan2 of
  // every corner a third; with it gone, the two hypot per corner still 29%
  // and the loop itself 28%), so two shortcuts that leave the value as it
  // was, bit for bit:
  //  - the winding is counted, not summed: with every corner strictly
  //    positive and less than a half turn, the corners wind k times round v
  //    exactly when k of them (taken half-open, (a, b]) contain the direction
  //    of the first neighbour, the last one always. Two sign tests per
  //    corner; their products are those of the corner tests with the
  //    factors swapped, so the signs agree with them.
  //  - the smallest sine is found on the squared sine cross^2 / (|a|^2 |b|^2)
  //    (no root), and only the corners within 1e-12 of the smallest (or
  //    whose squares leave the normal range) get the exact formula
  //    cross / (|a| |b|); the two differ by a few ulps, so the smallest is
  //    among those.
  double star_margin(const std::vector<Vec2>& p, int v) const {
    const std::vector<int>& ring = topo.ring[v];
    const std::size_t d = ring.size();
    const double cx = p[v][0], cy = p[v][1];
    const double fx = p[ring[0]][0] - cx, fy = p[ring[0]][1] - cy;
    double ax = fx, ay = fy, la2 = ax * ax + ay * ay;
    if (!(ax != 0 || ay != 0)) return 0;
    // Squared sine of every corner (or -1: take it exactly).
    double* squared = corner_scratch.data();
    double least = std::numeric_limits<double>::infinity();
    int windings = 0;
    for (std::size_t j = 0; j < d; ++j) {
      const Vec2& b = p[ring[(j + 1) % d]];
      const double bx = b[0] - cx, by = b[1] - cy;
      const double cross = ax * by - ay * bx;
      if (!(cross > 0) || !(bx != 0 || by != 0)) return 0;
      const double lb2 = bx * bx + by * by, norms = la2 * lb2, cross2 = cross * cross;
      const double q = cross2 / norms;
      constexpr double kNormal = std::numeric_limits<double>::min();
      if (norms >= kNormal && cross2 >= kNormal && std::isfinite(norms) && std::isfinite(q)) {
        squared[j] = q;
        least = std::min(least, q);
      } else {
        squared[j] = -1;
      }
      if (j + 1 == d || (j > 0 && ax * fy - ay * fx > 0 && fx * by - fy * bx >= 0)) ++windings;
      ax = bx;
      ay = by;
      la2 = lb2;
    }
    if (windings != 1) return 0;
    double smallest_sine = 1;
    const double bound = least * (1 + 1e-12);
    for (std::size_t j = 0; j < d; ++j) {
      if (!(squared[j] <= bound) && squared[j] >= 0) continue;
      const Vec2& a = p[ring[j]];
      const Vec2& b = p[ring[(j + 1) % d]];
      const double ax = a[0] - cx, ay = a[1] - cy, bx = b[0] - cx, by = b[1] - cy;
      // The root of the product of the squared lengths where that product
      // is normal (within an ulp or two of the hypot product, and several
      // times faster: hypot was still 3% of a blended frame once the mean
      // value weights no longer took it), else hypot.
      const double lengths = squared[j] >= 0 ? std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by))
                                             : std::hypot(ax, ay) * std::hypot(bx, by);
      smallest_sine = std::min(smallest_sine, (ax * by - ay * bx) / lengths);
    }
    return smallest_sine;
  }

  // How much of v's weights come from the guide frame g (step 4): all of
  // them while v's star there is at least half as good as in the source
  // and the target (a star that is thin in both ends is no warning sign),
  // falling smoothly to none as the star degenerates. Every corner of a
  // triangle that flips passes through sine 0, so the trust of the figure
  // vertices around a flip goes to 0 continuously: no frame pops.
  double trust(const std::vector<Vec2>& g, int v) const {
    return smoothstep01(star_margin(g, v) / full_trust_margin[v]);
  }

  // The trust of v at u, smoothed over time: trust() of the frame itself
  // (which must be 0 where v's star is invalid: only there would its mean
  // value weights not be positive), and no more than the trust at any
  // sampled time plus the time to it over kTrustRamp. A star that will be
  // invalid a little later already hands its weights over gradually, so a
  // guide that folds quickly (a stroke swinging through another) does not
  // make the morph jump in one frame.
  //
  // A vertex trusted fully at every sample (most of them) is bounded only
  // by trust() <= 1, so its samples are not walked (sample_guide notes which).
  double trust_at(const std::vector<Vec2>& g, double u, int v) const {
    double a = trust(g, v);
    if (a <= 1 && !sampled_below_one.empty() && !sampled_below_one[std::size_t(v)]) return a;
    for (int j = 0; j <= kTrustSamples && a > 0; ++j)
      a = std::min(a, double(trust_samples[j][v]) + std::abs(u - sample_u[j]) / kTrustRamp);
    return a;
  }

  // Samples the guide at kTrustSamples + 1 times of its own timing
  // (RigidGuide::parameter_at): the placement of step 2, the trust of every
  // judged node for trust_at, and,
  // where some vertex does not trust the guide fully, the frame the morph
  // will actually make there (unverified: it only times the morph). If any
  // such frame exists, the morph is timed by its own motion rather than
  // the guide's (parameter_at), since where it leaves the guide it may move
  // faster or slower than the guide does.
  void sample_guide() {
    const int n = tri.figure_vertices;
    sample_u.assign(kTrustSamples + 1, 0.0);
    trust_samples.assign(kTrustSamples + 1, std::vector<float>(std::size_t(tri.node_count()), 1.0f));
    // The guide frame at each sample with either placement of its Steiner
    // vertices (step 2), and the one that the guide can be trusted with at
    // more samples (see below): the
    // rigid placement follows the figure's turns, W(u) the barycentric
    // morph, and neither is better on every pair (a long thin fan from the
    // enclosure to a stroke that slides sideways keeps its shape under W(u)
    // and not when placed rigidly). One placement for the whole morph, so
    // the guide frame and the trust stay continuous in time.
    std::vector<std::vector<Vec2>> weighted(kTrustSamples + 1), placed(kTrustSamples + 1);
    // The rigid placement is an option, never a new way to fail: where its
    // system cannot be factorized or solved in floating point, W(u) alone.
    bool can_place = tri.steiner_vertices > 0;
    for (int j = 0; j <= kTrustSamples; ++j) {
      sample_u[j] = guide->parameter_at(sample_time(j), Easing::None);
      if (j == 0 || j == kTrustSamples) continue;  // the inputs themselves
      blend_weights(sample_u[j]);
      weighted[j] = guide_frame(sample_u[j], false);
      if (can_place) {
        placed[j] = figure_held_at(sample_u[j]);
        can_place = place_rigidly(sample_u[j], placed[j]);
      }
    }
    auto score = [&](const std::vector<std::vector<Vec2>>& frames, bool rigid) {
      const std::vector<int> nodes = judged_nodes(rigid);
      int trusted = 0;
      double deficit = 0;
      for (int j = 1; j < kTrustSamples; ++j) {
        bool all = true;
        for (int v : nodes) {
          const double a = trust(frames[j], v);
          deficit += 1 - a;
          all = all && a >= 1;
        }
        trusted += all;
      }
      return std::pair<int, double>(trusted, -deficit);
    };
    const std::pair<int, double> by_weights = score(weighted, false);
    const std::pair<int, double> by_placement = can_place ? score(placed, true) : by_weights;
    // The rigid placement only where it follows the guide at every sample
    // and W(u) does not, or at two samples more: on a near tie a last-bit
    // change of the inputs (a dummy vertex placed by another fit) would
    // otherwise switch the placement, and the motion with it.
    const int all = kTrustSamples - 1;
    rigid_placement = by_placement.first > by_weights.first &&
                      (by_placement.first == all || by_placement.first >= by_weights.first + 2);
    stats.trusted_samples = (rigid_placement ? by_placement : by_weights).first;
    stats.samples = kTrustSamples - 1;
    stats.rigid_steiner_placement = rigid_placement;
    judged = judged_nodes(rigid_placement);
    const std::vector<std::vector<Vec2>>& guide_frames = rigid_placement ? placed : weighted;
    for (int j = 1; j < kTrustSamples; ++j)
      for (int v : judged) trust_samples[j][v] = float(trust(guide_frames[j], v));
    sampled_below_one.assign(std::size_t(tri.node_count()), 0);
    for (int j = 0; j <= kTrustSamples; ++j)
      for (int v : judged)
        if (!(trust_samples[j][v] >= 1.0f)) sampled_below_one[std::size_t(v)] = 1;
    std::vector<std::vector<Vec2>> figure(kTrustSamples + 1);
    figure[0].assign(tri.source.begin(), tri.source.begin() + n);
    figure[kTrustSamples] = similarity.apply(1.0, std::vector<Vec2>(tri.target.begin(), tri.target.begin() + n));
    bool leaves_guide = false;
    double departure = 0;
    for (int j = 1; j < kTrustSamples; ++j) {
      bool exact = true;
      for (std::size_t r = 0; r < judged.size() && exact; ++r)
        exact = trust_at(guide_frames[j], sample_u[j], judged[r]) >= 1;
      std::vector<Vec2> p = guide_frames[j];
      if (!exact) {
        blend_weights(sample_u[j]);
        bool ignored = false;
        p = guided_frame(guide_frames[j], sample_u[j], ignored);
        leaves_guide = true;
        departure += edge_length_departure(p, guide_frames[j]);
      }
      figure[j] = similarity.apply(sample_u[j], std::vector<Vec2>(p.begin(), p.begin() + n));
    }
    stats.guide_departure = departure / (kTrustSamples - 1);
    own_timing.reset();
    if (!leaves_guide || !guide->retimed_by_morph()) return;
    // As RigidGuide::parameter_at: a morph that does not move beyond
    // rounding keeps the guide's timing.
    double size = 0;
    for (const Vec2& p : figure[0]) size = std::max({size, std::abs(p[0]), std::abs(p[1])});
    for (const Vec2& p : figure[kTrustSamples]) size = std::max({size, std::abs(p[0]), std::abs(p[1])});
    std::vector<double> own_motion(kTrustSamples + 1, 0.0), times(kTrustSamples + 1, 0.0);
    for (int j = 1; j <= kTrustSamples; ++j) {
      long double sum = 0;
      for (int v = 0; v < n; ++v) {
        const long double dx = figure[j][v][0] - figure[j - 1][v][0], dy = figure[j][v][1] - figure[j - 1][v][1];
        sum += dx * dx + dy * dy;
      }
      own_motion[j] = own_motion[j - 1] + std::sqrt(double(sum / n));
      times[j] = sample_time(j);
    }
    own_timing.emplace(std::move(times), std::move(own_motion), 1e-10 * size, kMostUnevenSpeed);
  }

  // The morph parameter u at animation time t: the guide's (RigidGuide::
  // parameter_at: its own time, evened where its speed is uneven), or, where
  // the morph leaves the guide, evened by the morph's own sampled motion as
  // much as that is uneven (sample_guide), with the easing first.
  double parameter_at(double t) const {
    if (t == 0 || t == 1) return t;
    if (!own_timing) return guide->parameter_at(t, easing);
    const double eased = easing == Easing::InOut ? t * t * (3 - 2 * t) : t;
    // The guide's time at the morph's own; between samples, as the guide's
    // timing goes.
    return guide->parameter_at(own_timing->at(eased), Easing::None);
  }

  // Steps 3-4: the guide frame when every interior node trusts it fully,
  // otherwise guide weights where the guide's stars are valid. `exact`
  // tells which; `solve` asks for the solve even then (its weights, mean
  // value coordinates of the guide frame everywhere, reproduce it: a frame
  // that rounding spoiled is refined from there).
  std::vector<Vec2> guided_frame(const std::vector<Vec2>& g, double u, bool& exact, bool solve = false) {
    std::vector<double> trusts(std::size_t(tri.node_count()), 0.0);
    exact = true;
    for (int v : judged) {
      trusts[v] = trust_at(g, u, v);
      if (trusts[v] < 1) exact = false;
    }
    // Every judged node's star is valid in g, so its mean value weights
    // there are positive and reproduce it, and every other interior node
    // (a Steiner vertex placed by W(u)) is reproduced by W(u): g is the
    // solution of a system with positive weights, a valid triangulation by
    // Tutte's theorem, up to the rounding that the exact check of the
    // output frame catches.
    if (exact && !solve) return g;
    // Into storage kept between frames (mixed, offset_scratch,
    // weight_scratch): a frame's thousand small allocations were 5% of it.
    mixed.resize(std::size_t(tri.node_count()));
    for (int v : topo.interior_nodes) {
      const double a = trusts[v];
      mixed[v] = wt[v];
      if (a <= 0) continue;
      // Too close to degenerate for weights: [8]'s own.
      if (!try_node_weights(topo, g, v, WeightKind::MeanValue, offset_scratch, weight_scratch)) continue;
      for (std::size_t j = 0; j < mixed[v].size(); ++j)
        mixed[v][j] = a * weight_scratch[j] + (1 - a) * wt[v][j];
    }
    std::vector<Vec2> x = tri.source;
    const bool ok = full_system.solve(u, [&](int v) -> const std::vector<double>& { return mixed[v]; }, x);
    if (!ok) throw VerificationError("the rigid morph's blended system is singular");
    return x;
  }
};

GuidedMorph::GuidedMorph(const FigureTriangulation& normalised, const StickFigure& source,
                         const Decomposition& source_decomposition, const std::vector<Vec2>& target_vertices,
                         const SimilarityMotion& similarity, RigidGuide guide, WeightKind kind, Easing easing)
    : GuidedMorph(normalised, source, source_decomposition, target_vertices, similarity,
                  std::make_unique<const RigidGuide>(std::move(guide)), kind, easing) {}

GuidedMorph::GuidedMorph(const FigureTriangulation& normalised, const StickFigure& source,
                         const Decomposition& source_decomposition, const std::vector<Vec2>& target_vertices,
                         const SimilarityMotion& similarity, std::unique_ptr<const GuideTrajectory> guide,
                         WeightKind kind, Easing easing)
    : state_(std::make_unique<State>(normalised, source, source_decomposition, similarity, std::move(guide), kind,
                                     easing)) {
  State& s = *state_;
  const FigureTriangulation& tri = s.tri;
  require_positive(tri, tri.source, "source");
  require_positive(tri, tri.target, "target");
  require_enclosure(tri);
  if (int(target_vertices.size()) != tri.figure_vertices)
    throw InvalidArgumentError("GuidedMorph: the target has " + std::to_string(target_vertices.size()) +
                               " vertices, the triangulation " + std::to_string(tri.figure_vertices));
  s.timed = !s.guide->vertex_times(0.5).empty();
  s.stats.local_timing = s.timed;
  if (s.timed) s.order_steiner_times();
  s.w0.assign(tri.node_count(), {});
  s.w1.assign(tri.node_count(), {});
  s.wt.assign(tri.node_count(), {});
  for (int v : s.topo.interior_nodes) {
    s.w0[v] = node_weights(tri, s.topo, tri.source, v, kind);
    s.w1[v] = node_weights(tri, s.topo, tri.target, v, kind);
    s.wt[v] = s.w0[v];
  }
  // Below this sine of its smallest corner angle a star is too thin to be
  // trusted fully whatever the ends look like: about 6 degrees, where mean
  // value weights near a flat corner start to dominate a row.
  constexpr double kMostTrustMargin = 0.1;
  s.full_trust_margin.assign(std::size_t(tri.node_count()), 1.0);
  for (int v : s.topo.interior_nodes) {
    const double ends = std::min(s.star_margin(tri.source, v), s.star_margin(tri.target, v));
    // Both ends are valid triangulations, so ends > 0 unless it underflows.
    s.full_trust_margin[v] = std::max(std::min(kMostTrustMargin, 0.5 * ends), 1e-12);
  }
  auto start = Clock::now();
  s.sample_guide();
  s.steiner_system.begin_playback();
  // The sampled solves' factorizations are not kept as anchors: a playback
  // in order then solves bit for bit as with one anchor (issue 29; see
  // ConvexCombinationSystem::begin_playback).
  s.full_system.begin_playback();
  s.stats.guide_ms += ms_since(start);
  s.count_factorizations();
  // The triangulation in output space (section 6's rotated enclosure).
  s.output = tri;
  s.output.target = similarity.apply(1.0, tri.target);
  for (int v = 0; v < tri.figure_vertices; ++v) s.output.target[v] = target_vertices[v];
  require_figure_edges(s.output, s.source);
  // The last frame is the real target, not a solve. The caller's
  // CompatiblePair already proved the figure compatible with the source
  // (section 2.1); what is left to prove is that the triangulation moved
  // to it is still a disk triangulation, which the certificate's theorem
  // does (frame_certificate.h). FrameCheck::Full frames rebuild it again.
  const std::string defect =
      output_defect(s.output, s.source, s.decomposition, s.output.target, -1, 1.0, FrameCheck::Certificate);
  if (!defect.empty())
    throw VerificationError("the rigid morph's triangulation moved to the target: " + defect);
}

GuidedMorph::~GuidedMorph() = default;
GuidedMorph::GuidedMorph(GuidedMorph&&) noexcept = default;
GuidedMorph& GuidedMorph::operator=(GuidedMorph&&) noexcept = default;

const FigureTriangulation& GuidedMorph::triangulation() const { return state_->output; }
const SimilarityMotion& GuidedMorph::similarity() const { return state_->similarity; }
const GuidedMorphStats& GuidedMorph::stats() const { return state_->stats; }


GuidedFrame GuidedMorph::frame(double t, int frame, bool verify, const std::string& context, FrameCheck check) {
  if (!(t >= 0 && t <= 1)) throw InvalidArgumentError("the morph time must be in [0, 1]");
  State& s = *state_;
  GuidedFrame result;
  auto defect_of = [&](const std::vector<Vec2>& p) {
    const auto start = Clock::now();
    std::string defect = output_defect(s.output, s.source, s.decomposition, p, frame, t, check);
    result.verify_ms += ms_since(start);
    s.stats.verify_ms += ms_since(start);
    return defect;
  };
  if (t == 0 || t == 1) {
    // The inputs themselves, bit for bit (FORMAT.md).
    result.parameter = t;
    result.positions = t == 0 ? s.output.source : s.output.target;
    if (verify) {
      const std::string defect = defect_of(result.positions);
      if (!defect.empty()) throw VerificationError(context + defect);
    }
    return result;
  }
  const double u = s.parameter_at(t);
  result.parameter = u;
  auto start = Clock::now();
  s.blend_weights(u);
  const std::vector<Vec2> g = s.guide_frame(u);
  s.stats.guide_ms += ms_since(start);

  // Steps 3-4.
  start = Clock::now();
  bool exact = false;
  std::vector<Vec2> normalised = s.guided_frame(g, u, exact);
  result.positions = s.similarity.apply(u, normalised);
  s.stats.solve_ms += ms_since(start);
  s.count_factorizations();
  result.fit = exact ? GuideFit::Exact : GuideFit::Blended;
  if (!verify) return result;
  std::string defect = defect_of(result.positions);
  if (defect.empty()) return result;
  // Rounding can flip a triangle thinner than doubles resolve here as in
  // the barycentric frame (checked_morph_frame), and the same two repairs
  // keep the figure where the guide put it, which the fallback below would
  // not: the solve refined in long double (the blended system's; for the
  // guide frame itself the Steiner system's, or with the rigid placement
  // the blended system with the guide frame's own mean value weights, which
  // reproduce it), then Steiner vertices of inverted
  // triangles moved into their stars' kernels. Each is checked again like
  // any frame.
  {
    start = Clock::now();
    if (exact && s.rigid_placement) normalised = s.guided_frame(g, u, exact, true);
    (exact && !s.rigid_placement ? s.steiner_system : s.full_system).refine(normalised, kRefinementRounds);
    std::vector<Vec2> repaired = s.similarity.apply(u, normalised);
    s.stats.solve_ms += ms_since(start);
    if (defect_of(repaired).empty() ||
        (untangle_steiner_vertices(s.output, repaired) && defect_of(repaired).empty())) {
      result.positions = std::move(repaired);
      result.refined = true;
      return result;
    }
  }

  // Step 5's fallback: [8] at u, with its own refinement, then moved.
  start = Clock::now();
  if (!s.fallback) s.fallback.emplace(s.tri, s.weight_kind);
  CheckedFrame plain =
      checked_morph_frame(*s.fallback, s.tri, s.source, s.decomposition, u, frame, true, context, check, t);
  s.stats.solve_ms += ms_since(start) - plain.verify_ms;
  s.stats.verify_ms += plain.verify_ms;
  result.verify_ms += plain.verify_ms;
  result.refined = plain.refined;
  s.count_factorizations();
  result.positions = s.similarity.apply(u, plain.positions);
  result.fit = GuideFit::Barycentric;
  defect = defect_of(result.positions);
  // The similarity's rounding can flip a triangle as thin as those that
  // checked_morph_frame untangles: the same repair in output space.
  if (!defect.empty() && untangle_steiner_vertices(s.output, result.positions)) defect = defect_of(result.positions);
  if (!defect.empty()) throw VerificationError(context + defect + " (moved by the rigid morph's similarity)");
  return result;
}

MorphResult guided_morph(GuidedMorph& morph, int frames, bool verify, GuidedMorphStats* stats, FrameCheck check) {
  MorphResult result;
  result.times.resize(frames);
  for (int f = 0; f < frames; ++f) result.times[f] = double(f) / double(frames - 1);
  int exact = 0, blended = 0, barycentric = 0, refined = 0;
  for (int f = 0; f < frames; ++f) {
    report_progress(f, frames);  // a caller's cancel stops here, between frames (cancellation.h)
    GuidedFrame frame = morph.frame(result.times[f], f, verify, "morph: ", check);
    if (f > 0 && f < frames - 1) {
      if (frame.fit == GuideFit::Exact) ++exact;
      if (frame.fit == GuideFit::Blended) ++blended;
      if (frame.fit == GuideFit::Barycentric) ++barycentric;
    }
    if (frame.refined) ++refined;
    result.frames.push_back(std::move(frame.positions));
  }
  if (stats) {
    *stats = morph.stats();
    stats->exact_frames = exact;
    stats->blended_frames = blended;
    stats->barycentric_frames = barycentric;
    stats->refined_frames = refined;
  }
  const GuidedMorphStats& s = morph.stats();
  result.stats.factorize_ms = 0;
  result.stats.solve_ms = s.guide_ms + s.solve_ms;
  result.stats.verify_ms = s.verify_ms;
  result.stats.refined_frames = refined;
  return result;
}

}  // namespace stickmorph
