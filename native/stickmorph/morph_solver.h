// The morph's linear system at any time t, solved repeatedly (Algorithm 3,
// step 4; Floater & Gotsman 1999, the paper's [8], summarised in section
// 2.2).
//
// [8]: with W0 and W1 the convex-combination weights of the source and the
// target, the triangulation at time t is the solution of
// (I - W_interior(t)) x = W_boundary(t) x_boundary, W(t) = (1 - t) W0 + t W1,
// the enclosure held fixed. A valid triangulation with the same
// connectivity for every t (Tutte's theorem: W(t) is positive and
// row-stochastic).
//
// A solver for repeated solves (as in geometry-central's): constructed once
// from a triangulation and a weight kind (the weights, the two endpoint
// matrices on one sparsity pattern, their symbolic factorization), then
// solve(t) for any t in [0, 1], in any order, e.g. for scrubbing through a
// morph. The first solve builds a reduced basis for all of [0, 1] (the
// moment space: factorizations at t = 0, 1/2 and 1, and at each the
// solution's first derivatives in t); every solve is then first projected
// onto that space and the earlier solutions (x(t) is analytic in t, so a
// few dozen vectors span it to many digits), taken as it is when its
// residual is small enough; otherwise GMRES preconditioned by the LU
// factorization nearest in time (an anchor) starts from the best warm
// start (that projection, the polynomial through the latest solutions, or
// the nearest one), and the solver factorizes anew only when that anchor
// is too far.
#pragma once

#include <memory>
#include <vector>

#include "stickmorph/figure_triangulation.h"
#include "stickmorph/morph.h"

namespace stickmorph {

/// The form check a MorphSolver starts with (morph_topology.h): a
/// triangulation of a disk bounded by its enclosure, every node's fan
/// whole. For callers that read the first figure_vertices nodes as a figure
/// before making a solver (stickmorph.MorphSolver): the message names what
/// is malformed instead of a figure error it would cause.
/// @throws InvalidArgumentError naming the node, triangle or side.
void check_morph_triangulation(const FigureTriangulation& triangulation);

/// What a MorphSolver spent, accumulated over its life.
struct MorphSolverStats {
  double factorize_ms = 0;  ///< numeric LU factorizations (and blending the matrix for them), the moment space
  double solve_ms = 0;      ///< iterations on the anchor, triangular solves, long double refinement
  int factorizations = 0;   ///< numeric LU factorizations
  int solves = 0;           ///< solve() and solve_directly() calls that returned
  int iterations = 0;       ///< GMRES steps on an anchor (one pair of triangular solves each)
  int projected = 0;        ///< solve() calls answered by the space of earlier solutions, no triangular solve
};

class MorphSolver {
 public:
  /// Computes both embeddings' weights and assembles the systems. Keeps its
  /// own copy of `triangulation`.
  /// @throws InvalidArgumentError as morph_triangulation does for a
  ///         malformed or invalid triangulation.
  MorphSolver(const FigureTriangulation& triangulation, WeightKind kind = WeightKind::MeanValue);
  ~MorphSolver();
  MorphSolver(MorphSolver&&) noexcept;
  MorphSolver& operator=(MorphSolver&&) noexcept;

  /// Interior (figure and Steiner) nodes: the unknowns of the system.
  int unknowns() const;

  /// All node positions at time t in [0, 1] (the enclosure's fixed). The
  /// first call builds the moment space (three factorizations, whatever t);
  /// every call projects onto the space, then if needed iterates on the
  /// nearest kept factorization, and factorizes at t when the iteration
  /// does not converge within a few steps. The result depends only on the sequence of times asked (and
  /// solve_directly calls) since construction, so two new solvers given the
  /// same times agree bit for bit; a time among the last three solved gives
  /// the same positions again. Positions to about ten digits of the
  /// exact solution (residual at most 1e-10 of the right-hand side); at t =
  /// 0 and 1 the solution, not the inputs themselves (morph_triangulation
  /// substitutes those).
  /// @throws InvalidArgumentError for t outside [0, 1]; VerificationError
  ///         if the system is singular (it never is for positive weights).
  std::vector<Vec2> solve(double t);

  /// All node positions at time t from a fresh factorization at t, which
  /// becomes an anchor; the solution joins the earlier ones that solve()
  /// starts from.
  /// @throws as solve().
  std::vector<Vec2> solve_directly(double t);

  /// The last solution (of solve or solve_directly) improved by `rounds`
  /// rounds of iterative refinement: residuals of the blended system in
  /// long double from the endpoint values (so the blend itself is not
  /// rounded to double), corrections from the anchor the last solve used
  /// (after solve_directly, its own factorization).
  /// @throws InvalidArgumentError if nothing was solved yet.
  std::vector<Vec2> refine(int rounds);

  /// Whether the last solve() or solve_directly() factorized at its own
  /// time, so that its result is the direct solution there (the moment
  /// space's factorizations, at other times, do not count).
  bool last_solve_factorized() const;

  const MorphSolverStats& stats() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace stickmorph
