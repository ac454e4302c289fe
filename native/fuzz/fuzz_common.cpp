#include "fuzz_common.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "stickmorph/figure_io.h"
#include "stickmorph/json.h"

namespace stickmorph::fuzz {

void report_finding(const std::string& what) {
  std::fprintf(stderr, "stickmorph fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

bool verification_is_finding() {
  static const bool enabled = [] {
    const char* value = std::getenv("STICKMORPH_FUZZ_VERIFICATION_IS_FINDING");
    return value != nullptr && std::strcmp(value, "1") == 0;
  }();
  return enabled;
}

bool tracing() {
  static const bool enabled = [] {
    const char* value = std::getenv("STICKMORPH_FUZZ_TRACE");
    return value != nullptr && std::strcmp(value, "1") == 0;
  }();
  return enabled;
}

void trace(const std::string& what) {
  if (tracing()) std::fprintf(stderr, "outcome: %s\n", what.c_str());
}

std::string figure_to_json(const StickFigure& figure) { return figure_json(figure, figure.name); }

bool same_figure(const StickFigure& a, const StickFigure& b) {
  // Bitwise comparison of the doubles: == would let -0.0 stand for 0.0,
  // and the writer promises the exact double back.
  if (a.vertices.size() != b.vertices.size() || a.edges != b.edges || a.name != b.name) return false;
  return a.vertices.empty() ||
         std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vec2)) == 0;
}

}  // namespace stickmorph::fuzz
