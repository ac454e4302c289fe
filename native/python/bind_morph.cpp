// The morph (Algorithm 3 end to end, through the engine's
// morph_stick_figures) and the stateful solvers for scrubbing any t
// (MorphSolver, RigidMorphSolver). Their arguments become engine options in
// morph_arguments.cpp; the limits and option rules the engine checks are
// exported by bind_options.cpp.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "bindings.h"
#include "progress_argument.h"
#include "conversions.h"
#include "morph_arguments.h"
#include "stickmorph/argument_limits.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/morph_solver.h"
#include "stickmorph/working_scale.h"
#include "stickmorph/morph_stick_figures.h"

namespace stickmorph::python {
namespace {

// The similarity the rigid method fitted, as stats["rigid"]["similarity"].
py::dict similarity_dict(const sm::SimilarityMotion& sim) {
  py::dict similarity;
  similarity["angle_degrees"] = sim.angle * 180.0 / 3.14159265358979323846;
  similarity["scale"] = sim.scale;
  similarity["source_center"] = py::make_tuple(sim.source_center[0], sim.source_center[1]);
  similarity["target_center"] = py::make_tuple(sim.target_center[0], sim.target_center[1]);
  return similarity;
}

py::dict rigid_dict(const sm::MorphStickFiguresStats& stats, const sm::MorphStickFiguresOptions& options) {
  const py::dict similarity = similarity_dict(stats.similarity);
  py::dict guide_frames;
  guide_frames["exact"] = stats.guide_exact_frames;
  guide_frames["blended"] = stats.guide_blended_frames;
  guide_frames["barycentric"] = stats.guide_barycentric_frames;
  py::dict rigid;
  rigid["rotation"] = sm::rotation_direction_name(options.rotation.value_or(sm::RotationDirection::Short));
  rigid["turns"] = options.turns.value_or(0);
  rigid["easing"] = sm::easing_name(options.easing.value_or(sm::Easing::None));
  rigid["similarity_factored"] = stats.similarity_factored;
  rigid["similarity"] = similarity;
  rigid["guide_frames"] = guide_frames;
  rigid["refinement_steiner_vertices"] = stats.triangulation.refinement_steiner;
  return rigid;
}

py::dict morph_dict(const sm::MorphStickFiguresResult& result, const sm::MorphStickFiguresOptions& options,
                    std::size_t n) {
  const sm::MorphMethod method = options.method;
  const sm::MorphStickFiguresStats& stats = result.stats;
  const bool linear = method == sm::MorphMethod::Linear;
  py::dict milliseconds;
  milliseconds["triangulate"] = stats.triangulate_ms;
  milliseconds["morph"] = stats.morph_ms;
  milliseconds["factorize"] = stats.factorize_ms;
  milliseconds["solve"] = stats.solve_ms;
  milliseconds["verify"] = stats.verify_ms;
  py::dict statistics;
  statistics["steiner_vertices"] = stats.steiner_vertices;
  statistics["triangles"] = stats.triangles;
  statistics["parts"] = stats.triangulation.parts;
  statistics["bridge_vertices"] = stats.triangulation.bridge_bends;
  statistics["milliseconds"] = milliseconds;
  statistics["method"] = sm::morph_method_name(method);
  if (!linear) {
    statistics["steiner_method"] = sm::steiner_method_name(result.triangulation_options.method);
    statistics["enclosure_sides"] = result.triangulation_options.enclosure_sides;
    statistics["weights"] = sm::weight_kind_name(result.morph_options.weights);
    statistics["verified"] = result.morph_options.verify;
  }
  statistics["refined_frames"] = stats.refined_frames;
  statistics["factorizations"] = stats.factorizations;
  if (linear) statistics["invalid_frames"] = to_list(stats.invalid_frames);
  if (method == sm::MorphMethod::Rigid) statistics["rigid"] = rigid_dict(stats, options);
  if (result.correspondence) {
    milliseconds["correspond"] = stats.correspond_ms;
    statistics["correspondence"] = matching_stats_dict(*result.correspondence);
  }
  py::dict dict;
  dict["times"] = py::array_t<double>(static_cast<py::ssize_t>(result.times.size()), result.times.data());
  dict["frames"] = frames_array(result.frames, n);
  if (result.triangulation)
    dict["triangulation"] = triangulation_dict(*result.triangulation, stats.triangulation);
  else
    dict["triangulation"] = py::none();
  dict["stats"] = statistics;
  if (result.correspondence) {
    dict["edges"] = to_edge_array(result.correspondence->source.edges);
    dict["correspondence"] = correspondence_dict(*result.correspondence);
  }
  return dict;
}

// ---------------------------------------------------------------------------
// MorphSolver

// The dict triangulate_figures returns (and morph returns as
// "triangulation"), back to the engine's type. Only the form is checked
// here; whether it is a triangulation the morph can use (node counts,
// indices in range, a disk bounded by the convex enclosure, every triangle
// counter-clockwise in both) is the engine's check, made by MorphSolver's
// constructor as morph_triangulation makes it.
sm::FigureTriangulation to_figure_triangulation(const py::object& object) {
  if (!py::isinstance<py::dict>(object))
    throw sm::InvalidArgumentError("triangulation must be the dict triangulate_figures returns, got " +
                                   py::str(py::type::of(object).attr("__name__")).cast<std::string>());
  const py::dict dict = py::reinterpret_borrow<py::dict>(object);
  const auto item = [&](const char* key) -> py::object {
    if (!dict.contains(key))
      throw sm::InvalidArgumentError(std::string("triangulation has no '") + key + "' entry");
    return dict[key];
  };
  // Bounded so that n + k + s cannot overflow the engine's int; any count
  // this large fails the engine's check against the positions anyway.
  constexpr long long kMaxCount = 1LL << 28;
  const auto count = [&](const char* key) {
    const std::string name = std::string("triangulation['") + key + "']";
    const py::object value = item(key);
    const long long n = to_count(value, name);
    if (n < 0 || n > kMaxCount)
      throw sm::InvalidArgumentError(name + " must be between 0 and " + std::to_string(kMaxCount) + ", got " +
                                     py::str(value).cast<std::string>());
    return static_cast<int>(n);
  };
  sm::FigureTriangulation tri;
  tri.figure_vertices = count("figure_vertices");
  tri.enclosure_vertices = count("enclosure_vertices");
  tri.steiner_vertices = count("steiner_vertices");
  tri.source = to_vertices(item("source"), "triangulation['source']");
  tri.target = to_vertices(item("target"), "triangulation['target']");

  const py::array triangles =
      py::module_::import("numpy").attr("asarray")(item("triangles")).cast<py::array>();
  const bool empty = triangles.ndim() == 1 && triangles.shape(0) == 0;
  if (!empty && (triangles.ndim() != 2 || triangles.shape(1) != 3))
    throw sm::InvalidArgumentError("triangulation['triangles'] must have shape (#T, 3), got " +
                                   py::str(triangles.attr("shape")).cast<std::string>());
  const char kind = triangles.dtype().kind();
  if (!empty && kind != 'i' && kind != 'u')
    throw sm::InvalidArgumentError("triangulation['triangles'] must hold integer node indices, got dtype " +
                                   py::str(triangles.dtype()).cast<std::string>());
  const py::ssize_t t = empty ? 0 : triangles.shape(0);
  tri.triangles.resize(static_cast<std::size_t>(t));
  if (t > 0) {
    // uint64 beyond INT64_MAX wraps negative in the cast: still refused
    // below, as out of range.
    const auto values = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(triangles);
    if (!values) throw py::error_already_set();
    const std::int64_t* data = values.data();
    for (py::ssize_t i = 0; i < 3 * t; ++i) {
      // An index beyond int becomes -1, which the engine reports as a node
      // out of range, naming the triangle.
      const std::int64_t v = data[i];
      tri.triangles[i / 3][i % 3] = v < INT_MIN || v > INT_MAX ? -1 : static_cast<int>(v);
    }
  }
  return tri;
}


// solve(t, all_nodes=, verify=) of MorphSolver and RigidMorphSolver: the
// arguments checked, the frame solved without the GIL, the figure's part.
template <class Binding>
py::array_t<double> solve_binding(Binding& self, const py::object& t, const py::object& all_nodes,
                                  const py::object& verify) {
  const double time = to_time(t);
  const bool all = to_flag(all_nodes, "all_nodes");
  const bool check = to_flag(verify, "verify");
  std::vector<sm::Vec2> positions;
  {
    py::gil_scoped_release release;
    positions = self.solve(time, check);
    if (!all) positions.resize(static_cast<std::size_t>(self.figure_vertices()));
  }
  return to_point_array(positions);
}

// stickmorph.MorphSolver: the engine's MorphSolver with the per-frame
// check and repair of morph_triangulation, so that a scrubbed frame is
// verified as a morph's frame is.
//
// Both solvers run in the working scale (working_scale.h): a triangulation
// or a pair beyond the numeric stages' comfortable magnitudes is solved
// multiplied by an exact power of two, and each frame multiplied back.
sm::FigureTriangulation scaled_triangulation(sm::FigureTriangulation triangulation, int exponent) {
  sm::scale_points(triangulation.source, exponent);
  sm::scale_points(triangulation.target, exponent);
  return triangulation;
}

// The rigid pair's working scale, its size ratio checked first so that a
// refusal names the sizes as given.
int checked_rigid_exponent(const sm::StickFigure& source, const sm::StickFigure& target) {
  sm::check_numeric_range(source, target, sm::MorphMethod::Rigid);
  return sm::working_scale_exponent(source, target);
}

class MorphSolverBinding {
 public:
  MorphSolverBinding(const sm::FigureTriangulation& triangulation, const sm::StickFigure& source,
                     sm::WeightKind kind)
      : exponent_(sm::working_scale_exponent(triangulation.source, triangulation.target)),
        tri_(scaled_triangulation(triangulation, exponent_)),
        source_(source),
        scaled_source_(sm::scaled_figure(source, exponent_)),
        decomposition_(sm::decompose(source_)),
        solver_(tri_, kind),
        kind_(kind) {
    // The frame certificate's precondition (frame_certificate.h).
    sm::require_figure_edges(tri_, scaled_source_);
  }

