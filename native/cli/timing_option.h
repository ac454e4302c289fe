// The morph command's --timing FILE.json (docs/FORMAT.md, "Local timing";
// issue 31): read with the other options, its length checked against the
// source (or key 1) once that is read, every message naming the file.
#pragma once

#include <optional>
#include <string>

#include "argument_parsing.h"
#include "stickmorph/local_timing.h"

namespace stickmorph::cli {

/// The timing in the file --timing names, or none without the option.
/// @throws JsonError, InvalidArgumentError or FileError as
///         read_timing_file, the message starting with the path.
std::optional<LocalTiming> timing_option(const ParsedArguments& arguments);

/// One weight per vertex of `figure_path`'s figure (`vertex_count`).
/// @throws InvalidArgumentError "<timing path>: delay has 3 entries for 12
///         vertices of <figure path>".
void check_timing_length(const ParsedArguments& arguments, const LocalTiming& timing, std::size_t vertex_count,
                         const std::string& figure_path);

}  // namespace stickmorph::cli
