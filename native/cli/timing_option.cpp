#include "timing_option.h"

#include "stickmorph/errors.h"
#include "stickmorph/io/timing_io.h"

namespace stickmorph::cli {

std::optional<LocalTiming> timing_option(const ParsedArguments& arguments) {
  const std::string* path = option_value(arguments, "--timing");
  if (path == nullptr) return std::nullopt;
  return read_timing_file(*path);
}

void check_timing_length(const ParsedArguments& arguments, const LocalTiming& timing, std::size_t vertex_count,
                         const std::string& figure_path) {
  try {
    timing.check_vertex_count(vertex_count, figure_path);
  } catch (const InvalidArgumentError& error) {
    const std::string* path = option_value(arguments, "--timing");
    throw InvalidArgumentError((path ? *path + ": " : std::string()) + error.what());
  }
}

}  // namespace stickmorph::cli
