#include "argument_parsing.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>

#include "stickmorph/errors.h"

namespace stickmorph::cli {
namespace {

// The argument before "--", if any, that names `option` (as "--name" or
// "--name=value"); `with_value` selects the "=value" form.
std::optional<std::size_t> find_argument(const std::vector<std::string>& arguments, const OptionSpec& option,
                                         bool with_value) {
  for (std::size_t k = 0; k < arguments.size() && arguments[k] != "--"; ++k) {
    const std::string& argument = arguments[k];
    const std::size_t equals = argument.find('=');
    const std::string name = argument.substr(0, equals);
    if (name != option.name && (option.short_name.empty() || name != option.short_name)) continue;
    if ((equals != std::string::npos) == with_value) return k;
  }
  return std::nullopt;
}

// CLI11 reports a value given to a flag and an option without its value
// both as ArgumentMismatch, in its own words; FORMAT.md's one-line errors
// name the option the way this CLI always has, so tell the two apart from
// the arguments themselves (not from CLI11's text, which changes between
// versions).
[[noreturn]] void fail_mismatch(const CommandSpec& command, const std::vector<std::string>& arguments,
                                const CLI::ParseError& error) {
  for (const OptionSpec& option : command.options)
    if (option.value_name.empty() && find_argument(arguments, option, true))
      fail_usage(command, "option " + single_quoted(option.name) + " takes no value");
  for (const OptionSpec& option : command.options) {
    if (option.value_name.empty()) continue;
    const auto bare = find_argument(arguments, option, false);
    const auto joined = find_argument(arguments, option, true);
    const bool at_end = bare && (*bare + 1 == arguments.size() || arguments[*bare + 1] == "--");
    const bool empty_join = joined && arguments[*joined].back() == '=';
    if (at_end || empty_join)
      fail_usage(command, "option " + single_quoted(option.name) + " needs a value " + std::string(option.value_name));
  }
  fail_usage(command, error.what());
}

}  // namespace


std::string usage_line(const CommandSpec& command) {
  std::string line = "stickmorph " + std::string(command.name);
  for (std::string_view positional : command.positional_names) {
    line += " " + std::string(positional);
  }
  if (!command.more_positionals.empty()) line += " " + std::string(command.more_positionals);
  if (!command.options.empty()) line += " [options]";
  return line;
}

// Argument mistakes name the command and point at its help.
[[noreturn]] void fail_usage(const CommandSpec& command, const std::string& what) {
  throw InvalidArgumentError(std::string(command.name) + ": " + what + " (usage: " +
                             usage_line(command) + "; see 'stickmorph " +
                             std::string(command.name) + " --help')");
}

std::string single_quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

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

// Parses a command's arguments with CLI11 into positionals and options.
// Accepts "--name value", "--name=value", "-o value"; "--" ends the options
// so that a file named "-x.json" can still be passed. Returns false if help
// was asked (-h or --help anywhere). Every mistake becomes one
// InvalidArgumentError naming the command (fail_usage), never CLI11's
// multi-line report.
bool parse_arguments(const CommandSpec& command, const std::vector<std::string>& arguments,
                     ParsedArguments& parsed) {
  CLI::App app{std::string(command.summary), "stickmorph " + std::string(command.name)};
  app.set_help_flag("-h,--help");
  // Every value is kept as text: the command converts and checks it (the
  // engine's limits, its own wording), and a repeated option is refused
  // below rather than by CLI11's policy so that the message names it.
  std::vector<std::vector<std::string>> values(command.options.size());
  std::vector<CLI::Option*> handles;
  for (std::size_t k = 0; k < command.options.size(); ++k) {
    const OptionSpec& option = command.options[k];
    std::string names(option.name);
    if (!option.short_name.empty()) names = std::string(option.short_name) + "," + names;
    if (option.value_name.empty()) {
      handles.push_back(app.add_flag(names)->description(std::string(option.help))->disable_flag_override());
    } else {
      handles.push_back(app.add_option(names, values[k], std::string(option.help))
                            ->type_name(std::string(option.value_name))
                            ->expected(1)
                            ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll));
    }
  }
  std::vector<std::string> files(command.positional_names.size());
  for (std::size_t k = 0; k < files.size(); ++k)
    app.add_option(std::string(command.positional_names[k]), files[k])->required();
  // The positionals after those, in order (CLI11 fills the required ones first).
  std::vector<std::string> more_files;
  if (!command.more_positionals.empty()) app.add_option("MORE", more_files);

