// The `stickmorph` command-line tool (../../shared/FORMAT.md, docs/CLI.md).
//
// A thin shell over the engine: it parses arguments, runs one command from
// the command table and turns every failure into one line on stderr with
// exit code 2. Adding a command means writing its run function and one
// table entry; argument checking, --help and error reporting come for free.
#include <cstdio>
#include <exception>
#include <iostream>
#include <map>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_io.h"

namespace stickmorph {
namespace {

constexpr const char* kVersion = STICKMORPH_VERSION;  // from CMake

// Exit codes of FORMAT.md.
constexpr int kExitSuccess = 0;
constexpr int kExitIncompatible = 1;  // only `check`
constexpr int kExitError = 2;

/// An option a command accepts, e.g. {"--frames", "", "N", ...}.
struct OptionSpec {
  std::string_view name;        ///< long form, "--frames"
  std::string_view short_name;  ///< "-o", or empty
  std::string_view value_name;  ///< "N" if the option takes a value, empty for a flag
  std::string_view help;
};

/// A command's arguments after parsing: positionals in order, options by
/// long name (flags map to an empty string).
struct ParsedArguments {
  std::vector<std::string> positional;
  std::map<std::string, std::string, std::less<>> options;
};

struct CommandSpec {
  std::string_view name;
  std::vector<std::string_view> positional_names;  ///< each one required
  std::vector<OptionSpec> options;
  std::string_view summary;      ///< one line for the global help
  std::string_view description;  ///< paragraph for the command's help
  int (*run)(const ParsedArguments& arguments);
};

std::string usage_line(const CommandSpec& command) {
  std::string line = "stickmorph " + std::string(command.name);
  for (std::string_view positional : command.positional_names) {
    line += " " + std::string(positional);
  }
  if (!command.options.empty()) line += " [options]";
  return line;
}

// Argument mistakes name the command and point at its help.
[[noreturn]] void fail_usage(const CommandSpec& command, const std::string& what) {
  throw InvalidArgumentError(std::string(command.name) + ": " + what + " (usage: " +
                             usage_line(command) + "; see 'stickmorph " +
                             std::string(command.name) + " --help')");
}

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

bool is_help_flag(std::string_view argument) { return argument == "--help" || argument == "-h"; }

// Writes text to stdout and reports a failed write (a closed pipe, a full
// disk) as an error instead of a silent success.
void write_stdout(const std::string& text) {
  std::cout << text;
  std::cout.flush();
  if (!std::cout) throw Error("cannot write to standard output");
}

// -- commands ---------------------------------------------------------------

int run_check(const ParsedArguments& arguments) {
  const StickFigure source = read_figure_file(arguments.positional[0]);
  const StickFigure target = read_figure_file(arguments.positional[1]);
  const CompatibilityReport report = check_compatibility(source, target);
  if (report.compatible()) {
    write_stdout("compatible\n");
    return kExitSuccess;
  }
  write_stdout("incompatible: " + report.reason + "\n");
  return kExitIncompatible;
}

const std::vector<CommandSpec>& commands() {
  static const std::vector<CommandSpec> table = {
      {"check",
       {"SOURCE.json", "TARGET.json"},
       {},
       "decide whether two stick figures are compatible",
       "Decides whether the two figures, whose vertices correspond by index, are\n"
       "compatible (same cyclic order of edges around every vertex and the same\n"
       "exterior sequence; Surazhsky & Gotsman 2001, section 2.1). Prints\n"
       "\"compatible\" (exit 0) or \"incompatible: <reason naming vertices>\" (exit 1).",
       &run_check},
  };
  return table;
}

std::string command_names() {
  std::string names;
  for (const CommandSpec& command : commands()) {
    if (!names.empty()) names += ", ";
    names += command.name;
  }
  return names;
}

std::string global_help() {
  std::string text =
      "usage: stickmorph COMMAND [ARGUMENTS]\n"
      "       stickmorph --help | --version\n"
      "\n"
      "Morphs planar stick figures (connected straight-line plane graphs) following\n"
      "Surazhsky & Gotsman, \"Morphing Stick Figures Using Optimized Compatible\n"
      "Triangulations\", 2001. Figures are JSON files:\n"
      "  {\"name\": \"...\", \"vertices\": [[x, y], ...], \"edges\": [[i, j], ...]}\n"
      "\n"
      "commands:\n";
  for (const CommandSpec& command : commands()) {
    text += "  " + usage_line(command) + "\n      " + std::string(command.summary) + "\n";
  }
  text +=
      "\n"
      "options:\n"
      "  -h, --help     print this help (or 'stickmorph COMMAND --help')\n"
      "  --version      print the version\n"
      "\n"
      "exit status: 0 success; 1 incompatible figures (check); 2 bad input or\n"
      "failure, with one line 'error: ...' on standard error.\n";
  return text;
}

std::string command_help(const CommandSpec& command) {
  std::string text =
      "usage: " + usage_line(command) + "\n\n" + std::string(command.description) + "\n";
  text += "\noptions:\n";
  for (const OptionSpec& option : command.options) {
    std::string left = "  ";
    if (!option.short_name.empty()) left += std::string(option.short_name) + ", ";
    left += std::string(option.name);
    if (!option.value_name.empty()) left += " " + std::string(option.value_name);
    text += left + "\n      " + std::string(option.help) + "\n";
  }
  text += "  -h, --help\n      print this help\n";
  return text;
}

const OptionSpec* find_option(const CommandSpec& command, std::string_view name) {
  for (const OptionSpec& option : command.options) {
    if (option.name == name || (!option.short_name.empty() && option.short_name == name)) {
      return &option;
    }
  }
  return nullptr;
}

// Splits a command's arguments into positionals and options. Accepts
// "--name value", "--name=value", "-o value"; "--" ends the options so that a
// file named "-x.json" can still be passed. Returns false if help was asked.
bool parse_arguments(const CommandSpec& command, const std::vector<std::string>& arguments,
                     ParsedArguments& parsed) {
  bool options_ended = false;
  for (std::size_t k = 0; k < arguments.size(); ++k) {
    const std::string& argument = arguments[k];
    const bool looks_like_option = argument.size() > 1 && argument[0] == '-';
    if (options_ended || !looks_like_option) {
      parsed.positional.push_back(argument);
      continue;
    }
    if (argument == "--") {
      options_ended = true;
      continue;
    }
    if (is_help_flag(argument)) return false;
    const std::size_t equals = argument.find('=');
    const std::string name = argument.substr(0, equals);
    const OptionSpec* option = find_option(command, name);
    if (option == nullptr) fail_usage(command, "unknown option " + quoted(name));
    const std::string long_name(option->name);
    if (parsed.options.count(long_name) != 0) {
      fail_usage(command, "option " + quoted(long_name) + " given twice");
    }
    if (option->value_name.empty()) {
      if (equals != std::string::npos) {
        fail_usage(command, "option " + quoted(long_name) + " takes no value");
      }
      parsed.options[long_name] = "";
    } else if (equals != std::string::npos) {
      parsed.options[long_name] = argument.substr(equals + 1);
    } else {
      if (k + 1 >= arguments.size()) {
        fail_usage(command, "option " + quoted(long_name) + " needs a value " +
                                std::string(option->value_name));
      }
      parsed.options[long_name] = arguments[++k];
    }
  }
  const std::size_t expected = command.positional_names.size();
  if (parsed.positional.size() < expected) {
    fail_usage(command, "missing argument " +
                            std::string(command.positional_names[parsed.positional.size()]));
  }
  if (parsed.positional.size() > expected) {
    fail_usage(command, "unexpected extra argument " + quoted(parsed.positional[expected]));
  }
  return true;
}

int run(const std::vector<std::string>& arguments) {
  if (arguments.empty()) {
    throw InvalidArgumentError("missing command; commands: " + command_names() +
                               " (see 'stickmorph --help')");
  }
  const std::string& first = arguments[0];
  const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
  if (is_help_flag(first) || first == "--version") {
    if (!rest.empty()) {
      throw InvalidArgumentError(first + " takes no arguments, got " + quoted(rest[0]));
    }
    write_stdout(first == "--version" ? std::string("stickmorph ") + kVersion + "\n"
                                      : global_help());
    return kExitSuccess;
  }
  for (const CommandSpec& command : commands()) {
    if (command.name != first) continue;
    ParsedArguments parsed;
    if (!parse_arguments(command, rest, parsed)) {
      write_stdout(command_help(command));
      return kExitSuccess;
    }
    return command.run(parsed);
  }
  const bool looks_like_option = first.size() > 1 && first[0] == '-';
  const std::string what = looks_like_option ? "unknown option " : "unknown command ";
  throw InvalidArgumentError(what + quoted(first) + "; commands: " + command_names() +
                             " (see 'stickmorph --help')");
}

// FORMAT.md promises exactly one line on stderr. Messages can quote paths
// or names from the input, which may hold line breaks; those are escaped.
std::string one_line(std::string_view message) {
  std::string line;
  line.reserve(message.size());
  for (const char byte : message) {
    const auto c = static_cast<unsigned char>(byte);
    if (c == '\n') {
      line += "\\n";
    } else if (c == '\r') {
      line += "\\r";
    } else if (c < 0x20 || c == 0x7F) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\x%02X", static_cast<unsigned>(c));
      line += escape;
    } else {
      line += byte;
    }
  }
  return line;
}

// Uses stdio rather than iostreams so that reporting an error does not
// depend on the state of std::cout, which may be what failed. Takes views so
// that the caller builds no string that could throw inside its handler.
void print_error(std::string_view prefix, std::string_view message) noexcept {
  try {
    const std::string line = "error: " + std::string(prefix) + one_line(message) + "\n";
    std::fputs(line.c_str(), stderr);
  } catch (...) {
    // Out of memory while building the message: say so without allocating.
    std::fputs("error: out of memory\n", stderr);
  }
  std::fflush(stderr);
}

}  // namespace
}  // namespace stickmorph

int main(int argc, char** argv) {
  using namespace stickmorph;
  try {
    const std::vector<std::string> arguments(argv + (argc > 0 ? 1 : 0), argv + argc);
    return run(arguments);
  } catch (const InternalError& error) {
    print_error("internal error: ", error.what());
  } catch (const Error& error) {
    print_error("", error.what());
  } catch (const std::bad_alloc&) {
    print_error("", "out of memory");
  } catch (const std::exception& error) {
    print_error("internal error: ", error.what());
  } catch (...) {
    print_error("internal error: ", "unknown exception");
  }
  return kExitError;
}
