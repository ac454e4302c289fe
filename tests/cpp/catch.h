// Catch2 for the engine's tests, whichever major version the system ships:
// Debian 12 packages Catch2 v2 (one header, catch2/catch.hpp), Debian 13 and
// later only v3 (catch2/catch_all.hpp, a compiled library with its own main).
// Tests include this header and name matchers through stickmorph_test, so one
// source serves both.
#pragma once

#if __has_include(<catch2/catch_all.hpp>)
#include <catch2/catch_all.hpp>
#include <string>

// v2 spelled these at global scope; v3 moved Approx into Catch.
using Catch::Approx;

namespace stickmorph_test {
// v3 renamed the substring matcher: its Contains matches an element of a range.
inline Catch::Matchers::StringContainsMatcher Contains(const std::string& text) {
  return Catch::Matchers::ContainsSubstring(text);
}
using Catch::Matchers::EndsWith;
using Catch::Matchers::Equals;
using Catch::Matchers::StartsWith;
}  // namespace stickmorph_test

#else
#include <catch2/catch.hpp>

namespace stickmorph_test {
using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;
using Catch::Matchers::Equals;
using Catch::Matchers::StartsWith;
}  // namespace stickmorph_test
#endif
