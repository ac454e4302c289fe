// The rigid morph following an as-rigid-as-possible guide; see guided_morph.h.
#include "stickmorph/guided_morph.h"

#include <Eigen/Dense>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/frame_certificate.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/internal/barycentric_weights.h"
#include "stickmorph/internal/compact_lu.h"
#include "stickmorph/internal/morph_topology.h"
#include "stickmorph/internal/preconditioned_gmres.h"
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

using LU = SymmetricOrderedLU;  // compact_lu.h

// One linear system x_v - sum_j w_vj x_j = 0 over the rows of some interior
// nodes, the other nodes known; a fixed sparsity pattern, so the symbolic
// factorization is done once.
class ConvexCombinationSystem {
 public:
  /// `tolerance`: the relative residual an iterative solve must reach.
  ConvexCombinationSystem(const Topology& topo, std::vector<int> rows, double tolerance)
      : topo_(topo), nodes_(std::move(rows)), tolerance_(tolerance) {
    unknown_.assign(topo.nodes, -1);
    for (int r = 0; r < int(nodes_.size()); ++r) unknown_[nodes_[r]] = r;
    // The pattern is the same in every frame (one row per node, one entry
    // per unknown neighbour), so it is built once here and each solve only
    // writes the values through slot_: rebuilding the triplets and calling
    // setFromTriplets, with their allocations, was about 4% of the blended
    // frames (perf, spiral at 10^3 vertices). The entries are summed in the
    // triplets' order, as
    // setFromTriplets sums duplicates, so the matrix is the same bit for bit.
    const int m = size();
    std::vector<Eigen::Triplet<double>> triplets;
    for (int row = 0; row < m; ++row) {
      const int v = nodes_[row];
      triplets.emplace_back(row, row, 0.0);
      for (int u : topo_.ring[v])
        if (unknown_[u] >= 0) triplets.emplace_back(row, unknown_[u], 0.0);
    }
    a_.resize(m, m);
    a_.setFromTriplets(triplets.begin(), triplets.end());
    a_.makeCompressed();
    auto slot_of = [&](int row, int column) {
      const int* begin = a_.innerIndexPtr() + a_.outerIndexPtr()[column];
      const int* end = a_.innerIndexPtr() + a_.outerIndexPtr()[column + 1];
      return int(std::lower_bound(begin, end, row) - a_.innerIndexPtr());
    };
    diagonal_slot_.resize(std::size_t(m));
    ring_start_.assign(1, 0);
    for (int row = 0; row < m; ++row) {
      const int v = nodes_[row];
      diagonal_slot_[std::size_t(row)] = slot_of(row, row);
      for (int u : topo_.ring[v]) slot_.push_back(unknown_[u] >= 0 ? slot_of(row, unknown_[u]) : -1);
      ring_start_.push_back(int(slot_.size()));
    }
    b_.resize(m, 2);
  }
  int size() const { return int(nodes_.size()); }
  int node(int row) const { return nodes_[row]; }

