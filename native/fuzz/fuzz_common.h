// What counts as a finding in the stickmorph fuzz targets.
//
// The engine's contract (native/stickmorph/errors.h) is that every bad input
// ends in a typed stickmorph::Error naming what is wrong. So for a fuzz
// target, throwing one of those is the expected, clean outcome of a bad
// input, and everything else is a finding that must abort the process (so
// that libFuzzer saves the input):
//
//  - InternalError: an invariant of the engine broke; the class exists to
//    signal bugs ("never the user's fault"), so it is a finding.
//  - VerificationError: the engine computed a result, checked it exactly and
//    refused it. That is the engine keeping its promise never to return an
//    invalid result, so by default it is a clean outcome. Set
//    STICKMORPH_FUZZ_VERIFICATION_IS_FINDING=1 to make it a finding too, to
//    hunt for inputs the engine should have handled (docs/TESTING.md).
//  - any other exception (std::bad_alloc, std::out_of_range, ...): the
//    engine let something escape that is not part of its contract.
//  - a crash, a sanitizer report, a timeout or running out of memory:
//    reported by libFuzzer and the sanitizers themselves.
//  - a broken oracle (a round trip that changes a value, a morph whose end
//    frames are not the input figures): report_finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <array>
#include <vector>

#include "stickmorph/errors.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::fuzz {

/// Prints "stickmorph fuzz finding: <what>" to stderr and aborts, which
/// libFuzzer records as a crash with the input saved.
[[noreturn]] void report_finding(const std::string& what);

/// True when STICKMORPH_FUZZ_VERIFICATION_IS_FINDING=1 (read once).
bool verification_is_finding();

/// True when STICKMORPH_FUZZ_TRACE=1 (read once): the targets then print
/// how each input ended (which error, or how far it got), to check that a
/// seed corpus reaches the stages it is meant to reach.
bool tracing();

/// Prints "outcome: <what>" to stderr when tracing().
void trace(const std::string& what);

/// Runs `body(input)`. Typed engine errors other than InternalError (and
/// VerificationError unless verification_is_finding()) return normally;
/// every other exception is reported as a finding.
template <typename Body>
void run_expecting_typed_errors(Body&& body) {
  try {
    body();
  } catch (const InternalError& error) {
    report_finding(std::string("InternalError: ") + error.what());
  } catch (const VerificationError& error) {
    if (verification_is_finding()) report_finding(std::string("VerificationError: ") + error.what());
    if (tracing()) trace(std::string("VerificationError: ") + error.what());
  } catch (const Error& error) {
    // JsonError, InvalidFigureError, InvalidArgumentError,
    // IncompatibleFiguresError: the input was bad and the engine said so.
    if (tracing()) trace(std::string("typed error: ") + error.what());
  } catch (const std::exception& error) {
    report_finding(std::string("exception outside the engine's contract: ") + error.what());
  } catch (...) {
    report_finding("exception of unknown type");
  }
}

/// Bytes read in order; missing bytes read as 0.
class ByteStream {
 public:
  ByteStream(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t next() { return position_ < size_ ? data_[position_++] : 0; }
  int next_signed() { return static_cast<std::int8_t>(next()); }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

/// A pair of figures of several parts on one edge set, decoded from bytes
/// by decode_parts_pair (not yet validated: make_stick_figure does that).
struct RawPartsPair {
  std::vector<Vec2> source, target;
  std::vector<std::array<std::int64_t, 2>> edges;
  int parts = 0;
};

/// The parts encoding shared by fuzz_morph_pair and fuzz_correspond_pair
/// (each selects it with a header bit). Groups of concentric rings side by
/// side, each ring inscribed in a circle and turned independently in the
/// target about its group's centre, so that most inputs are valid and keep
/// their nesting:
///   byte e: unit 2^(e - 128); 2 bytes: the whole figure's offset, signed
///     bytes times 2^(e - 128 + 14) (far from the origin); 1 byte: vertex
///     renumbering seed (0 keeps the order of construction)
///   byte: group count 1 + byte % 4; per group:
///     byte: ring count byte % 5; byte: group scale 2^(byte % 16) (tiny
///     groups beside huge ones); byte: gap to the previous group, a
///     fraction (byte + 1) / 512 of the larger outer radius (near the
///     other's convex hull); byte: y shift, signed byte / 128 of the radius
///     innermost: byte c: c % 4 = 0 nothing, 1 a dot, 2 up to 4 dots, 3 a
///       small tree (up to 6 vertices, as the grid figures, inside half the
///       core radius); each dot or tree: position bytes, then its target
///       turn byte (signed / 128 * pi about the centre) and wobble byte
///     per ring: byte sides 3 + byte % 10; byte gap: circumradius =
///       previous outer radius / cos(pi / sides) * (1 + (byte + 1) / 2550)
///       (gaps from 0.04 % to 10 %); byte phase; byte star: odd vertices
///       pulled in by (byte % 32) / 256 of the radius, pushing the ring out;
///       byte collinear: edge j gets its midpoint as a vertex when bit j % 8
///       is set; byte: target turn (signed / 128 * pi), byte: wobble; then
///       the annulus between it and the previous ring: byte a % 4 items,
///       each in a radial band of its own: byte kind (0 dot, 1 arc stroke
///       of 2 + (kind / 4) % 5 vertices, 2 radial stroke of 3 collinear
///       vertices, 3 dot), byte angle, byte span, byte turn, byte wobble
///   byte: the target's turn (byte * 2 pi / 256), byte: its scale
///     2^((byte % 64 - 32) / 8), 2 bytes: its shift (signed bytes times the
///     unit times 2^10)
/// A wobble w moves each vertex of the part by up to w / 256 of the local
/// clearance in a direction drawn from the vertex index, so that large
/// wobbles break validity or nesting (typed errors, not findings). Stops
/// adding parts at `max_vertices` vertices.
RawPartsPair decode_parts_pair(ByteStream& bytes, std::size_t max_vertices);

/// `figure` as a stick figure file (FORMAT.md), coordinates written as
/// shortest round-trip decimals by the engine's JsonWriter.
std::string figure_to_json(const StickFigure& figure);

/// True when both figures have bitwise the same vertices, edges and name.
bool same_figure(const StickFigure& a, const StickFigure& b);

}  // namespace stickmorph::fuzz
