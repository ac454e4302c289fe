// Reading local timing files (docs/FORMAT.md, "Local timing"):
// {"delay": [w_0, ..., w_n-1], "overlap": d}.
#pragma once

#include <string>

#include "stickmorph/local_timing.h"

namespace stickmorph {

/// Parses the JSON text of a timing file. Members other than "delay" and
/// "overlap" are ignored, as in figure files.
/// @param origin  name used in messages (usually the path)
/// @throws JsonError for malformed JSON or a wrong shape (a missing member,
///         an entry that is not a number), naming line and column and the
///         entry ("delay[3]"); InvalidArgumentError, prefixed with `origin`,
///         for a weight outside [0, 1] or an overlap outside [0, 1)
///         (LocalTiming's check).
LocalTiming parse_timing(const std::string& text, const std::string& origin);

/// Reads and parses the timing file at `path`.
/// @throws FileError if it cannot be read; as parse_timing.
LocalTiming read_timing_file(const std::string& path);

}  // namespace stickmorph
