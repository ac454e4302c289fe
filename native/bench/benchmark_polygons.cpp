// Benchmark of compatible triangulation of polygon pairs (paper, section 4).
//
// Surazhsky & Gotsman 2001, Figure 7, compares the number of Steiner vertices
// that the universal spiderweb of Aronov et al. [2] (575), the reduced
// spiderweb of [18] (334) and the improved method of section 4.2 (153) need
// for one pair of 38-gons. This program measures the same three methods on a
// corpus of polygon pairs (tests/data/polygon_pairs): Steiner vertices, their
// ratio to the number of corners, the smallest triangle angle before and after
// smoothing, and the time, then sets the corpus-wide ratios next to the
// paper's.
//
// It is a measurement tool, not a test: a method that throws on a pair is
// reported in that pair's row and the run goes on, and the exit status is 0
// whatever the methods did. Only bad arguments exit with 2.
//
// Usage: stickmorph_benchmark [--methods aronov,sg2001,improved] [--repeat N]
//                             [--json FILE] FILE_OR_DIR...
// --json also writes every pair's results as JSON, for make_benchmarks.py.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/json.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {
namespace {

namespace fs = std::filesystem;

constexpr int kExitSuccess = 0;
constexpr int kExitUsage = 2;

constexpr const char* kSourceSuffix = ".source.json";
constexpr const char* kTargetSuffix = ".target.json";
constexpr const char* kDefaultDirectory = "tests/data/polygon_pairs";

// Failure messages are cut to this many characters so a table row stays
// readable; the whole message goes to stderr.
constexpr std::size_t kFailureMessageLength = 60;

constexpr double kPi = 3.14159265358979323846;

// Paper, Figure 7: Steiner vertices for its pair of 38-gons.
constexpr int kPaperAronov = 575;
constexpr int kPaperSg2001 = 334;
constexpr int kPaperImproved = 153;

constexpr const char* kUsage =
    "usage: stickmorph_benchmark [--methods aronov,sg2001,improved] [--repeat N] "
    "[--json FILE] [FILE_OR_DIR...]\n"
    "\n"
    "Compatibly triangulates polygon pairs with each method and prints a Markdown\n"
    "table of Steiner vertices, Steiner/corner ratio, smallest angle and time.\n"
    "A FILE is NAME.source.json (NAME.target.json must exist beside it); a DIR\n"
    "contributes every *.source.json with a matching *.target.json. Without\n"
    "arguments, reads tests/data/polygon_pairs.\n"
    "\n"
    "  --methods LIST  comma-separated methods (default aronov,sg2001,improved)\n"
    "  --repeat N      time each method N times and keep the best (default 3)\n"
    "  --json FILE     also write the results as JSON to FILE\n";

struct Options {
  std::vector<SteinerMethod> methods;
  int repeat = 3;
  std::string json_path;
  std::vector<std::string> inputs;
  bool help = false;
};

/// One polygon pair of the corpus.
struct Case {
  std::string name;
  std::string source_path;
  std::string target_path;
};

/// What one method did on one pair.
struct MethodResult {
  bool succeeded = false;
  std::string failure;  ///< full message when !succeeded
  int steiner = 0;
  double min_angle_before_degrees = 0;
  double min_angle_after_degrees = 0;
  double best_milliseconds = 0;
};

struct CaseResult {
  std::string name;
  int corners = 0;
  std::string skipped;  ///< why the pair was not run; empty if it was
  std::vector<MethodResult> methods;  ///< parallel to Options::methods
};

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

// ---------------------------------------------------------------------------
// Arguments

std::vector<SteinerMethod> parse_methods(const std::string& text) {
  std::vector<SteinerMethod> methods;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = text.find(',', begin);
    const std::string name =
        text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
    if (name.empty()) {
      throw InvalidArgumentError("--methods: empty method name in '" + text +
                                 "' (expected a comma-separated list of aronov, sg2001, improved)");
    }
    const SteinerMethod method = parse_steiner_method(name);
    // A method listed twice would only repeat its columns.
    if (std::find(methods.begin(), methods.end(), method) != methods.end()) {
      throw InvalidArgumentError("--methods: '" + name + "' listed twice");
    }
    methods.push_back(method);
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return methods;
}

// CLI11 parses; the help is kUsage, and a mistake is one InvalidArgumentError
// line like every other failure of this program.
Options parse_arguments(int argc, char** argv) {
  Options options;
  options.methods = {SteinerMethod::Aronov, SteinerMethod::Sg2001, SteinerMethod::Improved};
  CLI::App app{"compatible triangulation benchmark", "stickmorph_benchmark"};
  app.set_help_flag("-h,--help");
  std::string methods;
  app.add_option("--methods", methods);
  app.add_option("--repeat", options.repeat)->check(CLI::Range(1, std::numeric_limits<int>::max()));
  app.add_option("--json", options.json_path);
  app.add_option("FILE_OR_DIR", options.inputs);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    options.help = true;
    return options;
  } catch (const CLI::ParseError& error) {
    throw InvalidArgumentError(std::string(error.what()) + " (see --help)");
  }
  if (app.count("--methods")) options.methods = parse_methods(methods);
  if (options.inputs.empty()) options.inputs.push_back(kDefaultDirectory);
  return options;
}

