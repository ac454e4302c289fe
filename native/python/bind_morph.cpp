// The morph (Algorithm 3 end to end, through the engine's
// morph_stick_figures) and the limits and option names the engine checks,
// exported so that the add-on and help texts quote them instead of copies.
//
// No binding of a stateful morph solver (scrubbing any t) yet: the engine
// has no public solver class; when it has one, it belongs here.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <string>
#include <vector>

#include "bindings.h"
#include "conversions.h"
#include "stickmorph/argument_limits.h"
#include "stickmorph/errors.h"
#include "stickmorph/morph_stick_figures.h"

namespace stickmorph::python {
namespace {

constexpr sm::OptionSpelling kKeyword = sm::OptionSpelling::Keyword;

// Arguments to engine options. None means "not given", so that the engine
// can refuse what method="linear" would ignore; everything is checked before
// the figures, as the CLI does.
sm::MorphStickFiguresOptions to_morph_options(const py::object& frames, const py::object& steiner,
                                              const py::object& weights, const py::object& enclosure_sides,
                                              const py::object& method, const py::object& verify) {
  sm::MorphStickFiguresOptions options;
  options.spelling = kKeyword;
  // Here rather than only in the engine so that the message quotes a Python
  // int beyond long long as given.
  options.frames = sm::check_frames(to_count(frames, "frames"), kKeyword, py::str(frames));
  options.method = sm::parse_morph_method(to_name(method, "method"));
  if (!steiner.is_none()) options.steiner = sm::parse_steiner_method(to_name(steiner, "steiner"));
  if (!weights.is_none()) options.weights = sm::parse_weight_kind(to_name(weights, "weights"));
  if (!verify.is_none()) options.verify = to_flag(verify, "verify");
  if (!enclosure_sides.is_none()) {
    const long long sides = to_count(enclosure_sides, "enclosure_sides");
    // Range checked by check_morph_options below, after the refusal of
    // options linear would ignore; only a saturated value needs its text.
    options.enclosure_sides = sides;
    if (options.method == sm::MorphMethod::Barycentric)
      sm::check_enclosure_sides(sides, kKeyword, py::str(enclosure_sides));
  }
  sm::check_morph_options(options);
  return options;
}

py::dict morph_dict(const sm::MorphStickFiguresResult& result, sm::MorphMethod method, std::size_t n) {
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
  py::dict dict;
  dict["times"] = py::array_t<double>(static_cast<py::ssize_t>(result.times.size()), result.times.data());
  dict["frames"] = frames_array(result.frames, n);
  if (result.triangulation)
    dict["triangulation"] = triangulation_dict(*result.triangulation, stats.triangulation);
  else
    dict["triangulation"] = py::none();
  dict["stats"] = statistics;
  return dict;
}

// stickmorph.limits: the engine's bounds by name, for range checks and help
// texts outside the engine (the add-on's properties, its preferences).
py::dict limits_dict() {
  py::dict limits;
  for (const auto& [name, value] : engine_limits()) {
    // Counts as ints; the coordinate bound (1e100) is a float.
    if (value == std::floor(value) && std::abs(value) < 1e15)
      limits[name.c_str()] = static_cast<long long>(value);
    else
      limits[name.c_str()] = value;
  }
  return limits;
}

// stickmorph.OPTION_NAMES: keyword -> CLI flag ("" where the CLI has none),
// from the engine's one table.
py::dict option_names_dict() {
  py::dict names;
  for (const sm::OptionName& row : sm::option_names()) names[row.keyword] = row.command_line;
  return names;
}

}  // namespace

void bind_morph(py::module_& m) {
  m.attr("limits") = limits_dict();
  m.attr("OPTION_NAMES") = option_names_dict();
  m.attr("METHOD_NAMES") = py::make_tuple("barycentric", "linear");

  m.def(
      "morph",
      [](const py::object& source_xy, const py::object& target_xy, const py::object& edges,
         const py::object& frames, const py::object& steiner, const py::object& weights,
         const py::object& enclosure_sides, const py::object& method, const py::object& verify,
         const py::object& target_edges) {
        // Arguments first, figures second, as the CLI does.
        const sm::MorphStickFiguresOptions options =
            to_morph_options(frames, steiner, weights, enclosure_sides, method, verify);
        const auto figures =
            make_figure_pair(source_xy, target_xy, edges, target_edges, "source_xy", "target_xy");
        sm::MorphStickFiguresResult result;
        {
          py::gil_scoped_release release;
          result = sm::morph_stick_figures(figures.first, figures.second, options);
        }
        return morph_dict(result, options.method, figures.first.vertices.size());
      },
      py::arg("source_xy"), py::arg("target_xy"), py::arg("edges"), py::arg("frames") = sm::kDefaultMorphFrames,
      py::arg("steiner") = py::none(), py::arg("weights") = py::none(), py::arg("enclosure_sides") = py::none(),
      py::arg("method") = "barycentric", py::arg("verify") = py::none(), py::arg("target_edges") = py::none(),
      with_limits(R"doc(Morphs one stick figure into a compatible one (paper, Algorithm 3).

The barycentric method (default) compatibly triangulates both figures inside
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
  method: "barycentric" (default) or "linear".
  verify: check every frame exactly (default True). Barycentric only.

  The options marked "barycentric only" default to None (not given); giving
  one with method="linear", which would ignore it, raises
  InvalidArgumentError, as `stickmorph morph --method linear` refuses them.
  target_edges: optional #E by 2 integer array-like, the target's edge list.

Returns:
  dict with
    "times"          (N,) float64 ndarray, k/(N-1): 0.0 first, 1.0 last
    "frames"         (N, #V, 2) float64 ndarray of the figure's vertices;
                     frames[0] is exactly source_xy, frames[-1] exactly
                     target_xy
    "triangulation"  the dict triangulate_figures returns, the triangulation
                     the morph used; None for method="linear"
    "stats"          dict: "steiner_vertices" (int), "triangles" (int),
                     "milliseconds" (dict of floats: "triangulate", "morph",
                     "factorize", "solve", "verify"), "refined_frames" (int,
                     frames refined in long double), "factorizations" (int,
                     frames whose warm-started iterative solve stalled or
                     failed the exact check and were solved with the direct
                     factorization), "method" (str); for
                     "barycentric" also "steiner_method", "enclosure_sides",
                     "weights" and "verified"; for "linear" also
                     "invalid_frames" (list of int, the frames that are not
                     stick figures compatible with the source). For "linear"
                     the counts, refined_frames, factorizations and the
                     triangulate and factorize times are 0, "solve" is the interpolation and "verify" the check
                     that finds the invalid frames.

Raises:
  InvalidFigureError: the source or the target is invalid (the message
    starts with "source: " or "target: ", and its role attribute says
    which).
  IncompatibleFiguresError: the figures are not compatible; its kind and
    vertices attributes are those of check_compatibility's report.
  InvalidArgumentError: frames out of range or not an integer, an unknown
    method, weights or steiner name, enclosure_sides out of range, an option
    method="linear" would ignore, or an array of the wrong shape or type.
  VerificationError: a triangulation or a frame failed exact verification
    and could not be repaired.)doc"));
}

}  // namespace stickmorph::python
