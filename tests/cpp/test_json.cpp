#include "catch.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "stickmorph/json.h"

using namespace stickmorph;
using stickmorph_test::Contains;
using stickmorph_test::Equals;
using stickmorph_test::StartsWith;

namespace {

// The message of the JsonError that parse_json must throw for `text`.
std::string parse_error(const std::string& text) {
  try {
    parse_json(text);
  } catch (const JsonError& error) {
    return error.what();
  }
  FAIL("parse_json accepted: " << text);
  return {};
}

// True when the two values are equal in kind and content (numbers bitwise,
// so that -0.0 and 0.0 differ).
bool same(const JsonValue& a, const JsonValue& b) {
  if (a.kind() != b.kind()) return false;
  switch (a.kind()) {
    case JsonValue::Kind::Null: return true;
    case JsonValue::Kind::Bool: return a.as_bool() == b.as_bool();
    case JsonValue::Kind::Number: {
      const double x = a.as_number(), y = b.as_number();
      return std::memcmp(&x, &y, sizeof x) == 0;
    }
    case JsonValue::Kind::String: return a.as_string() == b.as_string();
    case JsonValue::Kind::Array: {
      const auto &p = a.as_array(), &q = b.as_array();
      if (p.size() != q.size()) return false;
      for (std::size_t k = 0; k < p.size(); ++k)
        if (!same(p[k], q[k])) return false;
      return true;
    }
    case JsonValue::Kind::Object: {
      const auto &p = a.as_object(), &q = b.as_object();
      if (p.size() != q.size()) return false;
      for (std::size_t k = 0; k < p.size(); ++k)
        if (p[k].key != q[k].key || !same(p[k].value, q[k].value)) return false;
      return true;
    }
  }
  return false;
}

double number(const std::string& text) { return parse_json(text).as_number(); }

}  // namespace

TEST_CASE("literals and numbers parse", "[json]") {
  CHECK(parse_json("null").is_null());
  CHECK(parse_json("true").as_bool() == true);
  CHECK(parse_json("false").as_bool() == false);
  CHECK(number("0") == 0.0);
  CHECK(number("-0") == 0.0);
  CHECK(std::signbit(number("-0")));
  CHECK(number("42") == 42.0);
  CHECK(number("-17") == -17.0);
  CHECK(number("3.25") == 3.25);
  CHECK(number("0.1") == 0.1);
  CHECK(number("1e3") == 1000.0);
  CHECK(number("1E+3") == 1000.0);
  CHECK(number("25e-1") == 2.5);
  CHECK(number("-0.0e0") == 0.0);
  CHECK(number("1.7976931348623157e308") == std::numeric_limits<double>::max());
  CHECK(number("5e-324") == std::numeric_limits<double>::denorm_min());
  CHECK(number("123456789012345678901234567890") == 1.2345678901234568e29);
}

TEST_CASE("numbers too small for a double become zero", "[json]") {
  CHECK(number("1e-400") == 0.0);
  CHECK(std::signbit(number("-1e-400")));
  CHECK(number("0.00000000000000000000000000001e-320") == 0.0);
}

TEST_CASE("numbers too large for a double are errors naming the number", "[json]") {
  CHECK_THAT(parse_error("1e400"), Equals("line 1, column 1: number 1e400 overflows a double"));
  CHECK_THAT(parse_error("[0, -1e400]"),
             Equals("line 1, column 5: number -1e400 overflows a double"));
  CHECK_THAT(parse_error("1.7976931348623159e308"), Contains("overflows a double"));
  CHECK_THAT(parse_error("123e99999999999999999999999"), Contains("overflows a double"));
  // A hostile 100000-digit number is echoed only in part.
  const std::string huge = "9" + std::string(100000, '0');
  const std::string message = parse_error(huge);
  CHECK_THAT(message, Contains("overflows a double"));
  CHECK(message.size() < 200);
}

