// The morph's linear system at any time t; see morph_solver.h.
#include "stickmorph/morph_solver.h"

#include <Eigen/Dense>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "stickmorph/errors.h"
#include "stickmorph/internal/barycentric_weights.h"
#include "stickmorph/internal/compact_lu.h"
#include "stickmorph/internal/long_double_refinement.h"
#include "stickmorph/internal/morph_topology.h"
#include "stickmorph/internal/preconditioned_gmres.h"
#include "stickmorph/internal/solution_space.h"
#include "stickmorph/internal/stopwatch.h"
#include "stickmorph/internal/warm_start.h"

namespace stickmorph {
namespace {

using namespace internal;
using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major, as SparseLU wants
using LongVector = LongMatrixX2;  // long_double_refinement.h

using LU = SymmetricOrderedLU;  // compact_lu.h

/// (I - W_interior(t)) x = W_boundary(t) x_boundary for every t, with the
/// two endpoint matrices assembled on one sparsity pattern so that a frame
/// blends their value arrays and reuses one symbolic factorization.
///
/// Solver choice, measured (Release, g++ 12, one core; twisted polar webs of
/// radius 8 to 64, 50 frames, mean value weights; per interior frame; "err"
/// is the largest coordinate difference from the direct solve):
///   unknowns   SparseLU+COLAMD,     SparseLU with   BiCGSTAB warm start    exact checks
///              symbolic once        symbolic each   (Jacobi, tol 1e-13)    (verify)
///        113   0.125 ms             0.24 ms         0.036 ms, err 3e-13    0.61 ms
///        481   0.89 ms              1.37 ms         0.31 ms,  err 7e-12    2.8 ms
///       1985   5.4 ms               7.1 ms          2.9 ms,   err 5e-11    12 ms
///       8065   37 ms                47 ms           27 ms,    err 3e-10    53 ms
/// (BiCGSTAB with IncompleteLUT was slower than both LU variants; AMD and
/// natural orderings given to SparseLU as column orderings gave 1.1-4 times
/// the fill of COLAMD and up to 11 times the time. AMD applied to rows and
/// columns alike fills less than COLAMD and factorizes 1.3-2.9 times
/// faster, so the factorizations are now SymmetricOrderedLU's, see
/// compact_lu.h; the table predates it.) On the long thin triangulations around polylines and trees
/// neither helps much: a numeric refactorization costs nearly a fresh LU
/// there, and diagonally preconditioned BiCGSTAB converges slowly (up to 7
/// times slower, benchmark_morph); BiCGSTAB preconditioned with a nearby
/// frame's LU needs two preconditioner solves per column and step, and costs
/// about what a factorization does. What is fast everywhere: iterative
/// refinement on the LU of a nearby frame (the anchor), from the previous
/// frame's solution, both coordinates per solve. Consecutive systems differ
/// only by the blend, so it converges in a step or two; when it needs more
/// than kAnchorIterations the frame is factorized and becomes the new
/// anchor. An iterative result is never trusted on its own: every frame is
/// verified exactly, and one that fails is solved directly at its own time
/// (the factorization that the long double refinement then reuses).
///
/// Issue 15 (a frame at most a tenth of a fresh LU): at 10^3 vertices one
/// triangular solve pair already costs about a twentieth of a fresh LU
/// (factorizing these planar systems is cheap), and the iteration above took
/// 4-5 steps per frame of a 50-frame morph, with a factorization every few
/// frames (benchmark_morph, before this: frame / fresh LU 0.3-1.05 over the
/// families). Three additions, each measured there: (1) the Galerkin
/// projection onto the space of earlier solutions, accepted without a step
/// when its residual meets the tolerance, otherwise the warm start
/// (with the quadratic and linear extrapolation through the latest three
/// solutions and the nearest one: the least residual wins); (2) up to 16
/// factorizations kept (within kAnchorBudgetBytes), the nearest in time
/// iterated on, so that a random scrub stops refactorizing (at 10^3
/// vertices, 240 random times: 211 factorizations with one anchor, 11 with
/// sixteen); (3) the factors copied into plain compressed columns for the
/// solves (CompactLU). A block Krylov space of A_a^-1 (A1 - A0) at each
/// anchor (moment matching) was tried and dropped: accurate only within
/// about 0.1 of the anchor, and its solves cost more than they saved.
///
/// The moment space (build_moment_space, with its measurements) replaced
/// what bounded a single playback in order, described next: at 10^3
/// vertices it projects every frame (or all but a few) of five of the
/// seven benchmark families without a step. With one space per coordinate
/// (a quarter of the projection's cost, half the setup's) and nine levels,
/// frame / fresh LU went from 0.18-0.44 to 0.10-0.22 there, from 0.41 to
/// 0.24 on the polygon and from 0.44 to 0.40 on the spiral (whose solution
/// the moments span least); in the five, about four fifths of a frame is
/// now the setup's three factorizations and 30 solves, amortised over the
/// 48 frames. The anchors' iteration is GMRES (preconditioned_gmres.h)
/// rather than refinement: 10 factorizations instead of 13 on the spiral,
/// 5 instead of 11 on the polygon. Factorizations after the first are
/// static-pivot refactorizations on the latest anchor's structure
/// (CompactLU::refactorize; see factorize): the setup's two cost a quarter
/// of what SparseLU's did, and frame / fresh LU went to 0.09-0.21 in the
/// five families, 0.19 on the polygon and 0.33 on the spiral.
///
/// What bounded a frame of a single playback in order before (measured at 10^3
/// vertices, 48 frames): one triangular solve pair costs 0.02 ms and a
/// residual 0.02 ms, but a numeric factorization about as much as the fresh
/// LU itself, and a frame starts five to eight digits short of the
/// tolerance: the playback has not yet visited its time, so every guess is
/// an extrapolation (the polynomial through the latest three solutions
/// misses by about 1e6 tolerances, the space's projection by 5-30), and
/// each step on an anchor one frame behind gains about 1.5 digits. Two
/// alternatives were built and measured there and dropped: the anchor's
/// corrections added to the space as well (recycled FOM: 1-2 steps per
/// frame, but the space filled with 160 columns whose upkeep cost more
/// than the steps saved, frame / fresh LU 0.5-1.9) and a minimal-residual
/// iteration over the latest four solutions and the corrections only (no
/// lasting space: 5 steps per frame, 0.36-0.68). Scrubbing, or a second
/// playback, is where the space pays: its times are interpolated, and most
/// frames are projected (at 10^4 vertices, a playback then a scrub of 240
/// frames each: 251 of 476 frames without a step, 3 factorizations).
class MorphSystem {
 public:
  MorphSystem(const FigureTriangulation& tri, WeightKind kind)
      : tri_(tri),
        topo_(build_topology(tri)),
        space_(a0_, a1_, b0_, b1_, SolutionSpace::capacity_for(int(topo_.interior_nodes.size()))) {
    require_positive(tri, tri.source, "source");
    require_positive(tri, tri.target, "target");
    require_enclosure(tri);
    const int m = int(topo_.interior_nodes.size());
    for (int side = 0; side < 2; ++side) {
      const std::vector<Vec2>& positions = side ? tri.target : tri.source;
      std::vector<Eigen::Triplet<double>> triplets;
      LongVector rhs = LongVector::Zero(m, 2);
      for (int row = 0; row < m; ++row) {
        const int v = topo_.interior_nodes[row];
        const std::vector<double> w = node_weights(tri, topo_, positions, v, kind);
        triplets.emplace_back(row, row, 1.0);
        for (std::size_t j = 0; j < w.size(); ++j) {
          const int u = topo_.ring[v][j];
          if (topo_.unknown[u] >= 0) {
            triplets.emplace_back(row, topo_.unknown[u], -w[j]);
          } else {
            // The enclosure is the same in both embeddings and fixed.
            rhs(row, 0) += static_cast<long double>(w[j]) * tri.source[u][0];
            rhs(row, 1) += static_cast<long double>(w[j]) * tri.source[u][1];
          }
        }
      }
      SparseMatrix& A = side ? a1_ : a0_;
      A.resize(m, m);
      A.setFromTriplets(triplets.begin(), triplets.end());
      A.makeCompressed();
      (side ? b1_ : b0_) = rhs;
    }
    // Same rows, same neighbours: the compressed structures coincide.
    if (a0_.nonZeros() != a1_.nonZeros() ||
        !std::equal(a0_.innerIndexPtr(), a0_.innerIndexPtr() + a0_.nonZeros(), a1_.innerIndexPtr()) ||
        !std::equal(a0_.outerIndexPtr(), a0_.outerIndexPtr() + m + 1, a1_.outerIndexPtr()))
      throw InternalError("morph: the source and target systems have different sparsity patterns");
    a_ = a0_;
    lu_.analyzePattern(a_);
  }

