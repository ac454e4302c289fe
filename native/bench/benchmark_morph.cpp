// Benchmark of whole stick-figure morphs (Algorithm 3 + Floater-Gotsman)
// against size, on the corpus of bench_figures.h: Steiner vertices per
// method, time per stage, time per frame, peak memory, and the straight-line
// morph's self-intersecting frames next to ours.
//
// Not a test: it measures. Every (case, method) runs in a child process of
// its own, so that its peak resident memory (ru_maxrss from wait4) is its
// own, a crash or an exhausted memory limit costs one cell and not the run,
// and a time limit can stop it. Each result is one JSON object per line
// (--json FILE); stdout gets a short Markdown summary per case and stderr the
// progress.
//
// The paper's spiderwebs (aronov, sg2001) grow quadratically on long thin
// faces, so they are only run up to --aronov-max / --sg2001-max vertices.
// No method is run in a family past the first size at which it hit the time
// or memory limit. Every cell not run says why in its record.
//
//   stickmorph_benchmark_morph [--sizes 10,100,1000] [--families LIST] [--frames N]
//       [--json FILE] [--aronov-max N] [--sg2001-max N] [--time-limit S]
//       [--spiderweb-time-limit S] [--memory-limit-mib M]
#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <iostream>
#include <map>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "bench_figures.h"
#include "bench_child.h"
#include "stickmorph/argument_limits.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/frame_certificate.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/guided_morph.h"
#include "stickmorph/json.h"
#include "stickmorph/morph.h"
#include "stickmorph/morph_solver.h"
#include "stickmorph/morph_stick_figures.h"

namespace stickmorph::bench {
namespace {


constexpr const char* kUsage =
    "usage: stickmorph_benchmark_morph [--sizes 10,30,100,...] [--families LIST] [--frames N]\n"
    "           [--json FILE] [--aronov-max N] [--sg2001-max N] [--time-limit S]\n"
    "           [--spiderweb-time-limit S] [--memory-limit-mib M]\n"
    "\n"
    "Morphs a deterministic corpus of compatible stick-figure pairs and measures\n"
    "each case in a child process of its own.\n"
    "\n"
    "  --sizes LIST             requested vertex counts (default 10,30,100,300,1000,3000,10000)\n"
    "  --families LIST          polyline,spiral,polygon,tree,triangulation,thinned,rings (default all)\n"
    "  --frames N               frames per morph (default 50)\n"
    "  --json FILE              write one JSON object per (case, method) to FILE\n"
    "  --aronov-max N           run aronov only up to N requested vertices (default 300)\n"
    "  --sg2001-max N           run sg2001 only up to N requested vertices (default 1000)\n"
    "  --time-limit S           seconds of wall time for an improved case (default 150)\n"
    "  --spiderweb-time-limit S seconds for an aronov or sg2001 case (default 60)\n"
    "  --memory-limit-mib M     address-space limit of every child (default 4096)\n"
    "  --repeat K               run each improved case of at most --repeat-max-n requested\n"
    "                           vertices K times, each in its own child, and keep the run\n"
    "                           of median total time (triangulate + morph; default 1)\n"
    "  --repeat-max-n N         (default 1000)\n";

struct Options {
  std::vector<int> sizes = {10, 30, 100, 300, 1000, 3000, 10000};
  std::vector<std::string> families = family_names();
  int frames = 50;
  std::string json_path;
  int aronov_max = 300;
  int sg2001_max = 1000;
  int time_limit_s = 150;
  int spiderweb_time_limit_s = 60;
  long memory_limit_mib = 4096;
  int repeat = 1;          ///< runs of each improved case up to repeat_max_n
  int repeat_max_n = 1000;
  bool help = false;
};

// CLI11 parses and range-checks; the help is kUsage, and a mistake is one
// InvalidArgumentError line like every other failure of this program.
Options parse_arguments(int argc, char** argv) {
  Options options;
  CLI::App app{"morph benchmark", "stickmorph_benchmark_morph"};
  app.set_help_flag("-h,--help");
  constexpr int kMost = std::numeric_limits<int>::max();
  app.add_option("--sizes", options.sizes)->delimiter(',')->check(CLI::Range(3, kMost));
  app.add_option("--families", options.families)->delimiter(',')->check(CLI::IsMember(family_names()));
  app.add_option("--frames", options.frames)->check(CLI::Range(kMinMorphFrames, kMaxMorphFrames));
  app.add_option("--json", options.json_path);
  app.add_option("--aronov-max", options.aronov_max)->check(CLI::Range(0, kMost));
  app.add_option("--sg2001-max", options.sg2001_max)->check(CLI::Range(0, kMost));
  app.add_option("--time-limit", options.time_limit_s)->check(CLI::Range(1, kMost));
  app.add_option("--spiderweb-time-limit", options.spiderweb_time_limit_s)->check(CLI::Range(1, kMost));
  app.add_option("--memory-limit-mib", options.memory_limit_mib)->check(CLI::Range(64L, long(kMost)));
  app.add_option("--repeat", options.repeat)->check(CLI::Range(1, 99));
  app.add_option("--repeat-max-n", options.repeat_max_n)->check(CLI::Range(0, kMost));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    options.help = true;
  } catch (const CLI::ParseError& error) {
    throw InvalidArgumentError(std::string(error.what()) + " (see --help)");
  }
  return options;
}

// ---------------------------------------------------------------------------
// A JSON object written field by field (one line, flat values).

class Record {
 public:
  Record& set(const std::string& key, const std::string& value) { return raw(key, quote_json_string(value)); }
  Record& set(const std::string& key, const char* value) { return set(key, std::string(value)); }
  Record& set(const std::string& key, double value) {
    return raw(key, std::isfinite(value) ? format_json_number(value) : std::string("null"));
  }
  Record& set(const std::string& key, int value) { return raw(key, std::to_string(value)); }
  Record& set(const std::string& key, long value) { return raw(key, std::to_string(value)); }
  Record& set(const std::string& key, bool value) { return raw(key, value ? "true" : "false"); }
  /// A field whose value is already JSON text.
  Record& raw(const std::string& key, const std::string& json) {
    text_ += (text_.empty() ? "{" : ",") + quote_json_string(key) + ":" + json;
    return *this;
  }
  std::string str() const { return (text_.empty() ? "{" : text_) + "}"; }

