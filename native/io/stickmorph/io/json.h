// A strict JSON (RFC 8259) document model, reader and writer.
//
// Stick figure files are JSON (docs/FORMAT.md). Their readers must turn
// every malformed input into an error that says where it went wrong, so the
// reader keeps the line and column of every value, refuses everything the
// RFC does not allow (comments, trailing commas, NaN, leading zeros, ...),
// rejects duplicate object keys (which RFC 8259 leaves undefined, and which
// would make a file mean different things to different readers), and limits
// nesting so that hostile input cannot exhaust memory. The parsing is
// nlohmann-json's (json_reader.cpp says which checks are added to it and why).
//
// The writer emits doubles as the shortest decimal text that reads back as
// the same double, as FORMAT.md requires of every command's output.
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "stickmorph/errors.h"

namespace stickmorph {

/// Where a JSON value starts in its source text. Lines and columns count
/// from 1; a column counts bytes, so a multi-byte UTF-8 character before the
/// value advances it by more than one. A default location (0, 0) marks a
/// value that was built in code rather than parsed.
struct JsonLocation {
  std::size_t line = 0;
  std::size_t column = 0;
};

/// "line L, column C", the prefix of every parser message.
std::string describe_location(const JsonLocation& location);

class JsonValue;

/// One member of a JSON object: its key, where the key starts, its value.
struct JsonMember;

/// A JSON value: null, boolean, number, string, array or object.
///
/// Objects keep their members in document order. Numbers are doubles: JSON
/// numbers that a double cannot hold (1e400) are rejected by the parser.
class JsonValue {
 public:
  enum class Kind { Null, Bool, Number, String, Array, Object };
  using Array = std::vector<JsonValue>;
  using Object = std::vector<JsonMember>;

  /// null
  JsonValue() = default;
  JsonValue(std::nullptr_t) {}
  JsonValue(bool value) : data_(value) {}
  JsonValue(double value) : data_(value) {}
  /// Integers become numbers. Without this overload an int would be
  /// ambiguous between bool and double.
  template <typename Integer,
            typename = std::enable_if_t<std::is_integral_v<Integer> &&
                                        !std::is_same_v<Integer, bool>>>
  JsonValue(Integer value) : data_(static_cast<double>(value)) {}
  JsonValue(std::string value) : data_(std::move(value)) {}
  /// Without this overload a string literal would convert to bool.
  JsonValue(const char* value) : data_(std::string(value)) {}
  JsonValue(Array elements) : data_(std::move(elements)) {}
  JsonValue(Object members) : data_(std::move(members)) {}

  Kind kind() const { return static_cast<Kind>(data_.index()); }
  bool is_null() const { return kind() == Kind::Null; }
  bool is_bool() const { return kind() == Kind::Bool; }
  bool is_number() const { return kind() == Kind::Number; }
  bool is_string() const { return kind() == Kind::String; }
  bool is_array() const { return kind() == Kind::Array; }
  bool is_object() const { return kind() == Kind::Object; }

  /// The value as the given kind.
  /// @throws JsonError "line L, column C: expected a number, got a string"
  ///         when the value is of another kind.
  bool as_bool() const;
  double as_number() const;
  const std::string& as_string() const;
  const Array& as_array() const;
  const Object& as_object() const;
  Array& as_array();
  Object& as_object();

  /// The member of an object named `key`, or nullptr if there is none.
  /// @throws JsonError if this value is not an object.
  const JsonValue* find(std::string_view key) const;

  /// Where the parser found this value; (0, 0) for values built in code.
  const JsonLocation& location() const { return location_; }
  void set_location(const JsonLocation& location) { location_ = location; }

