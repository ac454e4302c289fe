// The `stickmorph` command-line tool (../../shared/FORMAT.md, docs/CLI.md).
//
// A thin shell over the engine: it parses arguments (argument_parsing.h:
// CLI11, one CLI::App per command built from the command table), runs one
// command and turns every failure into one line on stderr with exit code 2,
// CLI11's own errors included. Adding a command means writing its run function and one table
// entry; argument checking, --help and error reporting come for free. The
// help texts are this file's, not CLI11's, so that they stay as documented.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stickmorph/argument_limits.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/drawing_cleaning.h"
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/json.h"
#include "stickmorph/morph.h"
#include "stickmorph/io/result_files.h"
#include "stickmorph/morph_stick_figures.h"
#include "stickmorph/svg_output.h"
#include "argument_parsing.h"
#include "key_pose_command.h"
#include "timing_option.h"
#include "output_files.h"

namespace stickmorph {
namespace {

using cli::CommandSpec;
using cli::OptionSpec;
using cli::ParsedArguments;
using cli::command_help;
using cli::integer_option;
using cli::option_value;
using cli::required_option;
using cli::parse_arguments;
using cli::single_quoted;
using cli::usage_line;

constexpr const char* kVersion = STICKMORPH_VERSION;  // from CMake

// Exit codes of FORMAT.md.
constexpr int kExitSuccess = 0;
constexpr int kExitIncompatible = 1;  // only `check`
constexpr int kExitError = 2;

bool is_help_flag(std::string_view argument) { return argument == "--help" || argument == "-h"; }

// Writes text to stdout and reports a failed write (a closed pipe, a full
// disk) as an error instead of a silent success.
void write_stdout(const std::string& text) {
  std::cout << text;
  std::cout.flush();
  if (!std::cout) throw Error("cannot write to standard output");
}

// -- commands ---------------------------------------------------------------

// --correspond and --pin, as the engine takes them. Pins are parsed before
// any file is read; whether they exist in the figures is the matching's to say.
struct Matching {
  CorrespondenceMode mode = CorrespondenceMode::ByIndex;
  std::vector<VertexPin> pins;
};

// `correspond` always matches: it passes Auto as the mode.
Matching matching_options(const ParsedArguments& arguments, std::string_view command,
                          CorrespondenceMode mode = CorrespondenceMode::ByIndex);

int run_check(const ParsedArguments& arguments) {
  const Matching matching = matching_options(arguments, "check");
  const StickFigure source = read_figure_file(arguments.positional[0]);
  const StickFigure target = read_figure_file(arguments.positional[1]);
  if (matching.mode == CorrespondenceMode::Auto) {
    // Matchable is compatible: the matched pair is compatible by
    // construction (and checked). Bad pins are still exit 2.
    CorrespondenceOptions options;
    options.pins = matching.pins;
    try {
      correspond_figures(source, target, options);
    } catch (const IncompatibleFiguresError& error) {
      write_stdout(std::string("incompatible: ") + error.what() + "\n");
      return kExitIncompatible;
    }
    write_stdout("compatible\n");
    return kExitSuccess;
  }
  const CompatibilityReport report = check_compatibility(source, target);
  if (report.compatible()) {
    write_stdout("compatible\n");
    return kExitSuccess;
  }
  write_stdout("incompatible: " + report.reason + "\n");
  return kExitIncompatible;
}

// -- option values ----------------------------------------------------------

Matching matching_options(const ParsedArguments& arguments, std::string_view command, CorrespondenceMode mode) {
  Matching matching;
  matching.mode = mode;
  if (const std::string* name = option_value(arguments, "--correspond"))
    matching.mode = parse_correspondence_mode(*name);
  if (const auto pins = arguments.repeated.find("--pin"); pins != arguments.repeated.end())
    for (const std::string& text : pins->second) matching.pins.push_back(parse_vertex_pin(text));
  // The engine's rule, named with the command, before any other option of
  // the engine is checked (as the CLI always reported it).
  check_pins_need_auto(matching.mode, matching.pins, OptionSpelling::CommandLine, std::string(command) + ": ");
  return matching;
}

FigureTriangulationOptions triangulation_options(const ParsedArguments& arguments) {
  FigureTriangulationOptions options;
  if (const std::string* name = option_value(arguments, "--steiner")) options.method = parse_steiner_method(*name);
  if (const auto sides = integer_option(arguments, "--enclosure-sides"))
    options.enclosure_sides = check_enclosure_sides(*sides, OptionSpelling::CommandLine);
  return options;
}

// The output files a command will write (-o and, if given, --svg), resolved
// and checked before any work against each other and against the two input
// files, so that a typo in a folder name or an output naming an input fails
// at once, not after the morph (output_files.h).
// Every command here reads SOURCE.json and TARGET.json.
cli::OutputFiles prepare_outputs(const ParsedArguments& arguments, std::string_view command,
                                 const std::string& output) {
  std::vector<cli::NamedPath> outputs{{"--output", output}};
  if (const std::string* svg = option_value(arguments, "--svg")) outputs.push_back({"--svg", *svg});
  return cli::OutputFiles(std::string(command), outputs,
                          {{"SOURCE.json", arguments.positional[0]}, {"TARGET.json", arguments.positional[1]}});
}

int run_triangulate(const ParsedArguments& arguments) {
  const std::string& output = required_option(arguments, "triangulate", "--output");
  cli::OutputFiles outputs = prepare_outputs(arguments, "triangulate", output);
  const std::string* svg = option_value(arguments, "--svg");
  const FigureTriangulationOptions options = triangulation_options(arguments);
  const StickFigure source = read_figure_file(arguments.positional[0]);
  const StickFigure target = read_figure_file(arguments.positional[1]);
  const FigureTriangulation triangulation = triangulate_figures(source, target, options);
  std::vector<std::string> files{triangulation_file_json(triangulation)};
  if (svg)
    files.push_back(
        triangulation_svg(triangulation, source, "stickmorph triangulate --steiner " + steiner_method_name(options.method)));
  outputs.commit(files);
  return kExitSuccess;
}

// FORMAT.md's morph document, written by the IO library (result_files.h)
// from what the engine entry reports. The linear baseline has no
// triangulation and reports which frames self-intersect instead of the
// solver's counters.
std::string morph_document(const StickFigure& source, const MorphStickFiguresResult& result,
                           const MorphStickFiguresOptions& options) {
  const MorphMethod method = options.method;
  const bool linear = method == MorphMethod::Linear;
  const MorphStickFiguresStats& stats = result.stats;
  MorphStats solver;
  solver.factorize_ms = stats.factorize_ms;
  solver.solve_ms = stats.solve_ms;
  solver.verify_ms = stats.verify_ms;
  solver.refined_frames = stats.refined_frames;
  solver.factorizations = stats.factorizations;
  MorphProvenance how;
  how.method = morph_method_name(method);
  how.triangulation = result.triangulation ? &*result.triangulation : nullptr;
  how.triangulation_options = result.triangulation_options;
  how.options = result.morph_options;
  how.stats = linear ? nullptr : &solver;
  how.invalid_frames = linear ? &stats.invalid_frames : nullptr;
  RigidMotionReport rigid;
  if (method == MorphMethod::Rigid) {
    rigid.rotation = rotation_direction_name(options.rotation.value_or(RotationDirection::Short));
    rigid.turns = int(options.turns.value_or(0));
    rigid.easing = easing_name(options.easing.value_or(Easing::None));
    rigid.similarity = stats.similarity;
    rigid.similarity_factored = stats.similarity_factored;
    rigid.exact_frames = stats.guide_exact_frames;
    rigid.blended_frames = stats.guide_blended_frames;
    rigid.barycentric_frames = stats.guide_barycentric_frames;
    rigid.refinement_steiner = stats.triangulation.refinement_steiner;
    how.rigid = &rigid;
  }
  how.triangulate_ms = stats.triangulate_ms;
  how.morph_ms = stats.morph_ms;
  how.parts = stats.triangulation.parts;
  how.bridge_vertices = stats.triangulation.bridge_bends;
  if (result.correspondence) {
    how.correspondence = &*result.correspondence;
    how.correspond_ms = stats.correspond_ms;
  }
  return morph_file_json(result.correspondence ? result.correspondence->source : source, result.times,
                         result.frames, how);
}

int run_morph(const ParsedArguments& arguments) {
  if (cli::is_key_pose_run(arguments)) return cli::run_key_poses(arguments);
  const std::string& output = required_option(arguments, "morph", "--output");
  cli::OutputFiles outputs = prepare_outputs(arguments, "morph", output);
  const std::string* svg = option_value(arguments, "--svg");
  const bool overlay = option_value(arguments, "--svg-triangulation") != nullptr;
  const bool compare_linear = option_value(arguments, "--svg-compare-linear") != nullptr;
  MorphStickFiguresOptions options;
  options.spelling = OptionSpelling::CommandLine;
  // Checked at once (check_morph_options checks it again) so that a bad
  // count is reported before the drawing options, as it always was.
  if (const auto frames = integer_option(arguments, "--frames"))
    options.frames = check_frames(*frames, OptionSpelling::CommandLine);
  if (const std::string* name = option_value(arguments, "--weights")) options.weights = parse_weight_kind(*name);
  if (const std::string* name = option_value(arguments, "--method")) options.method = parse_morph_method(*name);
  // Drawing options that would have no effect are refused rather than
  // ignored, like the engine's options that --method linear would ignore.
  for (const char* drawing : {"--svg-triangulation", "--svg-compare-linear"})
    if (option_value(arguments, drawing) && svg == nullptr)
      throw InvalidArgumentError("morph: option " + std::string(drawing) + " needs --svg FILE");
  if (overlay && compare_linear)
    throw InvalidArgumentError("morph: --svg-triangulation and --svg-compare-linear cannot be combined");
  if (options.method == MorphMethod::Linear)
    for (const char* drawing : {"--svg-triangulation", "--svg-compare-linear"})
      if (option_value(arguments, drawing))
        throw InvalidArgumentError("morph: option " + std::string(drawing) +
                                   " has no effect with --method linear (the straight-line morph uses no "
                                   "triangulation)");
  if (option_value(arguments, "--no-verify")) options.verify = false;
  if (const std::string* name = option_value(arguments, "--frame-check"))
    options.frame_check = parse_frame_check(*name);
  if (const std::string* name = option_value(arguments, "--steiner")) options.steiner = parse_steiner_method(*name);
  options.enclosure_sides = integer_option(arguments, "--enclosure-sides");
  if (const std::string* name = option_value(arguments, "--rotation"))
    options.rotation = parse_rotation_direction(*name);
  options.turns = integer_option(arguments, "--turns");
  if (const std::string* name = option_value(arguments, "--easing")) options.easing = parse_easing(*name);
  const Matching matching = matching_options(arguments, "morph");
  options.correspond = matching.mode;
  options.pins = matching.pins;
  // The triangulation drawn under the filmstrip needs every node's position.
  options.keep_node_frames = overlay;
  options.timing = cli::timing_option(arguments);
  check_morph_options(options);
  const StickFigure source = read_figure_file(arguments.positional[0]);
  const StickFigure target = read_figure_file(arguments.positional[1]);
  if (options.timing) cli::check_timing_length(arguments, *options.timing, source.vertices.size(), arguments.positional[0]);
  const std::string title = "stickmorph morph: " + (source.name.empty() ? arguments.positional[0] : source.name) +
                            " -> " + (target.name.empty() ? arguments.positional[1] : target.name);

  const MorphStickFiguresResult result = morph_stick_figures(source, target, options);
  std::vector<std::string> files{morph_document(source, result, options)};
  // The figure the frames are of: the matched one with --correspond auto.
  const StickFigure& drawn = result.correspondence ? result.correspondence->source : source;
  if (svg && compare_linear) {
    MorphStickFiguresOptions linear;
    linear.method = MorphMethod::Linear;
    linear.frames = options.frames;
    const MorphStickFiguresResult straight =
        result.correspondence ? morph_stick_figures(result.correspondence->source, result.correspondence->target, linear)
                              : morph_stick_figures(source, target, linear);
    files.push_back(comparison_filmstrip_svg(drawn, result.frames, straight.frames, result.times, 7,
                                             straight.stats.invalid_frames, title));
  } else if (svg) {
    files.push_back(filmstrip_svg(drawn, overlay ? result.node_frames : result.frames, result.times, 7,
                                  overlay ? &*result.triangulation : nullptr, title));
  }
  outputs.commit(files);
  return kExitSuccess;
}

int run_correspond(const ParsedArguments& arguments) {
  const std::string& output = required_option(arguments, "correspond", "--output");
  cli::OutputFiles outputs = prepare_outputs(arguments, "correspond", output);
  Matching matching = matching_options(arguments, "correspond", CorrespondenceMode::Auto);
  const StickFigure source = read_figure_file(arguments.positional[0]);
  const StickFigure target = read_figure_file(arguments.positional[1]);
  CorrespondenceOptions options;
  options.pins = std::move(matching.pins);
  const FigureCorrespondence correspondence = correspond_figures(source, target, options);
  outputs.commit({correspondence_file_json(correspondence)});
  return kExitSuccess;
}

// Cleans a drawing (strokes, or a figure whose edges cross) into a stick
// figure file that morph reads, with what changed (drawing_cleaning.h).
int run_clean(const ParsedArguments& arguments) {
  const std::string& output = required_option(arguments, "clean", "--output");
  cli::OutputFiles outputs("clean", {{"--output", output}}, {{"INPUT.json", arguments.positional[0]}});
  DrawingCleaningOptions options;
  options.tolerance = cli::number_option(arguments, "--tolerance");
  if (options.tolerance && *options.tolerance < 0)
    throw InvalidArgumentError("clean: option --tolerance must be >= 0, got " + format_double(*options.tolerance));
  const Drawing drawing = read_drawing_file(arguments.positional[0]);
  CleanedDrawing cleaned;
  try {
    cleaned = clean_drawing(drawing, options);
  } catch (const InvalidDrawingError& error) {
    throw InvalidDrawingError(error.defect(), arguments.positional[0] + ": " + error.what(), error.stroke(),
                              error.point(), error.other_stroke());
  }
  // The check beside the algorithm: the figure is valid and every moved
  // point is reported. Linear next to the cleaning itself.
  validate_cleaning(cleaned, drawing);
  outputs.commit({cleaned_drawing_json(cleaned, drawing, drawing.name)});
  write_stdout("cleaned: " + cleaned.summary() + "\n");
  return kExitSuccess;
}

// Help lines that quote limits read them from argument_limits.h, so that the
// help cannot drift from what the engine enforces.
std::string range_help(int fallback, int least, int most) {
  return "(default " + std::to_string(fallback) + ", " + std::to_string(least) + " to " + std::to_string(most) + ")";
}

std::string frames_help() {
  return "number of frames, at t = k/(N-1) " + range_help(kDefaultMorphFrames, kMinMorphFrames, kMaxMorphFrames);
}

std::string enclosure_sides_help() {
  return "sides of the common convex enclosure " +
         range_help(kDefaultEnclosureSides, kMinEnclosureSides, kMaxEnclosureSides);
}

std::string turns_help() {
  return "rigid: extra whole turns, counter-clockwise positive (default 0, " + std::to_string(-kMaxExtraTurns) +
         " to " + std::to_string(kMaxExtraTurns) + ")";
}

constexpr const char* kCorrespondHelp =
    "index (default: vertex i becomes vertex i) or auto (match figures drawn separately; dummy vertices "
    "where a vertex has no partner)";
constexpr const char* kPinHelp =
    "with --correspond auto: source vertex S must become target vertex T (repeatable)";

const std::vector<CommandSpec>& commands() {
  static const std::vector<CommandSpec> table = {
      {"check",
       {"SOURCE.json", "TARGET.json"},
       "",
       {{"--correspond", "", "MODE", kCorrespondHelp},
        {"--pin", "", "S:T", kPinHelp, true}},
       "decide whether two stick figures are compatible",
       "Decides whether the two figures, whose vertices correspond by index, are\n"
       "compatible (same cyclic order of edges around every vertex and the same\n"
       "exterior sequence; Surazhsky & Gotsman 2001, section 2.1). Prints\n"
       "\"compatible\" (exit 0) or \"incompatible: <reason naming vertices>\" (exit 1).\n"
       "With --correspond auto: whether the figures can be matched (see correspond).",
       &run_check},
      {"triangulate",
       {"SOURCE.json", "TARGET.json"},
       "",
       {{"--output", "-o", "OUT.json", "where to write the triangulation object (required)"},
        {"--steiner", "", "NAME", "compatible triangulation method: improved (default), sg2001 or aronov"},
        {"--enclosure-sides", "", "K", enclosure_sides_help()},
        {"--svg", "", "FILE", "also draw both triangulations side by side"}},
       "compatibly triangulate two stick figures inside a common enclosure",
       "Builds the compatible triangulation of the two figures that the morph uses\n"
       "(Surazhsky & Gotsman 2001, Algorithm 3): every face compatibly triangulated\n"
       "(section 4), the exterior enclosed by a common convex polygon and cut open.\n"
       "Writes the \"triangulation\" object of FORMAT.md: figure vertices first, then\n"
       "the enclosure counter-clockwise, then the Steiner vertices. The result is\n"
       "verified in exact arithmetic before it is written.",
       &run_triangulate},
      {"morph",
       {"SOURCE.json", "TARGET.json"},
       "[KEY3.json ...]",
       {{"--output", "-o", "OUT.json", "where to write the morph (required)"},
        {"--frames", "", "N", frames_help()},
        {"--steiner", "", "NAME", "compatible triangulation method: improved (default), sg2001 or aronov"},
        {"--weights", "", "KIND", "barycentric weights: mvc (default), uniform or floater"},
        {"--enclosure-sides", "", "K", enclosure_sides_help()},
        {"--method", "", "NAME",
         "rigid (default: as rigid as validity allows), barycentric (the paper's morph) or linear "
         "(straight-line baseline, Fig. 8d)"},
        {"--rotation", "", "DIR", "rigid: which way the figure turns as a whole: short (default), ccw or cw"},
        {"--turns", "", "K", turns_help()},
        {"--easing", "", "NAME", "rigid: none (default: even speed) or in-out (slow in and out)"},
        {"--timing", "", "FILE.json",
         "rigid: local timing, {\"delay\": [w per source vertex, 0 to 1], \"overlap\": d in [0, 1)}: "
         "weight-1 parts lag weight-0 parts by d (overlapping action)"},
        {"--correspond", "", "MODE", kCorrespondHelp},
        {"--pin", "", "S:T", kPinHelp, true},
        {"--no-verify", "", "", "skip the exact check of every frame"},
        {"--frame-check", "", "MODE",
         "certificate (default: every triangle counter-clockwise in the convex enclosure, a proof in O(T)) "
         "or full (also rebuild each frame's figure and compare it with the source)"},
        {"--svg", "", "FILE", "also draw a filmstrip of about seven frames"},
        {"--svg-triangulation", "", "", "draw the triangulation under the filmstrip's figures"},
        {"--svg-compare-linear", "", "", "draw the straight-line morph as a second filmstrip row (Figure 8d)"},
        {"--keys-at", "", "F1,...,FK",
         "key poses: the frame of every key, increasing from 0 to N-1 (default: evenly spaced)"},
        {"--loop", "", "", "key poses: return to the first key at the last frame, smoothly"},
        {"--hold", "", "K1,...", "key poses: stop at these keys (numbered from 1)"}},
       "morph one stick figure into a compatible one, or through key poses",
       "Morphs SOURCE into TARGET (Surazhsky & Gotsman 2001, Algorithm 3): both are\n"
       "embedded in one compatible triangulation of a common convex enclosure, whose\n"
       "barycentric coordinates are interpolated (Floater & Gotsman 1999). The rigid\n"
       "method (default) first factors out the best-fit rotation, scale and\n"
       "translation and then follows an as-rigid-as-possible motion of the figure\n"
       "wherever that is valid, at even speed. Every frame\n"
       "is checked in exact arithmetic to be a stick figure with the source's cyclic\n"
       "sequences unless --no-verify is given (by default through the triangulation:\n"
       "all its triangles counter-clockwise inside the convex enclosure prove it;\n"
       "--frame-check full also rebuilds the figure); a frame that fails is refined or the\n"
       "command fails naming it. With --method linear the vertices move on straight\n"
       "lines and the frames that self-intersect are listed in stats.invalid_frames.\n"
       "\n"
       "Given more than two files (KEY1.json KEY2.json ... KEYK.json, the same\n"
       "vertices and edges, each compatible with the next), or --keys-at, --loop or\n"
       "--hold: one continuous rigid motion through every key, key k exactly at frame\n"
       "F_k (--keys-at; default evenly spaced, N = 49 per segment + 1), its velocity\n"
       "continuous through the keys; --rotation and --turns take one value or one per\n"
       "segment. The output adds \"keys\" and has \"triangulations\", one per segment.",
       &run_morph},
      {"correspond",
       {"SOURCE.json", "TARGET.json"},
       "",
       {{"--output", "-o", "OUT.json", "where to write the matched figures (required)"},
        {"--pin", "", "S:T", kPinHelp, true}},
       "match two stick figures drawn separately",
       "Matches two figures that need not correspond by index (other vertex counts,\n"
       "numbering or subdivision): their junctions and ends as plane maps, their\n"
       "strokes by arc length, with dummy vertices where a vertex has no partner\n"
       "(Surazhsky & Gotsman 2001, section 6). Writes the matched figure on the\n"
       "source and on the target drawing and the \"correspondence\" of morph\n"
       "--correspond auto.",
       &run_correspond},
      {"clean",
       {"INPUT.json"},
       "",
       {{"--output", "-o", "OUT.json", "where to write the cleaned stick figure (required)"},
        {"--tolerance", "", "T",
         "snap stroke ends this close to a stroke; points within T/100 merge (default: 1% of the "
         "drawing's bounding-box diagonal; 0: only exact duplicates merge, nothing snaps)"}},
       "clean a drawing (strokes that cross and touch) into a stick figure",
       "Reads a drawing file {\"strokes\": [{\"points\": [[x, y], ...], \"cyclic\": false},\n"
       "...]} or a stick figure file whose edges may cross, and writes a valid stick\n"
       "figure file: crossings and touchings become shared vertices, stroke ends within\n"
       "the tolerance of a stroke snap onto it, duplicate points merge. The output's\n"
       "\"cleaning\" member lists every change (merge, snap, crossing, touch) and each\n"
       "stroke's vertex path; stdout gets one summary line. Strokes that overlap along\n"
       "a length, a stroke that retraces itself, a stroke of one point and an empty\n"
       "drawing are errors naming the stroke. The output is checked in exact\n"
       "arithmetic (Surazhsky & Gotsman 2001, section 1: a stick figure is a plane graph).",
       &run_clean},
  };
  return table;
}

std::string command_names() {
  std::string names;
  for (const CommandSpec& command : commands()) {
    if (!names.empty()) names += ", ";
    names += command.name;
  }
  return names;
}

std::string global_help() {
  std::string text =
      "usage: stickmorph COMMAND [ARGUMENTS]\n"
      "       stickmorph --help | --version\n"
      "\n"
      "Morphs planar stick figures (connected straight-line plane graphs) following\n"
      "Surazhsky & Gotsman, \"Morphing Stick Figures Using Optimized Compatible\n"
      "Triangulations\", 2001. Figures are JSON files:\n"
      "  {\"name\": \"...\", \"vertices\": [[x, y], ...], \"edges\": [[i, j], ...]}\n"
      "\n"
      "commands:\n";
  for (const CommandSpec& command : commands()) {
    text += "  " + usage_line(command) + "\n      " + std::string(command.summary) + "\n";
  }
  text +=
      "\n"
      "options:\n"
      "  -h, --help     print this help (or 'stickmorph COMMAND --help')\n"
      "  --version      print the version\n"
      "\n"
      "exit status: 0 success; 1 incompatible figures (check); 2 bad input or\n"
      "failure, with one line 'error: ...' on standard error.\n";
  return text;
}


int run(const std::vector<std::string>& arguments) {
  if (arguments.empty()) {
    throw InvalidArgumentError("missing command; commands: " + command_names() +
                               " (see 'stickmorph --help')");
  }
  const std::string& first = arguments[0];
  const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
  if (is_help_flag(first) || first == "--version") {
    if (!rest.empty()) {
      throw InvalidArgumentError(first + " takes no arguments, got " + single_quoted(rest[0]));
    }
    write_stdout(first == "--version" ? std::string("stickmorph ") + kVersion + "\n"
                                      : global_help());
    return kExitSuccess;
  }
  for (const CommandSpec& command : commands()) {
    if (command.name != first) continue;
    ParsedArguments parsed;
    if (!parse_arguments(command, rest, parsed)) {
      write_stdout(command_help(command));
      return kExitSuccess;
    }
    return command.run(parsed);
  }
  const bool looks_like_option = first.size() > 1 && first[0] == '-';
  const std::string what = looks_like_option ? "unknown option " : "unknown command ";
  throw InvalidArgumentError(what + single_quoted(first) + "; commands: " + command_names() +
                             " (see 'stickmorph --help')");
}

// FORMAT.md promises exactly one line on stderr. Messages can quote paths
// or names from the input, which may hold line breaks; those are escaped.
std::string one_line(std::string_view message) {
  std::string line;
  line.reserve(message.size());
  for (const char byte : message) {
    const auto c = static_cast<unsigned char>(byte);
    if (c == '\n') {
      line += "\\n";
    } else if (c == '\r') {
      line += "\\r";
    } else if (c < 0x20 || c == 0x7F) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\x%02X", static_cast<unsigned>(c));
      line += escape;
    } else {
      line += byte;
    }
  }
  return line;
}

// Uses stdio rather than iostreams so that reporting an error does not
// depend on the state of std::cout, which may be what failed. Takes views so
// that the caller builds no string that could throw inside its handler.
void print_error(std::string_view prefix, std::string_view message) noexcept {
  try {
    const std::string line = "error: " + std::string(prefix) + one_line(message) + "\n";
    std::fputs(line.c_str(), stderr);
  } catch (...) {
    // Out of memory while building the message: say so without allocating.
    std::fputs("error: out of memory\n", stderr);
  }
  std::fflush(stderr);
}

}  // namespace
}  // namespace stickmorph

int main(int argc, char** argv) {
  using namespace stickmorph;
  try {
    const std::vector<std::string> arguments(argv + (argc > 0 ? 1 : 0), argv + argc);
    return run(arguments);
  } catch (const InternalError& error) {
    print_error("internal error: ", error.what());
  } catch (const Error& error) {
    print_error("", error.what());
  } catch (const std::bad_alloc&) {
    print_error("", "out of memory");
  } catch (const std::exception& error) {
    print_error("internal error: ", error.what());
  } catch (...) {
    print_error("internal error: ", "unknown exception");
  }
  return kExitError;
}
