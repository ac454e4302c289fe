// The CLI's commands as data and the parsing of their arguments: each
// command is a CommandSpec (name, positionals, options, help texts, run
// function), and parse_arguments turns its command line into
// ParsedArguments with CLI11, every mistake one InvalidArgumentError that
// names the command (FORMAT.md's one-line errors), never CLI11's report.
// Apart from main.cpp so that the commands read as what they do, not how
// their arguments are taken apart.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stickmorph::cli {

/// An option a command accepts, e.g. {"--frames", "", "N", ...}.
struct OptionSpec {
  std::string_view name;        ///< long form, "--frames"
  std::string_view short_name;  ///< "-o", or empty
  std::string_view value_name;  ///< "N" if the option takes a value, empty for a flag
  std::string help;             ///< built at start-up where it quotes the engine's limits
  bool repeatable = false;      ///< may be given more than once (--pin); all values kept in order
};

/// A command's arguments after parsing: positionals in order, options by
/// long name (flags map to an empty string).
struct ParsedArguments {
  std::vector<std::string> positional;
  std::map<std::string, std::string, std::less<>> options;
  /// Repeatable options: every value, in command-line order.
  std::map<std::string, std::vector<std::string>, std::less<>> repeated;
};

struct CommandSpec {
  std::string_view name;
  std::vector<std::string_view> positional_names;  ///< each one required
  /// Further positionals the command accepts after those ("[KEY3.json ...]"
  /// in the usage line), or empty for none.
  std::string_view more_positionals;
  std::vector<OptionSpec> options;
  std::string_view summary;      ///< one line for the global help
  std::string_view description;  ///< paragraph for the command's help
  int (*run)(const ParsedArguments& arguments);
};

/// "stickmorph morph SOURCE.json TARGET.json [options]".
std::string usage_line(const CommandSpec& command);

/// Argument mistakes name the command and point at its help.
/// @throws InvalidArgumentError "<command>: <what> (usage: ...; see ...)".
[[noreturn]] void fail_usage(const CommandSpec& command, const std::string& what);

/// "'text'".
std::string single_quoted(std::string_view text);

/// The text of 'stickmorph COMMAND --help'.
std::string command_help(const CommandSpec& command);

/// The value of an option given once, or null.
const std::string* option_value(const ParsedArguments& arguments, std::string_view name);

/// The value of an option the command needs.
/// @throws InvalidArgumentError "<command>: missing option <name> ...".
const std::string& required_option(const ParsedArguments& arguments, std::string_view command,
                                   std::string_view name);

/// A whole number option, e.g. --frames; its range is the engine's to check
/// (argument_limits.h), so that the CLI and the module refuse the same values.
/// @throws InvalidArgumentError naming the option for anything but a whole number.
std::optional<long long> integer_option(const ParsedArguments& arguments, std::string_view name);

/// A finite number option, e.g. --tolerance 0.5.
/// @throws InvalidArgumentError naming the option for anything else.
std::optional<double> number_option(const ParsedArguments& arguments, std::string_view name);

/// A comma-separated list of whole numbers, e.g. --keys-at 0,20,48.
/// @throws InvalidArgumentError naming the option and the entry.
std::vector<long long> integer_list_option(const ParsedArguments& arguments, std::string_view name);

/// Parses a command's arguments into positionals and options. Accepts
/// "--name value", "--name=value", "-o value", "-o=value"; "--" ends the
/// options so that a file named "-x.json" can still be passed.
/// @returns false if help was asked (-h or --help anywhere).
/// @throws InvalidArgumentError (fail_usage) for every mistake.
bool parse_arguments(const CommandSpec& command, const std::vector<std::string>& arguments,
                     ParsedArguments& parsed);

}  // namespace stickmorph::cli
