// Fuzz target: the engine end to end on a pair of figures.
//
// check_compatibility -> morph_stick_figures (Algorithm 3, every frame
// verified exactly) -> morph_stick_figures with the linear method, the
// engine's one entry the CLI and the module use, with these oracles besides
// the typed-error contract of fuzz_common.h:
//  - morph_stick_figures succeeds or fails with a non-compatibility error
//    exactly when check_compatibility says compatible; on incompatible
//    figures it must throw IncompatibleFiguresError.
//  - the triangulation's first n nodes are the figures' vertices, bitwise.
//  - the morph has the requested number of frames, its times run from 0 to
//    1, its frames hold the figure's n vertices (step 5), and its first and
//    last frames of all nodes are exactly the triangulation's source and
//    target positions (morph.h).
//  - the rigid morph with local timing (local_timing.h, issue 31; delay
//    weights spread over [0, 1] by vertex index, overlap 0.4) succeeds on
//    the same pair, with the same frame count and its first and last
//    frames exactly the figures.
//
// Two input encodings, told apart by the first byte:
//
// '{' (JSON): a pair document {"source": FIGURE, "target": FIGURE} with
//   optional "steiner" and "weights" names (as on the CLI). Seeds are the
//   pairs of tests/data; 3 frames. aronov and sg2001 build spiderwebs that
//   grow quadratically with the face size (README, Limits), so with those
//   methods inputs above kMaxVerticesForSpiderwebs vertices are skipped:
//   they are legitimately slow, not findings.
//
// anything else (binary): a small figure on an integer grid and a target
//   that moves each vertex a little, so that most valid inputs are
//   compatible and reach the triangulation and the morph:
//     byte 0: options: bits 0-1 Steiner method, 2-3 weights, 4-5 frames - 2,
//             bit 6 target edges reversed in order and direction, bit 7
//             the parts encoding below instead
//     byte 1: n - 1 (n = 1 + byte % 16 vertices)
//     byte 2: scale exponent e = byte - 128: coordinates are multiples of 2^e
//     byte 3: enclosure sides - 3 (3 + byte % 8)
//     then n (x, y) source positions, signed bytes times 2^e
//     then n - 1 tree edges: vertex i joins vertex (byte % i), so the edges
//             connect every vertex
//     then one byte k and k % (n + 1) extra edges (two bytes each, % n)
//     then n (dx, dy) target moves, signed bytes times 2^(e - 4)
//   Missing bytes read as 0.
//
// binary with bit 7 of byte 0 set (parts): figures of several parts,
//   nested rings, dots and strokes in their annuli, small trees in the
//   innermost ring, groups of them side by side, each part turned and
//   wobbled on its own in the target (fuzz_common.h, decode_parts_pair):
//     byte 0: options as above (bits 0-6)
//     byte 1: enclosure sides - 3 (3 + byte % 8)
//     then decode_parts_pair's bytes, at most kMaxPartsVertices vertices
//   Every seed from before has bit 7 clear and decodes as before.
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
#include "stickmorph/figure_io.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/json.h"
#include "stickmorph/local_timing.h"
#include "stickmorph/morph.h"
#include "stickmorph/morph_stick_figures.h"

using namespace stickmorph;

namespace {

constexpr std::size_t kMaxVerticesForSpiderwebs = 24;
constexpr int kJsonFrames = 3;

struct PairInput {
  StickFigure source;
  StickFigure target;
  MorphStickFiguresOptions options;
};

bool same_positions(const Vec2* a, const Vec2* b, std::size_t count) {
  return count == 0 || std::memcmp(a, b, count * sizeof(Vec2)) == 0;
}

// The pair document: each figure is written back to text and read with
// parse_figure, the reader the CLI uses, so its validation runs unchanged.
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
  if (const JsonValue* steiner = document.find("steiner")) {
    input.options.steiner = parse_steiner_method(steiner->as_string());
  }
  if (const JsonValue* weights = document.find("weights")) {
    input.options.weights = parse_weight_kind(weights->as_string());
  }
  input.options.frames = kJsonFrames;
  return input;
}

class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t next() { return position_ < size_ ? data_[position_++] : 0; }
  int next_signed() { return static_cast<std::int8_t>(next()); }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

constexpr std::size_t kMaxPartsVertices = 96;

void set_binary_options(std::uint8_t flags, PairInput& input) {
  static constexpr SteinerMethod kMethods[] = {SteinerMethod::Improved, SteinerMethod::Sg2001,
                                               SteinerMethod::Aronov, SteinerMethod::Improved};
  static constexpr WeightKind kWeights[] = {WeightKind::MeanValue, WeightKind::Uniform,
                                            WeightKind::Floater, WeightKind::MeanValue};
  input.options.steiner = kMethods[flags & 3];
  input.options.weights = kWeights[(flags >> 2) & 3];
  input.options.frames = 2 + ((flags >> 4) & 3);
}

