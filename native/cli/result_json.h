// JSON documents the CLI writes (../shared/FORMAT.md).
#pragma once

#include <string>
#include <vector>

#include "stickmorph/figure_triangulation.h"
#include "stickmorph/json.h"

namespace stickmorph::cli {

/// The "triangulation" object of FORMAT.md: figure vertices, then the
/// enclosure counter-clockwise, then Steiner vertices.
void write_triangulation(JsonWriter& out, const FigureTriangulation& triangulation);

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
