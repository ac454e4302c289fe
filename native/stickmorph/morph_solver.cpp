// The morph's linear system at any time t; see morph_solver.h.
#include "stickmorph/morph_solver.h"

#include <Eigen/SparseLU>

#include <algorithm>

#include "stickmorph/errors.h"
#include "stickmorph/internal/barycentric_weights.h"
#include "stickmorph/internal/morph_topology.h"
#include "stickmorph/internal/stopwatch.h"

namespace stickmorph {
namespace {

using namespace internal;
using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major, as SparseLU wants
using LongVector = Eigen::Matrix<long double, Eigen::Dynamic, 2>;

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
/// natural orderings gave 1.1-4 times the fill of COLAMD and up to 11 times
/// the time.) On the long thin triangulations around polylines and trees
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
class MorphSystem {
 public:
  MorphSystem(const FigureTriangulation& tri, WeightKind kind) : tri_(tri), topo_(build_topology(tri)) {
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

  /// Blends the system to time t and factorizes it. False if singular
  /// (it never is for positive weights: I - W_interior is then an
  /// irreducibly diagonally dominant M-matrix).
  bool factorize(double t) {
    t_ = t;
    const double* v0 = a0_.valuePtr();
    const double* v1 = a1_.valuePtr();
    double* v = a_.valuePtr();
    for (Eigen::Index e = 0; e < a_.nonZeros(); ++e) v[e] = (1 - t) * v0[e] + t * v1[e];
    lu_.factorize(a_);
    return lu_.info() == Eigen::Success;
  }

  /// Solves the system blended to time t by iterative refinement on the last
  /// factorization (the anchor), starting from `guess`: x += LU^-1 (b - A x),
  /// both coordinates in one pass. Consecutive systems differ only by the
  /// blend, so the anchor's inverse is close to this system's and each step
  /// gains several digits. False if the residual does not drop below the
  /// tolerance within kAnchorIterations steps: the anchor is too far, and the
  /// caller factorizes at t instead.
  bool iterate(double t, const Eigen::MatrixX2d& guess, Eigen::MatrixX2d& x) {
    t_ = t;
    const double* v0 = a0_.valuePtr();
    const double* v1 = a1_.valuePtr();
    double* v = a_.valuePtr();
    for (Eigen::Index e = 0; e < a_.nonZeros(); ++e) v[e] = (1 - t) * v0[e] + t * v1[e];
    const Eigen::MatrixX2d b = rhs().cast<double>();
    // Positions to about ten digits: far finer than any animation needs, and
    // every frame is verified exactly whatever the residual.
    const double tolerance = 1e-10 * std::max(b.norm(), 1e-300);
    x = guess;
    for (int step = 0; step < kAnchorIterations; ++step) {
      const Eigen::MatrixX2d residual = b - a_ * x;
      if (!residual.allFinite()) return false;
      if (residual.norm() <= tolerance) return true;
      x += lu_.solve(residual);
    }
    return (b - a_ * x).norm() <= tolerance && x.allFinite();
  }
  /// Steps after which an anchor counts as too far from the frame.
  static constexpr int kAnchorIterations = 8;

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
    return lu_.solve(b);
  }

  /// Iterative refinement: residuals of the blended system computed in long
  /// double from the endpoint values (so the blend itself is not rounded to
  /// double), corrections solved with the double factorization.
  Eigen::MatrixX2d refine(const Eigen::MatrixX2d& start, int rounds) const {
    const long double t = t_;
    LongVector x = start.cast<long double>();
    const LongVector b = rhs();
    for (int round = 0; round < rounds; ++round) {
      LongVector r = b;
      for (int col = 0; col < a0_.outerSize(); ++col)
        for (Eigen::Index e = a0_.outerIndexPtr()[col]; e < a0_.outerIndexPtr()[col + 1]; ++e) {
          const int row = a0_.innerIndexPtr()[e];
          const long double a = (1 - t) * a0_.valuePtr()[e] + t * a1_.valuePtr()[e];
          r(row, 0) -= a * x(col, 0);
          r(row, 1) -= a * x(col, 1);
        }
      const Eigen::MatrixX2d correction = lu_.solve(Eigen::MatrixX2d(r.cast<double>()));
      if (!correction.allFinite()) break;
      x += correction.cast<long double>();
    }
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
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace

struct MorphSolver::State {
  State(const FigureTriangulation& triangulation, WeightKind kind) : tri(triangulation), system(tri, kind) {}
  const FigureTriangulation tri;  // before `system`, which refers to it
  MorphSystem system;
  Eigen::MatrixX2d guess;  // warm start of the next solve(): the previous solve()'s solution
  Eigen::MatrixX2d x;      // the last solution
  bool solved = false;
  bool anchored = false;        // a factorization exists to iterate on
  bool anchor_too_far = false;  // the last iteration did not converge
  bool last_factorized = false;
  MorphSolverStats stats;

  // The direct factorization of the system at t, into x.
  void factorize_and_solve(double t) {
    auto begin = Clock::now();
    if (!system.factorize(t))
      throw VerificationError("the morph system at t = " + format_double(t) + " is singular");
    stats.factorize_ms += ms_since(begin);
    begin = Clock::now();
    x = system.solve();
    stats.solve_ms += ms_since(begin);
    ++stats.factorizations;
    last_factorized = true;
    solved = true;
  }
};

namespace {
void check_time(double t) {
  if (!(t >= 0 && t <= 1)) throw InvalidArgumentError("the morph time must be in [0, 1]");
}
}  // namespace

MorphSolver::MorphSolver(const FigureTriangulation& triangulation, WeightKind kind)
    : state_(std::make_unique<State>(triangulation, kind)) {
  state_->guess = state_->system.source_coordinates();
}
MorphSolver::~MorphSolver() = default;
MorphSolver::MorphSolver(MorphSolver&&) noexcept = default;
MorphSolver& MorphSolver::operator=(MorphSolver&&) noexcept = default;

int MorphSolver::unknowns() const { return state_->system.unknowns(); }

std::vector<Vec2> MorphSolver::solve(double t) {
  check_time(t);
  State& s = *state_;
  // The first solve is factorized; later ones iterate on the latest
  // factorization and refactorize only when it is too far. Right after an
  // iteration that did not converge, times are too far apart for the
  // anchor: factorize without trying.
  bool direct = !s.anchored || s.anchor_too_far;
  s.last_factorized = false;
  if (!direct) {
    const auto begin = Clock::now();
    direct = !s.system.iterate(t, s.guess, s.x);
    s.stats.solve_ms += ms_since(begin);
    s.anchor_too_far = direct;
    s.solved = true;
  } else {
    s.anchor_too_far = false;
  }
  if (direct) s.factorize_and_solve(t);
  s.anchored = true;
  s.guess = s.x;
  return s.system.positions(s.x);
}

std::vector<Vec2> MorphSolver::solve_directly(double t) {
  check_time(t);
  state_->factorize_and_solve(t);
  state_->anchored = true;
  return state_->system.positions(state_->x);
}

std::vector<Vec2> MorphSolver::refine(int rounds) {
  State& s = *state_;
  if (!s.solved) throw InvalidArgumentError("MorphSolver::refine needs a solve first");
  const auto begin = Clock::now();
  std::vector<Vec2> positions = s.system.positions(s.system.refine(s.x, rounds));
  s.stats.solve_ms += ms_since(begin);
  return positions;
}

bool MorphSolver::last_solve_factorized() const { return state_->last_factorized; }

const MorphSolverStats& MorphSolver::stats() const { return state_->stats; }

}  // namespace stickmorph