PairInput decode_parts_binary_pair(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteStream bytes(data, size);
  const std::uint8_t flags = bytes.next();
  PairInput input;
  input.options.enclosure_sides = 3 + bytes.next() % 8;
  set_binary_options(flags, input);
  fuzz::RawPartsPair pair = fuzz::decode_parts_pair(bytes, kMaxPartsVertices);
  std::vector<std::array<std::int64_t, 2>> target_edges = pair.edges;
  if ((flags >> 6) & 1) {
    std::reverse(target_edges.begin(), target_edges.end());
    for (auto& edge : target_edges) std::swap(edge[0], edge[1]);
  }
  input.source = make_stick_figure(std::move(pair.source), pair.edges, "source");
  input.target = make_stick_figure(std::move(pair.target), target_edges, "target");
  if (fuzz::tracing())
    fuzz::trace("parts pair: " + std::to_string(pair.parts) + " parts, " +
                std::to_string(input.source.vertices.size()) + " vertices: {\"source\":" +
                fuzz::figure_to_json(input.source) + ",\"target\":" + fuzz::figure_to_json(input.target) + "}");
  return input;
}

PairInput decode_binary_pair(const std::uint8_t* data, std::size_t size) {
  if (size > 0 && (data[0] & 0x80)) return decode_parts_binary_pair(data, size);
  ByteReader bytes(data, size);
  const std::uint8_t flags = bytes.next();
  const int n = 1 + bytes.next() % 16;
  const int exponent = int(bytes.next()) - 128;
  PairInput input;
  input.options.enclosure_sides = 3 + bytes.next() % 8;
  static constexpr SteinerMethod kMethods[] = {SteinerMethod::Improved, SteinerMethod::Sg2001,
                                               SteinerMethod::Aronov, SteinerMethod::Improved};
  static constexpr WeightKind kWeights[] = {WeightKind::MeanValue, WeightKind::Uniform,
                                            WeightKind::Floater, WeightKind::MeanValue};
  input.options.steiner = kMethods[flags & 3];
  input.options.weights = kWeights[(flags >> 2) & 3];
  input.options.frames = 2 + ((flags >> 4) & 3);
  const bool reverse_target_edges = (flags >> 6) & 1;

  std::vector<Vec2> source(n);
  for (Vec2& p : source) {
    p[0] = std::ldexp(double(bytes.next_signed()), exponent);
    p[1] = std::ldexp(double(bytes.next_signed()), exponent);
  }
  std::vector<std::array<std::int64_t, 2>> edges;
  for (int i = 1; i < n; ++i) edges.push_back({i, bytes.next() % i});
  const int extra = bytes.next() % (n + 1);
  for (int k = 0; k < extra; ++k) {
    const std::int64_t a = bytes.next() % n;
    edges.push_back({a, bytes.next() % n});
  }
  std::vector<Vec2> target = source;
  for (Vec2& p : target) {
    p[0] += std::ldexp(double(bytes.next_signed()), exponent - 4);
    p[1] += std::ldexp(double(bytes.next_signed()), exponent - 4);
  }
  std::vector<std::array<std::int64_t, 2>> target_edges = edges;
  if (reverse_target_edges) {
    std::reverse(target_edges.begin(), target_edges.end());
    for (auto& edge : target_edges) std::swap(edge[0], edge[1]);
  }
  input.source = make_stick_figure(std::move(source), edges, "source");
  input.target = make_stick_figure(std::move(target), target_edges, "target");
  return input;
}

void triangulate_and_morph(const PairInput& input);

void morph_pair(const PairInput& input) {
  const StickFigure& source = input.source;
  const StickFigure& target = input.target;
  const CompatibilityReport report = check_compatibility(source, target);
  if (!report.compatible()) {
    try {
      morph_stick_figures(source, target, input.options);
    } catch (const IncompatibleFiguresError&) {
      fuzz::trace("incompatible: " + report.reason);
      return;  // the expected answer
    } catch (const Error& error) {
      fuzz::report_finding(std::string("incompatible figures (") + report.reason +
                           "), but morph_stick_figures threw another error: " + error.what());
    }
    fuzz::report_finding("morph_stick_figures accepted figures check_compatibility rejects: " +
                         report.reason);
  }
  if (input.options.steiner.value_or(SteinerMethod::Improved) != SteinerMethod::Improved &&
      source.vertices.size() > kMaxVerticesForSpiderwebs) {
    fuzz::trace("skipped: spiderweb method on a large figure");
    return;
  }

  // From here on both figures are valid and compatible and the options are
  // valid, so the only acceptable error is the engine refusing a result it
  // could not verify (VerificationError). An InvalidFigureError or
  // InvalidArgumentError would be about something the engine built itself.
  try {
    triangulate_and_morph(input);
  } catch (const VerificationError&) {
    throw;
  } catch (const InternalError&) {
    throw;
  } catch (const Error& error) {
    fuzz::report_finding(std::string("valid compatible figures, but the engine threw: ") + error.what());
  }
}