  // All node positions at t; see the docstring for the contract. The frame
  // is made and checked exactly as a morph's frame (checked_morph_frame).
  std::vector<sm::Vec2> solve(double t, bool verify) {
    // One solve at a time: the engine solver carries state from solve to
    // solve, and the GIL is released while it runs.
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<sm::Vec2> positions =
        sm::checked_morph_frame(solver_, tri_, scaled_source_, decomposition_, t, -1, verify, "MorphSolver.solve: ")
            .positions;
    sm::scale_frame_back(positions, exponent_, source_, decomposition_, verify, -1, t);
    return positions;
  }

  int figure_vertices() const { return tri_.figure_vertices; }
  sm::WeightKind kind() const { return kind_; }
  sm::MorphSolverStats stats() {
    std::lock_guard<std::mutex> lock(mutex_);
    return solver_.stats();
  }

 private:
  const int exponent_;
  const sm::FigureTriangulation tri_;  ///< in the working scale
  const sm::StickFigure source_;
  const sm::StickFigure scaled_source_;
  const sm::Decomposition decomposition_;  ///< the same at either scale
  sm::MorphSolver solver_;
  const sm::WeightKind kind_;
  std::mutex mutex_;
};

// stickmorph.RigidMorphSolver: the rigid method's GuidedMorph, made once,
// then any animation time t, each frame checked exactly as morph()'s are.
class RigidMorphSolverBinding {
 public:
  RigidMorphSolverBinding(const sm::StickFigure& source, const sm::StickFigure& target,
                          const sm::MorphStickFiguresOptions& options)
      : exponent_(checked_rigid_exponent(source, target)),
        source_(source),
        decomposition_(sm::decompose(source)),
        morph_(sm::prepare_rigid_morph(sm::scaled_figure(source, exponent_), sm::scaled_figure(target, exponent_),
                                       options, &stats_)),
        triangulation_(morph_.triangulation()),
        n_(int(source.vertices.size())) {
    sm::scale_triangulation_back(triangulation_, source_, exponent_);
    for (sm::Vec2* center : {&stats_.similarity.source_center, &stats_.similarity.target_center})
      for (double& c : *center) c = std::ldexp(c, -exponent_);
  }

