// Fuzz target: automatic correspondence of two figures drawn separately.
//
// correspond_figures (figure_correspondence.h) -> on small matches
// morph_stick_figures with correspond = Auto, with these oracles besides the
// typed-error contract of fuzz_common.h:
//  - pins: correspond_figures throws InvalidArgumentError exactly when a pin
//    is ill-formed as the header defines it (a vertex that does not exist, a
//    vertex pinned twice, or vertices of different degrees: a node matches
//    only a node of its degree, a degree-2 vertex only a degree-2 vertex).
//    Checked here independently of the engine's own test. On valid figures
//    its only other clean outcome is IncompatibleFiguresError.
//  - a faithful redrawing (binary encoding: the derived target, not
//    reflected, no vertex moved, so only subdivided, renumbered, its edges
//    reordered and the whole rotated, scaled and translated) is the same
//    plane map as the source, and every pin naming its vertex's own image is
//    satisfied by that identity; so with such pins, well formed,
//    IncompatibleFiguresError is a finding too.
//  - on success: is_valid(c, source, target); the matched figures are
//    compatible by index (check_compatibility), which the header promises
//    "by construction"; every pin is honoured (matched vertex s, the source's
//    vertex s, has target place vertex t); the matched source starts with the
//    source's n vertices, bitwise.
//  - for matches of at most kMaxMorphVertices vertices: morph_stick_figures
//    with correspond = Auto and the same pins, 3 frames, returns the same
//    matching and frames whose first and last are exactly the matched
//    source's and target's vertices. On this valid, matchable pair its only
//    clean failure is VerificationError (fuzz_common.h's policy).
// A pair that is already compatible by index with equal vertex counts needs
// no special oracle: correspond_figures may match it another way if the
// geometry says so.
//
// Two input encodings, told apart by the first byte:
//
// '{' (JSON): a pair document {"source": FIGURE, "target": FIGURE,
//   "pins": [[s, t], ...]} ("pins" optional). Seeds are the pairs of
//   tests/data, redrawn (subdivided, renumbered) and pinned.
//
// anything else (binary): a small figure on an integer grid and a target
//   drawn from it the way a second drawing of the same figure differs, so
//   that most valid inputs are matchable and reach the matching, the dummy
//   vertices and the morph:
//     byte 0: flags: bit 0 the target is an independent second figure (read
//             like the source) instead of one derived from it; bit 1 target
//             edges in reverse order; bit 2 every target edge reversed; bit 3
//             the derived target reflected (x -> -x; a mirror image, refused
//             unless the figure is symmetric); bits 4-5 pin count (3 reads
//             as 2); bit 6: with bit 7, redraw the deformed target (each
//             part turned and wobbled on its own) instead of the source;
//             bit 7: the parts encoding (below)
//     byte 1: exponent e = byte - 128: grid coordinates are multiples of 2^e
//     then the source FIGURE:
//       byte n - 1 (n = 1 + byte % 16 vertices), n (x, y) signed bytes times
//       2^e, n - 1 tree edges (vertex i joins vertex byte % i, so the edges
//       connect every vertex), then one byte k and k % (n + 1) extra edges
//       (two bytes each, % n)
//     then, if bit 0: the target FIGURE, read the same way; else:
//       byte d: d % 9 subdivisions, each two bytes: the edge (% the current
//         edge count; the first part keeps its place, the second is
//         appended) and the fraction (byte + 1) / 257 along it, the new
//         vertex appended
//       m - 1 renumbering bytes (m = the subdivided vertex count):
//         Fisher-Yates from the last index down to 1, index i swapped with
//         i - byte % (i + 1), so zero bytes keep the numbering
//       byte r: the edge list rotated by r % (edge count) (then bits 1, 2)
//       m (dx, dy) moves, signed bytes times 2^(e - 5), before the renumbering
//       4 bytes: rotation byte * 2 pi / 256, scale 2^((byte % 64 - 32) / 16),
//         translation (signed bytes times 2^(e + 3))
//     then per pin two bytes: s = byte % (n + 1) (n, out of range, is an
//       invalid pin); if the second byte has bit 7 set and the target is
//       derived, t is s's own vertex in the target (a satisfiable pin when
//       s is an original vertex), else t = (byte & 127) % (target count + 1)
//   Missing bytes read as 0.
//
// binary with bit 7 of byte 0 set (parts): as above, but the source FIGURE
//   is decode_parts_pair's source (fuzz_common.h: nested rings, dots and
//   strokes in annuli, trees in the innermost ring, groups side by side; at
//   most kMaxPartsVertices vertices) and, with bit 0, the independent
//   target is a second such source. The derived target redraws the source,
//   or with bit 6 the decoded target (every part turned on its own: not
//   faithful), with the bytes of the derived target above. Matches of up to
//   kMaxPartsMorphVertices vertices are morphed. Every seed from before has
//   bit 7 clear and decodes as before.
//
// With STICKMORPH_FUZZ_TRACE=1 the target also prints the decoded pair as a
// pair document of the JSON encoding and, on a match, the matched pair
// (compatible by index, the input of fuzz_morph_pair): a binary finding can
// then be described as figures, and a morph finding told from a matching one.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "fuzz_common.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/json.h"
#include "stickmorph/morph_stick_figures.h"
#include "stickmorph/working_scale.h"

