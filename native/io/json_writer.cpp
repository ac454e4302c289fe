// JSON output: numbers as the shortest text that reads back as the same
// double, string literals, and the incremental JsonWriter (json.h).
#include "stickmorph/io/json.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace stickmorph {

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