 private:
  // The alternatives are in the order of Kind, so index() is the kind.
  std::variant<std::nullptr_t, bool, double, std::string, Array, Object> data_;
  JsonLocation location_;
};

struct JsonMember {
  std::string key;
  JsonLocation key_location;
  JsonValue value;
};

/// The kind with its article, for messages: "null", "a boolean", "a number",
/// "a string", "an array", "an object".
const char* describe_kind(JsonValue::Kind kind);

/// Deepest nesting of arrays and objects that parse_json accepts. Real
/// documents (a figure file nests 3 levels) stay far below it. The parser
/// itself does not recurse, but code that walks the model does (the
/// destructor, the writer), once per level; the limit bounds its stack use.
constexpr std::size_t kMaxJsonDepth = 256;

/// Parses one JSON text (RFC 8259): a single value surrounded by optional
/// whitespace. A leading UTF-8 byte order mark is skipped (RFC 8259 section
/// 8.1 allows a parser to ignore it). String contents are kept as bytes;
/// escapes, including \uXXXX surrogate pairs, are decoded to UTF-8.
///
/// @param text  the whole document; any bytes, of any length
/// @return the document's value, every nested value knowing its location
/// @throws JsonError "line L, column C: <what is wrong>" for every input that
///         is not a JSON text, that nests deeper than kMaxJsonDepth, that has
///         an object with a repeated key, or that holds a number outside the
///         range of a double. Numbers too small for a double become zero.
JsonValue parse_json(std::string_view text);

/// The shortest decimal text that reads back as exactly `value`, always
/// marked as a floating-point number ("1.0", not "1") so that readers which
/// tell integers from floats (Python's json) give a float back.
/// @throws InvalidArgumentError for NaN and infinities, which JSON lacks.
std::string format_json_number(double value);

/// `text` as a JSON string literal, quotes included. Bytes are copied as
/// they are except '"', '\\' and control characters, which are escaped.
std::string quote_json_string(std::string_view text);

/// Writes JSON incrementally, for outputs too large to build as a
/// JsonValue first (a morph's frames).
///
/// Calls must form one well-nested value: inside an object, every value is
/// preceded by key(). A call that breaks this is a bug in the caller and
/// throws InternalError.
///
/// In pretty mode every object member and every element that is itself an
/// array or object starts a new, indented line, while numbers and strings
/// follow each other on one line, so that [[x, y], ...] reads as one point
/// per line.
class JsonWriter {
 public:
  explicit JsonWriter(bool pretty = false) : pretty_(pretty) {}

  void begin_object();
  void end_object();
  void begin_array();
  void end_array();
  /// The name of the next value inside an object.
  void key(std::string_view name);

  void null();
  void value(bool flag);
  /// @throws InvalidArgumentError for NaN and infinities.
  void value(double number);
  /// Integers are written without a fraction ("3"): they are indices.
  template <typename Integer,
            typename = std::enable_if_t<std::is_integral_v<Integer> &&
                                        !std::is_same_v<Integer, bool>>>
  void value(Integer number) {
    char digits[24];  // enough for any 64-bit integer and its sign
    const auto end = std::to_chars(digits, digits + sizeof digits, number).ptr;
    write_number_text(std::string_view(digits, static_cast<std::size_t>(end - digits)));
  }
  void value(std::string_view text);
  void value(const std::string& text) { value(std::string_view(text)); }
  /// Without this overload a string literal would convert to bool.
  void value(const char* text) { value(std::string_view(text)); }
  /// Writes a whole document-model value.
  void value(const JsonValue& json);

  /// True once one complete top-level value has been written.
  bool complete() const;
  /// The text written so far.
  const std::string& text() const { return out_; }
  /// The finished document, ending with a newline in pretty mode.
  /// @throws InternalError unless complete().
  std::string finish();

 private:
  struct Level {
    bool is_object;
    bool empty = true;                  // nothing written inside yet
    bool has_container_child = false;   // closing bracket needs its own line
    bool key_pending = false;           // key() called, its value not yet
  };
  // Writes what must precede a value (separator, newline, indentation) and
  // checks that a value is allowed here.
  void before_value(bool is_container, const char* what);
  void close(bool is_object);
  void newline_and_indent(std::size_t depth);
  void write_number_text(std::string_view text);

  bool pretty_;
  bool done_ = false;
  std::vector<Level> stack_;
  std::string out_;
};

/// `value` as JSON text (see JsonWriter for the pretty layout).
/// @throws InvalidArgumentError for non-finite numbers.
std::string to_json(const JsonValue& value, bool pretty = false);

}  // namespace stickmorph
