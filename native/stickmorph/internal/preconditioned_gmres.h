// GMRES (Saad & Schultz 1986) on the morph's two-coordinate systems,
// right-preconditioned with the LU factorization of a nearby system (the
// anchor), for both stateful solvers: MorphSolver (the barycentric morph,
// Algorithm 3 step 4) and GuidedMorph (the rigid morph's blended frames).
//
// Why GMRES and not iterative refinement x += LU_a^-1 (b - A x): both take
// one two-column pair of triangular solves and one product with A per step,
// but refinement's residual after k steps is (I - A LU_a^-1)^k r0, one
// element of the affine space r0 + A LU_a^-1 K_k that GMRES minimises the
// residual over, so GMRES is never slower per step; and where a few
// eigenvalues of A LU_a^-1 lie far from 1 (the long thin triangulations
// around polylines and spirals, or rows whose weights change quickly)
// refinement's rate approaches or passes 1 while GMRES still converges.
// Measured in both solvers (guided_morph.cpp, morph_solver.cpp).
//
// Each coordinate has its own Krylov space; the two preconditioner solves
// of a step are one two-column solve (CompactLU solves both coordinates
// interleaved).
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <vector>

#include "stickmorph/internal/compact_lu.h"

namespace stickmorph::internal {

/// Storage of preconditioned_gmres, kept between calls so that a frame
/// allocates nothing once the first has run.
struct GmresWorkspace {
  struct Krylov {
    Eigen::MatrixXd v, z, h;    // the basis, its preconditioned images, the Hessenberg matrix
    Eigen::VectorXd g, cs, sn;  // the rotated right-hand side and the Givens rotations
    int steps = 0;
  };
  Krylov krylov[2];        // per coordinate
  Eigen::MatrixX2d basis;  // the latest basis vector of each coordinate
  std::vector<double> estimates;  // the residual estimate after each step
};

/// Solves A x = b (#A by 2) by GMRES right-preconditioned with
/// `preconditioner` (an LU of a matrix near A), from the start x, with at
/// most `max_steps` steps, and up to one restart when rounding left the
/// true residual just above `tolerance`. Stops early when, at the rate of
/// its last two steps, the tolerance would not be met within the steps
/// left (a factorization is then cheaper than going on). `x` receives the
/// improved solution whatever the outcome; `steps` (if given) the number of
/// preconditioner solves. True iff the true residual norm of x (Frobenius,
/// both coordinates) is at most `tolerance`.
bool preconditioned_gmres(const Eigen::SparseMatrix<double>& a, const CompactLU& preconditioner,
                          const Eigen::MatrixX2d& b, Eigen::MatrixX2d& x, double tolerance, int max_steps,
                          GmresWorkspace& work, int* steps = nullptr);

}  // namespace stickmorph::internal