  // "-o=x.json" is "-o x.json", as "--output=x.json" is: CLI11 would take
  // "=x.json" as the value and write a file of that name.
  std::vector<std::string> split;
  bool options_over = false;
  for (const std::string& argument : arguments) {
    options_over = options_over || argument == "--";
    const OptionSpec* joined = nullptr;
    if (!options_over)
      for (const OptionSpec& option : command.options)
        if (!option.short_name.empty() && argument.size() > option.short_name.size() &&
            argument.compare(0, option.short_name.size(), option.short_name) == 0 &&
            argument[option.short_name.size()] == '=')
          joined = &option;
    if (joined == nullptr) {
      split.push_back(argument);
      continue;
    }
    split.push_back(std::string(joined->short_name));
    split.push_back(argument.substr(joined->short_name.size() + 1));
  }
  const auto options_end = std::find(split.begin(), split.end(), std::string("--"));
  std::vector<std::string> reversed(split.rbegin(), split.rend());  // CLI11 pops from the back
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    return false;
  } catch (const CLI::ArgumentMismatch& error) {
    fail_mismatch(command, split, error);
  } catch (const CLI::RequiredError&) {
    for (std::size_t k = 0; k < files.size(); ++k)
      if (app.get_option(std::string(command.positional_names[k]))->count() == 0)
        fail_usage(command, "missing argument " + std::string(command.positional_names[k]));
    fail_usage(command, "missing argument");
  } catch (const CLI::ExtrasError&) {
    // The first argument CLI11 could not place, in command-line order.
    const std::string first = app.remaining().front();
    if (first.size() > 1 && first[0] == '-' && std::find(split.begin(), options_end, first) != options_end)
      fail_usage(command, "unknown option " + single_quoted(first.substr(0, first.find('='))));
    fail_usage(command, "unexpected extra argument " + single_quoted(first));
  } catch (const CLI::ParseError& error) {
    fail_usage(command, error.what());
  }
  for (std::size_t k = 0; k < command.options.size(); ++k) {
    const OptionSpec& option = command.options[k];
    if (option.repeatable) {
      if (handles[k]->count() > 0) parsed.repeated[std::string(option.name)] = values[k];
      continue;
    }
    if (handles[k]->count() > 1) fail_usage(command, "option " + single_quoted(option.name) + " given twice");
    if (handles[k]->count() == 1)
      parsed.options[std::string(option.name)] = option.value_name.empty() ? std::string() : values[k].front();
  }
  // CLI11 reads "-1" as a number and places it as a file; docs/CLI.md
  // promises that before "--" every argument starting with '-' (but "-")
  // is an option.
  for (const std::string& file : files)
    if (file.size() > 1 && file[0] == '-' && std::find(split.begin(), options_end, file) != options_end)
      fail_usage(command, "unknown option " + single_quoted(file.substr(0, file.find('='))));
  for (std::size_t k = 0; k < files.size(); ++k) {
    // "" would otherwise surface as ": cannot read file", naming nothing.
    if (files[k].empty())
      fail_usage(command, "empty file name given for " + std::string(command.positional_names[k]));
  }
  for (const std::string& file : more_files) {
    if (file.size() > 1 && file[0] == '-' && std::find(split.begin(), options_end, file) != options_end)
      fail_usage(command, "unknown option " + single_quoted(file.substr(0, file.find('='))));
    if (file.empty()) fail_usage(command, "empty file name given as argument " + std::to_string(files.size() + 1));
    files.push_back(file);
  }
  parsed.positional = std::move(files);
  return true;
}

const std::string* option_value(const ParsedArguments& arguments, std::string_view name) {
  const auto it = arguments.options.find(name);
  return it == arguments.options.end() ? nullptr : &it->second;
}

const std::string& required_option(const ParsedArguments& arguments, std::string_view command,
                                   std::string_view name) {
  const std::string* value = option_value(arguments, name);
  if (value == nullptr)
    throw InvalidArgumentError(std::string(command) + ": missing option " + std::string(name) + " (see 'stickmorph " +
                               std::string(command) + " --help')");
  return *value;
}

namespace {

std::optional<long long> whole_number(std::string_view text) {
  long long value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || ptr != end) return std::nullopt;
  return value;
}

}  // namespace

std::optional<long long> integer_option(const ParsedArguments& arguments, std::string_view name) {
  const std::string* text = option_value(arguments, name);
  if (text == nullptr) return std::nullopt;
  const std::optional<long long> value = whole_number(*text);
  if (!value)
    throw InvalidArgumentError("option " + std::string(name) + " needs a whole number, got " + single_quoted(*text));
  return value;
}

std::optional<double> number_option(const ParsedArguments& arguments, std::string_view name) {
  const std::string* text = option_value(arguments, name);
  if (text == nullptr) return std::nullopt;
  double value = 0;
  const char* end = text->data() + text->size();
  const auto [ptr, error] = std::from_chars(text->data(), end, value);
  if (text->empty() || error != std::errc() || ptr != end || !std::isfinite(value))
    throw InvalidArgumentError("option " + std::string(name) + " needs a finite number, got " + single_quoted(*text));
  return value;
}

std::vector<long long> integer_list_option(const ParsedArguments& arguments, std::string_view name) {
  std::vector<long long> values;
  const std::string* text = option_value(arguments, name);
  if (text == nullptr) return values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text->find(',', start);
    const std::string_view entry = std::string_view(*text).substr(start, comma - start);
    const std::optional<long long> value = whole_number(entry);
    if (!value)
      throw InvalidArgumentError("option " + std::string(name) + " needs whole numbers separated by commas; entry " +
                                 std::to_string(values.size() + 1) + " is " + single_quoted(entry) + " in " +
                                 single_quoted(*text));
    values.push_back(*value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

}  // namespace stickmorph::cli
