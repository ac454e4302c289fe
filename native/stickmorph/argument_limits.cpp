#include "stickmorph/argument_limits.h"

#include "stickmorph/errors.h"
#include "stickmorph/similarity_motion.h"

namespace stickmorph {

const std::vector<OptionName>& option_names() {
  static const std::vector<OptionName> table = {
      {Option::Frames, "--frames", "frames"},
      {Option::Method, "--method", "method"},
      {Option::Steiner, "--steiner", "steiner"},
      {Option::Weights, "--weights", "weights"},
      {Option::EnclosureSides, "--enclosure-sides", "enclosure_sides"},
      {Option::Verify, "--no-verify", "verify"},
      // compatible_triangulation only; the CLI has no command for it.
      {Option::SmoothingRounds, "", "smoothing_rounds"},
      // The rigid method's (issue 12).
      {Option::Rotation, "--rotation", "rotation"},
      {Option::Turns, "--turns", "turns"},
      {Option::Easing, "--easing", "easing"},
      // Figures drawn separately (issue 13).
      {Option::Correspond, "--correspond", "correspond"},
      {Option::Pins, "--pin", "pins"},
      {Option::FrameCheck, "--frame-check", "frame_check"},
      // Local timing (issue 31): the CLI reads weights and overlap from one
      // file; the keywords are delay= and overlap=, named by the first.
      {Option::Timing, "--timing", "delay"},
  };
  return table;
}

std::string describe_option(Option option, OptionSpelling spelling) {
  for (const OptionName& row : option_names()) {
    if (row.option != option) continue;
    if (spelling == OptionSpelling::CommandLine && *row.command_line != '\0')
      return std::string("option ") + row.command_line;
    return row.keyword;
  }
  throw InternalError("describe_option: option " + std::to_string(static_cast<int>(option)) +
                      " is missing from the option-name table");
}

int check_count(Option option, long long value, long long least, long long most, OptionSpelling spelling,
                const std::string& as_typed) {
  const auto shown = [&] { return as_typed.empty() ? std::to_string(value) : as_typed; };
  if (value < least)
    throw InvalidArgumentError(describe_option(option, spelling) + " must be at least " + std::to_string(least) +
                               ", got " + shown());
  if (value > most)
    throw InvalidArgumentError(describe_option(option, spelling) + " must be at most " + std::to_string(most) +
                               ", got " + shown());
  return static_cast<int>(value);
}

int check_frames(long long frames, OptionSpelling spelling, const std::string& as_typed) {
  return check_count(Option::Frames, frames, kMinMorphFrames, kMaxMorphFrames, spelling, as_typed);
}

int check_enclosure_sides(long long sides, OptionSpelling spelling, const std::string& as_typed) {
  return check_count(Option::EnclosureSides, sides, kMinEnclosureSides, kMaxEnclosureSides, spelling, as_typed);
}

int check_smoothing_rounds(long long rounds, OptionSpelling spelling, const std::string& as_typed) {
  return check_count(Option::SmoothingRounds, rounds, kMinSmoothingRounds, kMaxSmoothingRounds, spelling, as_typed);
}

int check_turns(long long turns, OptionSpelling spelling, const std::string& as_typed) {
  return check_count(Option::Turns, turns, -kMaxExtraTurns, kMaxExtraTurns, spelling, as_typed);
}

}  // namespace stickmorph
