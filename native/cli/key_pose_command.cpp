// The morph command's sequence form; see key_pose_command.h.
#include "key_pose_command.h"

#include <string>
#include <vector>

#include "output_files.h"
#include "timing_option.h"
#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/frame_certificate.h"
#include "stickmorph/io/result_files.h"
#include "stickmorph/io/svg_output.h"
#include "stickmorph/key_pose_morph.h"
#include "stickmorph/morph.h"
#include "stickmorph/similarity_motion.h"

namespace stickmorph::cli {
namespace {

// The pair morph's options that a sequence does not take (yet), and why.
struct Unsupported {
  const char* option;
  const char* why;
};
constexpr Unsupported kUnsupported[] = {
    {"--svg-triangulation", "each segment has its own triangulation; --svg draws the sequence's filmstrip"},
    {"--svg-compare-linear", "--svg draws the sequence's filmstrip; the straight-line comparison is built for "
                             "pairs"},
};

// --rotation, --easing and --turns: one value for every segment, or one per segment.
std::vector<std::string> comma_list(const std::string& text) {
  std::vector<std::string> entries;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    entries.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) return entries;
    start = comma + 1;
  }
}

// A per-segment option takes one value for every segment or one per segment.
void check_segment_count(const char* option, const char* what, std::size_t given, std::size_t segments) {
  if (given != 1 && given != segments)
    throw InvalidArgumentError("morph: " + std::string(option) + " takes one " + what +
                               " for every segment or one per segment (" + std::to_string(segments) + "), got " +
                               std::to_string(given));
}

// --rotation and --easing: comma-separated names, one per segment after
// the count is checked (empty when the option is absent).
template <class Parse>
auto per_segment(const ParsedArguments& arguments, const char* option, const char* what, std::size_t segments,
                 Parse parse) -> std::vector<decltype(parse(std::string()))> {
  std::vector<decltype(parse(std::string()))> values;
  const std::string* text = option_value(arguments, option);
  if (!text) return values;
  const std::vector<std::string> names = comma_list(*text);
  check_segment_count(option, what, names.size(), segments);
  for (std::size_t s = 0; s < segments; ++s) values.push_back(parse(names[names.size() == 1 ? 0 : s]));
  return values;
}

}  // namespace

bool is_key_pose_run(const ParsedArguments& arguments) {
  return arguments.positional.size() > 2 || option_value(arguments, "--keys-at") ||
         option_value(arguments, "--loop") || option_value(arguments, "--hold");
}

int run_key_poses(const ParsedArguments& arguments) {
  const std::string& output = required_option(arguments, "morph", "--output");
  for (const Unsupported& unsupported : kUnsupported)
    if (option_value(arguments, unsupported.option) || arguments.repeated.count(unsupported.option))
      throw InvalidArgumentError("morph: option " + std::string(unsupported.option) +
                                 " is not available for key poses: " + unsupported.why);
  // --pin S:T pins vertex S of key 1 to vertex T of key 2; the matching
  // carries the pinned vertex on through the later keys.
  std::vector<VertexPin> pins;
  if (const auto pin_texts = arguments.repeated.find("--pin"); pin_texts != arguments.repeated.end())
    for (const std::string& text : pin_texts->second) pins.push_back(parse_vertex_pin(text));
  if (const std::string* method = option_value(arguments, "--method"))
    if (parse_morph_method(*method) != MorphMethod::Rigid)
      throw InvalidArgumentError("morph: key poses are morphed with --method rigid only (its guide is what makes the "
                                 "motion smooth through the keys), got " + single_quoted(*method));
  std::vector<NamedPath> inputs;
  for (std::size_t k = 0; k < arguments.positional.size(); ++k)
    inputs.push_back({"KEY" + std::to_string(k + 1) + ".json", arguments.positional[k]});
  std::vector<NamedPath> written{{"--output", output}};
  const std::string* svg = option_value(arguments, "--svg");
  if (svg) written.push_back({"--svg", *svg});
  OutputFiles outputs("morph", written, inputs);

  const std::size_t keys = arguments.positional.size();
  KeyPoseMorphOptions options;
  options.loop = option_value(arguments, "--loop") != nullptr;
  const std::size_t segments = options.loop ? keys : keys - 1;
  options.frames = integer_option(arguments, "--frames");
  options.keys_at = integer_list_option(arguments, "--keys-at");
  const std::vector<long long> holds = integer_list_option(arguments, "--hold");
  if (!holds.empty()) {
    options.hold.assign(keys, false);
    for (long long key : holds) {
      if (key < 1 || key > static_cast<long long>(keys))
        throw InvalidArgumentError("morph: --hold names keys 1 to " + std::to_string(keys) + ", got " +
                                   std::to_string(key));
      options.hold[std::size_t(key - 1)] = true;
    }
  }
  options.rotation = per_segment(arguments, "--rotation", "direction", segments,
                                 [](const std::string& name) { return parse_rotation_direction(name); });
  options.easing =
      per_segment(arguments, "--easing", "easing", segments, [](const std::string& name) { return parse_easing(name); });
  if (option_value(arguments, "--turns")) {
    const std::vector<long long> turns = integer_list_option(arguments, "--turns");
    check_segment_count("--turns", "count", turns.size(), segments);
    for (std::size_t s = 0; s < segments; ++s) options.turns.push_back(turns[turns.size() == 1 ? 0 : s]);
  }
  if (const std::string* name = option_value(arguments, "--correspond"))
    options.correspond = parse_correspondence_mode(*name);
  check_pins_need_auto(options.correspond, pins, OptionSpelling::CommandLine, "morph: ");
  if (!pins.empty()) options.pins.push_back(pins);
  if (const std::string* name = option_value(arguments, "--steiner")) options.steiner = parse_steiner_method(*name);
  if (const std::string* name = option_value(arguments, "--weights")) options.weights = parse_weight_kind(*name);
  options.enclosure_sides = integer_option(arguments, "--enclosure-sides");
  if (option_value(arguments, "--no-verify")) options.verify = false;
  if (const std::string* name = option_value(arguments, "--frame-check")) options.frame_check = parse_frame_check(*name);
  options.timing = timing_option(arguments);

  std::vector<StickFigure> figures;
  for (const std::string& path : arguments.positional) figures.push_back(read_figure_file(path));
  if (options.timing) check_timing_length(arguments, *options.timing, figures[0].vertices.size(), arguments.positional[0]);
  const KeyPoseMorphResult result = morph_key_poses(figures, options);
  std::vector<std::string> files{key_pose_file_json(figures[0], result, options.verify.value_or(true))};
  if (svg) {
    // The frames' own figure: the matched one with --correspond auto.
    const StickFigure& drawn = result.correspondence ? result.correspondence->keys[0] : figures[0];
    files.push_back(key_pose_filmstrip_svg(drawn, result.frames, result.times, result.key_frames, 2,
                                           "stickmorph morph: " + std::to_string(keys) + " key poses"));
  }
  outputs.commit(files);
  return 0;
}

}  // namespace stickmorph::cli
