#include "stickmorph/io/json.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>
#include <unordered_map>

namespace stickmorph {

std::string describe_location(const JsonLocation& location) {
  return "line " + std::to_string(location.line) + ", column " + std::to_string(location.column);
}

namespace {

// Message text for a value at `location`; values built in code have no
// location worth naming.
std::string located(const JsonLocation& location, const std::string& what) {
  if (location.line == 0) return what;
  return describe_location(location) + ": " + what;
}

// Echoes of the input inside messages are cut short so that a hostile
// megabyte-long number or key cannot produce a megabyte-long message.
constexpr std::size_t kMaxEcho = 40;

std::string excerpt(std::string_view text) {
  if (text.size() <= kMaxEcho) return std::string(text);
  return std::string(text.substr(0, kMaxEcho)) + "...";
}

bool is_digit(unsigned char c) { return c >= '0' && c <= '9'; }
bool is_letter(unsigned char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_word_char(unsigned char c) { return is_letter(c) || is_digit(c) || c == '_'; }

int hex_value(unsigned char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

void append_utf8(std::string& out, std::uint32_t code_point) {
  if (code_point < 0x80) {
    out += static_cast<char>(code_point);
  } else if (code_point < 0x800) {
    out += static_cast<char>(0xC0 | (code_point >> 6));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else if (code_point < 0x10000) {
    out += static_cast<char>(0xE0 | (code_point >> 12));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code_point >> 18));
    out += static_cast<char>(0x80 | ((code_point >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  }
}

std::string hex_byte(unsigned char c) {
  char text[5];
  std::snprintf(text, sizeof text, "0x%02X", static_cast<unsigned>(c));
  return text;
}

// True when a number whose conversion was out of range is too large (rather
// than too small) for a double. `text` matches the JSON number grammar.
// from_chars reports both overflow and underflow as out of range, and only
// the extreme ends of the range fail (decimal exponents above 308 or below
// -323), so the sign of the decimal exponent of the leading significant
// digit tells the two apart.
bool is_overflow(std::string_view text) {
  std::size_t i = 0;
  if (text[i] == '-') ++i;
  long long leading_exponent = 0;  // decimal exponent of the first nonzero digit
  bool found = false;
  long long integer_digits = 0;
  for (; i < text.size() && is_digit(text[i]); ++i) {
    if (!found && text[i] != '0') found = true;
    if (found) ++integer_digits;
  }
  if (found) leading_exponent = integer_digits - 1;
  if (i < text.size() && text[i] == '.') {
    ++i;
    for (long long position = 1; i < text.size() && is_digit(text[i]); ++i, ++position) {
      if (!found && text[i] != '0') {
        found = true;
        leading_exponent = -position;
      }
    }
  }
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool negative = false;
    if (text[i] == '+' || text[i] == '-') negative = text[i++] == '-';
    long long exponent = 0;
    // Saturate: an exponent with a thousand digits is still just "huge".
    for (; i < text.size(); ++i) {
      if (exponent < 1000000000) exponent = exponent * 10 + (text[i] - '0');
    }
    leading_exponent += negative ? -exponent : exponent;
  }
  return found && leading_exponent > 0;
}

// Offset of the first byte that breaks strict UTF-8 (no overlong forms, no
// surrogates, nothing above U+10FFFF), or npos.
std::size_t invalid_utf8_offset(std::string_view bytes) {
  std::size_t i = 0;
  while (i < bytes.size()) {
    const unsigned char b = static_cast<unsigned char>(bytes[i]);
    std::size_t length;
    unsigned lo = 0x80, hi = 0xBF;  // range of the second byte
    if (b < 0x80) length = 1;
    else if (b >= 0xC2 && b <= 0xDF) length = 2;
    else if (b == 0xE0) length = 3, lo = 0xA0;
    else if (b == 0xED) length = 3, hi = 0x9F;
    else if (b >= 0xE1 && b <= 0xEF) length = 3;
    else if (b == 0xF0) length = 4, lo = 0x90;
    else if (b >= 0xF1 && b <= 0xF3) length = 4;
    else if (b == 0xF4) length = 4, hi = 0x8F;
    else return i;
    if (i + length > bytes.size()) return i;
    for (std::size_t k = 1; k < length; ++k) {
      const unsigned char c = static_cast<unsigned char>(bytes[i + k]);
      if (c < (k == 1 ? lo : 0x80) || c > (k == 1 ? hi : 0xBF)) return i;
    }
    i += length;
  }
  return std::string_view::npos;
}

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  JsonValue parse_document() {
    // RFC 8259 section 8.1: a parser may ignore a leading byte order mark.
    // Editors on some systems write one.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") {
      pos_ = 3;
      line_start_ = 3;
    }
    skip_whitespace();
    if (at_end()) {
      fail(here(), text_.empty() ? "empty input, expected a JSON value"
                                 : "no JSON value, only whitespace");
    }
    JsonValue value = parse_value(0);
    skip_whitespace();
    if (!at_end()) fail_unexpected(" after the JSON value");
    return value;
  }

 private:
  JsonLocation here() const { return {line_, pos_ - line_start_ + 1}; }
  bool at_end() const { return pos_ >= text_.size(); }
  unsigned char peek() const { return static_cast<unsigned char>(text_[pos_]); }
  unsigned char peek_at(std::size_t offset) const {
    return pos_ + offset < text_.size() ? static_cast<unsigned char>(text_[pos_ + offset]) : 0;
  }

  [[noreturn]] void fail(const JsonLocation& location, const std::string& what) const {
    throw JsonError(describe_location(location) + ": " + what);
  }

  // Reports the byte at the current position (or the end of input) as out
  // of place. `context` follows "unexpected <byte>" and says where the byte
  // is or what was expected instead (", expected ':'").
  [[noreturn]] void fail_unexpected(const std::string& context) const {
    if (at_end()) fail(here(), "unexpected end of input" + context);
    const unsigned char c = peek();
    if (c == '/' && (peek_at(1) == '/' || peek_at(1) == '*')) {
      fail(here(), "comments are not allowed in JSON");
    }
    if (c == '\'') fail(here(), "unexpected character '\\'', JSON strings use double quotes");
    const bool printable = c >= 0x21 && c <= 0x7E;
    const std::string what = printable ? std::string("character '") + static_cast<char>(c) + "'"
                                       : "byte " + hex_byte(c);
    fail(here(), "unexpected " + what + context);
  }

  [[noreturn]] void fail_unclosed(const char* container, const JsonLocation& opened) const {
    fail(here(), std::string("unexpected end of input, the ") + container + " opened at " +
                     describe_location(opened) + " is not closed");
  }

  void skip_whitespace() {
    while (!at_end()) {
      const unsigned char c = peek();
      if (c == '\n') {
        ++line_;
        line_start_ = pos_ + 1;
      } else if (c != ' ' && c != '\t' && c != '\r') {
        return;
      }
      ++pos_;
    }
  }

  // Parses the value starting at the current position (whitespace already
  // skipped). `depth` counts the arrays and objects enclosing it.
  JsonValue parse_value(std::size_t depth) {
    if (at_end()) fail(here(), "unexpected end of input, expected a JSON value");
    const JsonLocation location = here();
    const unsigned char c = peek();
    JsonValue value;
    if (c == '{') {
      value = parse_object(depth);
    } else if (c == '[') {
      value = parse_array(depth);
    } else if (c == '"') {
      value = parse_string();
    } else if (c == '-' || is_digit(c)) {
      value = parse_number();
    } else if (is_letter(c)) {
      value = parse_word();
    } else {
      fail_unexpected(", expected a JSON value");
    }
    value.set_location(location);
    return value;
  }

  void enter_container(std::size_t depth, const JsonLocation& location) const {
    if (depth + 1 > kMaxJsonDepth) {
      fail(location, "arrays and objects nest deeper than " + std::to_string(kMaxJsonDepth) +
                         " levels");
    }
  }

  JsonValue parse_array(std::size_t depth) {
    const JsonLocation opened = here();
    enter_container(depth, opened);
    ++pos_;  // '['
    JsonValue::Array elements;
    skip_whitespace();
    if (!at_end() && peek() == ']') {
      ++pos_;
      return JsonValue(std::move(elements));
    }
    while (true) {
      if (at_end()) fail_unclosed("array", opened);
      elements.push_back(parse_value(depth + 1));
      skip_whitespace();
      if (at_end()) fail_unclosed("array", opened);
      if (peek() == ']') {
        ++pos_;
        return JsonValue(std::move(elements));
      }
      if (peek() != ',') fail_unexpected(" in an array, expected ',' or ']'");
      const JsonLocation comma = here();
      ++pos_;
      skip_whitespace();
      if (!at_end() && peek() == ']') fail(comma, "trailing comma before ']'");
    }
  }

  JsonValue parse_object(std::size_t depth) {
    const JsonLocation opened = here();
    enter_container(depth, opened);
    ++pos_;  // '{'
    JsonValue::Object members;
    // RFC 8259 leaves repeated keys undefined; readers disagree on which one
    // wins, so a repeated key is an error rather than a silent choice.
    std::unordered_map<std::string, JsonLocation> first_location_of_key;
    skip_whitespace();
    if (!at_end() && peek() == '}') {
      ++pos_;
      return JsonValue(std::move(members));
    }
    while (true) {
      if (at_end()) fail_unclosed("object", opened);
      if (peek() != '"') fail_unexpected(" in an object, expected a string key");
      const JsonLocation key_location = here();
      std::string key = parse_string();
      const auto [previous, inserted] = first_location_of_key.emplace(key, key_location);
      if (!inserted) {
        fail(key_location, "duplicate key " + quote_json_string(excerpt(key)) + " (first at " +
                               describe_location(previous->second) + ")");
      }
      skip_whitespace();
      if (at_end()) fail_unclosed("object", opened);
      if (peek() != ':') fail_unexpected(" after an object key, expected ':'");
      ++pos_;
      skip_whitespace();
      if (at_end()) fail_unclosed("object", opened);
      JsonValue value = parse_value(depth + 1);
      members.push_back(JsonMember{std::move(key), key_location, std::move(value)});
      skip_whitespace();
      if (at_end()) fail_unclosed("object", opened);
      if (peek() == '}') {
        ++pos_;
        return JsonValue(std::move(members));
      }
      if (peek() != ',') fail_unexpected(" in an object, expected ',' or '}'");
      const JsonLocation comma = here();
      ++pos_;
      skip_whitespace();
      if (!at_end() && peek() == '}') fail(comma, "trailing comma before '}'");
    }
  }

  // Reads four hex digits after "\u" at the current position.
  std::uint32_t parse_hex4(const JsonLocation& escape) {
    std::uint32_t code_unit = 0;
    for (int k = 0; k < 4; ++k) {
      const int digit = at_end() ? -1 : hex_value(peek());
      if (digit < 0) fail(escape, "\\u in a string must be followed by 4 hex digits");
      code_unit = code_unit * 16 + static_cast<std::uint32_t>(digit);
      ++pos_;
    }
    return code_unit;
  }

  std::string parse_string() {
    const JsonLocation opened = here();
    ++pos_;  // '"'
    std::string out;
    while (true) {
      // Copy the run of ordinary bytes in one go.
      const std::size_t run_start = pos_;
      while (!at_end() && peek() != '"' && peek() != '\\' && peek() >= 0x20) ++pos_;
      // RFC 8259, section 8.1: JSON text is UTF-8. A string never spans a
      // line, so the bad byte's column follows from its offset.
      const std::size_t bad = invalid_utf8_offset(std::string_view(text_).substr(run_start, pos_ - run_start));
      if (bad != std::string_view::npos)
        fail({line_, run_start + bad - line_start_ + 1},
             "invalid UTF-8 in a string (the string starts at " + describe_location(opened) + ")");
      out.append(text_, run_start, pos_ - run_start);
      if (at_end()) fail(opened, "unterminated string");
      const unsigned char c = peek();
      if (c == '"') {
        ++pos_;
        return out;
      }
      if (c < 0x20) {
        char name[8];
        std::snprintf(name, sizeof name, "U+%04X", static_cast<unsigned>(c));
        fail(here(), std::string("unescaped control character ") + name +
                         " in a string (the string starts at " + describe_location(opened) +
                         ")");
      }
      // A backslash escape.
      const JsonLocation escape = here();
      ++pos_;
      if (at_end()) fail(opened, "unterminated string");
      const unsigned char kind = peek();
      ++pos_;
      switch (kind) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          std::uint32_t code_point = parse_hex4(escape);
          if (code_point >= 0xDC00 && code_point <= 0xDFFF) {
            fail(escape, "unpaired UTF-16 low surrogate in a \\u escape");
          }
          if (code_point >= 0xD800 && code_point <= 0xDBFF) {
            // A high surrogate must be followed by an escaped low surrogate;
            // together they encode one code point above U+FFFF.
            const JsonLocation second = here();
            if (peek_at(0) != '\\' || peek_at(1) != 'u') {
              fail(escape, "unpaired UTF-16 high surrogate in a \\u escape");
            }
            pos_ += 2;
            const std::uint32_t low = parse_hex4(second);
            if (low < 0xDC00 || low > 0xDFFF) {
              fail(escape, "UTF-16 high surrogate not followed by a low surrogate");
            }
            code_point = 0x10000 + ((code_point - 0xD800) << 10) + (low - 0xDC00);
          }
          append_utf8(out, code_point);
          break;
        }
        default: {
          const std::string shown = kind >= 0x21 && kind <= 0x7E
                                        ? std::string("'\\") + static_cast<char>(kind) + "'"
                                        : "'\\' followed by byte " + hex_byte(kind);
          fail(escape, "invalid escape " + shown + " in a string");
        }
      }
    }
  }