TEST_CASE("number grammar is strict", "[json]") {
  CHECK_THAT(parse_error("01"), Equals("line 1, column 1: a number must not have a leading zero"));
  CHECK_THAT(parse_error("[-012]"), Equals("line 1, column 2: a number must not have a leading zero"));
  CHECK_THAT(parse_error("00"), Contains("leading zero"));
  CHECK_THAT(parse_error("-"), Equals("line 1, column 1: expected a digit after '-'"));
  CHECK_THAT(parse_error("- 1"), Contains("expected a digit after '-'"));
  CHECK_THAT(parse_error("1."), Contains("expected a digit after the decimal point"));
  CHECK_THAT(parse_error("1.e5"), Contains("expected a digit after the decimal point"));
  CHECK_THAT(parse_error("1e"), Contains("expected a digit in the exponent"));
  CHECK_THAT(parse_error("1e+"), Contains("expected a digit in the exponent"));
  CHECK_THAT(parse_error(".5"), Equals("line 1, column 1: unexpected character '.', expected a JSON value"));
  CHECK_THAT(parse_error("+1"), Equals("line 1, column 1: unexpected character '+', expected a JSON value"));
  CHECK_THAT(parse_error("0x10"), Equals("line 1, column 2: unexpected character 'x' after the JSON value"));
  CHECK_THAT(parse_error("1.5.2"), Contains("column 4: unexpected character '.' after the JSON value"));
}

TEST_CASE("NaN and Infinity are not JSON", "[json]") {
  CHECK_THAT(parse_error("NaN"),
             Equals("line 1, column 1: NaN is not a JSON number (JSON has no NaN or infinity)"));
  CHECK_THAT(parse_error("[1, Infinity]"),
             Equals("line 1, column 5: Infinity is not a JSON number (JSON has no NaN or infinity)"));
  CHECK_THAT(parse_error("[-Infinity]"), Equals("line 1, column 2: -Infinity is not a JSON number "
                                                "(JSON has no NaN or infinity)"));
  CHECK_THAT(parse_error("nan"), Contains("nan is not a JSON number"));
  CHECK_THAT(parse_error("-inf"), Contains("-inf is not a JSON number"));
}

TEST_CASE("words other than true, false, null are rejected", "[json]") {
  CHECK_THAT(parse_error("True"), Equals("line 1, column 1: unexpected word 'True', expected a JSON value"));
  CHECK_THAT(parse_error("None"), Contains("unexpected word 'None'"));
  CHECK_THAT(parse_error("nul"), Contains("unexpected word 'nul'"));
  CHECK_THAT(parse_error("truex"), Contains("unexpected word 'truex'"));
  CHECK_THAT(parse_error("{key: 1}"), Equals("line 1, column 2: unexpected character 'k' in an "
                                             "object, expected a string key"));
}

TEST_CASE("strings decode escapes and keep bytes", "[json]") {
  CHECK(parse_json(R"("")").as_string().empty());
  CHECK(parse_json(R"("plain text")").as_string() == "plain text");
  CHECK(parse_json(R"("\" \\ \/ \b \f \n \r \t")").as_string() == "\" \\ / \b \f \n \r \t");
  CHECK(parse_json(R"("\u0041\u00e9\u20AC")").as_string() == "A\xC3\xA9\xE2\x82\xAC");
  // U+1F600 as a surrogate pair becomes 4 bytes of UTF-8.
  CHECK(parse_json(R"("\uD83D\uDE00")").as_string() == "\xF0\x9F\x98\x80");
  CHECK(parse_json(R"("\u0000")").as_string() == std::string(1, '\0'));
  // UTF-8 passes through unchanged.
  CHECK(parse_json("\"caf\xC3\xA9\"").as_string() == "caf\xC3\xA9");
  CHECK(parse_json("\"\xF0\x9F\x98\x80\"").as_string() == "\xF0\x9F\x98\x80");
  CHECK(parse_json("\"\x7F\"").as_string() == "\x7F");
}

TEST_CASE("strings must be UTF-8 (RFC 8259, section 8.1)", "[json]") {
  // Bytes that are not UTF-8, overlong forms, encoded surrogates, code
  // points above U+10FFFF, truncated sequences: each named by position.
  for (const char* text : {"\"\xFF\xFE\"", "\"caf\xE9\"", "\"\xC0\xAF\"", "\"\xE0\x80\xAF\"",
                           "\"\xED\xA0\x80\"", "\"\xF4\x90\x80\x80\"", "\"ab\xE2\x82\""}) {
    INFO(text);
    CHECK_THAT(parse_error(text), Contains("invalid UTF-8 in a string"));
  }
  CHECK_THAT(parse_error("{\"name\": \"caf\xE9\"}"), StartsWith("line 1, column 14"));
}