  int unknowns() const { return int(topo_.interior_nodes.size()); }
  /// Numeric factorizations so far.
  int factorizations() const { return factorizations_; }

  /// Blends the system to time t and factorizes it. False if singular
  /// (it never is for positive weights: I - W_interior is then an
  /// irreducibly diagonally dominant M-matrix).
  ///
  /// Unless `pivoting`, a factorization after the first is first tried as
  /// a static-pivot refactorization on the latest anchor's structure
  /// (CompactLU::refactorize: 0.1-0.6 of SparseLU's numeric factorization
  /// on factors that fill in sparsely, see refactorization_pays; SparseLU
  /// repeats its symbolic work and pivot search every time), kept only if
  /// its solution at t meets the iteration's tolerance; otherwise, and with `pivoting` (solve_directly, which is
  /// solve_morph_frame bit for bit), SparseLU factorizes.
  bool factorize(double t, bool pivoting = false) {
    t_ = t;
    blend(t);
    // The latest anchor's structure, copied: the anchor itself stays.
    const bool refactorize = !pivoting && !anchors_.empty() && anchors_[current_].factors->refactorization_pays();
    auto factors = refactorize ? std::make_unique<CompactLU>(*anchors_[current_].factors) : std::make_unique<CompactLU>();
    if (!factorize_checked(a_, rhs().cast<double>(), 1e-10, refactorize, lu_, *factors)) return false;
    ++factorizations_;
    // A new anchor while there is room, else the least recently used one
    // is replaced.
    std::size_t slot = anchors_.size();
    if (anchors_.size() < kMaxAnchors &&
        (anchors_.empty() || double(anchors_.size() + 1) * anchor_bytes() <= kAnchorBudgetBytes)) {
      anchors_.push_back({t, 0, nullptr});
    } else {
      slot = 0;
      for (std::size_t i = 1; i < anchors_.size(); ++i)
        if (anchors_[i].used < anchors_[slot].used) slot = i;
    }
    Anchor& anchor = anchors_[slot];
    anchor.t = t;
    anchor.used = ++clock_;
    anchor.factors = std::move(factors);
    current_ = slot;
    return true;
  }