  void skip_digits() {
    while (!at_end() && is_digit(peek())) ++pos_;
  }

  // Words that are not JSON: NaN and Infinity get their own message since
  // they are the likely mistake (Python's json writes them by default).
  [[noreturn]] void fail_word(const JsonLocation& location, std::string_view word) const {
    std::string lower;
    for (char c : word) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    const std::string_view bare = lower[0] == '-' ? std::string_view(lower).substr(1) : lower;
    if (bare == "nan" || bare == "infinity" || bare == "inf") {
      fail(location, excerpt(word) + " is not a JSON number (JSON has no NaN or infinity)");
    }
    fail(location, "unexpected word '" + excerpt(word) + "', expected a JSON value");
  }

  JsonValue parse_word() {
    const JsonLocation location = here();
    const std::size_t start = pos_;
    while (!at_end() && is_word_char(peek())) ++pos_;
    const std::string_view word = text_.substr(start, pos_ - start);
    if (word == "true") return JsonValue(true);
    if (word == "false") return JsonValue(false);
    if (word == "null") return JsonValue(nullptr);
    fail_word(location, word);
  }

  // RFC 8259 section 6: -? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?
  // The grammar is checked here; the conversion is std::from_chars, which
  // unlike strtod does not depend on the C locale (Blender sets one).
  JsonValue parse_number() {
    const JsonLocation location = here();
    const std::size_t start = pos_;
    if (peek() == '-') {
      ++pos_;
      if (!at_end() && is_letter(peek())) {
        while (!at_end() && is_word_char(peek())) ++pos_;
        fail_word(location, text_.substr(start, pos_ - start));
      }
      if (at_end() || !is_digit(peek())) fail(location, "expected a digit after '-'");
    }
    if (peek() == '0') {
      ++pos_;
      if (!at_end() && is_digit(peek())) fail(location, "a number must not have a leading zero");
    } else {
      skip_digits();
    }
    if (!at_end() && peek() == '.') {
      ++pos_;
      if (at_end() || !is_digit(peek())) {
        fail(location, "expected a digit after the decimal point");
      }
      skip_digits();
    }
    if (!at_end() && (peek() == 'e' || peek() == 'E')) {
      ++pos_;
      if (!at_end() && (peek() == '+' || peek() == '-')) ++pos_;
      if (at_end() || !is_digit(peek())) fail(location, "expected a digit in the exponent");
      skip_digits();
    }
    const std::string_view text = text_.substr(start, pos_ - start);
    double value = 0.0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (result.ec == std::errc::result_out_of_range) {
      if (is_overflow(text)) fail(location, "number " + excerpt(text) + " overflows a double");
      // Too small for a double: zero is the nearest value, as strtod gives.
      value = text[0] == '-' ? -0.0 : 0.0;
    } else if (result.ec != std::errc() || result.ptr != text.data() + text.size()) {
      throw InternalError(describe_location(location) + ": std::from_chars rejected the number " +
                          excerpt(text) + " that matches the JSON grammar");
    }
    return JsonValue(value);
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;  // offset of the first byte of the current line
};

}  // namespace

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

JsonValue parse_json(std::string_view text) { return Parser(text).parse_document(); }

std::string format_json_number(double value) {
  if (std::isnan(value)) throw InvalidArgumentError("JSON cannot represent the number NaN");
  if (std::isinf(value)) {
    throw InvalidArgumentError(std::string("JSON cannot represent the number ") +
                               (value > 0 ? "infinity" : "-infinity"));
  }
  // Without a precision argument to_chars writes the shortest text that
  // reads back as the same double.
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  std::string text(buffer, end);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string quote_json_string(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '"';
  for (const char byte : text) {
    const auto c = static_cast<unsigned char>(byte);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          char escape[8];
          std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
          out += escape;
        } else {
          out += byte;
        }
    }
  }
  out += '"';
  return out;
}

