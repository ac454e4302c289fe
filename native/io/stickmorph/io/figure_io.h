// Reading stick figure files (../shared/FORMAT.md, "Stick figure file").
#pragma once

#include <string>

#include "stickmorph/drawing_cleaning.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// Parses the JSON text of a stick figure file and validates the figure.
///
/// @param text    file contents
/// @param origin  name used in messages (usually the path)
/// @throws JsonError for malformed JSON or a wrong shape, naming line and
///         column; InvalidFigureError (message prefixed with origin) for a
///         figure that breaks a rule of make_stick_figure.
StickFigure parse_figure(const std::string& text, const std::string& origin);

/// Reads and parses the file at `path`. Throws JsonError if it cannot be read.
StickFigure read_figure_file(const std::string& path);

/// The bytes of the regular file at `path` (no FIFO, device or directory;
/// at most 64 MiB): what every input file of the CLI is read with.
/// @throws FileError naming the path and why it cannot be read.
std::string read_input_file(const std::string& path);

/// Parses the JSON text of a drawing to clean (docs/FORMAT.md, "Cleaning a
/// drawing"): either a drawing file {"strokes": [{"points": [[x, y], ...],
/// "cyclic": false}, ...]} or a stick figure file, read without the figure
/// check (its edges become strokes: it may cross itself).
/// @throws JsonError for malformed JSON or a wrong shape, naming line,
///         column and the stroke; InvalidDrawingError for an edge naming a
///         vertex that does not exist.
Drawing parse_drawing(const std::string& text, const std::string& origin);

/// Reads and parses the drawing file at `path`.
/// @throws FileError if it cannot be read; as parse_drawing.
Drawing read_drawing_file(const std::string& path);

/// The cleaned figure as a stick figure file with a "cleaning" member: the
/// tolerance, the counts, every change and each stroke's vertex path
/// (docs/FORMAT.md, "Cleaning a drawing").
std::string cleaned_drawing_json(const CleanedDrawing& cleaned, const Drawing& drawing, const std::string& name);

/// The figure as the JSON text of a stick figure file, named `name`, with
/// shortest round-trip decimals: parse_figure reads back the same doubles
/// (test regression files, the fuzzer's round-trip oracle).
std::string figure_json(const StickFigure& figure, const std::string& name);

}  // namespace stickmorph
