// A convex-combination (Tutte) system solved frame after frame: every
// unknown node is a convex combination of its neighbours,
// x_v - sum_j w_vj x_j = 0, the other nodes known (Tutte 1963; Floater
// 1997, "Parametrization and smooth approximation of surface
// triangulations"; the paper's [8] and [17]). The weights change from one
// solve to the next, the sparsity pattern does not.
//
// A stateful solver (geometry-central style) for GuidedMorph's two systems
// (its Steiner nodes with the figure held, and all interior nodes), whose
// weights follow the guide's trust and so are given per solve rather than
// blended from two endpoints as in MorphSolver's system. The pieces both
// share are internal: factorize_checked (refactorization or SparseLU,
// compact_lu.h), preconditioned_gmres on the kept factors and
// refine_in_long_double (long_double_refinement.h). What is this system's
// own: the assembly through fixed slots, several anchors (the nearest in u
// iterated on) with a skip-after-failure policy, and the warm start from
// the span of the kept solutions nearest in u.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <cstddef>
#include <functional>
#include <vector>

#include "stickmorph/internal/compact_lu.h"
#include "stickmorph/stick_figure.h"  // Vec2
#include "stickmorph/internal/morph_topology.h"
#include "stickmorph/internal/preconditioned_gmres.h"
#include "stickmorph/internal/warm_start.h"

namespace stickmorph {
namespace internal {

/// One linear system x_v - sum_j w_vj x_j = 0 over the rows of some interior
/// nodes, the other nodes known; a fixed sparsity pattern, so the symbolic
/// factorization is done once.
class ConvexCombinationSystem {
 public:
  /// The weights of node v over topo.ring[v] (a reference that stays valid
  /// during the solve).
  using Weights = std::function<const std::vector<double>&(int v)>;

  /// `rows`: the unknown nodes, in row order. `tolerance`: the relative
  /// residual an iterative solve must reach. Keeps a reference to `topo`.
  ConvexCombinationSystem(const Topology& topo, std::vector<int> rows, double tolerance);

  int size() const { return int(nodes_.size()); }
  int node(int row) const { return nodes_[row]; }

  /// Solves with the weights weights(v) over topo.ring[v] of every row's
  /// node; `positions` supplies the known nodes and receives the solution.
  /// `u`: the morph parameter of the solve, which chooses the anchor (the
  /// kept factorization nearest in u) and the warm start (the
  /// least-squares start from the kept solutions nearest in u,
  /// warm_start.h; starting from the guide frame instead was measured to
  /// converge less often).
  /// The result depends only on the sequence of solves since construction
  /// (their u, weights and known positions) and begin_playback calls.
  /// When u never decreases after begin_playback (a playback in order) the
  /// nearest anchor is always the latest factorization and the nearest
  /// solutions the latest ones, so such a playback solves exactly as with
  /// the single anchor and the latest solutions before (issue 29).
  /// False if the system is singular (never, for positive weights).
  bool solve(double u, const Weights& weights, std::vector<Vec2>& positions);

  /// Forgets every anchor but the latest (which the next factorization
  /// then replaces) and marks the kept solutions as earlier than any to
  /// come, so that the solves that follow (a playback) choose as if they
  /// came first: GuidedMorph calls it after its set-up's
  /// solves at sampled times, whose factorizations would otherwise be
  /// nearer than the latest to some frames of a playback in order, which
  /// would then no longer be solved bit for bit as before.
  void begin_playback();

  /// Numeric factorizations so far.
  int factorizations() const { return factorizations_; }
  /// Factorizations kept now (at most kMaxAnchors).
  int anchors() const { return int(anchors_.size()); }

  /// Iterative refinement of the latest solve, whose unknowns `positions`
  /// holds: `rounds` rounds of the residual of the system as assembled
  /// accumulated in long double, corrected with the kept factors (of this
  /// system, or of a nearby one when the solve iterated on them). Leaves
  /// `positions` as it was if a correction is not finite.
  void refine(std::vector<Vec2>& positions, int rounds) const;

 private:
  /// GMRES steps before the anchor counts as too far (see the .cpp for the
  /// measurements): four, twelve where the factors fill in densely.
  static constexpr int kAnchorIterations = 4;
  static constexpr int kAnchorIterationsDense = 12;
  static constexpr int kMostSkipped = 8;
  /// Solutions a warm start combines (least_squares_start).
  static constexpr std::size_t kHistory = 6;
  /// Anchors kept (see the .cpp for the choice and the measurements): up to
  /// kMaxAnchors, and no more than kAnchorBudgetBytes of factors in all;
  /// then the least recently used one (never the one just iterated on) is
  /// factorized anew.
  static constexpr std::size_t kMaxAnchors = 16;
  static constexpr double kAnchorBudgetBytes = 256.0 * 1024 * 1024;
  /// Solutions kept for warm starts (each 16 bytes a row).
  static constexpr std::size_t kPool = 32;

  const Topology& topo_;
  std::vector<int> nodes_;
  const double tolerance_;
  std::vector<int> unknown_;
  Eigen::SparseMatrix<double> a_;   // the fixed pattern; values rewritten by each solve
  std::vector<int> diagonal_slot_;  // row -> index of its diagonal in a_'s values
  std::vector<int> ring_start_;     // row -> its first entry in slot_
  std::vector<int> slot_;           // per row and ring neighbour: index in a_'s values, or -1 (known)
  Eigen::MatrixX2d b_;
  bool analysed_ = false;
  bool factorized_ = false;
  int skipped_ = 0;            // solves left that factorize without trying the iteration
  int failures_in_a_row_ = 0;  // iterations that did not converge since the last that did
  int factorizations_ = 0;
  // Solutions kept for the warm starts (least_squares_start, warm_start.h),
  // in the order solved: each with its parameter u, its place in that
  // order, and whether it came before begin_playback (then it is chosen
  // only when fewer than kHistory later ones exist, the latest first).
  struct Kept {
    KeptSolution solution;
    long order = 0;
    bool before_playback = false;
  };
  std::vector<Kept> pool_;
  long solves_ = 0;
  void keep_solution(double u, const Eigen::MatrixX2d& x);
  std::vector<const KeptSolution*> nearest_solutions(double u) const;
  LeastSquaresStartStorage warm_start_storage_;
  GmresWorkspace gmres_;  // preconditioned_gmres's storage
  SymmetricOrderedLU lu_;
  // A factorization (lu_'s as plain columns, for the solves) at its u.
  struct Anchor {
    double u = 0;
    long used = 0;  // solves_ when last iterated on or made
    bool before_playback = false;  // the set-up's latest, kept by begin_playback
    CompactLU factors;
  };
  std::vector<Anchor> anchors_;
  std::size_t current_ = 0;  // the anchor of the latest solve: refine's
  std::size_t choose_anchor(double u) const;
  std::size_t free_anchor_slot();
};

}  // namespace internal
}  // namespace stickmorph