using namespace stickmorph;

namespace {

// The morph is the slow stage (a triangulation and a rigid guide, checked
// exactly); above this many matched vertices only the matching is checked,
// so that the fuzzer spends its time where the new code is.
constexpr std::size_t kMaxMorphVertices = 40;
constexpr int kMorphFrames = 3;
// The parts encoding: figures of several parts are larger, and the bridges
// between the parts are new code, so larger matches are morphed too.
constexpr std::size_t kMaxPartsVertices = 64;
constexpr std::size_t kMaxPartsMorphVertices = 96;
constexpr double kPi = 3.14159265358979323846;

struct PairInput {
  StickFigure source;
  StickFigure target;
  std::vector<VertexPin> pins;
  /// Binary encoding only: the target is a faithful redrawing of the source
  /// and every pin names a source vertex's own image (see the header).
  bool faithful = false;
  /// Binary parts encoding (bit 7): matches up to kMaxPartsMorphVertices are morphed.
  bool parts = false;
};

bool same_positions(const Vec2* a, const Vec2* b, std::size_t count) {
  return count == 0 || std::memcmp(a, b, count * sizeof(Vec2)) == 0;
}

// A pin index from JSON. Out of int range (or not a whole number) is refused
// here, as the CLI's "S:T" parser refuses it: converting such a double to
// int would be undefined behaviour in the target, not in the engine. Negative
// and too-large indices within int range reach the engine.
int pin_index(const JsonValue& value) {
  const double number = value.as_number();
  if (!(number >= -2147483648.0 && number <= 2147483647.0) || number != std::floor(number))
    throw JsonError("a pin index is not a whole number in int range");
  return int(number);
}

// As fuzz_morph_pair: each figure is written back to text and read with
// parse_figure, the CLI's reader, so that its validation runs unchanged.
PairInput decode_json_pair(const std::string& text) {
  const JsonValue document = parse_json(text);
  const JsonValue* source = document.find("source");
  const JsonValue* target = document.find("target");
  if (source == nullptr || target == nullptr) {
    throw JsonError("pair document without \"source\" or \"target\"");
  }
  PairInput input;
  input.source = parse_figure(to_json(*source), "source");
  input.target = parse_figure(to_json(*target), "target");
  if (const JsonValue* pins = document.find("pins")) {
    for (const JsonValue& pin : pins->as_array()) {
      const JsonValue::Array& pair = pin.as_array();
      if (pair.size() != 2) throw JsonError("a pin is not [source, target]");
      input.pins.push_back({pin_index(pair[0]), pin_index(pair[1])});
    }
  }
  return input;
}

using ByteReader = fuzz::ByteStream;  // missing bytes read as 0

using RawEdges = std::vector<std::array<std::int64_t, 2>>;

struct RawFigure {
  std::vector<Vec2> vertices;
  RawEdges edges;
};

// A connected grid figure: a tree plus extra edges (fuzz_morph_pair's).
RawFigure read_grid_figure(ByteReader& bytes, int exponent) {
  RawFigure figure;
  const int n = 1 + bytes.next() % 16;
  figure.vertices.resize(std::size_t(n));
  for (Vec2& p : figure.vertices) {
    p[0] = std::ldexp(double(bytes.next_signed()), exponent);
    p[1] = std::ldexp(double(bytes.next_signed()), exponent);
  }
  for (int i = 1; i < n; ++i) figure.edges.push_back({i, bytes.next() % i});
  const int extra = bytes.next() % (n + 1);
  for (int k = 0; k < extra; ++k) {
    const std::int64_t a = bytes.next() % n;
    figure.edges.push_back({a, bytes.next() % n});
  }
  return figure;
}

// The second drawing of `source`: subdivided, moved a little, renumbered,
// its edges reordered, then rotated, scaled and moved as a whole (and
// reflected if asked). `image` receives each vertex's index in the result.
RawFigure redraw(const StickFigure& source, std::uint8_t flags, int exponent, ByteReader& bytes,
                 std::vector<int>& image, bool& moved) {
  std::vector<Vec2> vertices = source.vertices;
  RawEdges edges;
  for (const Edge& e : source.edges) edges.push_back({e[0], e[1]});

  const int subdivisions = bytes.next() % 9;
  for (int k = 0; k < subdivisions; ++k) {
    const std::size_t which = bytes.next();
    const double fraction = (double(bytes.next()) + 1) / 257;
    if (edges.empty()) continue;  // a single vertex has nothing to subdivide
    auto& edge = edges[which % edges.size()];
    const Vec2 a = vertices[std::size_t(edge[0])], b = vertices[std::size_t(edge[1])];
    const std::int64_t middle = std::int64_t(vertices.size());
    vertices.push_back({a[0] + fraction * (b[0] - a[0]), a[1] + fraction * (b[1] - a[1])});
    const std::int64_t end = edge[1];
    edge[1] = middle;
    edges.push_back({middle, end});
  }

  const std::size_t m = vertices.size();
  std::vector<int> order(m);  // order[new index] = old index
  for (std::size_t i = 0; i < m; ++i) order[i] = int(i);
  for (std::size_t i = m; i-- > 1;) std::swap(order[i], order[i - bytes.next() % (i + 1)]);
  image.assign(m, -1);
  for (std::size_t i = 0; i < m; ++i) image[std::size_t(order[i])] = int(i);

  const std::size_t shift = bytes.next();  // read even with no edges, so later bytes keep their place
  if (!edges.empty()) std::rotate(edges.begin(), edges.begin() + std::ptrdiff_t(shift % edges.size()), edges.end());
  if ((flags >> 1) & 1) std::reverse(edges.begin(), edges.end());
  if ((flags >> 2) & 1)
    for (auto& edge : edges) std::swap(edge[0], edge[1]);
  for (auto& edge : edges) edge = {image[std::size_t(edge[0])], image[std::size_t(edge[1])]};

  moved = false;
  for (Vec2& p : vertices) {
    const int dx = bytes.next_signed(), dy = bytes.next_signed();
    moved = moved || dx != 0 || dy != 0;
    p[0] += std::ldexp(double(dx), exponent - 5);
    p[1] += std::ldexp(double(dy), exponent - 5);
  }
  const double angle = double(bytes.next()) * 2 * kPi / 256;
  const double scale = std::exp2((double(bytes.next() % 64) - 32) / 16);
  const double tx = std::ldexp(double(bytes.next_signed()), exponent + 3);
  const double ty = std::ldexp(double(bytes.next_signed()), exponent + 3);
  const double c = scale * std::cos(angle), s = scale * std::sin(angle);
  const bool reflect = (flags >> 3) & 1;
  RawFigure target;
  target.vertices.resize(m);
  for (std::size_t v = 0; v < m; ++v) {
    const double x = reflect ? -vertices[v][0] : vertices[v][0], y = vertices[v][1];
    target.vertices[std::size_t(image[v])] = {c * x - s * y + tx, s * x + c * y + ty};
  }
  target.edges = std::move(edges);
  return target;
}

// The source of the parts encoding, and its decoded target (validated).
RawFigure read_parts_figure(ByteReader& stream, RawFigure* deformed) {
  fuzz::RawPartsPair pair = fuzz::decode_parts_pair(stream, kMaxPartsVertices);
  if (deformed) *deformed = RawFigure{std::move(pair.target), pair.edges};
  return RawFigure{std::move(pair.source), std::move(pair.edges)};
}

PairInput decode_binary_pair(const std::uint8_t* data, std::size_t size) {
  ByteReader bytes(data, size);
  const std::uint8_t flags = bytes.next();
  const int exponent = int(bytes.next()) - 128;
  const bool parts = (flags >> 7) & 1;
  const bool use_deformed = parts && ((flags >> 6) & 1);
  const bool independent = flags & 1;
  PairInput input;
  input.parts = parts;
  RawFigure deformed;
  RawFigure source = parts ? read_parts_figure(bytes, &deformed) : read_grid_figure(bytes, exponent);
  input.source = make_stick_figure(std::move(source.vertices), source.edges, "source");
  StickFigure base = input.source;
  if (use_deformed && !independent) base = make_stick_figure(std::move(deformed.vertices), deformed.edges, "target");
  std::vector<int> image;  // derived target only: source vertex -> target vertex
  bool moved = false;
  RawFigure target = independent ? (parts ? read_parts_figure(bytes, nullptr) : read_grid_figure(bytes, exponent))
                                 : redraw(base, flags, exponent, bytes, image, moved);
  input.faithful = !independent && !((flags >> 3) & 1) && !moved && !use_deformed;
  const int ns = int(input.source.vertices.size()), nt = int(target.vertices.size());
  const int pins = std::min((flags >> 4) & 3, 2);
  for (int k = 0; k < pins; ++k) {
    const int s = bytes.next() % (ns + 1);
    const std::uint8_t t = bytes.next();
    if ((t & 0x80) && !independent && s < ns) {
      input.pins.push_back({s, image[std::size_t(s)]});
    } else {
      input.pins.push_back({s, (t & 0x7f) % (nt + 1)});
      input.faithful = false;  // a pin the identity need not satisfy
    }
  }
  // Made last, so that an invalid redrawing is still a typed error but the
  // pin bytes are read at a fixed place either way.
  input.target = make_stick_figure(std::move(target.vertices), target.edges, "target");
  return input;
}

std::vector<int> degrees(const StickFigure& figure) {
  std::vector<int> degree(figure.vertices.size(), 0);
  for (const Edge& e : figure.edges) {
    ++degree[std::size_t(e[0])];
    ++degree[std::size_t(e[1])];
  }
  return degree;
}

// The header's rule for pins, restated here so that the engine's check is
// itself under test: every index in range, no vertex pinned twice on either
// side, and a pin joins two vertices of the same degree (nodes of one degree,
// or two degree-2 vertices inside strokes).
bool pins_well_formed(const PairInput& input) {
  const std::vector<int> ds = degrees(input.source), dt = degrees(input.target);
  std::vector<bool> source_seen(ds.size()), target_seen(dt.size());
  for (const VertexPin& pin : input.pins) {
    if (pin.source < 0 || std::size_t(pin.source) >= ds.size() || pin.target < 0 ||
        std::size_t(pin.target) >= dt.size())
      return false;
    if (source_seen[std::size_t(pin.source)] || target_seen[std::size_t(pin.target)]) return false;
    source_seen[std::size_t(pin.source)] = target_seen[std::size_t(pin.target)] = true;
    if (ds[std::size_t(pin.source)] != dt[std::size_t(pin.target)]) return false;
  }
  return true;
}

std::string describe_pins(const std::vector<VertexPin>& pins) {
  std::string text;
  for (const VertexPin& pin : pins)
    text += (text.empty() ? "" : ", ") + std::to_string(pin.source) + ":" + std::to_string(pin.target);
  return "pins [" + text + "]";
}

void morph_matched(const PairInput& input, const FigureCorrespondence& c);

// The ratio of the two figures' sizes (the larger side of each bounding
// box), as the rigid method's range check measures it; 1 when either is a
// single point.
double size_ratio(const StickFigure& a, const StickFigure& b) {
  const auto size = [](const StickFigure& figure) {
    double low[2] = {figure.vertices[0][0], figure.vertices[0][1]}, high[2] = {low[0], low[1]};
    for (const Vec2& p : figure.vertices)
      for (int c = 0; c < 2; ++c) {
        low[c] = std::min(low[c], p[c]);
        high[c] = std::max(high[c], p[c]);
      }
    return 2 * std::max(high[0] / 2 - low[0] / 2, high[1] / 2 - low[1] / 2);  // halves: no overflow
  };
  const double sa = size(a), sb = size(b);
  if (sa == 0 || sb == 0) return 1;
  return std::max(sa / sb, sb / sa);
}

// True when two vertices of one figure are closer than 2^-40 of that
// figure's extent, or a vertex is that close to an edge it does not end.
// The header lets correspond_figures refuse such a pair with a
// VerificationError: the dummies it places on the other figure's edges
// (a + f (b - a), f from arc length) cannot then be told apart in double
// precision, and a dummy rounded off its edge by part of a unit in the last
// place turns the piece of edge it ends, which can then cross an edge that
// close to it. Above this resolution a VerificationError is a finding.
bool below_resolution(const StickFigure& figure) {
  if (figure.vertices.size() < 2) return false;
  double lo[2] = {figure.vertices[0][0], figure.vertices[0][1]}, hi[2] = {lo[0], lo[1]};
  for (const Vec2& v : figure.vertices)
    for (int axis = 0; axis < 2; ++axis) {
      lo[axis] = std::min(lo[axis], v[axis]);
      hi[axis] = std::max(hi[axis], v[axis]);
    }
  const double extent = std::max(hi[0] / 2 - lo[0] / 2, hi[1] / 2 - lo[1] / 2) * 2;  // halves: no overflow
  const double finest = std::ldexp(1.0, -40);
  if (extent == 0) return false;
  // Measured in units of the extent, from the box's corner: no overflow in
  // the squares below, whatever the coordinates' magnitude.
  std::vector<Vec2> unit;
  unit.reserve(figure.vertices.size());
  for (const Vec2& v : figure.vertices) unit.push_back({(v[0] - lo[0]) / extent, (v[1] - lo[1]) / extent});
  for (std::size_t i = 0; i < unit.size(); ++i)
    for (std::size_t j = i + 1; j < unit.size(); ++j)
      if (std::max(std::abs(unit[i][0] - unit[j][0]), std::abs(unit[i][1] - unit[j][1])) < finest) return true;
  for (const Edge& e : figure.edges) {
    const Vec2& a = unit[std::size_t(e[0])];
    const Vec2& b = unit[std::size_t(e[1])];
    const double dx = b[0] - a[0], dy = b[1] - a[1], length2 = dx * dx + dy * dy;
    if (length2 == 0) continue;
    for (std::size_t v = 0; v < unit.size(); ++v) {
      if (int(v) == e[0] || int(v) == e[1]) continue;
      const double t = std::clamp(((unit[v][0] - a[0]) * dx + (unit[v][1] - a[1]) * dy) / length2, 0.0, 1.0);
      if (std::hypot(unit[v][0] - (a[0] + t * dx), unit[v][1] - (a[1] + t * dy)) < finest) return true;
    }
  }
  return false;
}

// The decoded pair as a pair document of the JSON encoding, so that a
// binary finding can be read, described and replayed as figures.
std::string pair_document(const PairInput& input) {
  std::string pins;
  for (const VertexPin& pin : input.pins)
    pins += (pins.empty() ? "[" : ",[") + std::to_string(pin.source) + "," + std::to_string(pin.target) + "]";
  return "{\"source\":" + fuzz::figure_to_json(input.source) + ",\"target\":" + fuzz::figure_to_json(input.target) +
         ",\"pins\":[" + pins + "]}";
}

void correspond_pair(const PairInput& input) {
  if (fuzz::tracing()) fuzz::trace("pair: " + pair_document(input) + (input.faithful ? " (faithful)" : ""));
  const bool well_formed = pins_well_formed(input);
  FigureCorrespondence c;
  try {
    c = correspond_figures(input.source, input.target, CorrespondenceOptions{input.pins});
  } catch (const InvalidArgumentError& error) {
    if (well_formed)
      fuzz::report_finding("correspond_figures refused well-formed " + describe_pins(input.pins) + ": " +
                           error.what());
    fuzz::trace(std::string("bad pin: ") + error.what());
    return;
  } catch (const IncompatibleFiguresError& error) {
    if (!well_formed)
      fuzz::report_finding("ill-formed " + describe_pins(input.pins) +
                           ", but correspond_figures threw IncompatibleFiguresError, not InvalidArgumentError: " +
                           error.what());
    if (input.faithful)
      fuzz::report_finding("a faithful redrawing of the source (subdivided, renumbered, moved as a whole) with " +
                           describe_pins(input.pins) + " naming the vertices' own images was refused: " +
                           error.what());
    fuzz::trace(std::string("unmatchable: ") + error.what());
    return;
  } catch (const InternalError&) {
    throw;
  } catch (const VerificationError& error) {
    if (!below_resolution(input.source) && !below_resolution(input.target))
      fuzz::report_finding(std::string("correspond_figures refused a pair above the resolution limit: ") +
                           error.what());
    fuzz::trace(std::string("below resolution: ") + error.what());
    return;
  } catch (const NumericRangeError& error) {
    // Below the resolution limit the engine may also refuse the numbers
    // themselves: features 2^-40 of a figure's extent apart, scaled back
    // from the working scale, can leave dummies below the smallest normal
    // double (figure_correspondence.cpp). Above it, a finding.
    if (!below_resolution(input.source) && !below_resolution(input.target))
      fuzz::report_finding(std::string("correspond_figures refused the numbers of a pair above the resolution "
                                       "limit: ") + error.what());
    fuzz::trace(std::string("below resolution: ") + error.what());
    return;
  } catch (const Error& error) {
    // Both figures are valid (make_stick_figure), so an InvalidFigureError
    // would be about something the engine built.
    fuzz::report_finding(std::string("correspond_figures on valid figures threw another error: ") + error.what());
  }
  if (!well_formed)
    fuzz::report_finding("correspond_figures accepted ill-formed " + describe_pins(input.pins));

  const std::size_t ns = input.source.vertices.size();
  const std::size_t m = c.source.vertices.size();
  if (!is_valid(c, input.source, input.target)) fuzz::report_finding("is_valid rejects the correspondence");
  const CompatibilityReport report = check_compatibility(c.source, c.target);
  if (!report.compatible()) fuzz::report_finding("the matched figures are not compatible: " + report.reason);
  if (m < ns || !same_positions(c.source.vertices.data(), input.source.vertices.data(), ns))
    fuzz::report_finding("the matched source does not start with the source's vertices");
  for (const VertexPin& pin : input.pins) {
    if (c.target_places.size() != m || c.target_places[std::size_t(pin.source)].vertex != pin.target)
      fuzz::report_finding("the correspondence breaks pin " + std::to_string(pin.source) + ":" +
                           std::to_string(pin.target));
  }
  fuzz::trace("matched: " + std::to_string(ns) + " + " + std::to_string(input.target.vertices.size()) + " -> " +
              std::to_string(m) + " vertices, " + std::to_string(c.candidates) + " candidates");
  // The matched figures, compatible by index: fuzz_morph_pair's input, to
  // tell a finding in the matching from one in the morph.
  if (fuzz::tracing())
    fuzz::trace("matched pair: {\"source\":" + fuzz::figure_to_json(c.source) +
                ",\"target\":" + fuzz::figure_to_json(c.target) + "}");
  if (m > (input.parts ? kMaxPartsMorphVertices : kMaxMorphVertices)) return;

  // From here on the pair is valid and matchable with these pins, so the
  // only acceptable error is the engine refusing a result it could not
  // verify (VerificationError).
  try {
    morph_matched(input, c);
  } catch (const VerificationError&) {
    throw;
  } catch (const InternalError&) {
    throw;
  } catch (const NumericRangeError& error) {
    // The rigid method's documented limit (working_scale.h): figures whose
    // sizes differ by more than kMaxRigidSizeRatio are refused before any
    // work. Below the limit the refusal is a finding.
    if (size_ratio(c.source, c.target) <= kMaxRigidSizeRatio)
      fuzz::report_finding(std::string("a matchable pair within the rigid method's size ratio, but "
                                       "morph_stick_figures refused its range: ") + error.what());
    fuzz::trace(std::string("beyond the size ratio: ") + error.what());
  } catch (const Error& error) {
    fuzz::report_finding(std::string("a matchable pair, but morph_stick_figures threw: ") + error.what());
  }
}

void morph_matched(const PairInput& input, const FigureCorrespondence& c) {
  MorphStickFiguresOptions options;
  options.frames = kMorphFrames;
  options.correspond = CorrespondenceMode::Auto;
  options.pins = input.pins;
  const MorphStickFiguresResult morph = morph_stick_figures(input.source, input.target, options);
  // The frames are the matched figure's; the morph must have found the same
  // matching as the call above, or the end frames below would be compared
  // with the wrong figures.
  if (!morph.correspondence || !fuzz::same_figure(morph.correspondence->source, c.source) ||
      !fuzz::same_figure(morph.correspondence->target, c.target))
    fuzz::report_finding("morph_stick_figures matched the pair differently from correspond_figures");
  const std::size_t m = c.source.vertices.size();
  if (morph.frames.size() != std::size_t(kMorphFrames)) fuzz::report_finding("the morph has the wrong frame count");
  for (const std::vector<Vec2>& frame : morph.frames)
    if (frame.size() != m) fuzz::report_finding("a morph frame does not hold the matched figure's vertices");
  if (!same_positions(morph.frames.front().data(), c.source.vertices.data(), m) ||
      !same_positions(morph.frames.back().data(), c.target.vertices.data(), m))
    fuzz::report_finding("the morph's first or last frame is not the matched source or target");
  fuzz::trace("morphed: " + std::to_string(m) + " matched vertices, " + std::to_string(kMorphFrames) + " frames");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::run_expecting_typed_errors([&] {
    const PairInput input = size > 0 && data[0] == '{'
                                ? decode_json_pair(std::string(reinterpret_cast<const char*>(data), size))
                                : decode_binary_pair(data, size);
    correspond_pair(input);
  });
  return 0;
}
