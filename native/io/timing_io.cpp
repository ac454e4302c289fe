#include "stickmorph/io/timing_io.h"

#include <utility>
#include <vector>

#include "stickmorph/errors.h"
#include "stickmorph/io/figure_io.h"
#include "stickmorph/io/json.h"

namespace stickmorph {
namespace {

[[noreturn]] void fail(const std::string& origin, const JsonValue& at, const std::string& what) {
  throw JsonError((origin.empty() ? "" : origin + ": ") + describe_location(at.location()) + ": " + what);
}

}  // namespace

LocalTiming parse_timing(const std::string& text, const std::string& origin) {
  const std::string prefix = origin.empty() ? "" : origin + ": ";
  JsonValue document;
  try {
    document = parse_json(text);
  } catch (const JsonError& error) {
    throw JsonError(prefix + error.what());
  }
  if (!document.is_object())
    fail(origin, document,
         std::string("a timing file must hold a JSON object with \"delay\" and \"overlap\", got ") +
             describe_kind(document.kind()));
  const JsonValue* delay = document.find("delay");
  if (delay == nullptr) fail(origin, document, "missing field \"delay\" in the timing object");
  const JsonValue* overlap = document.find("overlap");
  if (overlap == nullptr) fail(origin, document, "missing field \"overlap\" in the timing object");
  if (!delay->is_array())
    fail(origin, *delay, std::string("\"delay\" must be an array of numbers, got ") + describe_kind(delay->kind()));
  std::vector<double> weights;
  weights.reserve(delay->as_array().size());
  for (std::size_t v = 0; v < delay->as_array().size(); ++v) {
    const JsonValue& entry = delay->as_array()[v];
    if (!entry.is_number())
      fail(origin, entry, "delay[" + std::to_string(v) + "] must be a number, got " + describe_kind(entry.kind()));
    weights.push_back(entry.as_number());
  }
  if (!overlap->is_number())
    fail(origin, *overlap, std::string("\"overlap\" must be a number, got ") + describe_kind(overlap->kind()));
  try {
    return LocalTiming(std::move(weights), overlap->as_number());
  } catch (const InvalidArgumentError& error) {
    throw InvalidArgumentError(prefix + error.what());
  }
}

LocalTiming read_timing_file(const std::string& path) { return parse_timing(read_input_file(path), path); }

}  // namespace stickmorph
