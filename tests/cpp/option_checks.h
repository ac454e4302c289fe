// The refusal of engine options, for tests of check_morph_options and of
// the methods' own options (test_morph_stick_figures, test_guided_morph).
#pragma once

#include <string>

#include "stickmorph/errors.h"
#include "stickmorph/morph_stick_figures.h"

namespace stickmorph::test {

/// The message of the InvalidArgumentError `options` is refused with, or ""
/// if check_morph_options accepts them.
inline std::string refusal(const MorphStickFiguresOptions& options) {
  try {
    check_morph_options(options);
  } catch (const InvalidArgumentError& e) {
    return e.what();
  }
  return "";
}

}  // namespace stickmorph::test
