// Fuzz target: cleaning a drawing (drawing_cleaning.h, issue 32).
//
// Input: either a drawing file's text (starts with '{': parse_drawing, then
// clean_drawing), or a compact binary encoding that makes near-degenerate
// drawings likely: points on a small integer grid (exact collinearity,
// touching, duplicates) with an optional sub-grid jitter (near misses within
// the tolerance):
//   byte: tolerance choice (% 4: default, 0, 1/4 unit, 2 units)
//   byte: jitter scale 2^-(byte % 8) of a unit (byte & 0x80: no jitter)
//   byte: stroke count 1 + byte % 8; per stroke: byte: point count
//     1 + byte % 24 (bit 7: cyclic); per point: x byte % 16, y byte % 16,
//     and, with jitter, one byte: two signed nibbles times the scale / 8.
// Oracles on every cleaned drawing: validate_cleaning (the figure valid in
// exact arithmetic, every stroke a path of its edges, every moved point
// reported with its distance) and idempotence: the cleaned figure, cleaned
// again with the same tolerance, changes nothing.
// Typed errors (InvalidDrawingError for overlaps, retraces, one-point
// strokes) are the clean outcome of bad input (fuzz_common.h).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_common.h"
#include "stickmorph/drawing_cleaning.h"
#include "stickmorph/io/figure_io.h"

using namespace stickmorph;

namespace {

Drawing decode(fuzz::ByteStream& bytes, DrawingCleaningOptions& options) {
  switch (bytes.next() % 4) {
    case 1: options.tolerance = 0.0; break;
    case 2: options.tolerance = 0.25; break;
    case 3: options.tolerance = 2.0; break;
    default: break;
  }
  const std::uint8_t jitter_byte = bytes.next();
  const bool jitter = (jitter_byte & 0x80) == 0;
  const double scale = 1.0 / double(1 << (jitter_byte % 8));
  const int strokes = 1 + bytes.next() % 8;
  std::vector<std::vector<Vec2>> points;
  std::vector<bool> cyclic;
  for (int s = 0; s < strokes; ++s) {
    const std::uint8_t header = bytes.next();
    const int count = 1 + header % 24;
    cyclic.push_back((header & 0x80) != 0);
    std::vector<Vec2> stroke;
    for (int i = 0; i < count; ++i) {
      Vec2 p{double(bytes.next() % 16), double(bytes.next() % 16)};
      if (jitter) {
        const std::uint8_t nibbles = bytes.next();
        p[0] += (int(nibbles & 0x0f) - 8) * scale / 8;
        p[1] += (int(nibbles >> 4) - 8) * scale / 8;
      }
      stroke.push_back(p);
    }
    points.push_back(std::move(stroke));
  }
  return drawing_from_strokes(points, std::move(cyclic));
}

void check(const Drawing& drawing, const DrawingCleaningOptions& options) {
  const CleanedDrawing cleaned = clean_drawing(drawing, options);
  validate_cleaning(cleaned, drawing);  // InternalError: a finding
  std::vector<std::array<std::int64_t, 2>> edges;
  for (const Edge& e : cleaned.figure.edges) edges.push_back({e[0], e[1]});
  const Drawing again = drawing_from_figure(cleaned.figure.vertices, edges);
  DrawingCleaningOptions same;
  same.tolerance = cleaned.tolerance;
  CleanedDrawing twice;
  try {
    twice = clean_drawing(again, same);
  } catch (const Error& error) {
    fuzz::report_finding(std::string("a cleaned figure does not clean again: ") + error.what());
  }
  if (!twice.changes.empty() || twice.figure.vertices != cleaned.figure.vertices ||
      twice.figure.edges != cleaned.figure.edges)
    fuzz::report_finding("a cleaned figure changes when cleaned again: " + twice.summary());
  fuzz::trace("cleaned: " + cleaned.summary());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::run_expecting_typed_errors([&] {
    if (size > 0 && data[0] == '{') {
      const Drawing drawing = parse_drawing(std::string(reinterpret_cast<const char*>(data), size), "fuzz input");
      if (drawing.points.size() > 2000) return;  // keep each run short
      check(drawing, {});
      return;
    }
    fuzz::ByteStream bytes(data, size);
    DrawingCleaningOptions options;
    const Drawing drawing = decode(bytes, options);
    check(drawing, options);
  });
  return 0;
}
