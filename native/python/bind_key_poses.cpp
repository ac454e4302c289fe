// stickmorph.morph_key_poses: the morph through a sequence of key poses
// (issue 28), a thin shell over the engine's morph_key_poses
// (key_pose_morph.h), as `stickmorph morph KEY1.json ... KEYK.json` is.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <string>
#include <vector>

#include "bindings.h"
#include "progress_argument.h"
#include "conversions.h"
#include "morph_arguments.h"
#include "stickmorph/argument_limits.h"
#include "stickmorph/errors.h"
#include "stickmorph/key_pose_morph.h"

namespace stickmorph::python {
namespace {

bool is_sequence(const py::object& object) {
  return py::isinstance<py::sequence>(object) && !py::isinstance<py::str>(object) &&
         !py::isinstance<py::bytes>(object);
}

// A value for every segment, or a sequence of one per segment.
template <class Convert>
auto per_segment(const py::object& object, const std::string& name, Convert convert)
    -> std::vector<decltype(convert(object, name))> {
  std::vector<decltype(convert(object, name))> values;
  if (object.is_none()) return values;
  if (!is_sequence(object)) {
    values.push_back(convert(object, name));
    return values;
  }
  const py::sequence items = object.cast<py::sequence>();
  for (std::size_t s = 0; s < items.size(); ++s)
    values.push_back(convert(items[s], name + "[" + std::to_string(s) + "]"));
  return values;
}

// How deeply nested an array-like is: 0 for a scalar, ndim for an array,
// for a sequence 1 + its deepest item's depth (1 when empty). It tells one
// #E by 2 edge list (depth 2) from one per key (depth 3), and one pin list
// from one per pair of keys (which may be empty: [[], [(3, 4)]]).
int nesting_depth(const py::handle& object) {
  if (py::isinstance<py::array>(object)) return int(object.cast<py::array>().ndim());
  if (!is_sequence(py::reinterpret_borrow<py::object>(object))) return 0;
  int deepest = 0;
  for (const py::handle item : object.cast<py::sequence>()) {
    deepest = std::max(deepest, nesting_depth(item));
    if (deepest >= 2) break;  // deep enough to tell the forms apart
  }
  return 1 + deepest;
}

// Where each vertex of the frames is on each key: matched, what the
// matching said; by index, every key's own vertex i.
py::list places_list(const std::optional<sm::KeyPoseCorrespondence>& correspondence, std::size_t keys,
                     std::size_t n) {
  py::list list;
  for (std::size_t k = 0; k < keys; ++k) {
    if (correspondence) {
      list.append(places_dict(correspondence->places[k]));
      continue;
    }
    std::vector<sm::MatchedPlace> own(n);
    for (std::size_t i = 0; i < n; ++i) own[i].vertex = int(i);
    list.append(places_dict(own));
  }
  return list;
}

py::list correspondence_list(const sm::KeyPoseCorrespondence& correspondence) {
  py::list pairs;
  for (const sm::FigureCorrespondence& match : correspondence.matches) pairs.append(matching_stats_dict(match));
  return pairs;
}

py::dict segment_dict(const sm::KeyPoseSegment& segment) {
  const sm::MorphStickFiguresStats& stats = segment.stats;
  py::dict guide_frames;
  guide_frames["exact"] = stats.guide_exact_frames;
  guide_frames["blended"] = stats.guide_blended_frames;
  guide_frames["barycentric"] = stats.guide_barycentric_frames;
  py::dict milliseconds;
  milliseconds["triangulate"] = stats.triangulate_ms;
  milliseconds["morph"] = stats.morph_ms;
  py::dict dict;
  dict["from_key"] = segment.from_key;
  dict["to_key"] = segment.to_key;
  dict["first_frame"] = segment.first_frame;
  dict["last_frame"] = segment.last_frame;
  dict["triangulation"] = triangulation_dict(segment.triangulation, stats.triangulation);
  dict["steiner_vertices"] = segment.triangulation.steiner_vertices;
  dict["similarity_factored"] = stats.similarity_factored;
  dict["guide_frames"] = guide_frames;
  dict["refined_frames"] = stats.refined_frames;
  dict["milliseconds"] = milliseconds;
  return dict;
}

// The keys and options of morph_key_poses and KeyPoseMorphSolver, from
// their keyword arguments: arguments first, figures second, as morph() does.
struct KeyPoseInputs {
  std::vector<sm::StickFigure> keys;
  sm::KeyPoseMorphOptions options;
};

KeyPoseInputs key_pose_inputs(const py::object& keys_xy, const py::object& edges, const py::object& frames,
                              const py::object& keys_at, const py::object& loop, const py::object& hold,
                              const py::object& rotation, const py::object& turns, const py::object& steiner,
                              const py::object& weights, const py::object& enclosure_sides, const py::object& verify,
                              const py::object& frame_check, const py::object& correspond, const py::object& pins,
                              const py::object& easing, const py::object& delay, const py::object& overlap) {
  const sm::MorphStickFiguresOptions shared =
      to_morph_options(py::int_(sm::kDefaultMorphFrames), steiner, weights, enclosure_sides, py::str("rigid"),
                       verify, py::none(), py::none(), py::none(), py::none(), py::none(), frame_check);
  sm::KeyPoseMorphOptions options;
  options.steiner = shared.steiner;
  options.weights = shared.weights;
  options.enclosure_sides = shared.enclosure_sides;
  options.verify = shared.verify;
  options.frame_check = shared.frame_check;
  options.timing = to_local_timing(delay, overlap);
  if (!correspond.is_none())
    options.correspond = sm::parse_correspondence_mode(to_name(correspond, "correspond"));
  // One #P by 2 list (keys 1 and 2) or one per pair of keys.
  if (!pins.is_none() && nesting_depth(pins) == 3) {
    const py::sequence lists = pins.cast<py::sequence>();
    for (std::size_t p = 0; p < lists.size(); ++p) options.pins.push_back(to_pins(lists[p]));
  } else if (!pins.is_none()) {
    std::vector<sm::VertexPin> first = to_pins(pins);
    if (!first.empty()) options.pins.push_back(std::move(first));
  }
  if (!frames.is_none()) options.frames = to_count(frames, "frames");
  if (!keys_at.is_none()) {
    if (!is_sequence(keys_at)) throw sm::InvalidArgumentError("keys_at must be a sequence of frame numbers");
    const py::sequence items = keys_at.cast<py::sequence>();
    for (std::size_t k = 0; k < items.size(); ++k)
      options.keys_at.push_back(to_count(items[k], "keys_at[" + std::to_string(k) + "]"));
  }
  options.loop = to_flag(loop, "loop");
  if (!hold.is_none()) {
    if (!is_sequence(hold)) throw sm::InvalidArgumentError("hold must be a sequence of one bool per key");
    const py::sequence items = hold.cast<py::sequence>();
    for (std::size_t k = 0; k < items.size(); ++k)
      options.hold.push_back(to_flag(items[k], "hold[" + std::to_string(k) + "]"));
  }
  options.rotation = per_segment(rotation, "rotation", [](const py::object& o, const std::string& name) {
    return sm::parse_rotation_direction(to_name(o, name));
  });
  options.turns = per_segment(turns, "turns", [](const py::object& o, const std::string& name) {
    return to_count(o, name);
  });
  options.easing = per_segment(easing, "easing", [](const py::object& o, const std::string& name) {
    return sm::parse_easing(to_name(o, name));
  });
  if (!is_sequence(keys_xy)) throw sm::InvalidArgumentError("keys_xy must be a sequence of #V by 2 arrays");
  const py::sequence key_items = keys_xy.cast<py::sequence>();
  // One edge list for every key, or (keys drawn separately) one per key.
  const bool edges_per_key = nesting_depth(edges) == 3;
  if (edges_per_key && py::len(edges) != key_items.size())
    throw sm::InvalidArgumentError("edges: one edge list for every key, or one per key (" +
                                   std::to_string(key_items.size()) + "), got " +
                                   std::to_string(py::len(edges)) + " lists");
  std::vector<sm::StickFigure> keys;
  for (std::size_t k = 0; k < key_items.size(); ++k) {
    const std::string index = "[" + std::to_string(k) + "]";
    // Owned: an array's item is a new view, not kept alive by the array.
    const py::object key_edges = edges_per_key ? py::object(edges.cast<py::sequence>()[k]) : edges;
    keys.push_back(make_named_figure(key_items[k], key_edges,
                                     "keys_xy" + index, edges_per_key ? "edges" + index : "edges",
                                     "key " + std::to_string(k + 1)));
  }
  // One rotation or turn count for every segment, as the CLI takes it.
  const std::size_t segments = options.loop ? keys.size() : keys.size() - (keys.empty() ? 0 : 1);
  if (options.rotation.size() == 1 && segments > 1) options.rotation.assign(segments, options.rotation[0]);
  if (options.turns.size() == 1 && segments > 1) options.turns.assign(segments, options.turns[0]);
  if (options.easing.size() == 1 && segments > 1) options.easing.assign(segments, options.easing[0]);
  return {std::move(keys), std::move(options)};
}

}  // namespace

void bind_key_poses(py::module_& m) {
  m.def(
      "morph_key_poses",
      [](const py::object& keys_xy, const py::object& edges, const py::object& frames, const py::object& keys_at,
         const py::object& loop, const py::object& hold, const py::object& rotation, const py::object& turns,
         const py::object& steiner, const py::object& weights, const py::object& enclosure_sides,
         const py::object& verify, const py::object& frame_check, const py::object& correspond,
         const py::object& pins, const py::object& easing, const py::object& progress, const py::object& delay,
         const py::object& overlap) {
        KeyPoseInputs inputs = key_pose_inputs(keys_xy, edges, frames, keys_at, loop, hold, rotation, turns, steiner,
                                               weights, enclosure_sides, verify, frame_check, correspond, pins,
                                               easing, delay, overlap);
        const std::vector<sm::StickFigure>& keys = inputs.keys;
        const sm::KeyPoseMorphOptions& options = inputs.options;
        std::shared_ptr<sm::Progress> watched = to_progress(progress);
        sm::KeyPoseMorphResult result;
        {
          py::gil_scoped_release release;
          CallProgress installed(std::move(watched));
          result = sm::morph_key_poses(keys, options);
          installed.finished();
        }
        // Matched keys: the frames are the common figure's.
        const sm::StickFigure& figure = result.correspondence ? result.correspondence->keys[0] : keys[0];
        const std::size_t n = figure.vertices.size();
        py::dict dict;
        dict["frames"] = frames_array(result.frames, n);
        dict["times"] = py::array_t<double>(py::ssize_t(result.times.size()), result.times.data());
        dict["edges"] = to_edge_array(figure.edges);
        dict["keys_at"] = to_list(result.key_frames);
        dict["places"] = places_list(result.correspondence, keys.size(), n);
        if (result.correspondence) dict["correspondence"] = correspondence_list(*result.correspondence);
        py::list segment_list;
        for (const sm::KeyPoseSegment& segment : result.segments) segment_list.append(segment_dict(segment));
        dict["segments"] = segment_list;
        return dict;
      },
      py::arg("keys_xy"), py::arg("edges"), py::arg("frames") = py::none(), py::arg("keys_at") = py::none(),
      py::arg("loop") = false, py::arg("hold") = py::none(), py::arg("rotation") = py::none(),
      py::arg("turns") = py::none(), py::arg("steiner") = py::none(), py::arg("weights") = py::none(),
      py::arg("enclosure_sides") = py::none(), py::arg("verify") = py::none(), py::arg("frame_check") = py::none(),
      py::arg("correspond") = py::none(), py::arg("pins") = py::none(), py::arg("easing") = py::none(),
      py::arg("progress") = py::none(), py::arg("delay") = py::none(), py::arg("overlap") = py::none(),
      R"doc(Morphs a stick figure through a sequence of key poses (issue 28): one continuous,
valid motion that shows key k exactly at frame keys_at[k], its velocity continuous through
every key (unless hold stops it there). The same computation as
`stickmorph morph KEY1.json ... KEYK.json`.

Each segment is a rigid morph of its pair of keys with its own compatible triangulation,
following one as-rigid-as-possible guide through all keys; every frame is verified exactly.

Args:
  keys_xy: K >= 2 arrays, #V by 2 each: the keys, vertex i of each the same vertex (with
    correspond="auto" each key its own #V_k by 2).
  edges: #E by 2 integer array-like, the edges of every key; with correspond="auto" also a
    sequence of K of them, one per key.
  frames: the frames of the whole sequence (default 49 per segment + 1).
  keys_at: K frame numbers, strictly increasing from 0 to frames - 1 (below it with loop);
    default evenly spaced.
  loop: after the last key return to the first, at the last frame, smoothly.
  hold: one bool per key: stop the motion at that key.
  rotation: "short", "ccw" or "cw" for every segment, or one per segment.
  turns: extra whole turns for every segment, or one per segment.
  easing: "none" or "in-out" for every segment, or one per segment: an eased segment starts
    from rest and comes to rest (both its keys held).
  steiner, weights, enclosure_sides, verify, frame_check: as for morph().
  correspond: "index" (default) or "auto": keys drawn separately (other vertex counts,
    numbering, subdivision) are matched onto one common figure of m vertices, key 1's first,
    and every key vertex is a vertex of every frame.
  pins: with correspond="auto", #P by 2 (vertex of key 1, vertex of key 2) pairs, or a
    sequence of K - 1 such lists, list k for keys k and k + 1 in their own numbering.
  progress: optional stickmorph.Progress to watch and cancel the call from another thread
    (stages "correspond", "check", "triangulate" once per segment, "frames" counted in
    frames); None: the one a `with progress:` block installed on this thread, if any.
  delay, overlap: local timing as for morph(), given together: one delay weight per vertex of
    key 1 (with correspond="auto" a dummy takes the weight interpolated along its edge of
    key 1) and the overlap d in [0, 1). Each segment runs the delays on its own clock, key
    to key, so every key stays exact at its frame and lagging parts catch up by every key.

Returns:
  dict with "frames" (N by #V by 2 float64; frames[keys_at[k]] is key k exactly), "times"
  (N floats f / (N - 1)), "edges", "keys_at" (list of K ints) and "segments" (one dict per
  segment: "from_key", "to_key" (indices into keys_xy), "first_frame", "last_frame",
  "triangulation" (as morph()'s), "steiner_vertices", "similarity_factored",
  "guide_frames", "refined_frames", "milliseconds"), "places" (K dicts of #m arrays
  "vertex", "edge", "fraction": where frame vertex i is on key k's own drawing, its vertex, or
  -1 and a dummy at that fraction along that edge of the key's own edge list; by index
  vertex i is i) and with correspond="auto" "correspondence" (per pair of keys, how the
  match was found, as correspond()'s "stats").

Raises:
  InvalidFigureError: a key is not a valid stick figure (its message starts "key k: ").
  InvalidArgumentError: fewer than two keys, keys of other vertex counts, bad options
    (each message names the key, the frame or the option).
  IncompatibleFiguresError: two consecutive keys are not compatible, or with correspond="auto"
    cannot be matched ("key 2 and key 3: ...").
  NumericRangeError, VerificationError: as morph().
  CancelledError: progress.cancel() was called; nothing is returned.
)doc");

  // The stateful form, for scrubbing: set up once, then any frame or time.
  py::class_<sm::KeyPoseMorphSolver>(m, "KeyPoseMorphSolver", R"doc(The morph through key poses set up once
(keys matched and checked, the guide and every segment's triangulation and factorizations), then
any frame of the sequence or the figure at any time, each verified: for scrubbing a timeline.
Takes morph_key_poses()'s arguments; solver.frame(f) is morph_key_poses(...)["frames"][f]
bit for bit, in any order. progress= as for morph_key_poses() (its set-up is the long part:
stages "correspond", "check" and "triangulate").)doc")
      .def(py::init([](const py::object& keys_xy, const py::object& edges, const py::object& frames,
                       const py::object& keys_at, const py::object& loop, const py::object& hold,
                       const py::object& rotation, const py::object& turns, const py::object& steiner,
                       const py::object& weights, const py::object& enclosure_sides, const py::object& verify,
                       const py::object& frame_check, const py::object& correspond, const py::object& pins,
                       const py::object& easing, const py::object& progress, const py::object& delay,
                       const py::object& overlap) {
             KeyPoseInputs inputs = key_pose_inputs(keys_xy, edges, frames, keys_at, loop, hold, rotation, turns,
                                                    steiner, weights, enclosure_sides, verify, frame_check,
                                                    correspond, pins, easing, delay, overlap);
             std::shared_ptr<sm::Progress> watched = to_progress(progress);
             py::gil_scoped_release release;
             CallProgress installed(std::move(watched));
             auto solver = std::make_unique<sm::KeyPoseMorphSolver>(inputs.keys, inputs.options);
             installed.finished();
             return solver;
           }),
           py::arg("keys_xy"), py::arg("edges"), py::arg("frames") = py::none(), py::arg("keys_at") = py::none(),
           py::arg("loop") = false, py::arg("hold") = py::none(), py::arg("rotation") = py::none(),
           py::arg("turns") = py::none(), py::arg("steiner") = py::none(), py::arg("weights") = py::none(),
           py::arg("enclosure_sides") = py::none(), py::arg("verify") = py::none(),
           py::arg("frame_check") = py::none(), py::arg("correspond") = py::none(), py::arg("pins") = py::none(),
           py::arg("easing") = py::none(), py::arg("progress") = py::none(), py::arg("delay") = py::none(),
           py::arg("overlap") = py::none())
      .def(
          "solve",
          [](sm::KeyPoseMorphSolver& solver, const py::object& time) {
            const double t = to_time(time);
            std::vector<sm::Vec2> positions;
            {
              py::gil_scoped_release release;
              positions = solver.solve(t);
            }
            return to_point_array(positions);
          },
          py::arg("t"),
          "The figure (#V by 2) at time t in [0, 1] of the whole sequence (key k at keys_at[k] / (frame_count - 1)).")
      .def(
          "frame",
          [](sm::KeyPoseMorphSolver& solver, const py::object& f) {
            const long long index = to_count(f, "f");
            if (index > sm::kMaxMorphFrames)
              throw sm::InvalidArgumentError("frame must be between 0 and " +
                                             std::to_string(solver.frame_count() - 1) + ", got " +
                                             std::to_string(index));
            std::vector<sm::Vec2> positions;
            {
              py::gil_scoped_release release;
              positions = solver.frame(int(index));
            }
            return to_point_array(positions);
          },
          py::arg("f"), "Frame f (#V by 2) of the sequence's frame_count frames.")
      .def_property_readonly("frame_count", &sm::KeyPoseMorphSolver::frame_count)
      .def_property_readonly("keys_at", [](const sm::KeyPoseMorphSolver& solver) { return to_list(solver.key_frames()); })
      .def_property_readonly("edges",
                             [](const sm::KeyPoseMorphSolver& solver) { return to_edge_array(solver.keys()[0].edges); })
      .def_property_readonly("places",
                             [](const sm::KeyPoseMorphSolver& solver) {
                               return places_list(solver.correspondence(), solver.keys().size(),
                                                  solver.keys()[0].vertices.size());
                             })
      .def_property_readonly("segments", [](const sm::KeyPoseMorphSolver& solver) {
        py::list list;
        for (const sm::KeyPoseSegment& segment : solver.segments()) list.append(segment_dict(segment));
        return list;
      });
}

}  // namespace stickmorph::python