TEST_CASE("string errors name their position", "[json]") {
  CHECK_THAT(parse_error("\"abc"), Equals("line 1, column 1: unterminated string"));
  CHECK_THAT(parse_error("[\"abc\\"), Equals("line 1, column 2: unterminated string"));
  CHECK_THAT(parse_error("\"a\nb\""),
             Equals("line 1, column 3: unescaped control character U+000A in a string "
                    "(the string starts at line 1, column 1)"));
  CHECK_THAT(parse_error("\"a\tb\""), Contains("unescaped control character U+0009"));
  CHECK_THAT(parse_error(std::string("\"a\0b\"", 5)), Contains("unescaped control character U+0000"));
  CHECK_THAT(parse_error(R"("a\x")"), Equals("line 1, column 3: invalid escape '\\x' in a string"));
  CHECK_THAT(parse_error(R"("\'")"), Contains("invalid escape '\\''"));
  CHECK_THAT(parse_error(R"("\u12")"), Contains("column 2: \\u in a string must be followed by 4 hex digits"));
  CHECK_THAT(parse_error(R"("\u12G4")"), Contains("must be followed by 4 hex digits"));
  CHECK_THAT(parse_error(R"("\uD83D")"), Contains("unpaired UTF-16 high surrogate"));
  CHECK_THAT(parse_error(R"("\uD83Dx")"), Contains("unpaired UTF-16 high surrogate"));
  CHECK_THAT(parse_error(R"("\uD83D\u0041")"),
             Contains("UTF-16 high surrogate not followed by a low surrogate"));
  CHECK_THAT(parse_error(R"("\uDE00")"), Contains("unpaired UTF-16 low surrogate"));
  CHECK_THAT(parse_error("'single'"),
             Equals("line 1, column 1: unexpected character '\\'', JSON strings use double quotes"));
}

TEST_CASE("arrays and objects keep order and locations", "[json]") {
  const JsonValue value = parse_json("{\n  \"b\": [1,\n    true],\r\n  \"a\": {\"x\": null}\n}");
  REQUIRE(value.is_object());
  const auto& members = value.as_object();
  REQUIRE(members.size() == 2);
  CHECK(members[0].key == "b");  // document order, not sorted
  CHECK(members[1].key == "a");
  CHECK(members[0].key_location.line == 2);
  CHECK(members[0].key_location.column == 3);
  const JsonValue& b = members[0].value;
  CHECK(b.location().line == 2);
  CHECK(b.location().column == 8);
  REQUIRE(b.as_array().size() == 2);
  CHECK(b.as_array()[1].location().line == 3);
  CHECK(b.as_array()[1].location().column == 5);
  // "\r\n" ends a line like "\n".
  CHECK(members[1].key_location.line == 4);
  CHECK(members[1].key_location.column == 3);
  CHECK(value.find("a")->find("x")->is_null());
  CHECK(value.find("missing") == nullptr);
  CHECK(value.location().line == 1);
  CHECK(value.location().column == 1);
  CHECK(parse_json(" [ ] ").as_array().empty());
  CHECK(parse_json("{ }").as_object().empty());
}

TEST_CASE("structural errors: trailing commas, missing separators, unclosed", "[json]") {
  CHECK_THAT(parse_error("[1, 2,]"), Equals("line 1, column 6: trailing comma before ']'"));
  CHECK_THAT(parse_error("{\"a\": 1,\n}"), Equals("line 1, column 8: trailing comma before '}'"));
  CHECK_THAT(parse_error("[1 2]"),
             Equals("line 1, column 4: unexpected character '2' in an array, expected ',' or ']'"));
  CHECK_THAT(parse_error("[,1]"), Equals("line 1, column 2: unexpected character ',', expected a JSON value"));
  CHECK_THAT(parse_error("{\"a\" 1}"),
             Equals("line 1, column 6: unexpected character '1' after an object key, expected ':'"));
  CHECK_THAT(parse_error("{\"a\": 1 \"b\": 2}"),
             Contains("column 9: unexpected character '\"' in an object, expected ',' or '}'"));
  CHECK_THAT(parse_error("{\"a\": }"), Contains("unexpected character '}', expected a JSON value"));
  CHECK_THAT(parse_error("[1, [2, 3]"),
             Equals("line 1, column 11: unexpected end of input, the array opened at line 1, "
                    "column 1 is not closed"));
  CHECK_THAT(parse_error("{\"a\": [1]"), Contains("the object opened at line 1, column 1 is not closed"));
  CHECK_THAT(parse_error("{\"a\""), Contains("the object opened at line 1, column 1 is not closed"));
  CHECK_THAT(parse_error("["), Contains("the array opened at line 1, column 1 is not closed"));
  CHECK_THAT(parse_error("]"), Equals("line 1, column 1: unexpected character ']', expected a JSON value"));
}

TEST_CASE("duplicate keys are rejected with both positions", "[json]") {
  CHECK_THAT(parse_error("{\"edges\": [],\n \"edges\": []}"),
             Equals("line 2, column 2: duplicate key \"edges\" (first at line 1, column 2)"));
  // Keys compare after unescaping.
  CHECK_THAT(parse_error(R"({"a": 1, "\u0061": 2})"), Contains("duplicate key \"a\""));
  // The same key in different objects is fine.
  CHECK_NOTHROW(parse_json(R"([{"a": 1}, {"a": 2}])"));
}

TEST_CASE("comments and trailing garbage are rejected", "[json]") {
  CHECK_THAT(parse_error("// comment\n1"), Equals("line 1, column 1: comments are not allowed in JSON"));
  CHECK_THAT(parse_error("[1, /* two */ 2]"), Equals("line 1, column 5: comments are not allowed in JSON"));
  CHECK_THAT(parse_error("1 // end"), Equals("line 1, column 3: comments are not allowed in JSON"));
  CHECK_THAT(parse_error("{} {}"), Equals("line 1, column 4: unexpected character '{' after the JSON value"));
  CHECK_THAT(parse_error("[]\n\n  x"),
             Equals("line 3, column 3: unexpected character 'x' after the JSON value"));
  CHECK_THAT(parse_error("1\x01"), Equals("line 1, column 2: unexpected byte 0x01 after the JSON value"));
}

TEST_CASE("empty, blank and binary input are errors", "[json]") {
  CHECK_THAT(parse_error(""), Equals("line 1, column 1: empty input, expected a JSON value"));
  CHECK_THAT(parse_error(" \n\t "), Equals("line 2, column 3: no JSON value, only whitespace"));
  CHECK_THAT(parse_error("\x7F" "ELF\x02\x01"),
             Equals("line 1, column 1: unexpected byte 0x7F, expected a JSON value"));
  CHECK_THAT(parse_error(std::string(1, '\0')), Contains("unexpected byte 0x00"));
  std::string all_bytes;
  for (int b = 0; b < 256; ++b) all_bytes += static_cast<char>(b);
  CHECK_THAT(parse_error(all_bytes), StartsWith("line 1, column 1: unexpected byte 0x00"));
  // Only the byte order mark: nothing after it.
  CHECK_THAT(parse_error("\xEF\xBB\xBF"), Contains("no JSON value"));
}

TEST_CASE("a leading UTF-8 byte order mark is skipped", "[json]") {
  const JsonValue value = parse_json("\xEF\xBB\xBF[1]");
  CHECK(value.as_array().size() == 1);
  CHECK(value.location().column == 1);
  CHECK_THAT(parse_error("[1]\xEF\xBB\xBF"), Contains("unexpected byte 0xEF after the JSON value"));
}

TEST_CASE("nesting depth is limited", "[json]") {
  const std::size_t limit = kMaxJsonDepth;
  const std::string at_limit = std::string(limit, '[') + std::string(limit, ']');
  CHECK_NOTHROW(parse_json(at_limit));
  const std::string beyond = std::string(limit + 1, '[') + std::string(limit + 1, ']');
  CHECK_THAT(parse_error(beyond), Equals("line 1, column 257: arrays and objects nest deeper "
                                         "than 256 levels"));
  // Far beyond the limit: an error, not a stack overflow.
  CHECK_THAT(parse_error(std::string(100000, '[')), Contains("nest deeper than 256 levels"));
  std::string objects;
  for (int k = 0; k < 100000; ++k) objects += "{\"a\":";
  CHECK_THAT(parse_error(objects), Contains("nest deeper than 256 levels"));
}

// Inputs where nlohmann-json, which parse_json uses, is laxer than FORMAT.md
// or notices a problem somewhere other than the value at fault; parse_json
// must still answer as for every other input.
TEST_CASE("where the JSON library is lax or reports elsewhere, the rules hold", "[json]") {
  // The library takes a NUL byte for the end of the input.
  CHECK_THAT(parse_error(std::string("[1]\0x", 5)),
             Equals("line 1, column 4: unexpected byte 0x00 after the JSON value"));
  CHECK_THAT(parse_error(std::string("[1,\0]", 5)),
             Equals("line 1, column 4: unexpected byte 0x00, expected a JSON value"));
  // The library skips one byte order mark of its own accord; a second one is
  // not whitespace.
  CHECK_THAT(parse_error("\xEF\xBB\xBF\xEF\xBB\xBF[1]"),
             Equals("line 1, column 1: unexpected byte 0xEF, expected a JSON value"));
  // The library reads "null" and then fails at "x"; the word is at fault.
  CHECK_THAT(parse_error("[nullx]"), Equals("line 1, column 2: unexpected word 'nullx', expected a JSON value"));
  // The library reads "-0" as the integer 0.
  CHECK(std::signbit(parse_json("[1.5, -0]").as_array()[1].as_number()));
  // The library stops after the second escape; the first is at fault.
  CHECK_THAT(parse_error(R"("\uD83D\uD83D")"),
             Equals("line 1, column 2: UTF-16 high surrogate not followed by a low surrogate"));
  // The library stops at the backslash of the next escape.
  CHECK_THAT(parse_error(R"("\u12\u0041")"),
             Equals("line 1, column 2: \\u in a string must be followed by 4 hex digits"));
  // A sequence cut short by the closing quote or by the end of the input
  // is named at its first byte, not where the library noticed it.
  CHECK_THAT(parse_error("\"ab\xC3\""), StartsWith("line 1, column 4: invalid UTF-8 in a string"));
  CHECK_THAT(parse_error("\"2\xC3"), StartsWith("line 1, column 3: invalid UTF-8 in a string"));
  // A trailing comma after an empty key, and separators the library reports
  // at the next token.
  CHECK_THAT(parse_error(R"({"": 1,})"), Equals("line 1, column 7: trailing comma before '}'"));
  CHECK_THAT(parse_error("[1 , ,2]"), Equals("line 1, column 6: unexpected character ',', expected a JSON value"));
  CHECK_THAT(parse_error("\n\n  [1,\n 2,\n]"), Equals("line 4, column 3: trailing comma before ']'"));
}

TEST_CASE("accessors of the wrong kind throw JsonError naming the location", "[json]") {
  const JsonValue value = parse_json("[1, \"two\"]");
  try {
    value.as_array()[1].as_number();
    FAIL("as_number accepted a string");
  } catch (const JsonError& error) {
    CHECK_THAT(error.what(), Equals("line 1, column 5: expected a number, got a string"));
  }
  CHECK_THROWS_AS(value.as_object(), JsonError);
  CHECK_THROWS_AS(value.find("x"), JsonError);
  CHECK_THROWS_AS(JsonValue(true).as_string(), JsonError);
  CHECK(std::string(describe_kind(JsonValue::Kind::Array)) == "an array");
}

TEST_CASE("format_json_number round-trips and marks floats", "[json][writer]") {
  CHECK(format_json_number(1.0) == "1.0");
  CHECK(format_json_number(0.0) == "0.0");
  CHECK(format_json_number(-0.0) == "-0.0");
  CHECK(format_json_number(0.1) == "0.1");
  CHECK(format_json_number(-2.5) == "-2.5");
  CHECK(format_json_number(1e100) == "1e+100");
  CHECK(format_json_number(5e-324) == "5e-324");
  CHECK(format_json_number(1.0 / 3.0) == "0.3333333333333333");
  CHECK_THROWS_AS(format_json_number(std::numeric_limits<double>::quiet_NaN()), InvalidArgumentError);
  CHECK_THROWS_AS(format_json_number(-std::numeric_limits<double>::infinity()), InvalidArgumentError);

  // Random bit patterns: every finite double reads back bit for bit.
  std::mt19937_64 random(12345);
  int checked = 0;
  while (checked < 20000) {
    const std::uint64_t bits = random();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    if (!std::isfinite(value)) continue;
    const double back = parse_json(format_json_number(value)).as_number();
    REQUIRE(std::memcmp(&back, &value, sizeof value) == 0);
    ++checked;
  }
}

TEST_CASE("quote_json_string escapes what JSON requires", "[json][writer]") {
  CHECK(quote_json_string("plain") == "\"plain\"");
  CHECK(quote_json_string("a\"b\\c") == R"("a\"b\\c")");
  CHECK(quote_json_string("\n\t\x01") == R"("\n\t\u0001")");
  CHECK(quote_json_string("caf\xC3\xA9") == "\"caf\xC3\xA9\"");
  // Every ASCII character and UTF-8 sequences of each length round-trip.
  std::string all_characters;
  for (int b = 1; b < 128; ++b) all_characters += static_cast<char>(b);
  all_characters += "\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80";
  CHECK(parse_json(quote_json_string(all_characters)).as_string() == all_characters);
}

TEST_CASE("to_json writes compact and pretty documents", "[json][writer]") {
  const JsonValue value = parse_json(
      R"({"name": "A", "edges": [[0, 1], [1, 2]], "times": [0, 0.5, 1], "empty": [], "o": {},)"
      R"( "flag": true, "none": null})");
  CHECK(to_json(value) ==
        R"({"name":"A","edges":[[0.0,1.0],[1.0,2.0]],"times":[0.0,0.5,1.0],"empty":[],"o":{},)"
        R"("flag":true,"none":null})");
  CHECK(to_json(value, true) ==
        "{\n"
        "  \"name\": \"A\",\n"
        "  \"edges\": [\n"
        "    [0.0, 1.0],\n"
        "    [1.0, 2.0]\n"
        "  ],\n"
        "  \"times\": [0.0, 0.5, 1.0],\n"
        "  \"empty\": [],\n"
        "  \"o\": {},\n"
        "  \"flag\": true,\n"
        "  \"none\": null\n"
        "}\n");
  CHECK(same(parse_json(to_json(value)), value));
  CHECK(same(parse_json(to_json(value, true)), value));
  CHECK(to_json(JsonValue(2.5)) == "2.5");
  CHECK(to_json(JsonValue("x")) == "\"x\"");
}

TEST_CASE("JsonWriter streams values and rejects misuse", "[json][writer]") {
  JsonWriter writer;
  writer.begin_object();
  writer.key("edges");
  writer.begin_array();
  writer.begin_array();
  writer.value(0);
  writer.value(std::size_t{1});
  writer.end_array();
  writer.end_array();
  writer.key("t");
  writer.value(0.25);
  writer.key("s");
  writer.value(std::string("x"));
  CHECK_FALSE(writer.complete());
  writer.end_object();
  CHECK(writer.complete());
  CHECK(writer.finish() == R"({"edges":[[0,1]],"t":0.25,"s":"x"})");

  JsonWriter misuse;
  CHECK_THROWS_AS(misuse.key("k"), InternalError);
  CHECK_THROWS_AS(misuse.end_array(), InternalError);
  CHECK_THROWS_AS(misuse.finish(), InternalError);
  misuse.begin_object();
  CHECK_THROWS_AS(misuse.value(1.0), InternalError);  // no key
  CHECK_THROWS_AS(misuse.end_array(), InternalError);
  misuse.key("k");
  CHECK_THROWS_AS(misuse.key("again"), InternalError);
  CHECK_THROWS_AS(misuse.end_object(), InternalError);
  CHECK_THROWS_AS(misuse.value(std::numeric_limits<double>::infinity()), InvalidArgumentError);
  misuse.value(1.0);
  misuse.end_object();
  CHECK_THROWS_AS(misuse.value(2.0), InternalError);  // after the document
}

TEST_CASE("mutated documents never crash the parser", "[json][fuzz]") {
  // Every mutation must either parse or throw JsonError; a crash, hang or
  // other exception fails the test.
  const std::string seed =
      R"({"name": "A \u00e9\uD83D\uDE00", "vertices": [[0, 0], [1.5e3, -2], [3, 4.25]],)"
      R"( "edges": [[0, 1], [1, 2]], "extra": {"t": true, "f": false, "n": null}})";
  std::mt19937 random(2024);
  const std::string alphabet = "[]{}\",:.-+eE0123456789 \n\\u/*tfnaxNI\x01\xFF";
  int parsed = 0;
  for (int round = 0; round < 20000; ++round) {
    std::string text = seed;
    const int edits = 1 + static_cast<int>(random() % 4);
    for (int k = 0; k < edits && !text.empty(); ++k) {
      const std::size_t at = random() % text.size();
      switch (random() % 3) {
        case 0: text[at] = alphabet[random() % alphabet.size()]; break;
        case 1: text.erase(at, 1 + random() % 3); break;
        default: text.insert(at, 1, alphabet[random() % alphabet.size()]); break;
      }
    }
    try {
      parse_json(text);
      ++parsed;
    } catch (const JsonError& error) {
      REQUIRE_THAT(error.what(), StartsWith("line "));
    }
  }
  // Some mutations (inside strings, digits for digits) keep the document valid.
  CHECK(parsed > 0);
}
