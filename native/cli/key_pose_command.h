// `stickmorph morph KEY1.json KEY2.json ... KEYK.json` (docs/FORMAT.md, "Key
// poses"): the morph command's sequence form, a thin shell over
// morph_key_poses (key_pose_morph.h). Apart from main.cpp, whose morph
// command hands over when it is given more than two files or a sequence
// option.
#pragma once

#include "argument_parsing.h"

namespace stickmorph::cli {

/// More than two files, or --keys-at, --loop or --hold: a sequence.
bool is_key_pose_run(const ParsedArguments& arguments);

/// Reads the keys, morphs them and writes the morph file with "keys".
/// @returns the exit code (0); every mistake throws (main prints one
///          `error:` line and exits 2), and nothing is written then.
int run_key_poses(const ParsedArguments& arguments);

}  // namespace stickmorph::cli
