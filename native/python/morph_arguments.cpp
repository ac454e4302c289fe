#include "morph_arguments.h"

#include <string>

#include "conversions.h"
#include "stickmorph/argument_limits.h"
#include "stickmorph/morph_options.h"

namespace stickmorph::python {

sm::MorphStickFiguresOptions to_morph_options(const py::object& frames, const py::object& steiner,
                                              const py::object& weights, const py::object& enclosure_sides,
                                              const py::object& method, const py::object& verify,
                                              const py::object& rotation, const py::object& turns,
                                              const py::object& easing, const py::object& correspond,
                                              const py::object& pins, const py::object& frame_check,
                                              const py::object& delay, const py::object& overlap) {
  constexpr sm::OptionSpelling kKeyword = sm::OptionSpelling::Keyword;
  sm::MorphStickFiguresOptions options;
  options.spelling = kKeyword;
  // The counts are checked as soon as they are read, with their text as
  // passed, so that a Python int beyond long long (saturated by to_count)
  // is quoted as given; check_morph_options checks them again.
  options.frames = sm::check_frames(to_count(frames, "frames"), kKeyword, py::str(frames));
  // None is the default, as for every other option.
  if (!method.is_none()) options.method = sm::parse_morph_method(to_name(method, "method"));
  if (!steiner.is_none()) options.steiner = sm::parse_steiner_method(to_name(steiner, "steiner"));
  if (!weights.is_none()) options.weights = sm::parse_weight_kind(to_name(weights, "weights"));
  if (!verify.is_none()) options.verify = to_flag(verify, "verify");
  if (!frame_check.is_none()) options.frame_check = sm::parse_frame_check(to_name(frame_check, "frame_check"));
  if (!enclosure_sides.is_none()) {
    options.enclosure_sides = to_count(enclosure_sides, "enclosure_sides");
    sm::check_count_option(sm::Option::EnclosureSides, *options.enclosure_sides, options.method, kKeyword,
                           py::str(enclosure_sides));
  }
  if (!rotation.is_none()) options.rotation = sm::parse_rotation_direction(to_name(rotation, "rotation"));
  if (!turns.is_none()) {
    options.turns = to_count(turns, "turns");
    sm::check_count_option(sm::Option::Turns, *options.turns, options.method, kKeyword, py::str(turns));
  }
  if (!easing.is_none()) options.easing = sm::parse_easing(to_name(easing, "easing"));
  if (!correspond.is_none()) options.correspond = sm::parse_correspondence_mode(to_name(correspond, "correspond"));
  options.pins = to_pins(pins);
  options.timing = to_local_timing(delay, overlap);
  sm::check_morph_options(options);
  return options;
}

}  // namespace stickmorph::python