  /// Solves with the weights weights(v) over topo.ring[v] of every row's
  /// node; `positions` supplies the known nodes and receives the solution.
  /// `u`: the morph parameter of the solve, for the warm start (see
  /// warm_start; starting from the guide frame instead was measured to
  /// converge less often).
  /// False if the system is singular (never, for positive weights).
  template <class Weights>
  bool solve(double u, const Weights& weights, std::vector<Vec2>& positions) {
    if (nodes_.empty()) return true;
    const int m = size();
    double* values = a_.valuePtr();
    std::fill(values, values + a_.nonZeros(), 0.0);
    b_.setZero();
    for (int row = 0; row < m; ++row) {
      const int v = nodes_[row];
      const std::vector<double>& w = weights(v);
      const int* slot = slot_.data() + ring_start_[std::size_t(row)];
      values[diagonal_slot_[std::size_t(row)]] += 1.0;
      for (std::size_t j = 0; j < w.size(); ++j) {
        if (slot[j] >= 0) {
          values[slot[j]] += -w[j];
        } else {
          const int u = topo_.ring[v][j];
          b_(row, 0) += w[j] * positions[u][0];
          b_(row, 1) += w[j] * positions[u][1];
        }
      }
    }
    const Eigen::MatrixX2d& b = b_;
    if (!analysed_) {
      lu_.analyzePattern(a_);
      analysed_ = true;
    }
    // As MorphSolver does (morph_solver.cpp, where the choice is measured):
    // consecutive frames' systems differ only a little, so an iteration
    // preconditioned with the last factorization (the anchor), from the
    // warm start, converges in a few steps; factorize only when it does
    // not. The result is never trusted on its own: every frame is checked
    // exactly.
    Eigen::MatrixX2d x;
    bool solved = false;
    // After an iteration that did not converge the anchor is too far:
    // factorize without trying (as MorphSolver does) for the next solves,
    // one after the first failure, then twice as many after each further
    // one in a row (up to kMostSkipped), none again after a success. The
    // blended system of the star polygon, the rings and the spiral at 10^3
    // vertices never converged in its kAnchorIterations steps: it
    // refactorized in every frame, and skipping only the solve after each
    // failure still spent a warm start and four steps on every other one
    // (measured: 0.2-0.25 ms of a 1.1-1.2 ms frame there). Trying in every
    // solve instead saves factorizations (spiral 29 -> 23, rings 13 -> 7,
    // measured with GMRES) but costs as much in steps.
    if (factorized_ && !history_.empty() && skipped_ == 0) {
      const double tolerance = tolerance_ * std::max(b.norm(), 1e-300);
      x = warm_start(u, b);
      // Densely filled factors (see kAnchorIterationsDense) iterate longer
      // and, after a failure, try again on the anchor just made: the next
      // frame converges on it in 4-6 steps, a fifth of what factorizing
      // again costs there.
      const bool dense = !factors_.refactorization_pays();
      solved = preconditioned_gmres(a_, factors_, b, x, tolerance,
                                    dense ? kAnchorIterationsDense : kAnchorIterations, gmres_);
      failures_in_a_row_ = solved ? 0 : failures_in_a_row_ + 1;
      if (!solved && !dense) skipped_ = std::min(kMostSkipped, 1 << std::min(failures_in_a_row_ - 1, 8));
    } else if (skipped_ > 0) {
      --skipped_;
    }
    if (!solved) {
      // A static-pivot refactorization on the last factors' structure
      // first, kept when its solution meets the tolerance; else SparseLU
      // with pivoting (factorize_checked, as MorphSolver does).
      factorized_ = factorize_checked(a_, b, tolerance_, factorized_, lu_, factors_, &x);
      if (!factorized_) return false;
      ++factorizations_;
    }
    if (!x.allFinite()) return false;
    if (history_.size() == kHistory) history_.erase(history_.begin());
    history_.push_back({u, x});
    for (int row = 0; row < m; ++row) positions[nodes_[row]] = {x(row, 0), x(row, 1)};
    return true;
  }

  // The iteration is GMRES right-preconditioned with the anchor's LU
  // (preconditioned_gmres.h). Why not the iterative refinement used
  // before: the blended system's rows change quickly wherever a figure
  // vertex's trust or its guide star does, and refinement on an anchor a
  // frame or two old stopped converging (rate above 0.7): 53-62
  // factorizations in the 48 frames of spiral and polygon at 10^3 vertices,
  // about one a frame (two for each failure, see solve). GMRES converges
  // where refinement diverges and, per step, at least as fast (measured
  // there: 33 and 28 factorizations; with the warm start and CompactLU, 29
  // and 27).

  /// Numeric factorizations so far.
  int factorizations() const { return factorizations_; }

  /// Iterative refinement of the latest solve, whose unknowns `positions`
  /// holds: `rounds` rounds of the residual of the system as assembled
  /// (a_, b_) accumulated in long double, corrected with the kept factors
  /// (of this system, or of a nearby one when the solve iterated on them).
  /// For a frame that rounding flipped (GuidedMorph::frame): the solve's
  /// tolerance leaves errors that a triangle near the tightly wound start
  /// of a 10^4-vertex spiral, thinner than 1e-8 of the figure, does not
  /// survive; refined, the positions are the exact solution's to about the
  /// spacing of doubles.
  void refine(std::vector<Vec2>& positions, int rounds) const {
    if (nodes_.empty() || !factorized_) return;
    const int m = size();
    std::vector<long double> x(2 * std::size_t(m)), r(2 * std::size_t(m));
    for (int row = 0; row < m; ++row) {
      x[2 * std::size_t(row)] = positions[nodes_[row]][0];
      x[2 * std::size_t(row) + 1] = positions[nodes_[row]][1];
    }
    Eigen::MatrixX2d residual(m, 2);
    for (int round = 0; round < rounds; ++round) {
      for (int row = 0; row < m; ++row) {
        r[2 * std::size_t(row)] = b_(row, 0);
        r[2 * std::size_t(row) + 1] = b_(row, 1);
      }
      for (int column = 0; column < m; ++column)
        for (SparseMatrix::InnerIterator it(a_, column); it; ++it) {
          const std::size_t row = std::size_t(it.row());
          r[2 * row] -= static_cast<long double>(it.value()) * x[2 * std::size_t(column)];
          r[2 * row + 1] -= static_cast<long double>(it.value()) * x[2 * std::size_t(column) + 1];
        }
      for (int row = 0; row < m; ++row) {
        residual(row, 0) = double(r[2 * std::size_t(row)]);
        residual(row, 1) = double(r[2 * std::size_t(row) + 1]);
      }
      const Eigen::MatrixX2d correction = factors_.solve(residual);
      if (!correction.allFinite()) return;
      for (int row = 0; row < m; ++row) {
        x[2 * std::size_t(row)] += correction(row, 0);
        x[2 * std::size_t(row) + 1] += correction(row, 1);
      }
    }
    for (int row = 0; row < m; ++row) positions[nodes_[row]] = {double(x[2 * std::size_t(row)]), double(x[2 * std::size_t(row) + 1])};
  }