void JsonWriter::newline_and_indent(std::size_t depth) {
  out_ += '\n';
  out_.append(2 * depth, ' ');
}

void JsonWriter::before_value(bool is_container, const char* what) {
  if (done_) {
    throw InternalError(std::string("JsonWriter: ") + what + " after the complete document");
  }
  if (stack_.empty()) return;  // the top-level value
  Level& level = stack_.back();
  if (level.is_object) {
    // key() already wrote the separator and the indentation.
    if (!level.key_pending) {
      throw InternalError(std::string("JsonWriter: ") + what + " inside an object without a key");
    }
    level.key_pending = false;
    return;
  }
  if (!level.empty) out_ += ',';
  if (pretty_) {
    if (is_container) {
      newline_and_indent(stack_.size());
      level.has_container_child = true;
    } else if (!level.empty) {
      out_ += ' ';
    }
  }
  level.empty = false;
}

void JsonWriter::close(bool is_object) {
  const char* what = is_object ? "end_object()" : "end_array()";
  if (stack_.empty() || stack_.back().is_object != is_object) {
    throw InternalError(std::string("JsonWriter: ") + what + " without a matching begin");
  }
  if (stack_.back().key_pending) {
    throw InternalError(std::string("JsonWriter: ") + what + " right after key()");
  }
  const bool own_line = pretty_ && stack_.back().has_container_child;
  stack_.pop_back();
  if (own_line) newline_and_indent(stack_.size());
  out_ += is_object ? '}' : ']';
  if (stack_.empty()) done_ = true;
}