// ---------------------------------------------------------------------------
// Corpus

std::string case_name(const fs::path& source) {
  const std::string file = source.filename().string();
  return file.substr(0, file.size() - std::string_view(kSourceSuffix).size());
}

fs::path target_of(const fs::path& source) {
  return source.parent_path() / (case_name(source) + kTargetSuffix);
}

/// Expands the inputs into pairs. Files named explicitly must form a pair;
/// in a directory a source without a target is only noted, since a corpus
/// folder may hold other files too.
std::vector<Case> collect_cases(const std::vector<std::string>& inputs) {
  std::vector<Case> cases;
  for (const std::string& input : inputs) {
    const fs::path path(input);
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (fs::is_directory(status)) {
      std::vector<fs::path> sources;
      for (const fs::directory_entry& entry : fs::directory_iterator(path)) {
        if (entry.is_regular_file() && ends_with(entry.path().filename().string(), kSourceSuffix)) {
          sources.push_back(entry.path());
        }
      }
      // Directory order is unspecified; sort so runs compare row by row.
      std::sort(sources.begin(), sources.end());
      for (const fs::path& source : sources) {
        const fs::path target = target_of(source);
        if (!fs::is_regular_file(target)) {
          std::cerr << "note: " << source.string() << " has no " << target.filename().string()
                    << "; skipped\n";
          continue;
        }
        cases.push_back({case_name(source), source.string(), target.string()});
      }
    } else if (fs::is_regular_file(status)) {
      if (!ends_with(path.filename().string(), kSourceSuffix)) {
        throw InvalidArgumentError("'" + input + "' is not a directory or a *" + kSourceSuffix +
                                   " file");
      }
      const fs::path target = target_of(path);
      if (!fs::is_regular_file(target)) {
        throw InvalidArgumentError("'" + input + "' has no matching '" + target.string() + "'");
      }
      cases.push_back({case_name(path), path.string(), target.string()});
    } else {
      throw InvalidArgumentError("'" + input + "': no such file or directory");
    }
  }
  if (cases.empty()) throw InvalidArgumentError("no polygon pairs (*.source.json with *.target.json) found");
  return cases;
}

// ---------------------------------------------------------------------------
// Measuring

double degrees(double radians) { return radians * 180.0 / kPi; }

MethodResult run_method(const PolygonPair& pair, SteinerMethod method, int repeat,
                        const std::string& label) {
  CompatibleTriangulationOptions options;
  options.method = method;
  options.label = label;
  MethodResult result;
  result.best_milliseconds = std::numeric_limits<double>::infinity();
  for (int run = 0; run < repeat; ++run) {
    CompatibleTriangulationStats stats;
    const auto start = std::chrono::steady_clock::now();
    try {
      const CompatibleTriangulation triangulation = compatible_triangulation(pair, options, &stats);
      const auto stop = std::chrono::steady_clock::now();
      result.best_milliseconds = std::min(
          result.best_milliseconds, std::chrono::duration<double, std::milli>(stop - start).count());
      result.steiner = triangulation.steiner_count();
    } catch (const std::exception& error) {
      // Any exception, not only stickmorph::Error: an implementation under
      // repair may also trip a CGAL precondition or run out of memory, and
      // that is a result of this pair, not a reason to stop measuring.
      result.failure = error.what();
      return result;
    }
    result.min_angle_before_degrees = degrees(stats.min_angle_before_smoothing);
    result.min_angle_after_degrees = degrees(stats.min_angle_after_smoothing);
  }
  result.succeeded = true;
  return result;
}

