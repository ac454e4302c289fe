// Morphing a compatible triangulation (Algorithm 3, step 4; Floater &
// Gotsman 1999, the paper's [8]): the frame loop with its exact checks, and
// the straight-line baseline. The pieces it uses:
//   morph_solver.h                  the linear system at any t (MorphSolver)
//   internal/barycentric_weights.h  mean value, uniform and Floater weights
//   internal/morph_topology.h       the disk and fan check, the fans
#include "stickmorph/morph.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "stickmorph/argument_limits.h"
#include "stickmorph/cancellation.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/internal/barycentric_weights.h"
#include "stickmorph/internal/morph_topology.h"
#include "stickmorph/internal/rounding_repair.h"
#include "stickmorph/internal/stopwatch.h"
#include "stickmorph/morph_solver.h"

namespace stickmorph {
namespace {

using namespace internal;

// t_f = f / (N - 1); the division makes the last time exactly 1.
std::vector<double> frame_times(int frames) {
  std::vector<double> times(frames);
  for (int f = 0; f < frames; ++f) times[f] = double(f) / double(frames - 1);
  return times;
}

void require_source_matches(const FigureTriangulation& tri, const StickFigure& source) {
  if (int(source.vertices.size()) != tri.figure_vertices)
    throw InvalidArgumentError("the figure has " + std::to_string(source.vertices.size()) +
                               " vertices, the triangulation " + std::to_string(tri.figure_vertices) +
                               " figure vertices");
  for (int v = 0; v < tri.figure_vertices; ++v)
    if (source.vertices[v] != tri.source[v])
      throw InvalidArgumentError("vertex " + std::to_string(v) +
                                 " of the figure is not at its position in the triangulation's source");
}

// The frame's defect, or empty: the certificate (frame_certificate.h: the
// enclosure convex and every triangle counter-clockwise, which proves the
// frame an embedding with the source's topology), then with FrameCheck::Full
// the independent check, verify_frame: the figure rebuilt and compared with
// the source.
std::string frame_defect(const FigureTriangulation& tri, const StickFigure& source,
                         const Decomposition& source_decomposition, const std::vector<Vec2>& positions,
                         int frame, double time, FrameCheck check) {
  const std::string defect = certificate_defect(tri, positions);
  if (!defect.empty()) return frame_label(frame, time) + ": " + defect;
  if (check == FrameCheck::Certificate) return {};
  const std::vector<Vec2> figure(positions.begin(), positions.begin() + tri.figure_vertices);
  try {
    verify_frame(source, source_decomposition, figure, frame, time);
  } catch (const VerificationError& error) {
    return error.what();
  }
  return {};
}

}  // namespace

WeightKind parse_weight_kind(const std::string& name) {
  if (name == "mvc") return WeightKind::MeanValue;
  if (name == "uniform") return WeightKind::Uniform;
  if (name == "floater") return WeightKind::Floater;
  throw InvalidArgumentError("unknown weight kind '" + name + "' (choose mvc, uniform or floater)");
}

std::string weight_kind_name(WeightKind kind) {
  switch (kind) {
    case WeightKind::MeanValue: return "mvc";
    case WeightKind::Uniform: return "uniform";
    case WeightKind::Floater: return "floater";
  }
  throw InternalError("weight_kind_name: unknown WeightKind");
}

Eigen::SparseMatrix<double, Eigen::RowMajor> barycentric_weights(const FigureTriangulation& triangulation,
                                                                 const std::vector<Vec2>& positions,
                                                                 WeightKind kind) {
  const Topology topo = build_topology(triangulation);
  if (int(positions.size()) != topo.nodes)
    throw InvalidArgumentError("barycentric_weights needs " + std::to_string(topo.nodes) + " positions, got " +
                               std::to_string(positions.size()));
  require_positive(triangulation, positions, "given positions");
  std::vector<Eigen::Triplet<double>> triplets;
  for (int v : topo.interior_nodes) {
    const std::vector<double> w = node_weights(triangulation, topo, positions, v, kind);
    for (std::size_t j = 0; j < w.size(); ++j) triplets.emplace_back(v, topo.ring[v][j], w[j]);
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> W(topo.nodes, topo.nodes);
  W.setFromTriplets(triplets.begin(), triplets.end());
  return W;
}

std::vector<Vec2> solve_morph_frame(const FigureTriangulation& triangulation, double t, WeightKind kind) {
  if (!(t >= 0 && t <= 1)) throw InvalidArgumentError("the morph time must be in [0, 1]");
  MorphSolver solver(triangulation, kind);
  return solver.solve_directly(t);
}

bool untangle_steiner_vertices(const FigureTriangulation& triangulation, std::vector<Vec2>& positions) {
  // The exact solution of [8] is an embedding, but a triangle thinner than
  // the spacing of doubles around it can flip when even the correctly
  // rounded positions are stored (the 10^4-vertex spiral: a Steiner vertex
  // next to two figure vertices where the target winds tightest, at 3e-8
  // degrees). The Steiner vertices are not part of the figure, so moving
  // one into the kernel of its star (untangle, exact) leaves the figure's
  // frame as solved and makes the triangulation an embedding again; the
  // caller checks the frame once more.
  if (int(positions.size()) != triangulation.node_count()) return false;
  std::vector<Vec2> repaired = positions;
  if (!untangle(repaired, triangulation.triangles, triangulation.figure_vertices + triangulation.enclosure_vertices))
    return false;
  positions = std::move(repaired);
  return true;
}

CheckedFrame checked_morph_frame(MorphSolver& solver, const FigureTriangulation& triangulation,
                                 const StickFigure& source, const Decomposition& source_decomposition,
                                 double t, int frame, bool verify, const std::string& context,
                                 FrameCheck check, std::optional<double> label_time) {
  const double shown = label_time.value_or(t);  // the time messages name
  // Refinement rounds for a frame that fails: each round gains roughly the
  // extra precision of long double until the result is correctly rounded;
  // beyond three it no longer changes.
  constexpr int kRefinementRounds = 3;
  // A singular system names the frame (it never is for positive weights).
  auto solve = [&](bool directly) {
    try {
      return directly ? solver.solve_directly(t) : solver.solve(t);
    } catch (const VerificationError&) {
      throw VerificationError(context + frame_label(frame, shown) + ": the morph's linear system is singular");
    }
  };
  CheckedFrame result;
  const bool endpoint = t == 0 || t == 1;
  bool direct = false;
  if (endpoint) {
    // The endpoints are the inputs themselves. The solve reproduces them
    // only up to rounding amplified by the condition number of
    // I - W_interior (the source is the fixed point of W0 in exact
    // arithmetic), while the contract (FORMAT.md) promises frames[0] is
    // the source and the last frame the target, bit for bit.
    result.positions = t == 0 ? triangulation.source : triangulation.target;
  } else {
    // Iterating on a nearby frame's factorization, refactorizing when it
    // is too far (MorphSolver::solve).
    result.positions = solve(false);
    direct = solver.last_solve_factorized();
  }
  if (!verify) return result;
  auto defect_now = [&] {
    const auto start = Clock::now();
    std::string defect =
        frame_defect(triangulation, source, source_decomposition, result.positions, frame, shown, check);
    result.verify_ms += ms_since(start);
    return defect;
  };
  std::string defect = defect_now();
  if (!defect.empty() && !endpoint && !direct) {
    // The iteration's residual can flip a nearly flat triangle: solve
    // this frame directly.
    result.positions = solve(true);
    defect = defect_now();
  }
  if (!defect.empty() && !endpoint) {
    // Rounding in the solve can flip a nearly flat triangle that is
    // positive in exact arithmetic (the theorem of [8] holds exactly).
    result.positions = solver.refine(kRefinementRounds);
    result.refined = true;
    defect = defect_now();
    if (!defect.empty() && untangle_steiner_vertices(triangulation, result.positions)) defect = defect_now();
    if (!defect.empty()) defect += " (after refinement in long double)";
  }
  if (!defect.empty()) throw VerificationError(context + defect);
  return result;
}

MorphResult morph_triangulation(const FigureTriangulation& triangulation, const StickFigure& source,
                                const MorphOptions& options) {
  return morph_triangulation(triangulation, source, decompose(source), options);
}

MorphResult morph_triangulation(const FigureTriangulation& triangulation, const StickFigure& source,
                                const Decomposition& source_decomposition, const MorphOptions& options) {
  // The interfaces check it first; the same check for direct callers.
  check_frames(options.frames, OptionSpelling::Keyword);
  MorphResult result;
  result.times = frame_times(options.frames);
  auto start = Clock::now();
  MorphSolver solver(triangulation, options.weights);
  require_source_matches(triangulation, source);
  require_figure_edges(triangulation, source);
  const double setup_ms = ms_since(start);

  result.frames.reserve(options.frames);
  for (int f = 0; f < options.frames; ++f) {
    report_progress(f, options.frames);  // and a caller's cancel stops here, between frames
    CheckedFrame frame =
        checked_morph_frame(solver, triangulation, source, source_decomposition, result.times[f], f, options.verify,
                            "morph: ", options.frame_check);
    result.stats.verify_ms += frame.verify_ms;
    if (frame.refined) ++result.stats.refined_frames;
    result.frames.push_back(std::move(frame.positions));
  }
  report_progress(options.frames, options.frames);
  result.stats.factorize_ms = setup_ms + solver.stats().factorize_ms;
  result.stats.solve_ms = solver.stats().solve_ms;
  result.stats.factorizations = solver.stats().factorizations;
  return result;
}

MorphResult linear_morph(const StickFigure& source, const StickFigure& target, int frames,
                         std::vector<int>* invalid_frames) {
  return linear_morph(source, target, frames, invalid_frames, nullptr);
}

MorphResult linear_morph(const StickFigure& source, const StickFigure& target, int frames,
                         std::vector<int>* invalid_frames, const Decomposition* source_decomposition) {
  check_frames(frames, OptionSpelling::Keyword);
  if (source.vertices.size() != target.vertices.size())
    throw InvalidArgumentError("the source has " + std::to_string(source.vertices.size()) +
                               " vertices and the target " + std::to_string(target.vertices.size()));
  MorphResult result;
  result.times = frame_times(frames);
  const std::size_t n = source.vertices.size();
  auto start = Clock::now();
  result.frames.reserve(frames);
  for (int f = 0; f < frames; ++f) {
    const double t = result.times[f];
    if (f == 0) {
      result.frames.push_back(source.vertices);
    } else if (f == frames - 1) {
      result.frames.push_back(target.vertices);
    } else {
      std::vector<Vec2> p(n);
      for (std::size_t v = 0; v < n; ++v)
        for (int c = 0; c < 2; ++c) p[v][c] = (1 - t) * source.vertices[v][c] + t * target.vertices[v][c];
      result.frames.push_back(std::move(p));
    }
  }
  result.stats.solve_ms = ms_since(start);
  if (invalid_frames) {
    start = Clock::now();
    invalid_frames->clear();
    const Decomposition own = source_decomposition ? Decomposition{} : decompose(source);
    const Decomposition& decomposition = source_decomposition ? *source_decomposition : own;
    for (int f = 0; f < frames; ++f) {
      report_progress(f, frames);  // the exact check is this morph's long part
      if (!is_frame_valid(source, decomposition, result.frames[f])) invalid_frames->push_back(f);
    }
    report_progress(frames, frames);
    result.stats.verify_ms = ms_since(start);
  }
  return result;
}

}  // namespace stickmorph