  std::vector<sm::Vec2> solve(double t, bool verify) {
    // One frame at a time: the morph keeps its blended weights between
    // calls, and the GIL is released while it runs.
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<sm::Vec2> positions = morph_.frame(t, -1, verify, "RigidMorphSolver.solve: ").positions;
    sm::scale_frame_back(positions, exponent_, source_, decomposition_, verify, -1, t);
    return positions;
  }

  int figure_vertices() const { return n_; }
  const sm::FigureTriangulation& triangulation() const { return triangulation_; }
  const sm::MorphStickFiguresStats& stats() const { return stats_; }

 private:
  const int exponent_;
  const sm::StickFigure source_;
  const sm::Decomposition decomposition_;
  sm::MorphStickFiguresStats stats_;
  sm::GuidedMorph morph_;  ///< in the working scale
  sm::FigureTriangulation triangulation_;  ///< at the figures' own scale
  const int n_;
  std::mutex mutex_;
};

}  // namespace

void bind_morph(py::module_& m) {

  py::class_<MorphSolverBinding>(m, "MorphSolver", R"doc(The morph of one triangulation at any time t, for scrubbing (paper, Algorithm 3, step 4).

MorphSolver(triangulation, edges, weights="mvc") computes the
convex-combination weights of both embeddings and analyses the linear
system once; solve(t) then gives the figure at any t in [0, 1], in any
order. The first solve builds a reduced basis for all of [0, 1] (three
factorizations, at t = 0, 1/2 and 1, and the solution's derivatives in t
there); every solve is projected onto it, iterates on the nearest kept
factorization where that is not enough, and factorizes anew only when
that is too far. The same solver and per-frame check as morph(), which
solves its frames in order with one such solver.

Args:
  triangulation: the dict triangulate_figures returns (or morph()'s
    "triangulation" entry): "figure_vertices", "enclosure_vertices",
    "steiner_vertices", "source", "target" and "triangles".
  edges: #E by 2 integer array-like, the source figure's edges over the
    first n nodes, as given to triangulate_figures. Needed for the frame
    check (a triangulation does not say which of its edges are the
    figure's); each must be an edge of the triangulation.
  weights: "mvc" (mean value coordinates, default), "uniform" or "floater",
    as for morph().

Raises:
  InvalidArgumentError: an unknown weights name, a triangulation that is not
    such a dict or not one the morph can use (malformed, a triangle not
    counter-clockwise, an enclosure that is not fixed and convex, a figure
    edge that is not one of its edges), or an array of the wrong shape or
    type.
  InvalidFigureError: the first n source nodes joined by edges are not a
    valid stick figure.

A MorphSolver may be shared between threads: solves run one at a time,
without the GIL.)doc")
      .def(py::init([](const py::object& triangulation, const py::object& edges, const py::object& weights) {
             // Arguments first, then the triangulation, then the figure.
             const sm::WeightKind kind = sm::parse_weight_kind(to_name(weights, "weights"));
             sm::FigureTriangulation tri = to_figure_triangulation(triangulation);
             {
               // The engine's form check before the first n positions are
               // read as a figure: it names what is malformed.
               py::gil_scoped_release release;
               sm::check_morph_triangulation(tri);
             }
             const std::vector<sm::Vec2> figure(tri.source.begin(), tri.source.begin() + tri.figure_vertices);
             sm::StickFigure source = make_figure(to_point_array(figure), edges, "triangulation['source']", "edges");
             py::gil_scoped_release release;
             return std::make_unique<MorphSolverBinding>(std::move(tri), std::move(source), kind);
           }),
           py::arg("triangulation"), py::arg("edges"), py::arg("weights") = "mvc")
      .def(
          "solve",
          [](MorphSolverBinding& self, const py::object& t, const py::object& all_nodes, const py::object& verify) {
            return solve_binding(self, t, all_nodes, verify);
          },
          py::arg("t"), py::kw_only(), py::arg("all_nodes") = false, py::arg("verify") = true,
          R"doc(The morph at time t.

Args:
  t: a number in [0, 1]; 0 is the source, 1 the target.
  all_nodes: return all n+k+s triangulation nodes (figure vertices, then
    enclosure, then Steiner vertices, as in the triangulation dict) instead
    of the figure's n vertices.
  verify: check the result exactly (default True), as morph() checks every
    frame by default: every triangle counter-clockwise inside the convex
    enclosure, which proves the figure a stick figure compatible with the
    source (the certificate, O(T)); a result that fails is solved directly at t
    and then refined in long double before it is refused. verify=False
    skips the check and the repair, for a scrubbing preview that must be
    fast; the result is then valid in exact arithmetic (Tutte's theorem)
    but not checked against rounding.

Returns:
  #n by 2 float64 ndarray of the figure's vertex positions at t (with
  all_nodes=True, (n+k+s) by 2). At t = 0 and t = 1 exactly the source and
  target positions. Elsewhere the solution of the morph's linear system to
  about ten significant digits (the engine's iteration tolerance): the same
  t can differ in the last digits depending on the times solved before it.
  Solving morph()'s times in order from a new MorphSolver gives morph()'s
  frames bit for bit.

Raises:
  InvalidArgumentError: t outside [0, 1], NaN or not a number; all_nodes or
    verify not a bool.
  VerificationError: with verify=True, the result failed the exact check
    even after refinement; the message names t.)doc")
      .def_property_readonly(
          "weights", [](const MorphSolverBinding& self) { return sm::weight_kind_name(self.kind()); },
          "The weight kind's name: \"mvc\", \"uniform\" or \"floater\".")
      .def_property_readonly(
          "stats",
          [](MorphSolverBinding& self) {
            const sm::MorphSolverStats stats = self.stats();
            py::dict dict;
            dict["factorizations"] = stats.factorizations;
            dict["factorize_ms"] = stats.factorize_ms;
            dict["solve_ms"] = stats.solve_ms;
            return dict;
          },
          "What the solver spent so far: \"factorizations\" (int, numeric LU factorizations), "
          "\"factorize_ms\" and \"solve_ms\" (float, milliseconds).");

  py::class_<RigidMorphSolverBinding>(m, "RigidMorphSolver", R"doc(The rigid morph at any time t, for scrubbing (issue 12; morph(method="rigid")).

RigidMorphSolver(source_xy, target_xy, edges, steiner=None, weights=None,
enclosure_sides=None, rotation=None, turns=None, easing=None,
target_edges=None) does once what morph() does before its frames: fits
the similarity, triangulates the pair inside an enclosure that holds the
rigid guide's way, and samples the guide. solve(t) then gives the figure at
any animation time t in [0, 1], in any order, checked exactly as morph()'s
frames are. Each solve iterates from the last one, so the same t can differ
in the ninth digit or so depending on the times solved before it; solving
morph()'s times k/(N-1) in order from a new RigidMorphSolver gives morph()'s
frames bit for bit.

Arguments as for morph() (method is always "rigid").

Raises:
  as morph().

A RigidMorphSolver may be shared between threads: solves run one at a
time, without the GIL.)doc")
      .def(py::init([](const py::object& source_xy, const py::object& target_xy, const py::object& edges,
                       const py::object& steiner, const py::object& weights, const py::object& enclosure_sides,
                       const py::object& rotation, const py::object& turns, const py::object& easing,
                       const py::object& target_edges, const py::object& delay, const py::object& overlap) {
             // Arguments first, figures second, as morph() does; frames is
             // morph()'s default, unused here.
             const sm::MorphStickFiguresOptions options =
                 to_morph_options(py::int_(sm::kDefaultMorphFrames), steiner, weights, enclosure_sides,
                                  py::str("rigid"), py::none(), rotation, turns, easing, py::none(), py::none(),
                                  py::none(), delay, overlap);
             const auto figures =
                 make_figure_pair(source_xy, target_xy, edges, target_edges, "source_xy", "target_xy");
             py::gil_scoped_release release;
             return std::make_unique<RigidMorphSolverBinding>(figures.first, figures.second, options);
           }),
           py::arg("source_xy"), py::arg("target_xy"), py::arg("edges"), py::arg("steiner") = py::none(),
           py::arg("weights") = py::none(), py::arg("enclosure_sides") = py::none(),
           py::arg("rotation") = py::none(), py::arg("turns") = py::none(), py::arg("easing") = py::none(),
           py::arg("target_edges") = py::none(), py::arg("delay") = py::none(), py::arg("overlap") = py::none())
      .def(
          "solve",
          [](RigidMorphSolverBinding& self, const py::object& t, const py::object& all_nodes,
             const py::object& verify) {
            return solve_binding(self, t, all_nodes, verify);
          },
          py::arg("t"), py::kw_only(), py::arg("all_nodes") = false, py::arg("verify") = true,
          R"doc(The rigid morph at animation time t.

Args:
  t: a number in [0, 1]; 0 is the source, 1 the target.
  all_nodes: return all n+k+s nodes of the triangulation (in output space:
    the enclosure moves with the figure's similarity) instead of the
    figure's n vertices.
  verify: check the frame exactly (default True): the moved enclosure
    convex and every triangle counter-clockwise, which proves the figure a
    stick figure compatible with the source (the certificate); a frame that
    fails falls back as in morph().

Returns:
  #n by 2 float64 ndarray (with all_nodes=True, (n+k+s) by 2). At t = 0 and
  t = 1 exactly the source and the target.

Raises:
  InvalidArgumentError: t outside [0, 1], NaN or not a number; all_nodes or
    verify not a bool.
  VerificationError: with verify=True, no candidate frame passed the exact
    check; the message names t.)doc")
      .def_property_readonly(
          "triangulation",
          [](const RigidMorphSolverBinding& self) {
            return triangulation_dict(self.triangulation(), self.stats().triangulation);
          },
          "The triangulation the morph uses, as morph()'s \"triangulation\" (output space).")
      .def_property_readonly(
          "similarity",
          [](const RigidMorphSolverBinding& self) {
            py::dict dict = similarity_dict(self.stats().similarity);
            dict["factored"] = self.stats().similarity_factored;
            return dict;
          },
          "The similarity fitted between the figures: \"angle_degrees\", \"scale\", \"source_center\", "
          "\"target_center\", and \"factored\" (bool), as in morph()'s stats[\"rigid\"].");

  m.def(
      "morph",
      [](const py::object& source_xy, const py::object& target_xy, const py::object& edges,
         const py::object& frames, const py::object& steiner, const py::object& weights,
         const py::object& enclosure_sides, const py::object& method, const py::object& verify,
         const py::object& target_edges, const py::object& rotation, const py::object& turns,
         const py::object& easing, const py::object& correspond, const py::object& pins,
         const py::object& frame_check, const py::object& progress, const py::object& delay,
         const py::object& overlap) {
        // Arguments first, figures second, as the CLI does.
        const sm::MorphStickFiguresOptions options =
            to_morph_options(frames, steiner, weights, enclosure_sides, method, verify, rotation, turns, easing,
                             correspond, pins, frame_check, delay, overlap);
        std::shared_ptr<sm::Progress> watched = to_progress(progress);
        const auto figures =
            make_figure_pair(source_xy, target_xy, edges, target_edges, "source_xy", "target_xy");
        sm::MorphStickFiguresResult result;
        {
          py::gil_scoped_release release;
          CallProgress installed(std::move(watched));
          result = sm::morph_stick_figures(figures.first, figures.second, options);
          installed.finished();
        }
        const std::size_t n = result.correspondence ? result.correspondence->source.vertices.size()
                                                    : figures.first.vertices.size();
        return morph_dict(result, options, n);
      },
      py::arg("source_xy"), py::arg("target_xy"), py::arg("edges"), py::arg("frames") = sm::kDefaultMorphFrames,
      py::arg("steiner") = py::none(), py::arg("weights") = py::none(), py::arg("enclosure_sides") = py::none(),
      py::arg("method") = "rigid", py::arg("verify") = py::none(), py::arg("target_edges") = py::none(),
      py::arg("rotation") = py::none(), py::arg("turns") = py::none(), py::arg("easing") = py::none(),
      py::arg("correspond") = py::none(), py::arg("pins") = py::none(), py::arg("frame_check") = py::none(),
      py::arg("progress") = py::none(), py::arg("delay") = py::none(), py::arg("overlap") = py::none(),
      with_limits(R"doc(Morphs one stick figure into a compatible one (paper, Algorithm 3).

The rigid method (default) morphs as rigidly as validity allows: the
best-fit rotation, uniform scale and translation between the figures are
factored out and interpolated back in (the rotation the short way unless
rotation/turns say otherwise, the scale geometrically), and the valid morph
follows an as-rigid-as-possible motion of the figure's edges wherever that
motion is valid, at even speed (easing="in-out" slows its start and end).
Its frames are verified exactly like the barycentric method's.

The barycentric method compatibly triangulates both figures inside
a common convex enclosure (triangulate_figures) and morphs the triangulation
by Floater & Gotsman: convex-combination weights interpolated linearly in
time, positions solved for at every frame. Every frame is then a stick
figure compatible with the source; with verify=True this is checked exactly
for every frame (frames failing through roundoff are refined in long
double, and a frame that still fails raises VerificationError). The linear
method is the paper's Figure 8d baseline: straight-line interpolation of
the vertices, whose invalid frames are reported, not refused. The same
computation as `stickmorph morph`.

Args:
  source_xy: #V by 2 float64 array-like, source coordinates.
  target_xy: #V by 2 float64 array-like, target coordinates; vertex i of the
    source corresponds to vertex i of the target.
  edges: #E by 2 integer array-like of vertex indices of the source (and of
    the target unless target_edges is given).
  frames: N, the number of frames, {min_frames} to {max_frames} (stickmorph.limits);
    frame k is at time k/(N-1).
  steiner: "improved" (default), "sg2001" or "aronov", as for
    triangulate_figures. Barycentric only.
  weights: "mvc" (mean value coordinates, default), "uniform" or "floater".
    Barycentric only.
  enclosure_sides: sides of the common regular enclosure,
    {min_enclosure_sides} to {max_enclosure_sides} (default {default_enclosure_sides}).
    Barycentric only.
  method: "rigid" (default), "barycentric" or "linear".
  verify: check every frame exactly (default True). Not for linear.
  frame_check: how, "certificate" (default: every triangle of the
    triangulation counter-clockwise inside the convex enclosure, which
    proves the frame an embedding with the source's topology, in O(T)) or
    "full" (also rebuild each frame's figure and compare its cyclic
    sequences with the source's). Not for linear, nor with verify=False.
  rotation: "short" (default), "ccw" or "cw": which way the figure turns as
    a whole. Rigid only.
  turns: extra whole turns, counter-clockwise positive, -{max_turns} to
    {max_turns} (default 0). Rigid only.
  easing: "none" (default, even speed) or "in-out". Rigid only.
  correspond: "index" (default: vertex i of the source becomes vertex i of
    the target) or "auto": the figures may differ in vertex count,
    numbering, edge order and subdivision; they are matched as correspond()
    does and the matched figure is morphed (every frame verified as usual).
  pins: with correspond="auto", optional #P by 2 integer array-like of
    (source vertex, target vertex) pairs the matching must respect.
  delay: local timing (overlapping action), given with overlap: #V delay
    weights in [0, 1], one per source vertex (with correspond="auto" a
    dummy takes the weight interpolated along its edge).
  overlap: d in [0, 1), given with delay. Every part moves at its local time
    clamp((t - d w) / (1 - d), 0, 1): weight-0 parts lead and finish at
    1 - d, weight-1 parts start at d and finish last; an edge turns and
    stretches at the mean of its ends' local times. Frames stay valid and
    verified; where the delayed motion is not valid the morph gives way as
    little as validity needs. overlap=0 is the plain morph, bit for bit.
    Rigid only.

  The options marked "barycentric only" (steiner, weights, enclosure_sides,
  verify) also apply to rigid; they default to None (not given), and giving
  one with method="linear", which would ignore it, raises
  InvalidArgumentError, as `stickmorph morph --method linear` refuses them.
  Likewise the rigid-only options with another method.
  stickmorph.option_rules lists, for each option, the methods it applies
  to, its range or accepted names and its default: the engine's table.
  target_edges: optional #E by 2 integer array-like, the target's edge list.
  progress: optional stickmorph.Progress, to watch the call (stage,
    fraction, summary()) and cancel it (cancel()) from another thread while
    it runs without the GIL; stages "check", "correspond" (with
    correspond="auto"), "triangulate" (for the rigid method also the
    solver's set-up) and "frames" (counted in frames). None (default): the
    Progress a `with progress:` block installed on this thread, if any.

Returns:
  dict with
    "times"          (N,) float64 ndarray, k/(N-1): 0.0 first, 1.0 last
    "frames"         (N, #V, 2) float64 ndarray of the figure's vertices;
                     frames[0] is exactly source_xy, frames[-1] exactly
                     target_xy
    "triangulation"  the dict triangulate_figures returns, the triangulation
                     the morph used; None for method="linear"
    "stats"          dict: "steiner_vertices" (int), "triangles" (int),
                     "parts" (int, the figure's parts), "bridge_vertices"
                     (int, Steiner vertices on the bridges joining them),
                     "milliseconds" (dict of floats: "triangulate", "morph",
                     "factorize", "solve", "verify"), "refined_frames" (int,
                     frames refined in long double), "factorizations" (int,
                     frames whose warm-started iterative solve stalled or
                     failed the exact check and were solved with the direct
                     factorization), "method" (str); for
                     "rigid" and "barycentric" also "steiner_method",
                     "enclosure_sides", "weights" and "verified"; for
                     "rigid" also "rigid": dict with "rotation", "turns",
                     "easing", "similarity_factored" (bool), "similarity"
                     (dict: "angle_degrees", "scale", "source_center",
                     "target_center") and "guide_frames" (dict of int:
                     interior frames that are the rigid guide itself
                     "exact", follow it where valid "blended", or fell back
                     to the barycentric frame "barycentric"); for "linear" also
                     "invalid_frames" (list of int, the frames that are not
                     stick figures compatible with the source). For "linear"
                     the counts, refined_frames, factorizations and the
                     triangulate and factorize times are 0, "solve" is the interpolation and "verify" the check
                     that finds the invalid frames. With correspond="auto"
                     also "correspondence" (as correspond()'s stats) and
                     milliseconds["correspond"].
    With correspond="auto" the frames are the matched figure's m vertices,
    and the dict also has
    "edges"          (#E', 2) int64 ndarray, the matched figure's edges
    "correspondence" dict of (m,) ndarrays: "source", "target" (the vertex
                     each matched vertex is in the source / target, -1 for
                     a dummy), "source_edge", "target_edge" (the edge a
                     dummy lies on, -1 for a vertex) and "source_fraction",
                     "target_fraction" (where along that edge, from its
                     first vertex to its second).

Raises:
  InvalidFigureError: the source or the target is invalid (the message
    starts with "source: " or "target: ", and its role attribute says
    which).
  IncompatibleFiguresError: the figures are not compatible; its kind and
    vertices attributes are those of check_compatibility's report. With
    correspond="auto": the figures cannot be matched, kind
    "topology_differs", "mirror_image", "exterior_differs",
    "nesting_differs" or "pins_unsatisfiable". Figures of several parts
    whose parts nest differently: kind "nesting_differs".
  InvalidArgumentError: frames out of range or not an integer, an unknown
    method, weights or steiner name, enclosure_sides out of range, an option
    method="linear" would ignore, or an array of the wrong shape or type.
  VerificationError: a triangulation or a frame failed exact verification
    and could not be repaired.
  CancelledError: progress.cancel() was called while the call ran (or
    before); it stopped at its next check and returns nothing.)doc"));
}

}  // namespace stickmorph::python