  /// Blends the matrix to time t (kept while t does not change).
  void blend(double t) {
    if (blended_ && t == blended_t_) return;
    const double* v0 = a0_.valuePtr();
    const double* v1 = a1_.valuePtr();
    double* v = a_.valuePtr();
    for (Eigen::Index e = 0; e < a_.nonZeros(); ++e) v[e] = (1 - t) * v0[e] + t * v1[e];
    blended_ = true;
    blended_t_ = t;
  }

  /// The residual norm of x for the system blended to time t (blend(t)
  /// first), into `residual`.
  double residual(const Eigen::MatrixX2d& b, const Eigen::MatrixX2d& x, Eigen::MatrixX2d& residual) const {
    residual.noalias() = b - a_ * x;
    return residual.allFinite() ? residual.norm() : std::numeric_limits<double>::infinity();
  }

  /// Makes the factorization nearest in time to t the anchor (the latest on
  /// a tie). False if there is none.
  bool choose_anchor(double t) {
    if (anchors_.empty()) return false;
    std::size_t best = current_;
    for (std::size_t i = 0; i < anchors_.size(); ++i)
      if (std::abs(anchors_[i].t - t) < std::abs(anchors_[best].t - t)) best = i;
    current_ = best;
    anchors_[best].used = ++clock_;
    return true;
  }

  /// Sets up the right-hand side and the matrix of time t for residual(),
  /// space_guess() and iterate().
  void prepare(double t) {
    t_ = t;
    blend(t);
    b_ = rhs().cast<double>();
    // Positions to about ten digits: far finer than any animation needs, and
    // every frame is verified exactly whatever the residual.
    tolerance_ = 1e-10 * std::max(b_.norm(), 1e-300);
  }
  /// The residual norm of x at the prepared time, into r.
  double residual(const Eigen::MatrixX2d& x, Eigen::MatrixX2d& r) const { return residual(b_, x, r); }
  /// A residual at which the projection onto the space is taken as it is,
  /// without a step: the iteration's own tolerance, so every frame meets the
  /// same residual bound. (A tenth of it, as before, was never met by a
  /// projection: its residual levels off at a few tenths of the tolerance
  /// once the space spans the morph, measured at 10^3 and 10^4 vertices.)
  double accept_tolerance() const { return tolerance_; }
  /// A projection this close to the tolerance is nearly in the space: once
  /// the space is half full its frame's solution no longer joins it (one
  /// step on the anchor recovers such a frame, while each column costs
  /// O(m k) in every later frame and brings the space nearer to full, after
  /// which nothing joins).
  double near_tolerance() const { return 10 * tolerance_; }

