// Fuzz target: the JSON reader and the stick figure reader.
//
// Input: any bytes, taken as the text of a stick figure file (FORMAT.md).
//  1. parse_json. On success, the writer's output must parse back to a
//     document that writes the same text (compact and pretty), since the
//     CLI's outputs are read again by other tools and by the tests.
//  2. parse_figure, which parses and validates with make_stick_figure
//     (exact predicates). On success the figure must pass is_valid, and
//     writing it and reading it again must give bitwise the same figure:
//     FORMAT.md promises shortest round-trip decimals.
// Typed errors are the clean outcome of bad input (fuzz_common.h).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_common.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/json.h"

using namespace stickmorph;

namespace {

// Parses text that the engine itself wrote; any error is a finding.
JsonValue reparse(const std::string& text, const char* what) {
  try {
    return parse_json(text);
  } catch (const Error& error) {
    fuzz::report_finding(std::string("the writer's ") + what + " output does not parse: " +
                         error.what() + "\n" + text);
  }
}

void check_json_round_trip(const std::string& text) {
  const JsonValue document = parse_json(text);
  const std::string compact = to_json(document);
  if (to_json(reparse(compact, "compact")) != compact) {
    fuzz::report_finding("compact JSON changes when read and written again:\n" + compact);
  }
  const std::string pretty = to_json(document, true);
  if (to_json(reparse(pretty, "pretty")) != compact) {
    fuzz::report_finding("pretty JSON reads back as another document:\n" + pretty);
  }
}

void check_figure_round_trip(const std::string& text) {
  const StickFigure figure = parse_figure(text, "fuzz input");
  if (!is_valid(figure)) fuzz::report_finding("parse_figure returned a figure that is_valid rejects");
  const std::string written = fuzz::figure_to_json(figure);
  StickFigure again;
  try {
    again = parse_figure(written, "written figure");
  } catch (const Error& error) {
    fuzz::report_finding(std::string("a valid figure, written, is not read back: ") + error.what() +
                         "\n" + written);
  }
  if (!fuzz::same_figure(figure, again)) {
    fuzz::report_finding("a figure changes when written and read again:\n" + written);
  }
  fuzz::trace("valid figure, " + std::to_string(figure.vertices.size()) + " vertices");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::run_expecting_typed_errors([&] { check_json_round_trip(text); });
  fuzz::run_expecting_typed_errors([&] { check_figure_round_trip(text); });
  return 0;
}