void JsonWriter::begin_object() {
  before_value(true, "begin_object()");
  out_ += '{';
  stack_.push_back(Level{true});
}

void JsonWriter::end_object() { close(true); }

void JsonWriter::begin_array() {
  before_value(true, "begin_array()");
  out_ += '[';
  stack_.push_back(Level{false});
}

void JsonWriter::end_array() { close(false); }

void JsonWriter::key(std::string_view name) {
  if (stack_.empty() || !stack_.back().is_object) {
    throw InternalError("JsonWriter: key() outside an object");
  }
  Level& level = stack_.back();
  if (level.key_pending) throw InternalError("JsonWriter: key() twice without a value");
  if (!level.empty) out_ += ',';
  if (pretty_) {
    newline_and_indent(stack_.size());
    level.has_container_child = true;  // members sit on their own lines
  }
  out_ += quote_json_string(name);
  out_ += pretty_ ? ": " : ":";
  level.empty = false;
  level.key_pending = true;
}

void JsonWriter::write_number_text(std::string_view text) {
  before_value(false, "a number");
  out_ += text;
  if (stack_.empty()) done_ = true;
}

void JsonWriter::null() {
  before_value(false, "null");
  out_ += "null";
  if (stack_.empty()) done_ = true;
}

void JsonWriter::value(bool flag) {
  before_value(false, "a boolean");
  out_ += flag ? "true" : "false";
  if (stack_.empty()) done_ = true;
}