  /// GMRES right-preconditioned with the last factorization (the anchor),
  /// from x, at the prepared time (preconditioned_gmres.h). Consecutive
  /// systems differ only by the blend, so the anchor's inverse is close to
  /// this system's and each step gains digits. False if the residual does
  /// not drop below the tolerance within kAnchorIterations steps, or if at
  /// the rate of its last steps it would not: the anchor is too far, and the
  /// caller factorizes at t instead. `steps` counts the preconditioner
  /// solves (two-column pairs of triangular solves).
  bool iterate(Eigen::MatrixX2d& x, int& steps) {
    return preconditioned_gmres(a_, lu(), b_, x, tolerance_, kAnchorIterations, gmres_, &steps);
  }
  /// Steps after which an anchor counts as too far from the frame.
  static constexpr int kAnchorIterations = 8;

  /// The space of the moments and earlier solutions (solution_space.h):
  /// each coordinate of every solution whose projection was not near the
  /// tolerance (near_tolerance) joins it (the singular values of 201
  /// solutions over [0, 1] fall below 1e-11 of the first after 30 to 70
  /// vectors across the benchmark's families, at 10^3 vertices).
  bool space_guess(double t, Eigen::MatrixX2d& x) const { return space_.guess(t, x); }
  void add_to_space(const Eigen::MatrixX2d& x) { space_.add(x); }

  /// The moment space: at each of kMomentAnchors times t_a in [0, 1] (a
  /// factorization each, kept as an anchor), the solution x(t_a) and its
  /// first kMomentLevels derivatives in t (SolutionSpace::add_moments), so
  /// that the projection interpolates x over all of [0, 1] rather than
  /// extrapolating from the times already played: measured at 10^3
  /// vertices (48 frames of 50, one space for both coordinates), every frame of the polyline, tree, triangulation,
  /// thinned and rings families projected within 0.06 of the tolerance,
  /// the polygon within 101 times it and the spiral (whose solution varies
  /// fastest) within 1e8 times it, against 40-1e9 times it for the space of
  /// earlier solutions in a playback; with a space per coordinate the same
  /// five project every frame, the polygon 30 of 48 and the spiral 15.
  /// (Two anchors with twelve levels left the triangulation 17 times the
  /// tolerance short, five with eight cost more columns than they saved.)
  /// Frames that it does not span are iterated on the nearest of the
  /// anchors, and their solutions join the space as before.
  void build_moment_space() {
    const Eigen::MatrixX2d db = (b1_ - b0_).cast<double>();
    for (int i = 0; i < kMomentAnchors; ++i) {
      const double ta = kMomentAnchors == 1 ? 0.5 : double(i) / (kMomentAnchors - 1);
      if (!factorize(ta)) throw VerificationError("the morph system at t = " + format_double(ta) + " is singular");
      space_.add_moments(lu(), solve(), db, kMomentLevels);
    }
  }
  static constexpr int kMomentAnchors = 3;
  /// Nine, measured at 10^3 vertices against eight and ten (frame / fresh
  /// LU): eight left the polyline's and the rings' frames short of the
  /// tolerance (65 and 9 GMRES steps), ten cost more in the setup than it
  /// gained (polyline 0.20 against 0.17, thinned 0.12 against 0.10).
  static constexpr int kMomentLevels = 9;

  /// Past half the capacity, a frame projected near the tolerance no longer
  /// adds its solution (near_tolerance).
  bool space_half_full() const { return space_.half_full(); }
  /// Columns of both coordinates' spaces (at most their capacity each).
  int space_size() const { return space_.size(); }

  /// Interior coordinates in the source embedding: the first warm start.
  Eigen::MatrixX2d source_coordinates() const {
    Eigen::MatrixX2d x(unknowns(), 2);
    for (int row = 0; row < unknowns(); ++row) {
      x(row, 0) = tri_.source[topo_.interior_nodes[row]][0];
      x(row, 1) = tri_.source[topo_.interior_nodes[row]][1];
    }
    return x;
  }

  /// Solves the factorized system; x holds the interior coordinates.
  Eigen::MatrixX2d solve() const {
    const Eigen::MatrixX2d b = rhs().cast<double>();
    return lu().solve(b);
  }

