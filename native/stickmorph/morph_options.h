// The rules of the morph's options, in one place: which methods each option
// applies to, its range or its accepted names, and its default (the table
// morph_option_rules), and the check that refuses what breaks them
// (check_morph_options).
//
// Every interface (the CLI, the Python module and through it the Blender
// add-on) asks these functions instead of keeping its own copy of a rule,
// so that an option greyed out in the add-on is the one the engine refuses,
// with the same words in every spelling (argument_limits.h).
#pragma once

#include <string>
#include <vector>

#include "stickmorph/argument_limits.h"
#include "stickmorph/figure_correspondence.h"

namespace stickmorph {

enum class MorphMethod;
struct MorphStickFiguresOptions;

/// A set of MorphMethod values, one bit per method.
using MethodSet = unsigned;
MethodSet method_bit(MorphMethod method);
constexpr MethodSet kAllMethods = 7;

/// What kind of value an option takes, and so which fields of its rule mean
/// something.
enum class OptionValueKind {
  Count,  ///< a whole number in [least, most]; default_count
  Name,   ///< one of choices; default_name
  Flag,   ///< true or false; default_flag
  Pins,   ///< vertex pairs "S:T"; no default (none given)
  Timing, ///< delay weights per vertex and an overlap (local_timing.h); no default (none given)
};

/// One option of morph_stick_figures as the interfaces expose it.
struct MorphOptionRule {
  Option option;
  MethodSet methods;  ///< the methods it applies to; given with another, it is refused
  /// Why it is refused with a method it does not apply to, quoted after the
  /// option's name ("" where it applies to every method).
  const char* refused_because;
  OptionValueKind kind;
  long long least = 0, most = 0, default_count = 0;  ///< Count
  std::vector<std::string> choices;                   ///< Name: every accepted name
  std::string default_name;                            ///< Name
  bool default_flag = false;                           ///< Flag
};

/// Every option the morph takes, in the order check_morph_options refuses
/// them (the order the CLI's checks always had, so that the first option
/// named in a message stays the same).
const std::vector<MorphOptionRule>& morph_option_rules();

/// The rule of `option`. @throws InternalError if it has none.
const MorphOptionRule& morph_option_rule(Option option);

/// Whether `option` applies to `method`.
bool option_applies(Option option, MorphMethod method);

/// A count option (frames, enclosure_sides, turns) as soon as an interface
/// has read it, with `method` already known: its range is checked if the
/// option applies to the method, so that a bad value is reported before the
/// options read after it and quoted `as_typed` (argument_limits.h's
/// check_count); one that does not apply is left for check_morph_options to
/// refuse by name, since its value does not matter then.
/// @throws InvalidArgumentError as check_count.
void check_count_option(Option option, long long value, MorphMethod method, OptionSpelling spelling,
                        const std::string& as_typed = {});

/// Pins given with a correspondence mode: pins need correspond = Auto.
/// `command`, if not empty, starts the message ("morph: "), as the CLI
/// names the command its option came with.
/// @throws InvalidArgumentError "option --pin needs --correspond auto (...)"
///         or "pins need correspond='auto' (...)".
void check_pins_need_auto(CorrespondenceMode mode, const std::vector<VertexPin>& pins, OptionSpelling spelling,
                          const std::string& command = {});

/// Checks `options` without morphing: what morph_stick_figures does first.
/// Interfaces call it before reading input files, so that a bad option is
/// reported before a file error and before any work.
/// @throws InvalidArgumentError: frames or enclosure_sides out of range, or
///         an option the linear method would ignore (steiner, weights,
///         enclosure_sides, verify, frame_check, keep_node_frames), or a
///         rigid-only option (rotation, turns, easing) with another method,
///         or frame_check with verify false, or pins without
///         correspond = Auto, or local timing (rigid only) with another
///         method.
void check_morph_options(const MorphStickFiguresOptions& options);

}  // namespace stickmorph
