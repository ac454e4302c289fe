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

/// `figure` as a stick figure file (FORMAT.md), coordinates written as
/// shortest round-trip decimals by the engine's JsonWriter.
std::string figure_to_json(const StickFigure& figure);

/// True when both figures have bitwise the same vertices, edges and name.
bool same_figure(const StickFigure& a, const StickFigure& b);

}  // namespace stickmorph::fuzz