  /// Iterative refinement: residuals of the blended system computed in long
  /// double from the endpoint values (so the blend itself is not rounded to
  /// double), corrections solved with the double factorization
  /// (long_double_refinement.h). A correction that is not finite ends the
  /// rounds, keeping those before it.
  Eigen::MatrixX2d refine(double time, const Eigen::MatrixX2d& start, int rounds) const {
    const long double t = time;
    LongVector x = start.cast<long double>();
    const LongVector b = (1 - t) * b0_ + t * b1_;
    const double* v0 = a0_.valuePtr();
    const double* v1 = a1_.valuePtr();
    refine_in_long_double(
        a0_, [&](Eigen::Index e) -> long double { return (1 - t) * v0[e] + t * v1[e]; }, b, lu(), x, rounds);
    return x.cast<double>();
  }

  /// All node positions with the interior coordinates x.
  std::vector<Vec2> positions(const Eigen::MatrixX2d& x) const {
    std::vector<Vec2> p = tri_.source;  // enclosure nodes stay put
    for (int row = 0; row < unknowns(); ++row) p[topo_.interior_nodes[row]] = {x(row, 0), x(row, 1)};
    return p;
  }

 private:
  LongVector rhs() const {
    const long double t = t_;
    return (1 - t) * b0_ + t * b1_;
  }

  const FigureTriangulation& tri_;
  Topology topo_;
  SparseMatrix a0_, a1_, a_;
  LongVector b0_, b1_;
  double t_ = 0;
  Eigen::MatrixX2d b_;   // the right-hand side at the prepared time
  double tolerance_ = 0;  // the iteration's residual tolerance there
  SolutionSpace space_;  // refers to a0_, a1_, b0_ and b1_
  bool blended_ = false;  // a_ holds the blend at blended_t_
  double blended_t_ = 0;
  /// Factorizations kept, each at its time: a scrub back and forth finds one
  /// near every time it asks, a playback in order uses the latest. Up to
  /// kMaxAnchors and kAnchorBudgetBytes for all, then the least recently
  /// used is factorized anew.
  struct Anchor {
    double t;
    long used;
    std::unique_ptr<CompactLU> factors;
  };
  LU lu_;  // analysed once; factorizes every anchor, whose factors it copies
  static constexpr std::size_t kMaxAnchors = 16;
  static constexpr double kAnchorBudgetBytes = 512.0 * 1024 * 1024;
  /// About what one anchor holds: its L and U nonzeros, value and index.
  double anchor_bytes() const {
    return 12.0 * double(anchors_.front().factors->nonzeros());
  }
  std::vector<Anchor> anchors_;
  std::size_t current_ = 0;  // the anchor of the iteration and refinement
  GmresWorkspace gmres_;     // iterate()'s storage
  long clock_ = 0;
  int factorizations_ = 0;
  const CompactLU& lu() const { return *anchors_[current_].factors; }
};

}  // namespace

struct MorphSolver::State {
  State(const FigureTriangulation& triangulation, WeightKind kind) : tri(triangulation), system(tri, kind) {}
  const FigureTriangulation tri;  // before `system`, which refers to it
  MorphSystem system;
  Eigen::MatrixX2d start;  // the interior coordinates of the source: the first warm start
  // The last kHistory solutions and their times, the latest last: the warm
  // starts of the next solve().
  static constexpr std::size_t kHistory = 3;
  std::vector<KeptSolution> history;  // warm_start.h
  Eigen::MatrixX2d x;  // the last solution
  double last_t = 0;   // its time
  bool solved = false;
  bool anchored = false;        // a factorization exists to iterate on
  bool moment_space = false;    // build_moment_space has run
  bool last_factorized = false;
  MorphSolverStats stats;

  // The direct factorization of the system at t, into x.
  void factorize_and_solve(double t, bool pivoting = false) {
    auto begin = Clock::now();
    if (!system.factorize(t, pivoting))
      throw VerificationError("the morph system at t = " + format_double(t) + " is singular");
    stats.factorize_ms += ms_since(begin);
    begin = Clock::now();
    x = system.solve();
    stats.solve_ms += ms_since(begin);
    ++stats.factorizations;
    last_factorized = true;
    solved = true;
  }

  // Records the last solution x at t as a warm start.
  void remember(double t) {
    ++stats.solves;
    last_t = t;
    for (auto it = history.begin(); it != history.end(); ++it)
      if (it->t == t) {
        history.erase(it);
        break;
      }
    if (history.size() == kHistory) history.erase(history.begin());
    history.push_back({t, x});
  }