/// Reads, checks and decomposes one pair, then runs every method on it.
CaseResult run_case(const Case& input, const Options& options) {
  CaseResult result;
  result.name = input.name;
  try {
    const StickFigure source = read_figure_file(input.source_path);
    const StickFigure target = read_figure_file(input.target_path);
    const CompatibilityReport report = check_compatibility(source, target);
    if (!report.compatible()) {
      result.skipped = "incompatible: " + report.reason;
      return result;
    }
    const Decomposition decomposition = decompose(source);
    std::vector<const CyclicSequence*> interior;
    for (const CyclicSequence& sequence : decomposition.sequences) {
      if (!sequence.exterior) interior.push_back(&sequence);
    }
    if (interior.size() != 1) {
      result.skipped = "not a single polygon: " + std::to_string(interior.size()) +
                       " interior cyclic sequences, the benchmark needs exactly one";
      return result;
    }
    // Algorithm 1 lists the heads of the darts with the region on their
    // left, i.e. the corners counter-clockwise, as PolygonPair expects. The
    // figures are compatible, so the same vertex order is the target's
    // interior sequence as well.
    PolygonPair pair;
    pair.corners = interior.front()->vertices;
    pair.source_positions = source.vertices;
    pair.target_positions = target.vertices;
    result.corners = int(pair.corners.size());
    for (SteinerMethod method : options.methods) {
      std::cerr << "  " << steiner_method_name(method) << "..." << std::flush;
      MethodResult measured = run_method(pair, method, options.repeat, input.name);
      if (measured.succeeded) {
        std::cerr << " " << measured.steiner << " Steiner vertices\n";
      } else {
        std::cerr << " FAILED: " << measured.failure << "\n";
      }
      result.methods.push_back(std::move(measured));
    }
  } catch (const Error& error) {
    // A file that does not read as a valid figure is a property of the
    // corpus, reported like an incompatible pair.
    result.skipped = error.what();
    result.methods.clear();
  }
  return result;
}

// ---------------------------------------------------------------------------
// Report

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string format_angle(double degrees_value) {
  // Thin triangles can have angles far below a hundredth of a degree; show
  // those in scientific notation rather than as 0.00.
  return format(degrees_value >= 0.1 || degrees_value == 0 ? "%.2f" : "%.2g", degrees_value);
}

std::string format_milliseconds(double milliseconds) {
  return format(milliseconds < 10 ? "%.2f" : milliseconds < 1000 ? "%.1f" : "%.0f", milliseconds);
}

std::string format_ratio(double numerator, double denominator) {
  return denominator > 0 ? format("%.2f", numerator / denominator) : std::string("n/a");
}

/// Makes text safe inside a Markdown table cell: one line, no column bar.
std::string table_cell(const std::string& text) {
  std::string cell;
  for (char c : text) {
    if (c == '\n' || c == '\r' || c == '\t') {
      cell += ' ';
    } else if (c == '|') {
      cell += "\\|";
    } else {
      cell += c;
    }
  }
  return cell;
}

/// The first kFailureMessageLength characters, without splitting a UTF-8
/// sequence.
std::string shorten(const std::string& message) {
  if (message.size() <= kFailureMessageLength) return message;
  std::size_t cut = kFailureMessageLength;
  while (cut > 0 && (static_cast<unsigned char>(message[cut]) & 0xC0) == 0x80) --cut;
  return message.substr(0, cut);
}

