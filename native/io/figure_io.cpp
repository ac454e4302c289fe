#include "stickmorph/io/figure_io.h"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stickmorph/errors.h"
#include "stickmorph/io/json.h"

namespace stickmorph {
namespace {

// A figure file larger than this is refused instead of read. A million
// vertices at full double precision take about 45 MB of JSON. The document
// model costs about 35 times the size of dense input (1.7 GB for 48 MB of
// "[0,0],"), so the cap bounds memory as well as keeping a mistaken argument
// such as /dev/zero from reading until memory runs out.
constexpr std::size_t kMaxFigureFileBytes = std::size_t{64} << 20;

// Builds shape errors: "<origin>: line L, column C: <what>".
class ShapeErrors {
 public:
  explicit ShapeErrors(const std::string& origin) : prefix_(origin.empty() ? "" : origin + ": ") {}

  [[noreturn]] void fail(const JsonValue& at, const std::string& what) const {
    throw JsonError(prefix_ + describe_location(at.location()) + ": " + what);
  }

  const std::string& prefix() const { return prefix_; }

 private:
  std::string prefix_;
};

// "an array of 3 values" rather than just "an array" when the length is
// what is wrong.
std::string describe_shape(const JsonValue& value) {
  if (!value.is_array()) return describe_kind(value.kind());
  const std::size_t size = value.as_array().size();
  if (size == 0) return "an empty array";
  return "an array of " + std::to_string(size) + (size == 1 ? " value" : " values");
}

const JsonValue& require_member(const JsonValue& figure, const char* key,
                                const ShapeErrors& errors) {
  const JsonValue* member = figure.find(key);
  if (member == nullptr) {
    errors.fail(figure, std::string("missing field \"") + key + "\" in the figure object");
  }
  return *member;
}

// One [x, y] entry; `name()` says which in a message ("vertex 3",
// "stroke 2, point 7").
template <typename Name>
Vec2 read_point(const JsonValue& entry, const Name& name, const ShapeErrors& errors) {
  if (!entry.is_array() || entry.as_array().size() != 2)
    errors.fail(entry, name() + " must be an array of 2 numbers [x, y], got " + describe_shape(entry));
  Vec2 position{};
  for (std::size_t axis = 0; axis < 2; ++axis) {
    const JsonValue& coordinate = entry.as_array()[axis];
    if (!coordinate.is_number())
      errors.fail(coordinate, name() + ": expected a number for " + (axis == 0 ? "x" : "y") + ", got " +
                                  describe_kind(coordinate.kind()));
    position[axis] = coordinate.as_number();
  }
  return position;
}

// The JSON document of `text`, its syntax errors prefixed with the origin.
JsonValue parse_document(const std::string& text, const ShapeErrors& errors) {
  try {
    return parse_json(text);
  } catch (const JsonError& error) {
    throw JsonError(errors.prefix() + error.what());
  }
}

std::vector<Vec2> read_vertices(const JsonValue& list, const ShapeErrors& errors) {
  if (!list.is_array()) {
    errors.fail(list, std::string("\"vertices\" must be an array of [x, y] pairs, got ") +
                          describe_kind(list.kind()));
  }
  std::vector<Vec2> vertices;
  vertices.reserve(list.as_array().size());
  for (const JsonValue& entry : list.as_array()) {
    // Built only for a message: a figure may have millions of vertices.
    vertices.push_back(read_point(entry, [&vertices] { return "vertex " + std::to_string(vertices.size()); }, errors));
  }
  return vertices;
}

std::vector<std::array<std::int64_t, 2>> read_edges(const JsonValue& list,
                                                    const ShapeErrors& errors) {
  if (!list.is_array()) {
    errors.fail(list, std::string("\"edges\" must be an array of [i, j] vertex index pairs, got ") +
                          describe_kind(list.kind()));
  }
  // Doubles in [-2^63, 2^63) convert to int64 exactly when integral; the
  // upper bound is exclusive because 2^63 itself does not fit.
  constexpr double kInt64Bound = 9223372036854775808.0;  // 2^63
  std::vector<std::array<std::int64_t, 2>> edges;
  edges.reserve(list.as_array().size());
  for (const JsonValue& entry : list.as_array()) {
    const auto name = [&edges] { return "edge " + std::to_string(edges.size()); };
    if (!entry.is_array() || entry.as_array().size() != 2) {
      errors.fail(entry, name() + " must be an array of 2 vertex indices [i, j], got " +
                             describe_shape(entry));
    }
    std::array<std::int64_t, 2> edge{};
    for (std::size_t end = 0; end < 2; ++end) {
      const JsonValue& index = entry.as_array()[end];
      if (!index.is_number()) {
        errors.fail(index, name() + ": expected a vertex index (an integer), got " +
                               describe_kind(index.kind()));
      }
      const double value = index.as_number();
      if (std::floor(value) != value) {
        errors.fail(index, name() + ": vertex index " + format_json_number(value) +
                               " is not an integer");
      }
      if (value < -kInt64Bound || value >= kInt64Bound) {
        errors.fail(index, name() + ": vertex index " + format_json_number(value) +
                               " is outside the 64-bit integer range");
      }
      // Range against the vertex count is make_stick_figure's check, so
      // that files and in-memory arrays get the same message.
      edge[end] = static_cast<std::int64_t>(value);
    }
    edges.push_back(edge);
  }
  return edges;
}

}  // namespace

StickFigure parse_figure(const std::string& text, const std::string& origin) {
  const ShapeErrors errors(origin);
  const JsonValue document = parse_document(text, errors);
  if (!document.is_object()) {
    errors.fail(document, std::string("a figure file must hold a JSON object with \"vertices\" "
                                      "and \"edges\", got ") +
                              describe_kind(document.kind()));
  }
  // Members other than these three are ignored, so that later versions can
  // add fields (colours, per-vertex labels) without breaking older readers.
  std::vector<Vec2> vertices = read_vertices(require_member(document, "vertices", errors), errors);
  const auto edges = read_edges(require_member(document, "edges", errors), errors);
  std::string name;
  if (const JsonValue* name_value = document.find("name")) {
    if (!name_value->is_string()) {
      errors.fail(*name_value, std::string("\"name\" must be a string, got ") +
                                   describe_kind(name_value->kind()));
    }
    name = name_value->as_string();
  }
  try {
    return make_stick_figure(std::move(vertices), edges, std::move(name));
  } catch (const InvalidFigureError& error) {
    throw InvalidFigureError(error.defect(), errors.prefix() + error.what(), error.vertices(),
                             error.edges());
  }
}

namespace {

// The kind of a non-regular file, for the message that refuses it.
const char* file_kind(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

std::string read_input_file(const std::string& path) {
  const auto fail = [&path](int error_number) {
    throw FileError(path, error_number, path + ": cannot read file: " + std::strerror(error_number));
  };
  // O_NONBLOCK so that opening a FIFO returns at once instead of waiting
  // for a writer; fstat on what was opened (not stat on the name, which a
  // race could swap) then refuses anything but a regular file: a FIFO, a
  // socket or a device could block a read forever or never end (/dev/zero).
  errno = 0;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) fail(errno != 0 ? errno : EIO);
  struct CloseDescriptor {
    int fd;
    ~CloseDescriptor() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0) fail(errno);
  if (S_ISDIR(info.st_mode)) fail(EISDIR);
  if (!S_ISREG(info.st_mode))
    throw FileError(path, EINVAL,
                    path + ": cannot read file: " + file_kind(info.st_mode) + ", not a regular file");
  if (info.st_size > 0 && std::uint64_t(info.st_size) > kMaxFigureFileBytes)
    throw FileError(path, EFBIG, path + ": cannot read file: larger than " +
                    std::to_string(kMaxFigureFileBytes >> 20) + " MiB");
  std::string text;
  char buffer[1 << 16];
  while (true) {
    const ssize_t count = ::read(fd, buffer, sizeof buffer);
    if (count < 0) {
      if (errno == EINTR) continue;
      fail(errno);
    }
    if (count == 0) break;
    text.append(buffer, std::size_t(count));
    // Checked while reading too: a file can grow after fstat.
    if (text.size() > kMaxFigureFileBytes) {
      throw FileError(path, EFBIG, path + ": cannot read file: larger than " +
                      std::to_string(kMaxFigureFileBytes >> 20) + " MiB");
    }
  }
  return text;
}

StickFigure read_figure_file(const std::string& path) { return parse_figure(read_input_file(path), path); }

namespace {

std::vector<std::vector<Vec2>> read_strokes(const JsonValue& list, const ShapeErrors& errors,
                                            std::vector<bool>& cyclic) {
  if (!list.is_array())
    errors.fail(list, std::string("\"strokes\" must be an array of {\"points\": [[x, y], ...]} objects, got ") +
                          describe_kind(list.kind()));
  std::vector<std::vector<Vec2>> strokes;
  for (const JsonValue& entry : list.as_array()) {
    const std::string name = "stroke " + std::to_string(strokes.size());
    if (!entry.is_object())
      errors.fail(entry, name + " must be an object {\"points\": [[x, y], ...], \"cyclic\": false}, got " +
                             describe_kind(entry.kind()));
    const JsonValue* points = entry.find("points");
    if (points == nullptr) errors.fail(entry, "missing field \"points\" in " + name);
    if (!points->is_array())
      errors.fail(*points, name + ": \"points\" must be an array of [x, y] pairs, got " + describe_kind(points->kind()));
    std::vector<Vec2> stroke;
    for (const JsonValue& point : points->as_array())
      stroke.push_back(
          read_point(point, [&] { return name + ", point " + std::to_string(stroke.size()); }, errors));
    bool closed = false;
    if (const JsonValue* flag = entry.find("cyclic")) {
      if (!flag->is_bool()) errors.fail(*flag, name + ": \"cyclic\" must be true or false, got " + describe_kind(flag->kind()));
      closed = flag->as_bool();
    }
    cyclic.push_back(closed);
    strokes.push_back(std::move(stroke));
  }
  return strokes;
}

}  // namespace

Drawing parse_drawing(const std::string& text, const std::string& origin) {
  const ShapeErrors errors(origin);
  const JsonValue document = parse_document(text, errors);
  if (!document.is_object())
    errors.fail(document, std::string("a drawing file must hold a JSON object with \"strokes\" (or a figure's "
                                      "\"vertices\" and \"edges\"), got ") +
                              describe_kind(document.kind()));
  std::string name;
  if (const JsonValue* name_value = document.find("name")) {
    if (!name_value->is_string())
      errors.fail(*name_value, std::string("\"name\" must be a string, got ") + describe_kind(name_value->kind()));
    name = name_value->as_string();
  }
  try {
    if (const JsonValue* strokes = document.find("strokes")) {
      if (document.find("vertices") || document.find("edges"))
        errors.fail(document, "a drawing file holds either \"strokes\" or a figure's \"vertices\" and \"edges\", not both");
      std::vector<bool> cyclic;
      std::vector<std::vector<Vec2>> points = read_strokes(*strokes, errors, cyclic);
      return drawing_from_strokes(points, std::move(cyclic), std::move(name));
    }
    if (!document.find("vertices") && !document.find("edges"))
      errors.fail(document, "missing field \"strokes\" (a drawing) or \"vertices\" and \"edges\" (a figure)");
    std::vector<Vec2> vertices = read_vertices(require_member(document, "vertices", errors), errors);
    const auto edges = read_edges(require_member(document, "edges", errors), errors);
    return drawing_from_figure(std::move(vertices), edges, std::move(name));
  } catch (const InvalidDrawingError& error) {
    throw InvalidDrawingError(error.defect(), errors.prefix() + error.what(), error.stroke(), error.point(),
                              error.other_stroke());
  }
}

Drawing read_drawing_file(const std::string& path) { return parse_drawing(read_input_file(path), path); }

std::string cleaned_drawing_json(const CleanedDrawing& cleaned, const Drawing& drawing, const std::string& name) {
  JsonWriter json;
  json.begin_object();
  json.key("name");
  json.value(name);
  json.key("vertices");
  json.begin_array();
  for (const Vec2& p : cleaned.figure.vertices) {
    json.begin_array();
    json.value(p[0]);
    json.value(p[1]);
    json.end_array();
  }
  json.end_array();
  json.key("edges");
  json.begin_array();
  for (const Edge& e : cleaned.figure.edges) {
    json.begin_array();
    json.value(e[0]);
    json.value(e[1]);
    json.end_array();
  }
  json.end_array();
  json.key("cleaning");
  json.begin_object();
  json.key("tolerance");
  json.value(cleaned.tolerance);
  json.key("junctions_made");
  json.value(cleaned.junctions_made);
  json.key("ends_snapped");
  json.value(cleaned.ends_snapped);
  json.key("points_merged");
  json.value(cleaned.points_merged);
  json.key("summary");
  json.value(cleaned.summary());
  json.key("changes");
  json.begin_array();
  const auto index_or_null = [&json](int value) {
    if (value < 0)
      json.null();
    else
      json.value(value);
  };
  for (const DrawingChange& change : cleaned.changes) {
    json.begin_object();
    json.key("kind");
    json.value(std::string(drawing_change_name(change.kind)));
    json.key("stroke");
    index_or_null(change.stroke);
    json.key("point");
    index_or_null(change.point);
    json.key("other_stroke");
    index_or_null(change.other_stroke);
    json.key("at");
    json.begin_array();
    json.value(change.at[0]);
    json.value(change.at[1]);
    json.end_array();
    json.key("distance");
    json.value(change.distance);
    json.end_object();
  }
  json.end_array();
  json.key("strokes");
  json.begin_array();
  for (std::size_t s = 0; s < cleaned.stroke_vertices.size(); ++s) {
    json.begin_object();
    json.key("vertices");
    json.begin_array();
    for (int v : cleaned.stroke_vertices[s]) json.value(v);
    json.end_array();
    json.key("cyclic");
    json.value(bool(cleaned.cyclic[s]));
    json.end_object();
  }
  json.end_array();
  // Per stroke, per input point, the vertex it became (a figure: per edge,
  // its two vertices').
  json.key("point_vertices");
  json.begin_array();
  for (const auto& stroke : drawing.strokes) {
    json.begin_array();
    for (int p : stroke) json.value(cleaned.point_vertex[std::size_t(p)]);
    json.end_array();
  }
  json.end_array();
  json.end_object();
  json.end_object();
  return json.finish();
}

std::string figure_json(const StickFigure& figure, const std::string& name) {
  JsonWriter json;
  json.begin_object();
  json.key("name");
  json.value(name);
  json.key("vertices");
  json.begin_array();
  for (const Vec2& p : figure.vertices) {
    json.begin_array();
    json.value(p[0]);
    json.value(p[1]);
    json.end_array();
  }
  json.end_array();
  json.key("edges");
  json.begin_array();
  for (const Edge& e : figure.edges) {
    json.begin_array();
    json.value(e[0]);
    json.value(e[1]);
    json.end_array();
  }
  json.end_array();
  json.end_object();
  return json.finish();
}

}  // namespace stickmorph