void triangulate_and_morph(const PairInput& input) {
  const StickFigure& source = input.source;
  const StickFigure& target = input.target;
  MorphStickFiguresOptions options = input.options;
  // All nodes too, to hold the frames against the triangulation's ends.
  options.keep_node_frames = true;
  const MorphStickFiguresResult morph = morph_stick_figures(source, target, options);
  if (!morph.triangulation) fuzz::report_finding("the barycentric morph returned no triangulation");
  const FigureTriangulation& triangulation = *morph.triangulation;
  const std::size_t n = source.vertices.size();
  if (std::size_t(triangulation.figure_vertices) != n ||
      triangulation.source.size() != std::size_t(triangulation.node_count()) ||
      triangulation.target.size() != std::size_t(triangulation.node_count()) ||
      !same_positions(triangulation.source.data(), source.vertices.data(), n) ||
      !same_positions(triangulation.target.data(), target.vertices.data(), n)) {
    fuzz::report_finding("the triangulation's figure nodes are not the input figures");
  }

  const std::size_t frames = std::size_t(options.frames);
  if (morph.frames.size() != frames || morph.node_frames.size() != frames || morph.times.size() != frames ||
      morph.times.front() != 0.0 || morph.times.back() != 1.0) {
    fuzz::report_finding("the morph has the wrong frame count or times");
  }
  const std::size_t nodes = triangulation.source.size();
  for (std::size_t f = 0; f < frames; ++f) {
    if (morph.node_frames[f].size() != nodes) fuzz::report_finding("a morph frame has the wrong node count");
    if (morph.frames[f].size() != n || !same_positions(morph.frames[f].data(), morph.node_frames[f].data(), n))
      fuzz::report_finding("a figure frame is not the first n nodes of its frame");
  }
  if (!same_positions(morph.node_frames.front().data(), triangulation.source.data(), nodes) ||
      !same_positions(morph.node_frames.back().data(), triangulation.target.data(), nodes)) {
    fuzz::report_finding("the morph's first or last frame is not the source or the target");
  }

  // Local timing on the same pair: the decoding is untouched, so the weights
  // come from the vertex numbers (every weight from 0 to 1 taken as n grows).
  if (options.method == MorphMethod::Rigid) {
    std::vector<double> delay(n);
    for (std::size_t v = 0; v < n; ++v) delay[v] = double((v * 7) % 11) / 10.0;
    MorphStickFiguresOptions timed = input.options;
    timed.timing = LocalTiming(std::move(delay), 0.4);
    const MorphStickFiguresResult lagged = morph_stick_figures(source, target, timed);
    if (lagged.frames.size() != frames || lagged.frames.front() != source.vertices ||
        lagged.frames.back() != target.vertices)
      fuzz::report_finding("the locally timed morph's frames or its end frames are not the input figures");
  }

  // The straight-line baseline on the same pair: it may self-intersect, but
  // must not fail on a valid pair.
  MorphStickFiguresOptions straight;
  straight.method = MorphMethod::Linear;
  straight.frames = options.frames;
  const MorphStickFiguresResult linear = morph_stick_figures(source, target, straight);
  if (linear.frames.size() != frames ||
      !same_positions(linear.frames.front().data(), source.vertices.data(), n) ||
      !same_positions(linear.frames.back().data(), target.vertices.data(), n)) {
    fuzz::report_finding("the linear morph's end frames are not the input figures");
  }
  fuzz::trace("morphed: " + std::to_string(n) + " vertices, " +
              std::to_string(triangulation.steiner_vertices) + " Steiner, " +
              std::to_string(frames) + " frames");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::run_expecting_typed_errors([&] {
    const PairInput input = size > 0 && data[0] == '{'
                                ? decode_json_pair(std::string(reinterpret_cast<const char*>(data), size))
                                : decode_binary_pair(data, size);
    morph_pair(input);
  });
  return 0;
}
