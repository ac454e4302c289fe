#include "result_json.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace stickmorph::cli {
namespace {

void write_points(JsonWriter& out, const std::vector<Vec2>& points) {
  out.begin_array();
  for (const Vec2& p : points) {
    out.begin_array();
    out.value(p[0]);
    out.value(p[1]);
    out.end_array();
  }
  out.end_array();
}

}  // namespace

void write_triangulation(JsonWriter& out, const FigureTriangulation& tri) {
  out.begin_object();
  out.key("figure_vertices");
  out.value(tri.figure_vertices);
  out.key("enclosure_vertices");
  out.value(tri.enclosure_vertices);
  out.key("steiner_vertices");
  out.value(tri.steiner_vertices);
  out.key("source");
  write_points(out, tri.source);
  out.key("target");
  write_points(out, tri.target);
  out.key("triangles");
  out.begin_array();
  for (const auto& t : tri.triangles) {
    out.begin_array();
    for (int v : t) out.value(v);
    out.end_array();
  }
  out.end_array();
  out.end_object();
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) throw Error(path + ": cannot write file: " + std::strerror(errno));
    file << text;
    file.flush();
    if (!file) {
      std::remove(temporary.c_str());
      throw Error(path + ": cannot write file: " + std::strerror(errno));
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw Error(path + ": cannot write file: " + reason);
  }
}

}  // namespace stickmorph::cli
