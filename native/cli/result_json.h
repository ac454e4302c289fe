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

/// Writes `text` to `path` through a temporary file renamed into place, so
/// that a failure never leaves a partial file behind.
/// @throws Error naming the path.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace stickmorph::cli