 private:
  /// GMRES steps before the anchor counts as too far. Four since
  /// factorizations are static-pivot refactorizations (CompactLU::
  /// refactorize), 0.1-0.6 of SparseLU's at 10^3 vertices: measured at 10^3 vertices (48
  /// frames), rigid frame / fresh LU with 16, 8 and 4 steps: spiral 0.60,
  /// 0.51, 0.45; polygon 0.59, 0.46, 0.42; rings 0.51, 0.45, 0.48; thinned
  /// 0.32, 0.28, 0.29 (two steps: no better than four, twice the
  /// factorizations). With SparseLU's factorizations sixteen steps were
  /// best.
  static constexpr int kAnchorIterations = 4;
  /// Where the factors fill in too densely for the static refactorization
  /// (CompactLU::refactorization_pays false: every factorization is
  /// SparseLU's with pivoting and a copy into CompactLU, 20-30 times a
  /// GMRES step), more steps before giving up on the anchor, and no solves
  /// skipped after a failure. Measured on thinned at 10^4 vertices (65
  /// nonzeros of L and U per row; 48 blended frames in order after
  /// prepare_rigid_morph): 4 steps with skipping, as elsewhere, 42
  /// factorizations and 25.7 ms a frame; without skipping, 8, 12, 16 and 24
  /// steps: 9, 5, 4 and 3 factorizations, 16.4, 16.4, 17.3 and 19.6 ms.
  /// The steps grow with the anchor's age, from 4-6 to about 14 over 15
  /// frames.
  static constexpr int kAnchorIterationsDense = 12;
  const Topology& topo_;
  std::vector<int> nodes_;
  const double tolerance_;
  std::vector<int> unknown_;
  SparseMatrix a_;                  // the fixed pattern; values rewritten by each solve
  std::vector<int> diagonal_slot_;  // row -> index of its diagonal in a_'s values
  std::vector<int> ring_start_;     // row -> its first entry in slot_
  std::vector<int> slot_;           // per row and ring neighbour: index in a_'s values, or -1 (known)
  Eigen::MatrixX2d b_;
  bool analysed_ = false;
  bool factorized_ = false;
  int skipped_ = 0;            // solves left that factorize without trying the iteration
  int failures_in_a_row_ = 0;  // iterations that did not converge since the last that did
  static constexpr int kMostSkipped = 8;
  int factorizations_ = 0;
  // The latest solutions (oldest first) and their parameters u: the warm
  // starts.
  struct Solution {
    double u;
    Eigen::MatrixX2d x;
  };
  static constexpr std::size_t kHistory = 6;
  std::vector<Solution> history_;
  GmresWorkspace gmres_;  // preconditioned_gmres's storage

