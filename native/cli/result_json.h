// Writing the CLI's output files to disk. Their contents (docs/FORMAT.md)
// are written by the IO library: stickmorph/io/result_files.h.
#pragma once

#include <string>
#include <vector>

#include "stickmorph/figure_triangulation.h"
#include "stickmorph/io/json.h"
#include "stickmorph/io/result_files.h"

namespace stickmorph::cli {

/// Kept so that CLI code written against it on other branches still
/// compiles; new code calls triangulation_file_json or morph_file_json.
inline void write_triangulation(JsonWriter& out, const FigureTriangulation& triangulation) {
  stickmorph::write_triangulation(out, triangulation);
}

/// One output of a command: where it goes and its whole content.
struct OutputFile {
  std::string path;
  std::string text;
};

/// Checks, before any work is done, that `path` can be an output file: not
/// empty, not an existing directory, and in a folder that exists. A command
/// that would fail only when writing its result fails at once instead.
/// @throws InvalidArgumentError naming the option and the path.
void check_output_path(const std::string& option, const std::string& path);

/// Writes every file through a temporary `<path>.partial` renamed into
/// place, all temporaries first, so that a failure never leaves a partial
/// file behind and a failure to write one output (a full disk) leaves none
/// of the others. Existing files are replaced only by complete ones.
/// @throws Error naming the path that failed.
void write_files_atomically(const std::vector<OutputFile>& files);

}  // namespace stickmorph::cli
