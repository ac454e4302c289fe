// The JSON document model (JsonValue and its locations): what the reader
// builds and the writer walks, kept apart from both so that neither needs
// the other.
#include "stickmorph/io/json.h"

#include <string>

namespace stickmorph {

std::string describe_location(const JsonLocation& location) {
  return "line " + std::to_string(location.line) + ", column " + std::to_string(location.column);
}

const char* describe_kind(JsonValue::Kind kind) {
  switch (kind) {
    case JsonValue::Kind::Null: return "null";
    case JsonValue::Kind::Bool: return "a boolean";
    case JsonValue::Kind::Number: return "a number";
    case JsonValue::Kind::String: return "a string";
    case JsonValue::Kind::Array: return "an array";
    case JsonValue::Kind::Object: return "an object";
  }
  return "an unknown kind of value";
}

namespace {

// Message text for a value at `location`; values built in code have no
// location worth naming.
std::string located(const JsonLocation& location, const std::string& what) {
  if (location.line == 0) return what;
  return describe_location(location) + ": " + what;
}

[[noreturn]] void fail_kind(const JsonValue& value, JsonValue::Kind wanted) {
  throw JsonError(located(value.location(), std::string("expected ") + describe_kind(wanted) +
                                                ", got " + describe_kind(value.kind())));
}
}  // namespace

bool JsonValue::as_bool() const {
  if (!is_bool()) fail_kind(*this, Kind::Bool);
  return std::get<bool>(data_);
}

double JsonValue::as_number() const {
  if (!is_number()) fail_kind(*this, Kind::Number);
  return std::get<double>(data_);
}

const std::string& JsonValue::as_string() const {
  if (!is_string()) fail_kind(*this, Kind::String);
  return std::get<std::string>(data_);
}

const JsonValue::Array& JsonValue::as_array() const {
  if (!is_array()) fail_kind(*this, Kind::Array);
  return std::get<Array>(data_);
}

const JsonValue::Object& JsonValue::as_object() const {
  if (!is_object()) fail_kind(*this, Kind::Object);
  return std::get<Object>(data_);
}

JsonValue::Array& JsonValue::as_array() {
  if (!is_array()) fail_kind(*this, Kind::Array);
  return std::get<Array>(data_);
}

JsonValue::Object& JsonValue::as_object() {
  if (!is_object()) fail_kind(*this, Kind::Object);
  return std::get<Object>(data_);
}

const JsonValue* JsonValue::find(std::string_view key) const {
  for (const JsonMember& member : as_object()) {
    if (member.key == key) return &member.value;
  }
  return nullptr;
}

}  // namespace stickmorph