void print_table(std::ostream& out, const Options& options, const std::vector<CaseResult>& results) {
  out << "| case | n |";
  for (SteinerMethod method : options.methods) {
    const std::string name = steiner_method_name(method);
    out << " " << name << " Steiner | " << name << " ratio | " << name << " min angle ° | "
        << name << " ms |";
  }
  out << "\n|---|--:|";
  for (std::size_t m = 0; m < options.methods.size(); ++m) out << "--:|--:|--:|--:|";
  out << "\n";
  for (const CaseResult& result : results) {
    if (!result.skipped.empty()) continue;
    out << "| " << table_cell(result.name) << " | " << result.corners << " |";
    for (const MethodResult& method : result.methods) {
      if (!method.succeeded) {
        out << " FAILED: " << table_cell(shorten(method.failure)) << " | - | - | - |";
        continue;
      }
      out << " " << method.steiner << " | " << format_ratio(method.steiner, result.corners) << " | "
          << format_angle(method.min_angle_after_degrees) << " ("
          << format_angle(method.min_angle_before_degrees) << ") | "
          << format_milliseconds(method.best_milliseconds) << " |";
    }
    out << "\n";
  }
  out << "\nratio = Steiner vertices / corners n; min angle ° = smallest triangle angle over "
         "both polygons after smoothing (before smoothing in parentheses); ms = best of "
      << options.repeat << " run" << (options.repeat == 1 ? "" : "s") << ".\n";
}

int method_index(const Options& options, SteinerMethod method) {
  const auto found = std::find(options.methods.begin(), options.methods.end(), method);
  return found == options.methods.end() ? -1 : int(found - options.methods.begin());
}

void print_summary(std::ostream& out, const Options& options,
                   const std::vector<CaseResult>& results) {
  const std::size_t method_count = options.methods.size();
  std::vector<long long> steiner(method_count, 0), corners(method_count, 0);
  std::vector<int> succeeded(method_count, 0), failed(method_count, 0);
  std::vector<double> milliseconds(method_count, 0);
  // Steiner totals over the pairs on which every selected method succeeded,
  // so that the ratios between methods compare like with like.
  std::vector<long long> common_steiner(method_count, 0);
  int common_cases = 0, run_cases = 0;
  for (const CaseResult& result : results) {
    if (!result.skipped.empty()) continue;
    ++run_cases;
    bool all_succeeded = true;
    for (std::size_t m = 0; m < method_count; ++m) {
      const MethodResult& method = result.methods[m];
      if (!method.succeeded) {
        ++failed[m];
        all_succeeded = false;
        continue;
      }
      ++succeeded[m];
      steiner[m] += method.steiner;
      corners[m] += result.corners;
      milliseconds[m] += method.best_milliseconds;
    }
    if (!all_succeeded) continue;
    ++common_cases;
    for (std::size_t m = 0; m < method_count; ++m) common_steiner[m] += result.methods[m].steiner;
  }

  out << "\n## Summary\n\n"
      << "| method | pairs succeeded | failures | Steiner total | corners total | "
         "Steiner / corner | ms total |\n"
      << "|---|--:|--:|--:|--:|--:|--:|\n";
  for (std::size_t m = 0; m < method_count; ++m) {
    out << "| " << steiner_method_name(options.methods[m]) << " | " << succeeded[m] << " | "
        << failed[m] << " | " << steiner[m] << " | " << corners[m] << " | "
        << format_ratio(double(steiner[m]), double(corners[m])) << " | "
        << format_milliseconds(milliseconds[m]) << " |\n";
  }

  const int aronov = method_index(options, SteinerMethod::Aronov);
  const int sg2001 = method_index(options, SteinerMethod::Sg2001);
  const int improved = method_index(options, SteinerMethod::Improved);
  out << "\nRatios of Steiner totals over the " << common_cases << " of " << run_cases
      << " pairs on which every selected method succeeded";
  if (common_cases > 0) {
    out << " (";
    for (std::size_t m = 0; m < method_count; ++m) {
      out << (m ? ", " : "") << steiner_method_name(options.methods[m]) << " "
          << common_steiner[m];
    }
    out << ")";
  }
  out << ":\n\n| ratio | this corpus | paper, Figure 7 |\n|---|--:|--:|\n";
  const auto ratio_row = [&](const char* label, int numerator, int denominator, int paper_numerator,
                             int paper_denominator) {
    std::string measured = "n/a (method not selected)";
    if (numerator >= 0 && denominator >= 0) {
      measured = common_cases == 0 ? std::string("n/a (no pair)")
                                   : format_ratio(double(common_steiner[numerator]),
                                                  double(common_steiner[denominator]));
    }
    out << "| " << label << " | " << measured << " | "
        << format_ratio(paper_numerator, paper_denominator) << " (" << paper_numerator << "/"
        << paper_denominator << ") |\n";
  };
  ratio_row("improved / sg2001", improved, sg2001, kPaperImproved, kPaperSg2001);
  ratio_row("improved / aronov", improved, aronov, kPaperImproved, kPaperAronov);

  out << "\nFailures:";
  for (std::size_t m = 0; m < method_count; ++m) {
    out << (m ? "," : "") << " " << steiner_method_name(options.methods[m]) << " " << failed[m];
  }
  out << "\n";

  bool any_skipped = false;
  for (const CaseResult& result : results) {
    if (result.skipped.empty()) continue;
    if (!any_skipped) out << "\nSkipped pairs:\n";
    any_skipped = true;
    out << "- " << result.name << ": " << result.skipped << "\n";
  }
}