  // The start of the iteration at u: the least-squares solution over the
  // span of the kept solutions (both coordinates of each; six solutions,
  // twelve columns: twelve products with A and a small QR, a fraction of
  // one preconditioner solve), unless the last solution itself has a
  // smaller residual (a rank-deficient span). With fewer than three kept,
  // the last one or the linear extrapolation in u through the last two.
  // Measured at 10^3 vertices, 50 frames: the Steiner system (linear in u)
  // starts 10^2 to 10^3 times closer than from the last solution and then
  // converges in 1-5 steps instead of 10-15 (polygon, 624 Steiner
  // vertices); the blended system only 5 to 10 times closer (its weights
  // follow the trust, which has kinks), about a step saved.
  //
  // The linear and quadratic extrapolations in u through the last two and
  // three solutions (Lagrange) were candidates too, each costing a product
  // with A for its residual; but they lie in the span, where the least
  // squares solution has the least residual of all, column by column, so
  // they could win only by rounding. Nor is the least-squares residual a
  // product with A: it is b minus the images times the coefficients.
  Eigen::MatrixX2d warm_start(double u, const Eigen::MatrixX2d& b) const {
    const std::size_t h = history_.size();
    Eigen::MatrixX2d best = history_.back().x;
    double best_norm = (b - a_ * best).norm();
    if (h == 2) {
      const Solution& p = history_[0];
      const Solution& q = history_[1];
      if (p.u != q.u) {
        Eigen::MatrixX2d candidate = q.x + ((u - q.u) / (q.u - p.u)) * (q.x - p.x);
        if ((b - a_ * candidate).norm() < best_norm) best = std::move(candidate);
      }
    }
    if (h >= 3) {
      basis_.resize(size(), 2 * int(h));
      for (std::size_t i = 0; i < h; ++i) basis_.middleCols(2 * int(i), 2) = history_[i].x;
      images_ = a_ * basis_;
      const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(images_);
      const Eigen::MatrixXd y = qr.solve(b);
      if (y.allFinite() && (b - images_ * y).norm() < best_norm) best = basis_ * y;
    }
    return best;
  }
  mutable Eigen::MatrixXd basis_, images_;  // warm_start's storage
  LU lu_;
  CompactLU factors_;  // lu_ as plain columns, for the solves
};

}  // namespace

struct GuidedMorph::State {
  State(const FigureTriangulation& normalised, const StickFigure& source_figure, const SimilarityMotion& motion,
        RigidGuide rigid_guide, WeightKind kind, Easing easing_kind)
      : tri(normalised),
        source(source_figure),
        decomposition(decompose(source_figure)),
        similarity(motion),
        guide(std::move(rigid_guide)),
        weight_kind(kind),
        easing(easing_kind),
        topo(build_topology(tri)),
        // The Steiner vertices of the guide frame only set the figure
        // vertices' trust and weights (any positive weights give a valid
        // frame), and a guide frame that is output is checked exactly like
        // any other: nine digits are plenty, and keep a frame scrubbed in
        // any order within about 1e-9 of the same frame solved in order.
        // The blended frame is the solution of [17]'s system, to the ten
        // digits of MorphSolver.
        steiner_system(topo, steiner_rows(tri), 1e-9),
        full_system(topo, topo.interior_nodes, 1e-10) {
    std::size_t largest = 0;
    for (const std::vector<int>& ring : topo.ring) largest = std::max(largest, ring.size());
    corner_scratch.resize(largest);
  }

  static std::vector<int> steiner_rows(const FigureTriangulation& tri) {
    std::vector<int> rows;
    for (int v = tri.figure_vertices + tri.enclosure_vertices; v < tri.node_count(); ++v) rows.push_back(v);
    return rows;
  }

  const FigureTriangulation tri;  // normalised
  FigureTriangulation output;     // output space
  const StickFigure source;
  const Decomposition decomposition;
  const SimilarityMotion similarity;
  const RigidGuide guide;
  const WeightKind weight_kind;
  const Easing easing;
  const Topology topo;
  std::vector<std::vector<double>> w0, w1;  // per node, over topo.ring (interior nodes only)
  std::vector<std::vector<double>> wt;      // the blend at the current u
  ConvexCombinationSystem steiner_system;
  ConvexCombinationSystem full_system;
  std::vector<double> full_trust_margin;  // per figure vertex, see trust()
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
  std::vector<char> sampled_below_one;  // per figure vertex: some trust_samples below 1 (empty: not known yet)
  std::vector<double> own_motion;
  std::optional<MorphSolver> fallback;  // [8] itself, made on first need
  GuidedMorphStats stats;

  // stats.factorizations after solves: both systems' and the fallback's.
  void count_factorizations() {
    stats.factorizations = steiner_system.factorizations() + full_system.factorizations() +
                           (fallback ? fallback->stats().factorizations : 0);
  }

  void blend_weights(double u) {
    for (int v : topo.interior_nodes)
      for (std::size_t j = 0; j < wt[v].size(); ++j) wt[v][j] = (1 - u) * w0[v][j] + u * w1[v][j];
  }