 private:
  std::string text_;
};

// ---------------------------------------------------------------------------
// The measured work, run inside a child.

/// Generation and validation, shared by every method's child.
struct Figures {
  StickFigure source, target;
  double twist = 0;
  double generate_ms = 0;
  double validate_ms = 0;  ///< make_stick_figure of both (exact planarity checks)
};

Figures make_figures(const std::string& family, int requested) {
  Figures figures;
  auto start = Clock::now();
  RawPair raw = make_pair(family, requested);
  figures.generate_ms = ms_since(start);
  figures.twist = raw.twist;
  start = Clock::now();
  figures.source = make_stick_figure(raw.source, raw.edges);
  figures.target = make_stick_figure(raw.target, raw.edges);
  figures.validate_ms = ms_since(start);
  return figures;
}

void add_triangulation_stats(Record& record, double total_ms, const FigureTriangulationStats& stats,
                             const FigureTriangulation& tri) {
  record.set("steiner", tri.steiner_vertices)
      .set("triangles", int(tri.triangles.size()))
      .set("interior_faces", stats.interior_faces)
      .set("cut_bends", stats.cut_bends)
      .set("interior_steiner", stats.interior_steiner)
      .set("min_angle_deg", stats.min_angle * 180 / kPi)
      .set("triangulate_ms", total_ms)
      .set("decompose_ms", stats.decompose_ms)
      .set("cut_ms", stats.cut_ms)
      .set("interior_faces_ms", stats.interior_faces_ms)
      .set("exterior_face_ms", stats.exterior_face_ms)
      .set("verify_triangulation_ms", stats.verify_ms);
}

/// aronov or sg2001: the compatible triangulation alone.
std::string run_spiderweb(const std::string& family, int requested, SteinerMethod method) {
  Record record;
  const Figures figures = make_figures(family, requested);
  record.set("n", int(figures.source.vertices.size())).set("edges", int(figures.source.edges.size()));
  FigureTriangulationOptions options;
  options.method = method;
  FigureTriangulationStats stats;
  const auto start = Clock::now();
  const FigureTriangulation tri = triangulate_figures(figures.source, figures.target, options, &stats);
  add_triangulation_stats(record, ms_since(start), stats, tri);
  return record.str();
}

/// Issue 15: what a frame costs as the product makes it, against a fresh
/// sparse LU factorize-and-solve of the same system (fresh_lu_ms, at t =
/// 0.5), all in this child. Barycentric: a new MorphSolver on the
/// barycentric method's triangulation solving the morph's interior times
/// f / (N - 1) in order, each solve followed by certificate_defect on its
/// result (what morph_triangulation does per frame). Rigid (the default):
/// prepare_rigid_morph, then GuidedMorph::frame(t, verify) at the same
/// times (the certificate included), against the fresh LU of the
/// barycentric system on the rigid triangulation's connectivity, the
/// pattern of its blended system. Mean (amortised: the first interior
/// frame factorizes, as in a morph) and median per interior frame, and for
/// the barycentric solver the mean without its one-time set-up.
void add_frame_costs(Record& record, const Figures& figures, int frames, const FigureTriangulation& barycentric_tri,
                     const FigureTriangulation& rigid_tri) {
  std::vector<double> times;
  for (int f = 1; f + 1 < frames; ++f) times.push_back(double(f) / (frames - 1));
  {
    const double lu = fresh_lu_ms(barycentric_tri, 0.5);
    MorphSolver solver(barycentric_tri);
    std::vector<double> frame_ms;
    double solve_ms = 0, certificate_ms = 0;
    double setup_ms = 0;  // the first solve's moment space (MorphSolverStats::factorize_ms then)
    int defects = 0;
    for (double t : times) {
      auto start = Clock::now();
      const std::vector<Vec2> positions = solver.solve(t);
      const double solved = ms_since(start);
      if (t == times.front()) setup_ms = solver.stats().factorize_ms;
      start = Clock::now();
      if (!certificate_defect(barycentric_tri, positions).empty()) ++defects;
      const double certified = ms_since(start);
      solve_ms += solved;
      certificate_ms += certified;
      frame_ms.push_back(solved + certified);
    }
    const double count = std::max<double>(1, double(times.size()));
    const double mean = (solve_ms + certificate_ms) / count;
    // The same frames without the solver's one-time set-up (the moment
    // space of the first solve: three factorizations and their moments),
    // what a frame costs once the stateful solver exists (scrubbing, a
    // long playback); later factorizations stay in.
    const double after_setup = (solve_ms + certificate_ms - setup_ms) / count;
    record.set("fresh_lu_ms", lu)
        .set("frame_mean_ms", mean)
        .set("frame_median_ms", median_of(frame_ms))
        .set("frame_solve_ms", solve_ms / count)
        .set("frame_certificate_ms", certificate_ms / count)
        .set("frame_lu_ratio", lu > 0 ? mean / lu : std::nan(""))
        .set("frame_setup_ms", setup_ms)
        .set("frame_after_setup_ms", after_setup)
        .set("frame_after_setup_lu_ratio", lu > 0 ? after_setup / lu : std::nan(""))
        .set("frame_factorizations", solver.stats().factorizations)
        .set("frame_iterations", solver.stats().iterations)
        .set("frame_certificate_defects", defects)
        .set("frame_unknowns", solver.unknowns());
  }
  {
    const double lu = fresh_lu_ms(rigid_tri, 0.5);
    MorphStickFiguresOptions options;
    options.frames = frames;
    GuidedMorph morph = prepare_rigid_morph(figures.source, figures.target, options);
    std::vector<double> frame_ms;
    for (double t : times) {
      const auto start = Clock::now();
      morph.frame(t, -1, true, "benchmark: ");
      frame_ms.push_back(ms_since(start));
    }
    double total = 0;
    for (double ms : frame_ms) total += ms;
    const double mean = total / std::max<double>(1, double(times.size()));
    record.set("rigid_fresh_lu_ms", lu)
        .set("rigid_frame_mean_ms", mean)
        .set("rigid_frame_median_ms", median_of(frame_ms))
        .set("rigid_frame_lu_ratio", lu > 0 ? mean / lu : std::nan(""));
  }
}

/// improved: the whole pipeline (the default, rigid method), then our frames
/// re-checked one by one, the barycentric morph timed and the straight-line
/// morph's frames counted.
std::string run_improved(const std::string& family, int requested, int frames) {
  Record record;
  const Figures figures = make_figures(family, requested);
  const StickFigure& source = figures.source;
  const int n = int(source.vertices.size());
  record.set("n", n).set("edges", int(source.edges.size())).set("twist", figures.twist);
  record.set("generate_ms", figures.generate_ms).set("validate_ms", figures.validate_ms);

  // The engine's one entry, as the CLI and the module run it.
  MorphStickFiguresOptions options;
  options.frames = frames;
  const MorphStickFiguresResult morph = morph_stick_figures(source, figures.target, options);
  const FigureTriangulation& tri = *morph.triangulation;
  add_triangulation_stats(record, morph.stats.triangulate_ms, morph.stats.triangulation, tri);
  record.set("morph_ms", morph.stats.morph_ms)
      .set("frames", frames)
      .set("morph_setup_ms", morph.stats.factorize_ms)
      .set("solve_ms", morph.stats.solve_ms)
      .set("verify_frames_ms", morph.stats.verify_ms)
      .set("factorizations", morph.stats.factorizations)
      .set("refined_frames", morph.stats.refined_frames);

  // The morph refuses a frame that fails its exact check, so a result means
  // every frame passed; count again with the public check, independently of
  // the morph's own bookkeeping.
  const Decomposition decomposition = decompose(source);
  int invalid = 0;
  for (const std::vector<Vec2>& frame : morph.frames)
    if (!is_frame_valid(source, decomposition, frame)) ++invalid;
  record.set("invalid_frames", invalid);

  // The paper's morph (method barycentric, on its own triangulation), for
  // the cost per frame of the rigid default against it (issue 12).
  MorphStickFiguresOptions paper;
  paper.method = MorphMethod::Barycentric;
  paper.frames = frames;
  const MorphStickFiguresResult barycentric = morph_stick_figures(source, figures.target, paper);
  record.set("barycentric_morph_ms", barycentric.stats.morph_ms)
      .set("barycentric_steiner", barycentric.stats.steiner_vertices);
  record.set("guide_exact_frames", morph.stats.guide_exact_frames)
      .set("guide_blended_frames", morph.stats.guide_blended_frames);

  MorphStickFiguresOptions straight;
  straight.method = MorphMethod::Linear;
  straight.frames = frames;
  const std::vector<int> linear_invalid = morph_stick_figures(source, figures.target, straight).stats.invalid_frames;
  record.set("linear_invalid_frames", int(linear_invalid.size()));
  record.set("linear_first_invalid", linear_invalid.empty() ? -1 : linear_invalid.front());
  add_frame_costs(record, figures, frames, *barycentric.triangulation, tri);
  return record.str();
}


const char* method_key(SteinerMethod method) {
  return method == SteinerMethod::Aronov ? "aronov" : method == SteinerMethod::Sg2001 ? "sg2001" : "improved";
}

std::string cell(const ChildResult& r, const std::string& key) {
  if (r.status != "ok") return r.status;
  try {
    const JsonValue value = parse_json(r.body);
    if (const JsonValue* item = value.find(key)) return to_json(*item);
  } catch (const JsonError&) {
    // The child's text is this program's own output; unreadable text would
    // be a bug here, shown in the table rather than hidden.
    return "unreadable";
  }
  return "-";
}

// triangulate_ms + morph_ms of a successful improved run (0 for a
// spiderweb-only run, which has no morph: its runs are never repeated).
double total_ms(const ChildResult& r) {
  const JsonValue value = parse_json(r.body);
  const JsonValue* triangulate = value.find("triangulate_ms");
  const JsonValue* morph = value.find("morph_ms");
  return triangulate && morph ? triangulate->as_number() + morph->as_number() : 0.0;
}

int run(int argc, char** argv) {
  const Options options = parse_arguments(argc, argv);
  if (options.help) {
    std::cout << kUsage;
    return 0;
  }
  std::ofstream json;
  if (!options.json_path.empty()) {
    json.open(options.json_path);
    if (!json) throw Error("cannot write '" + options.json_path + "'");
  }
  std::cout << "# Morph benchmark\n\n" << options.frames << " frames per morph.\n\n"
            << "| family | requested n | method | status | n | Steiner | triangulate ms | morph ms | peak MiB | "
               "linear invalid frames |\n|---|--:|---|---|--:|--:|--:|--:|--:|--:|\n";
  const SteinerMethod methods[3] = {SteinerMethod::Improved, SteinerMethod::Sg2001, SteinerMethod::Aronov};
  const int total = int(options.families.size() * options.sizes.size());
  int done = 0;
  const auto run_start = Clock::now();
  for (const std::string& family : options.families) {
    // Why a method is no longer run in this family, once it has hit the time
    // or memory limit: larger cases would only hit it again.
    std::map<SteinerMethod, std::string> stopped;
    for (int requested : options.sizes) {
      ++done;
      for (SteinerMethod method : methods) {
        const std::string name = method_key(method);
        Record record;
        record.set("family", family).set("requested_n", requested).set("method", name);
        std::string not_run;
        const int cap = method == SteinerMethod::Aronov ? options.aronov_max
                        : method == SteinerMethod::Sg2001 ? options.sg2001_max
                                                          : -1;
        if (stopped.count(method)) {
          not_run = stopped[method];
        } else if (cap >= 0 && requested > cap) {
          // Why the cap exists is said once in the report, not in every cell.
          not_run = "n > " + std::to_string(cap) + " (size cap)";
        }
        std::cerr << "[" << done << "/" << total << ", " << int(ms_since(run_start) / 1000) << " s] " << family
                  << " n~" << requested << " " << name << ": " << std::flush;
        if (!not_run.empty()) {
          record.set("status", "not_run").set("reason", not_run);
          std::cerr << "not run (" << not_run << ")\n";
        } else {
          const bool improved = method == SteinerMethod::Improved;
          // A small case takes milliseconds, where one run is at the mercy of
          // whatever else the machine does for them (a fit over 100 to 1000
          // vertices moved by 0.1 between runs): with --repeat, the run of
          // median total time is kept, the others' totals listed. A run that
          // does not succeed is reported as it is.
          const int runs = improved && requested <= options.repeat_max_n ? options.repeat : 1;
          std::vector<std::pair<double, ChildResult>> succeeded;
          ChildResult r;
          for (int k = 0; k < runs; ++k) {
            r = run_child([&] { return improved ? run_improved(family, requested, options.frames)
                                                : run_spiderweb(family, requested, method); },
                          improved ? options.time_limit_s : options.spiderweb_time_limit_s,
                          options.memory_limit_mib);
            if (r.status != "ok") break;
            succeeded.push_back({total_ms(r), r});
          }
          if (r.status == "ok" && runs > 1) {
            std::stable_sort(succeeded.begin(), succeeded.end(),
                             [](const auto& a, const auto& b) { return a.first < b.first; });
            r = succeeded[succeeded.size() / 2].second;
            std::string totals;
            for (const auto& entry : succeeded)
              totals += (totals.empty() ? "" : ",") + std::to_string(entry.first);
            record.set("repeats", runs).raw("total_ms_runs", "[" + totals + "]");
          }
          record.set("status", r.status).set("wall_ms", r.wall_ms).set("peak_kib", r.peak_kib);
          if (r.status == "ok") {
            record.raw("result", r.body);
          } else {
            record.set("reason", r.body);
            if (r.status == "timeout" || r.status == "out_of_memory")
              stopped[method] = std::string(r.status == "timeout" ? "timed out" : "out of memory") + " at n~" +
                                std::to_string(requested);
          }
          std::cerr << r.status << " in " << int(r.wall_ms) << " ms, peak " << r.peak_kib / 1024 << " MiB"
                    << (r.status == "ok" ? "" : ": " + r.body) << "\n";
          std::cout << "| " << family << " | " << requested << " | " << name << " | " << r.status << " | "
                    << cell(r, "n") << " | " << cell(r, "steiner") << " | " << cell(r, "triangulate_ms") << " | "
                    << cell(r, "morph_ms") << " | " << r.peak_kib / 1024 << " | "
                    << cell(r, "linear_invalid_frames") << " |\n"
                    << std::flush;
        }
        if (json) json << record.str() << "\n" << std::flush;
      }
    }
  }
  std::cerr << "done in " << int(ms_since(run_start) / 1000) << " s\n";
  if (json && !json.good()) throw Error("writing '" + options.json_path + "' failed");
  return 0;
}

}  // namespace
}  // namespace stickmorph::bench

int main(int argc, char** argv) {
  try {
    return stickmorph::bench::run(argc, argv);
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << "\n";
    return 2;
  }
}