/// The results as one JSON document: {"repeat": N, "pairs": [{"name", "corners",
/// "skipped", "methods": [{"method", "ok", "failure", "steiner", "ms",
/// "min_angle_before_deg", "min_angle_after_deg"}]}]}.
void write_json(const std::string& path, const Options& options, const std::vector<CaseResult>& results) {
  std::ofstream out(path);
  if (!out) throw Error("cannot write '" + path + "'");
  out << "{\"repeat\":" << options.repeat << ",\"pairs\":[";
  for (std::size_t c = 0; c < results.size(); ++c) {
    const CaseResult& result = results[c];
    out << (c ? "," : "") << "\n{\"name\":" << quote_json_string(result.name) << ",\"corners\":" << result.corners
        << ",\"skipped\":" << quote_json_string(result.skipped) << ",\"methods\":[";
    for (std::size_t m = 0; m < result.methods.size(); ++m) {
      const MethodResult& method = result.methods[m];
      out << (m ? "," : "") << "{\"method\":" << quote_json_string(steiner_method_name(options.methods[m]))
          << ",\"ok\":" << (method.succeeded ? "true" : "false")
          << ",\"failure\":" << quote_json_string(method.failure) << ",\"steiner\":" << method.steiner;
      if (method.succeeded) {
        out << ",\"ms\":" << format_json_number(method.best_milliseconds)
            << ",\"min_angle_before_deg\":" << format_json_number(method.min_angle_before_degrees)
            << ",\"min_angle_after_deg\":" << format_json_number(method.min_angle_after_degrees);
      }
      out << "}";
    }
    out << "]}";
  }
  out << "\n]}\n";
  out.flush();
  if (!out) throw Error("writing '" + path + "' failed");
}

int run(int argc, char** argv) {
  const Options options = parse_arguments(argc, argv);
  if (options.help) {
    std::cout << kUsage;
    return kExitSuccess;
  }
  const std::vector<Case> cases = collect_cases(options.inputs);

  std::vector<CaseResult> results;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    // Progress goes to stderr so that stdout is the Markdown report alone.
    std::cerr << "[" << k + 1 << "/" << cases.size() << "] " << cases[k].name << "\n";
    results.push_back(run_case(cases[k], options));
    if (!results.back().skipped.empty()) {
      std::cerr << "  skipped: " << results.back().skipped << "\n";
    }
  }

  std::ostringstream report;
  report << "# Compatible triangulation benchmark\n\n";
  print_table(report, options, results);
  print_summary(report, options, results);
  std::cout << report.str();
  std::cout.flush();
  if (!options.json_path.empty()) write_json(options.json_path, options, results);
  if (!std::cout) throw Error("cannot write to standard output");
  return kExitSuccess;
}

}  // namespace
}  // namespace stickmorph

int main(int argc, char** argv) {
  try {
    return stickmorph::run(argc, argv);
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << "\n";
    return stickmorph::kExitUsage;
  }
}