  // Steps 1-2: the guide frame in normalised space.
  std::vector<Vec2> guide_frame(double u) {
    const std::vector<Vec2> figure = similarity.unapply(u, guide.at(u));
    std::vector<Vec2> g = tri.source;  // the enclosure is fixed
    std::copy(figure.begin(), figure.end(), g.begin());
    // The Steiner nodes' values in g are not a warm start: the system
    // iterates from its own (warm_start).
    if (!steiner_system.solve(u, [&](int v) -> const std::vector<double>& { return wt[v]; }, g))
      throw VerificationError("the rigid morph's Steiner system at u = " + format_double(u) + " is singular");
    return g;
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

  // Samples the guide at kTrustSamples + 1 times evenly spaced along the
  // guide's motion: the trust of every figure vertex for trust_at, and,
  // where some vertex does not trust the guide fully, the frame the morph
  // will actually make there (unverified: it only times the morph). If any
  // such frame exists, the morph is timed by its own motion rather than
  // the guide's (parameter_at), since where it leaves the guide it may move
  // faster or slower than the guide does.
  void sample_guide() {
    const int n = tri.figure_vertices;
    sample_u.assign(kTrustSamples + 1, 0.0);
    trust_samples.assign(kTrustSamples + 1, std::vector<float>(n, 1.0f));
    std::vector<std::vector<Vec2>> guide_frames(kTrustSamples + 1);
    for (int j = 0; j <= kTrustSamples; ++j) {
      sample_u[j] = guide.parameter_at(sample_time(j), Easing::None);
      if (j == 0 || j == kTrustSamples) continue;  // the inputs themselves
      blend_weights(sample_u[j]);
      guide_frames[j] = guide_frame(sample_u[j]);
      for (int v = 0; v < n; ++v) trust_samples[j][v] = float(trust(guide_frames[j], v));
    }
    sampled_below_one.assign(std::size_t(n), 0);
    for (int j = 0; j <= kTrustSamples; ++j)
      for (int v = 0; v < n; ++v)
        if (!(trust_samples[j][v] >= 1.0f)) sampled_below_one[std::size_t(v)] = 1;
    std::vector<std::vector<Vec2>> figure(kTrustSamples + 1);
    figure[0].assign(tri.source.begin(), tri.source.begin() + n);
    figure[kTrustSamples] = similarity.apply(1.0, std::vector<Vec2>(tri.target.begin(), tri.target.begin() + n));
    bool leaves_guide = false;
    for (int j = 1; j < kTrustSamples; ++j) {
      bool exact = true;
      for (int v = 0; v < n && exact; ++v) exact = trust_at(guide_frames[j], sample_u[j], v) >= 1;
      std::vector<Vec2> p = guide_frames[j];
      if (!exact) {
        blend_weights(sample_u[j]);
        bool ignored = false;
        p = guided_frame(guide_frames[j], sample_u[j], ignored);
        leaves_guide = true;
      }
      figure[j] = similarity.apply(sample_u[j], std::vector<Vec2>(p.begin(), p.begin() + n));
    }
    own_motion.clear();
    if (!leaves_guide) return;
    // As RigidGuide::parameter_at: a morph that does not move beyond
    // rounding keeps the guide's timing.
    double size = 0;
    for (const Vec2& p : figure[0]) size = std::max({size, std::abs(p[0]), std::abs(p[1])});
    for (const Vec2& p : figure[kTrustSamples]) size = std::max({size, std::abs(p[0]), std::abs(p[1])});
    own_motion.assign(kTrustSamples + 1, 0.0);
    for (int j = 1; j <= kTrustSamples; ++j) {
      long double sum = 0;
      for (int v = 0; v < n; ++v) {
        const long double dx = figure[j][v][0] - figure[j - 1][v][0], dy = figure[j][v][1] - figure[j - 1][v][1];
        sum += dx * dx + dy * dy;
      }
      own_motion[j] = own_motion[j - 1] + std::sqrt(double(sum / n));
    }
    if (!(own_motion.back() > 1e-10 * size)) own_motion.clear();
  }

  // The morph parameter u at animation time t: even along the guide's
  // motion, or along the morph's own sampled motion where it leaves the
  // guide (sample_guide), with the easing on top.
  double parameter_at(double t) const {
    if (t == 0 || t == 1) return t;
    if (own_motion.empty() || !(own_motion.back() > 0)) return guide.parameter_at(t, easing);
    const double eased = easing == Easing::InOut ? t * t * (3 - 2 * t) : t;
    const double goal = eased * own_motion.back();
    const auto it = std::lower_bound(own_motion.begin(), own_motion.end(), goal);
    const int j = std::clamp(int(it - own_motion.begin()), 1, kTrustSamples);
    const double lo = own_motion[j - 1], hi = own_motion[j];
    const double f = hi > lo ? std::clamp((goal - lo) / (hi - lo), 0.0, 1.0) : 0.0;
    // Between samples, even along the guide.
    return guide.parameter_at((1 - f) * sample_time(j - 1) + f * sample_time(j), Easing::None);
  }

  // Steps 3-4: the guide frame when every figure vertex trusts it fully,
  // otherwise guide weights where the guide's stars are valid. `exact`
  // tells which.
  std::vector<Vec2> guided_frame(const std::vector<Vec2>& g, double u, bool& exact) {
    std::vector<double> trusts(tri.figure_vertices);
    exact = true;
    for (int v = 0; v < tri.figure_vertices; ++v) {
      trusts[v] = trust_at(g, u, v);
      if (trusts[v] < 1) exact = false;
    }
    // Every figure vertex's weights reproduce g (its star is valid there)
    // and every Steiner vertex's do by construction (guide_frame), so g is
    // the solution of a system with positive weights: a valid
    // triangulation by Tutte's theorem, up to the rounding that the exact
    // check of the output frame catches.
    if (exact) return g;
    // Into storage kept between frames (mixed, offset_scratch,
    // weight_scratch): a frame's thousand small allocations were 5% of it.
    mixed.resize(std::size_t(tri.figure_vertices));
    for (int v = 0; v < tri.figure_vertices; ++v) {
      const double a = trusts[v];
      mixed[v] = wt[v];
      if (a <= 0) continue;
      // Too close to degenerate for weights: [8]'s own.
      if (!try_node_weights(topo, g, v, WeightKind::MeanValue, offset_scratch, weight_scratch)) continue;
      for (std::size_t j = 0; j < mixed[v].size(); ++j)
        mixed[v][j] = a * weight_scratch[j] + (1 - a) * wt[v][j];
    }
    std::vector<Vec2> x = tri.source;
    const bool ok = full_system.solve(
        u, [&](int v) -> const std::vector<double>& { return v < tri.figure_vertices ? mixed[v] : wt[v]; }, x);
    if (!ok) throw VerificationError("the rigid morph's blended system is singular");
    return x;
  }
};

GuidedMorph::GuidedMorph(const FigureTriangulation& normalised, const StickFigure& source,
                         const std::vector<Vec2>& target_vertices, const SimilarityMotion& similarity,
                         RigidGuide guide, WeightKind kind, Easing easing)
    : state_(std::make_unique<State>(normalised, source, similarity, std::move(guide), kind, easing)) {
  State& s = *state_;
  const FigureTriangulation& tri = s.tri;
  require_positive(tri, tri.source, "source");
  require_positive(tri, tri.target, "target");
  require_enclosure(tri);
  if (int(target_vertices.size()) != tri.figure_vertices)
    throw InvalidArgumentError("GuidedMorph: the target has " + std::to_string(target_vertices.size()) +
                               " vertices, the triangulation " + std::to_string(tri.figure_vertices));
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
  s.full_trust_margin.resize(tri.figure_vertices);
  for (int v = 0; v < tri.figure_vertices; ++v) {
    const double ends = std::min(s.star_margin(tri.source, v), s.star_margin(tri.target, v));
    // Both ends are valid triangulations, so ends > 0 unless it underflows.
    s.full_trust_margin[v] = std::max(std::min(kMostTrustMargin, 0.5 * ends), 1e-12);
  }
  auto start = Clock::now();
  s.sample_guide();
  s.stats.guide_ms += ms_since(start);
  s.count_factorizations();
  // The triangulation in output space (section 6's rotated enclosure).
  s.output = tri;
  s.output.target = similarity.apply(1.0, tri.target);
  for (int v = 0; v < tri.figure_vertices; ++v) s.output.target[v] = target_vertices[v];
  require_figure_edges(s.output, s.source);
  // The last frame is checked in full once, here: it is the real target,
  // not a solve.
  const std::string defect =
      output_defect(s.output, s.source, s.decomposition, s.output.target, -1, 1.0, FrameCheck::Full);
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
  // not: the solve refined in long double (the blended system's, or the
  // Steiner system's for the guide frame itself), then Steiner vertices of
  // inverted triangles moved into their stars' kernels. Each is checked
  // again like any frame.
  {
    start = Clock::now();
    (exact ? s.steiner_system : s.full_system).refine(normalised, kRefinementRounds);
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
