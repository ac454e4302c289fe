// JSON input: parse_json on nlohmann-json's SAX parser, with the
// locations and the checks it adds (DocumentBuilder says which and why).
#include "stickmorph/io/json.h"

#include <charconv>
#include <cstdio>
#include <system_error>
#include <unordered_map>

#include <nlohmann/json.hpp>

namespace stickmorph {

namespace {

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
bool is_space(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string hex_byte(unsigned char c) {
  char text[5];
  std::snprintf(text, sizeof text, "0x%02X", static_cast<unsigned>(c));
  return text;
}

// Offset of the first byte that starts an invalid UTF-8 sequence (overlong
// forms, surrogates, code points above U+10FFFF, truncated sequences), or
// npos. The library reports the byte at which it noticed the problem, which
// for a truncated sequence is the byte after it; messages name the sequence.
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

// Turns byte offsets into lines and columns as FORMAT.md's messages count
// them: lines end at '\n' only ("\r\n" is '\r' then a line end), columns
// count bytes from 1, and a skipped byte order mark takes no column.
// Offsets asked for mostly grow, so it scans forward from the last one.
class Locator {
 public:
  Locator(std::string_view text, std::size_t first) : text_(text), first_(first), line_start_(first), scanned_(first) {}

  JsonLocation at(std::size_t offset) {
    if (offset < scanned_) {  // a message about an earlier byte: count again
      line_ = 1;
      line_start_ = scanned_ = first_;
    }
    for (; scanned_ < offset && scanned_ < text_.size(); ++scanned_) {
      if (text_[scanned_] == '\n') {
        ++line_;
        line_start_ = scanned_ + 1;
      }
    }
    return {line_, offset - line_start_ + 1};
  }

 private:
  std::string_view text_;
  std::size_t first_;
  std::size_t line_ = 1;
  std::size_t line_start_;
  std::size_t scanned_;
};

using Library = nlohmann::json;

// Builds the document model from nlohmann-json's SAX events.
//
// The library does the parsing and the RFC 8259 checks: grammar, numbers
// (including overflow: out_of_range.406), strings (escapes, surrogate
// pairs, control characters, UTF-8), comments and trailing data. It gives
// no positions for values, and its messages name the byte where it noticed
// a problem rather than the value at fault. So this builder follows the
// text alongside the events: every event is for the next token after
// `cursor_` (skipping whitespace and the one ',' or ':' the library has
// already checked), which gives each value its line and column. On an
// error it looks at the bytes after the last good token, knowing what the
// grammar expects there, and says what is wrong as FORMAT.md's messages
// do ("trailing comma before ']'", "the array opened at ... is not
// closed").
//
// Checks the library does not make, or makes differently, are made here:
// repeated object keys (RFC 8259 leaves them undefined and readers disagree
// on which one wins), the nesting limit, a leading zero ("01": the library
// reads the numbers 0 and 1), words that merely start with a literal
// ("truex": the library reads true, then fails at x), and a NUL byte after
// the value, which the library takes for the end of the input. Numbers are
// converted from their text with std::from_chars, which unlike the
// library's strtod keeps the sign of -0 (the library reads "-0" as the
// integer 0) and does not depend on the C locale (Blender sets one).
class DocumentBuilder final : public nlohmann::json_sax<Library> {
 public:
  DocumentBuilder(std::string_view text, std::size_t first) : text_(text), cursor_(first), where_(text, first) {}

  bool null() override { return literal("null", JsonValue(nullptr)); }
  bool boolean(bool flag) override { return literal(flag ? "true" : "false", JsonValue(flag)); }
  bool number_integer(number_integer_t) override { return number(); }
  bool number_unsigned(number_unsigned_t) override { return number(); }
  bool number_float(number_float_t, const string_t&) override { return number(); }

  bool string(string_t& text) override {
    const std::size_t start = token_start();
    cursor_ = string_end(start);
    return add(JsonValue(std::move(text)), start);
  }

  bool binary(binary_t&) override {
    throw InternalError("nlohmann-json reported binary data while parsing JSON text");
  }

  bool start_object(std::size_t) override { return open(true); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& name) override {
    const std::size_t start = token_start();
    cursor_ = string_end(start);
    Open& object = stack_.back();
    const JsonLocation location = where_.at(start);
    const auto [previous, inserted] = object.first_location_of_key.emplace(name, location);
    if (!inserted) {
      fail(start, "duplicate key " + quote_json_string(excerpt(name)) + " (first at " +
                      describe_location(previous->second) + ")");
    }
    object.pending_key = std::move(name);
    object.pending_key_location = location;
    expect_ = Expect::Colon;
    return true;
  }

  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& error) override {
    diagnose(position, error);
  }

  // After the library accepted the text: anything but whitespace after the
  // value is an error. The library stops at a NUL byte as if the input
  // ended there, so "[1]\0x" gets here.
  JsonValue finish() {
    const std::size_t after = skip_space(cursor_);
    if (after < text_.size()) fail_unexpected(after, " after the JSON value");
    return std::move(root_);
  }

 private:
  // What the grammar allows after the last event.
  enum class Expect {
    Value,       // the document's value
    FirstValue,  // after '[': a value or ']'
    FirstKey,    // after '{': a key or '}'
    Colon,       // after a key
    CommaOrEnd,  // after a value inside an array or object
    End,         // after the document's value
  };

  struct Open {
    JsonValue value;  // an empty array or object, filled as events come
    std::string pending_key;
    JsonLocation pending_key_location;
    std::unordered_map<std::string, JsonLocation> first_location_of_key;
  };

  [[noreturn]] void fail(std::size_t offset, const std::string& what) {
    throw JsonError(describe_location(where_.at(offset)) + ": " + what);
  }

  std::size_t skip_space(std::size_t offset) const {
    while (offset < text_.size() && is_space(static_cast<unsigned char>(text_[offset]))) ++offset;
    return offset;
  }

  unsigned char byte(std::size_t offset) const {
    return offset < text_.size() ? static_cast<unsigned char>(text_[offset]) : 0;
  }

  // Start of the token the current event is about.
  std::size_t token_start() const {
    std::size_t offset = skip_space(cursor_);
    if (byte(offset) == ',' || byte(offset) == ':') offset = skip_space(offset + 1);
    return offset;
  }

  // End of the string token starting at `start`, which the library has
  // checked: the first '"' not escaped by a backslash.
  std::size_t string_end(std::size_t start) const {
    std::size_t i = start + 1;
    while (i < text_.size() && text_[i] != '"') i += text_[i] == '\\' ? 2 : 1;
    return i + 1;
  }

  // End of the number starting at `start`: RFC 8259 section 6,
  // -? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?
  std::size_t number_end(std::size_t start) const {
    std::size_t i = start;
    const auto digits = [&] {
      while (is_digit(byte(i))) ++i;
    };
    if (byte(i) == '-') ++i;
    if (byte(i) == '0') ++i;
    else digits();
    if (byte(i) == '.' && is_digit(byte(i + 1))) {
      ++i;
      digits();
    }
    if (byte(i) == 'e' || byte(i) == 'E') {
      std::size_t exponent = i + 1;
      if (byte(exponent) == '+' || byte(exponent) == '-') ++exponent;
      if (is_digit(byte(exponent))) {
        i = exponent;
        digits();
      }
    }
    return i;
  }

  std::string_view word_at(std::size_t start) const {
    std::size_t end = start;
    if (byte(end) == '-') ++end;
    while (is_word_char(byte(end))) ++end;
    return text_.substr(start, end - start);
  }

  // Words that are not JSON: NaN and Infinity get their own message since
  // they are the likely mistake (Python's json writes them by default).
  [[noreturn]] void fail_word(std::size_t start) {
    const std::string_view word = word_at(start);
    std::string lower;
    for (char c : word) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    const std::string_view bare = lower[0] == '-' ? std::string_view(lower).substr(1) : lower;
    if (bare == "nan" || bare == "infinity" || bare == "inf") {
      fail(start, excerpt(word) + " is not a JSON number (JSON has no NaN or infinity)");
    }
    fail(start, "unexpected word '" + excerpt(word) + "', expected a JSON value");
  }

  // The byte at `offset` (or the end of input) is out of place. `context`
  // follows "unexpected <byte>" and says where the byte is or what was
  // expected instead (", expected ':'").
  [[noreturn]] void fail_unexpected(std::size_t offset, const std::string& context) {
    if (offset >= text_.size()) fail(offset, "unexpected end of input" + context);
    const unsigned char c = byte(offset);
    if (c == '/' && (byte(offset + 1) == '/' || byte(offset + 1) == '*')) {
      fail(offset, "comments are not allowed in JSON");
    }
    if (c == '\'') fail(offset, "unexpected character '\\'', JSON strings use double quotes");
    const bool printable = c >= 0x21 && c <= 0x7E;
    const std::string what = printable ? std::string("character '") + static_cast<char>(c) + "'"
                                       : "byte " + hex_byte(c);
    fail(offset, "unexpected " + what + context);
  }

  [[noreturn]] void fail_unclosed(std::size_t offset) {
    const bool is_object = stack_.back().value.is_object();
    fail(offset, std::string("unexpected end of input, the ") + (is_object ? "object" : "array") +
                     " opened at " + describe_location(stack_.back().value.location()) + " is not closed");
  }

  bool open(bool is_object) {
    const std::size_t start = token_start();
    if (stack_.size() >= kMaxJsonDepth) {
      fail(start, "arrays and objects nest deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }
    cursor_ = start + 1;
    Open level;
    level.value = is_object ? JsonValue(JsonValue::Object{}) : JsonValue(JsonValue::Array{});
    level.value.set_location(where_.at(start));
    stack_.push_back(std::move(level));
    expect_ = is_object ? Expect::FirstKey : Expect::FirstValue;
    return true;
  }

  bool close() {
    cursor_ = token_start() + 1;
    JsonValue value = std::move(stack_.back().value);
    stack_.pop_back();
    return attach(std::move(value));
  }

  bool add(JsonValue value, std::size_t start) {
    value.set_location(where_.at(start));
    return attach(std::move(value));
  }

  bool attach(JsonValue value) {
    if (stack_.empty()) {
      root_ = std::move(value);
      expect_ = Expect::End;
      return true;
    }
    Open& parent = stack_.back();
    if (parent.value.is_array()) {
      parent.value.as_array().push_back(std::move(value));
    } else {
      parent.value.as_object().push_back(
          JsonMember{std::move(parent.pending_key), parent.pending_key_location, std::move(value)});
    }
    expect_ = Expect::CommaOrEnd;
    return true;
  }

  bool literal(std::string_view name, JsonValue value) {
    const std::size_t start = token_start();
    if (word_at(start) != name) fail_word(start);  // "truex"
    cursor_ = start + name.size();
    return add(std::move(value), start);
  }

  bool number() {
    const std::size_t start = token_start();
    const std::size_t end = number_end(start);
    const std::size_t first_digit = start + (byte(start) == '-' ? 1 : 0);
    if (byte(first_digit) == '0' && is_digit(byte(first_digit + 1))) {
      fail(start, "a number must not have a leading zero");
    }
    const std::string_view text = text_.substr(start, end - start);
    double value = 0.0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (result.ec == std::errc::result_out_of_range) {
      // The library has already refused numbers too large for a double, so
      // this one is too small: zero is the nearest value, as strtod gives.
      value = text[0] == '-' ? -0.0 : 0.0;
    } else if (result.ec != std::errc() || result.ptr != text.data() + text.size()) {
      throw InternalError(describe_location(where_.at(start)) + ": std::from_chars rejected the number " +
                          excerpt(text) + " that matches the JSON grammar");
    }
    cursor_ = end;
    return add(JsonValue(value), start);
  }

  // The library's message without its prefix, for errors this builder has
  // no words of its own for.
  [[noreturn]] void fail_as_library(std::size_t position, const std::string& what) {
    std::string detail = what;
    const std::size_t colon = detail.find(": ");
    if (detail.rfind("[json.exception.parse_error", 0) == 0 && colon != std::string::npos) {
      detail = detail.substr(colon + 2);
    } else if (const std::size_t bracket = detail.find("] "); bracket != std::string::npos) {
      detail = detail.substr(bracket + 2);
    }
    fail(position == 0 ? 0 : position - 1, detail);
  }

  // Called with the library's error; never returns. `position` counts the
  // bytes the library had read, so position - 1 is where it stopped.
  [[noreturn]] void diagnose(std::size_t position, const nlohmann::detail::exception& error) {
    const std::string what = error.what();
    std::size_t at = skip_space(cursor_);
    Expect expect = expect_;
    if (expect == Expect::End) fail_unexpected(at, " after the JSON value");
    if (expect == Expect::Colon) {
      if (at >= text_.size()) fail_unclosed(at);
      if (byte(at) != ':') fail_unexpected(at, " after an object key, expected ':'");
      at = skip_space(at + 1);
      expect = Expect::Value;
    } else if (expect == Expect::CommaOrEnd) {
      const bool in_object = stack_.back().value.is_object();
      const char closing = in_object ? '}' : ']';
      if (at >= text_.size()) fail_unclosed(at);
      if (byte(at) == closing) fail_as_library(position, what);
      if (byte(at) != ',') {
        fail_unexpected(at, in_object ? " in an object, expected ',' or '}'" : " in an array, expected ',' or ']'");
      }
      const std::size_t comma = at;
      at = skip_space(at + 1);
      if (byte(at) == closing && at < text_.size()) {
        fail(comma, std::string("trailing comma before '") + closing + "'");
      }
      expect = in_object ? Expect::FirstKey : Expect::Value;
    }
    // `at` is where a value (or, in an object, a key) must start.
    if (at >= text_.size()) {
      if (stack_.empty()) fail(at, "unexpected end of input, expected a JSON value");
      fail_unclosed(at);
    }
    const unsigned char c = byte(at);
    if ((expect == Expect::FirstKey && c == '}') || (expect == Expect::FirstValue && c == ']')) {
      fail_as_library(position, what);
    }
    if (expect == Expect::FirstKey && c != '"') fail_unexpected(at, " in an object, expected a string key");
    if (c == '"') diagnose_string(at, position, what);
    if (c == '-' || is_digit(c)) diagnose_number(at, error.id, position, what);
    if (is_letter(c)) fail_word(at);
    if (c == '[' || c == '{') fail_as_library(position, what);
    fail_unexpected(at, ", expected a JSON value");
  }

  [[noreturn]] void diagnose_number(std::size_t start, int id, std::size_t position, const std::string& what) {
    if (byte(start) == '-' && is_letter(byte(start + 1))) fail_word(start);  // -Infinity
    if (id == 406) {  // out_of_range.406: number overflow
      fail(start, "number " + excerpt(text_.substr(start, number_end(start) - start)) + " overflows a double");
    }
    if (what.find("expected digit after '-'") != std::string::npos) fail(start, "expected a digit after '-'");
    if (what.find("expected digit after '.'") != std::string::npos) {
      fail(start, "expected a digit after the decimal point");
    }
    if (what.find("after exponent") != std::string::npos) fail(start, "expected a digit in the exponent");
    fail_as_library(position, what);
  }

  // The start of the last "\u" escape in the window of bytes [from, to].
  std::size_t last_escape(std::size_t from, std::size_t to, bool high_surrogate_only) const {
    if (to < from || to >= text_.size()) return std::string_view::npos;
    for (std::size_t q = to + 1; q-- > from;) {
      if (byte(q) != '\\' || byte(q + 1) != 'u') continue;
      if (!high_surrogate_only) return q;
      const unsigned char d = byte(q + 3);
      if ((byte(q + 2) == 'd' || byte(q + 2) == 'D') && (d == '8' || d == '9' || (d >= 'a' && d <= 'b') ||
                                                         (d >= 'A' && d <= 'B')))
        return q;
    }
    return std::string_view::npos;
  }

  [[noreturn]] void diagnose_string(std::size_t start, std::size_t position, const std::string& what) {
    const std::size_t at = position == 0 ? start : position - 1;
    if (at < start) fail_as_library(position, what);  // the library failed before this string
    const std::string opened = " (the string starts at " + describe_location(where_.at(start)) + ")";
    // Before the end-of-input check: a sequence cut short by the end of the
    // input is reported as invalid UTF-8.
    if (what.find("ill-formed UTF-8") != std::string::npos) {
      const std::size_t bad = invalid_utf8_offset(text_.substr(start + 1, at - start));
      if (bad != std::string_view::npos) fail(start + 1 + bad, "invalid UTF-8 in a string" + opened);
    }
    if (at >= text_.size() || what.find("missing closing quote") != std::string::npos) {
      fail(start, "unterminated string");
    }
    const unsigned char c = byte(at);
    if (what.find("control character") != std::string::npos && c < 0x20) {
      char name[8];
      std::snprintf(name, sizeof name, "U+%04X", static_cast<unsigned>(c));
      fail(at, std::string("unescaped control character ") + name + " in a string" + opened);
    }
    if (what.find("forbidden character after backslash") != std::string::npos) {
      const std::string shown = c >= 0x21 && c <= 0x7E ? std::string("'\\") + static_cast<char>(c) + "'"
                                                        : "'\\' followed by byte " + hex_byte(c);
      fail(at - 1, "invalid escape " + shown + " in a string");
    }
    // The library stops at the first byte that breaks the escape, so the
    // escape at fault starts 2 to 5 bytes earlier (at - 1 may already be the
    // backslash of the next escape: "\u12\u0041").
    if (what.find("must be followed by 4 hex digits") != std::string::npos) {
      const std::size_t escape = last_escape(at >= start + 5 ? at - 5 : start, at >= 2 ? at - 2 : 0, false);
      if (escape != std::string_view::npos) fail(escape, "\\u in a string must be followed by 4 hex digits");
    }
    if (what.find("must follow U+D800..U+DBFF") != std::string::npos) {
      const std::size_t escape = last_escape(at >= start + 5 ? at - 5 : start, at >= 2 ? at - 2 : 0, false);
      if (escape != std::string_view::npos) fail(escape, "unpaired UTF-16 low surrogate in a \\u escape");
    }
    // Here the library stops just after the high surrogate's escape (at + 6
    // or + 7: no "\u" follows) or at the end of the escape after it (at +
    // 11), which may itself be a high surrogate: "\uD83D\uD83D".
    if (what.find("must be followed by U+DC00..U+DFFF") != std::string::npos && at >= start + 6) {
      const std::size_t escape = last_escape(at >= start + 12 ? at - 12 : start, at - 6, true);
      if (escape != std::string_view::npos) {
        if (byte(escape + 6) == '\\' && byte(escape + 7) == 'u') {
          fail(escape, "UTF-16 high surrogate not followed by a low surrogate");
        }
        fail(escape, "unpaired UTF-16 high surrogate in a \\u escape");
      }
    }
    fail_as_library(position, what);
  }

  std::string_view text_;
  std::size_t cursor_;  // just after the last token an event was for
  Locator where_;
  Expect expect_ = Expect::Value;
  std::vector<Open> stack_;
  JsonValue root_;
};

}  // namespace

JsonValue parse_json(std::string_view text) {
  // RFC 8259 section 8.1: a parser may ignore a leading byte order mark.
  // Editors on some systems write one. The library skips it too; here it
  // only moves where columns start counting.
  const std::size_t first = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
  std::size_t value_start = first;
  while (value_start < text.size() && is_space(static_cast<unsigned char>(text[value_start]))) ++value_start;
  if (value_start == text.size()) {
    Locator where(text, first);
    throw JsonError(describe_location(where.at(value_start)) + ": " +
                    (text.empty() ? "empty input, expected a JSON value" : "no JSON value, only whitespace"));
  }
  DocumentBuilder builder(text, first);
  // strict: the text must end after the value; comments are not ignored.
  // Every error reaches the builder, which throws, so false means a bug.
  if (!Library::sax_parse(text.data(), text.data() + text.size(), &builder, nlohmann::json::input_format_t::json,
                          /*strict=*/true, /*ignore_comments=*/false)) {
    throw InternalError("nlohmann-json stopped parsing without reporting an error");
  }
  return builder.finish();
}

}  // namespace stickmorph
