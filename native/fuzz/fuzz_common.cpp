#include "fuzz_common.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

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

std::string figure_to_json(const StickFigure& figure) {
  JsonWriter writer;
  writer.begin_object();
  writer.key("name");
  writer.value(figure.name);
  writer.key("vertices");
  writer.begin_array();
  for (const Vec2& vertex : figure.vertices) {
    writer.begin_array();
    writer.value(vertex[0]);
    writer.value(vertex[1]);
    writer.end_array();
  }
  writer.end_array();
  writer.key("edges");
  writer.begin_array();
  for (const Edge& edge : figure.edges) {
    writer.begin_array();
    writer.value(edge[0]);
    writer.value(edge[1]);
    writer.end_array();
  }
  writer.end_array();
  writer.end_object();
  return writer.finish();
}

bool same_figure(const StickFigure& a, const StickFigure& b) {
  // Bitwise comparison of the doubles: == would let -0.0 stand for 0.0,
  // and the writer promises the exact double back.
  if (a.vertices.size() != b.vertices.size() || a.edges != b.edges || a.name != b.name) return false;
  return a.vertices.empty() ||
         std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vec2)) == 0;
}

}  // namespace stickmorph::fuzz