void JsonWriter::value(double number) {
  // Format first: a non-finite number must not leave a half-written value.
  const std::string text = format_json_number(number);
  write_number_text(text);
}

void JsonWriter::value(std::string_view text) {
  before_value(false, "a string");
  out_ += quote_json_string(text);
  if (stack_.empty()) done_ = true;
}

void JsonWriter::value(const JsonValue& json) {
  switch (json.kind()) {
    case JsonValue::Kind::Null: null(); break;
    case JsonValue::Kind::Bool: value(json.as_bool()); break;
    case JsonValue::Kind::Number: value(json.as_number()); break;
    case JsonValue::Kind::String: value(std::string_view(json.as_string())); break;
    case JsonValue::Kind::Array:
      begin_array();
      for (const JsonValue& element : json.as_array()) value(element);
      end_array();
      break;
    case JsonValue::Kind::Object:
      begin_object();
      for (const JsonMember& member : json.as_object()) {
        key(member.key);
        value(member.value);
      }
      end_object();
      break;
  }
}

bool JsonWriter::complete() const { return done_; }

std::string JsonWriter::finish() {
  if (!done_) throw InternalError("JsonWriter: finish() before the document is complete");
  std::string document = std::move(out_);
  if (pretty_) document += '\n';
  out_.clear();
  stack_.clear();
  done_ = false;
  return document;
}

std::string to_json(const JsonValue& value, bool pretty) {
  JsonWriter writer(pretty);
  writer.value(value);
  return writer.finish();
}

}  // namespace stickmorph
