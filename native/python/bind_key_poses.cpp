// stickmorph.morph_key_poses: the morph through a sequence of key poses
// (issue 28), a thin shell over the engine's morph_key_poses
// (key_pose_morph.h), as `stickmorph morph KEY1.json ... KEYK.json` is.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "bindings.h"
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

}  // namespace

void bind_key_poses(py::module_& m) {
  m.def(
      "morph_key_poses",
      [](const py::object& keys_xy, const py::object& edges, const py::object& frames, const py::object& keys_at,
         const py::object& loop, const py::object& hold, const py::object& rotation, const py::object& turns,
         const py::object& steiner, const py::object& weights, const py::object& enclosure_sides,
         const py::object& verify, const py::object& frame_check) {
        // Arguments first, figures second, as morph() does.
        const sm::MorphStickFiguresOptions shared =
            to_morph_options(py::int_(sm::kDefaultMorphFrames), steiner, weights, enclosure_sides, py::str("rigid"),
                             verify, py::none(), py::none(), py::none(), py::none(), py::none(), frame_check);
        sm::KeyPoseMorphOptions options;
        options.steiner = shared.steiner;
        options.weights = shared.weights;
        options.enclosure_sides = shared.enclosure_sides;
        options.verify = shared.verify;
        options.frame_check = shared.frame_check;
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
        if (!is_sequence(keys_xy)) throw sm::InvalidArgumentError("keys_xy must be a sequence of #V by 2 arrays");
        const py::sequence key_items = keys_xy.cast<py::sequence>();
        std::vector<sm::StickFigure> keys;
        for (std::size_t k = 0; k < key_items.size(); ++k)
          keys.push_back(make_named_figure(key_items[k], edges, "keys_xy[" + std::to_string(k) + "]", "edges",
                                           "key " + std::to_string(k + 1)));
        // One rotation or turn count for every segment, as the CLI takes it.
        const std::size_t segments = options.loop ? keys.size() : keys.size() - (keys.empty() ? 0 : 1);
        if (options.rotation.size() == 1 && segments > 1) options.rotation.assign(segments, options.rotation[0]);
        if (options.turns.size() == 1 && segments > 1) options.turns.assign(segments, options.turns[0]);
        sm::KeyPoseMorphResult result;
        {
          py::gil_scoped_release release;
          result = sm::morph_key_poses(keys, options);
        }
        py::dict dict;
        dict["frames"] = frames_array(result.frames, keys[0].vertices.size());
        dict["times"] = py::array_t<double>(py::ssize_t(result.times.size()), result.times.data());
        dict["edges"] = to_edge_array(keys[0].edges);
        dict["keys_at"] = to_list(result.key_frames);
        py::list segment_list;
        for (const sm::KeyPoseSegment& segment : result.segments) segment_list.append(segment_dict(segment));
        dict["segments"] = segment_list;
        return dict;
      },
      py::arg("keys_xy"), py::arg("edges"), py::arg("frames") = py::none(), py::arg("keys_at") = py::none(),
      py::arg("loop") = false, py::arg("hold") = py::none(), py::arg("rotation") = py::none(),
      py::arg("turns") = py::none(), py::arg("steiner") = py::none(), py::arg("weights") = py::none(),
      py::arg("enclosure_sides") = py::none(), py::arg("verify") = py::none(), py::arg("frame_check") = py::none(),
      R"doc(Morphs a stick figure through a sequence of key poses (issue 28): one continuous,
valid motion that shows key k exactly at frame keys_at[k], its velocity continuous through
every key (unless hold stops it there). The same computation as
`stickmorph morph KEY1.json ... KEYK.json`.

Each segment is a rigid morph of its pair of keys with its own compatible triangulation,
following one as-rigid-as-possible guide through all keys; every frame is verified exactly.

Args:
  keys_xy: K >= 2 arrays, #V by 2 each: the keys, vertex i of each the same vertex.
  edges: #E by 2 integer array-like, the edges of every key.
  frames: the frames of the whole sequence (default 49 per segment + 1).
  keys_at: K frame numbers, strictly increasing from 0 to frames - 1 (below it with loop);
    default evenly spaced.
  loop: after the last key return to the first, at the last frame, smoothly.
  hold: one bool per key: stop the motion at that key.
  rotation: "short", "ccw" or "cw" for every segment, or one per segment.
  turns: extra whole turns for every segment, or one per segment.
  steiner, weights, enclosure_sides, verify, frame_check: as for morph().

Returns:
  dict with "frames" (N by #V by 2 float64; frames[keys_at[k]] is key k exactly), "times"
  (N floats f / (N - 1)), "edges", "keys_at" (list of K ints) and "segments" (one dict per
  segment: "from_key", "to_key" (indices into keys_xy), "first_frame", "last_frame",
  "triangulation" (as morph()'s), "steiner_vertices", "similarity_factored",
  "guide_frames", "refined_frames", "milliseconds").

Raises:
  InvalidFigureError: a key is not a valid stick figure (its message starts "key k: ").
  InvalidArgumentError: fewer than two keys, keys of other vertex counts, bad options
    (each message names the key, the frame or the option).
  IncompatibleFiguresError: two consecutive keys are not compatible ("key 2 and key 3: ...").
  NumericRangeError, VerificationError: as morph().
)doc");
}

}  // namespace stickmorph::python