  // Warm starts for t, best first on a tie: the polynomial through the
  // latest solutions at distinct times evaluated at t (quadratic through
  // three, linear through two) and the remembered solution nearest in time
  // (extrapolated_starts, warm_start.h); before any solve, the source.
  // solve() starts from the one of least residual.
  std::vector<Eigen::MatrixX2d> warm_starts(double t) const {
    if (history.empty()) return {start};
    return extrapolated_starts(history, t);
  }
};

namespace {
void check_time(double t) {
  if (!(t >= 0 && t <= 1)) throw InvalidArgumentError("the morph time must be in [0, 1]");
}
}  // namespace

MorphSolver::MorphSolver(const FigureTriangulation& triangulation, WeightKind kind)
    : state_(std::make_unique<State>(triangulation, kind)) {
  state_->start = state_->system.source_coordinates();
}
MorphSolver::~MorphSolver() = default;
MorphSolver::MorphSolver(MorphSolver&&) noexcept = default;
MorphSolver& MorphSolver::operator=(MorphSolver&&) noexcept = default;

int MorphSolver::unknowns() const { return state_->system.unknowns(); }

std::vector<Vec2> MorphSolver::solve(double t) {
  check_time(t);
  State& s = *state_;
  s.last_factorized = false;
  // A time among the latest solved: the same positions again, bit for bit.
  for (const auto& entry : s.history)
    if (entry.t == t) {
      s.x = entry.x;
      s.remember(t);
      return s.system.positions(s.x);
    }
  bool solved = false, projected = false;
  double projection = std::numeric_limits<double>::infinity();  // its residual
  if (!s.moment_space) {
    // The first solve builds the moment space and its anchors, whatever t
    // (so that the result depends only on the times asked).
    const auto begin = Clock::now();
    const int before = s.system.factorizations();
    s.system.build_moment_space();
    s.stats.factorizations += s.system.factorizations() - before;
    s.stats.factorize_ms += ms_since(begin);
    s.moment_space = s.anchored = true;
  }
  {
    const auto begin = Clock::now();
    s.system.choose_anchor(t);
    s.system.prepare(t);
    // 1. The projection onto the space of earlier solutions, taken as it is
    //    when its residual is small enough: no triangular solve at all.
    Eigen::MatrixX2d r;
    double best = std::numeric_limits<double>::infinity();
    if (s.system.space_guess(t, s.x)) best = s.system.residual(s.x, r);
    projection = best;
    if (best <= s.system.accept_tolerance()) {
      solved = projected = true;
    } else {
      // 2. Iteration on the anchor from the best warm start: that
      //    projection, the extrapolations or the nearest solution.
      bool started = std::isfinite(best);
      for (Eigen::MatrixX2d& guess : s.warm_starts(t)) {
        const double norm = s.system.residual(guess, r);
        if (!(norm >= best)) {
          best = norm;
          s.x.swap(guess);
          started = true;
        }
      }
      int steps = 0;
      solved = started && s.x.rows() == s.system.unknowns() && s.system.iterate(s.x, steps);
      s.stats.iterations += steps;
    }
    s.stats.solve_ms += ms_since(begin);
  }
  // 3. A factorization at t, the new anchor.
  if (!solved) s.factorize_and_solve(t);
  if (projected) {
    ++s.stats.projected;
  } else if (!s.system.space_half_full() || !(projection <= s.system.near_tolerance())) {
    const auto begin = Clock::now();
    s.system.add_to_space(s.x);
    s.stats.solve_ms += ms_since(begin);
  }
  s.anchored = true;
  s.solved = true;
  s.remember(t);
  return s.system.positions(s.x);
}

std::vector<Vec2> MorphSolver::solve_directly(double t) {
  check_time(t);
  state_->factorize_and_solve(t, true);
  state_->system.add_to_space(state_->x);
  state_->anchored = true;
  state_->remember(t);
  return state_->system.positions(state_->x);
}

std::vector<Vec2> MorphSolver::refine(int rounds) {
  State& s = *state_;
  if (!s.solved) throw InvalidArgumentError("MorphSolver::refine needs a solve first");
  const auto begin = Clock::now();
  std::vector<Vec2> positions = s.system.positions(s.system.refine(s.last_t, s.x, rounds));
  s.stats.solve_ms += ms_since(begin);
  return positions;
}

bool MorphSolver::last_solve_factorized() const { return state_->last_factorized; }

const MorphSolverStats& MorphSolver::stats() const { return state_->stats; }

void check_morph_triangulation(const FigureTriangulation& triangulation) {
  (void)internal::build_topology(triangulation);
}

}  // namespace stickmorph
