// Limits on numeric options and the names options go by, shared by every
// interface: the engine entry (morph_stick_figures), the CLI, the Python
// module (which exports them as stickmorph.limits and stickmorph.OPTION_NAMES
// for the add-on and help texts).
//
// The counts scale work, not input: a count the engine would accept but
// spend minutes or all memory on is refused at the interface with an
// InvalidArgumentError instead of hanging the caller. Checking them here, in
// one function per option, is what makes the CLI and the module refuse the
// same values with the same words.
#pragma once

#include <string>
#include <vector>

#include "stickmorph/morph.h"  // kMaxMorphFrames, defined next to the morph that needs it

namespace stickmorph {

/// The fewest frames of a morph: its two ends.
constexpr int kMinMorphFrames = 2;

/// The fewest sides of the common enclosure: a triangle.
constexpr int kMinEnclosureSides = 3;

/// The largest number of sides of the common enclosure (--enclosure-sides,
/// enclosure_sides=). The annulus between figure and enclosure is
/// triangulated in time quadratic in the sides: 0.1 s for 1000 on the letter
/// A, 6 s for 10000, over a minute for 30000. The paper uses a hexagon.
constexpr int kMaxEnclosureSides = 1000;

/// Laplacian smoothing rounds of compatible_triangulation: 0 (none) to
/// kMaxSmoothingRounds. Each round moves every Steiner vertex once; the
/// default is 10.
constexpr int kMinSmoothingRounds = 0;
constexpr int kMaxSmoothingRounds = 1000;

/// Defaults of the options below, the same in every interface.
constexpr int kDefaultMorphFrames = 50;
constexpr int kDefaultEnclosureSides = 6;
constexpr int kDefaultSmoothingRounds = 10;

/// The options of Algorithm 3 that an interface exposes.
enum class Option {
  Frames,
  Method,
  Steiner,
  Weights,
  EnclosureSides,
  Verify,
  SmoothingRounds,
  Rotation,
  Turns,
  Easing,
  Correspond,
  Pins,
  FrameCheck,
  Timing,  ///< per-vertex delay weights and an overlap (local_timing.h)
};

/// Which interface's names messages use: the CLI's "--enclosure-sides" or
/// the Python keyword (and C++ field) "enclosure_sides".
enum class OptionSpelling { CommandLine, Keyword };

/// One row of the option-name table.
struct OptionName {
  Option option;
  const char* command_line;  ///< "--enclosure-sides"; "--no-verify" for Verify; "" if the CLI has none
  const char* keyword;       ///< "enclosure_sides"
};

/// Every option, in the order of the enum.
const std::vector<OptionName>& option_names();

/// How messages name an option: "option --frames" or "frames".
std::string describe_option(Option option, OptionSpelling spelling);

/// A count option in [least, most]. Takes long long so that an interface
/// can hand over values beyond int (Python ints) for the message.
/// `as_typed`, if not empty, is the value as the user wrote it, quoted in
/// the message instead of `value`: a Python int beyond long long arrives
/// saturated, and the message should still show what was passed.
/// @throws InvalidArgumentError "<option> must be at least <least>, got <v>"
///         or "... at most <most>, got <v>".
int check_count(Option option, long long value, long long least, long long most, OptionSpelling spelling,
                const std::string& as_typed = {});

/// check_count with each option's own limits.
int check_frames(long long frames, OptionSpelling spelling, const std::string& as_typed = {});
int check_enclosure_sides(long long sides, OptionSpelling spelling, const std::string& as_typed = {});
int check_smoothing_rounds(long long rounds, OptionSpelling spelling, const std::string& as_typed = {});
/// Whole extra turns of the rigid morph, -kMaxExtraTurns to kMaxExtraTurns.
int check_turns(long long turns, OptionSpelling spelling, const std::string& as_typed = {});

}  // namespace stickmorph
