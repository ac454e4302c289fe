// Benchmark of scrubbing (issue 15): a figure triangulated once, then a
// stateful solver giving the frame at any time on demand, as an editor's
// timeline or the Blender add-on asks for it.
//
// Per (family, size), in a child process of its own (bench_child.h): the
// pair generated and validated, triangulated once (timed), then
//  - barycentric: a MorphSolver built once (timed) on that triangulation;
//    --frames frames played back in order (t = k / (N - 1)) and the same
//    number at seeded random times (a scrub back and forth), each frame
//    MorphSolver::solve(t) plus certificate_defect on its result (the
//    per-frame check morph_triangulation makes);
//  - rigid (the default method): prepare_rigid_morph once (timed: it
//    triangulates in the guide's enclosure again), then GuidedMorph::frame
//    (t, verify) at the same times, the certificate included, with each
//    playback's guide, solve and check milliseconds and factorizations
//    (JSON only);
//  - a fresh sparse LU factorize-and-solve of the barycentric system at
//    t = 0.5, for scale.
// Frames per second are frames over the playback's total wall time. Every
// frame's certificate is counted: a frame that fails it would be a bug.
//
// Not a test: it measures. One JSON object per line (--json FILE), a
// Markdown table on stdout, progress on stderr.
//
//   stickmorph_benchmark_scrub [--sizes 1000,10000,100000] [--families polyline,triangulation]
//       [--frames N] [--json FILE] [--time-limit S] [--memory-limit-mib M] [--no-rigid]
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "bench_child.h"
#include "bench_figures.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/frame_certificate.h"
#include "stickmorph/guided_morph.h"
#include "stickmorph/json.h"
#include "stickmorph/morph_solver.h"
#include "stickmorph/morph_stick_figures.h"

namespace stickmorph::bench {
namespace {

struct Options {
  std::vector<int> sizes = {1000, 10000, 100000};
  std::vector<std::string> families = {"polyline", "triangulation"};
  int frames = 240;
  std::string json_path;
  int time_limit_s = 900;
  long memory_limit_mib = 8192;
  bool rigid = true;
  bool help = false;
};

Options parse_arguments(int argc, char** argv) {
  Options options;
  CLI::App app{"scrubbing benchmark", "stickmorph_benchmark_scrub"};
  constexpr int kMost = std::numeric_limits<int>::max();
  app.add_option("--sizes", options.sizes, "requested vertex counts (default 1000,10000,100000)")
      ->delimiter(',')
      ->check(CLI::Range(3, kMost));
  app.add_option("--families", options.families, "families of bench_figures.h (default polyline,triangulation)")
      ->delimiter(',')
      ->check(CLI::IsMember(family_names()));
  app.add_option("--frames", options.frames, "frames per playback (default 240)")->check(CLI::Range(3, 100000));
  app.add_option("--json", options.json_path, "one JSON object per case to FILE");
  app.add_option("--time-limit", options.time_limit_s, "seconds per case (default 900)")->check(CLI::Range(1, kMost));
  app.add_option("--memory-limit-mib", options.memory_limit_mib, "address-space limit per case (default 8192)")
      ->check(CLI::Range(64L, long(kMost)));
  bool no_rigid = false;
  app.add_flag("--no-rigid", no_rigid, "measure the barycentric MorphSolver only");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    options.help = true;
  } catch (const CLI::ParseError& error) {
    throw InvalidArgumentError(std::string(error.what()) + " (see --help)");
  }
  options.rigid = !no_rigid;
  return options;
}

/// Flat JSON fields, one object.
class Fields {
 public:
  Fields& set(const std::string& key, const std::string& value) { return raw(key, quote_json_string(value)); }
  Fields& set(const std::string& key, double value) {
    return raw(key, std::isfinite(value) ? format_json_number(value) : std::string("null"));
  }
  Fields& set(const std::string& key, int value) { return raw(key, std::to_string(value)); }
  Fields& raw(const std::string& key, const std::string& json) {
    text_ += (text_.empty() ? "{" : ",") + quote_json_string(key) + ":" + json;
    return *this;
  }
  std::string str() const { return (text_.empty() ? "{" : text_) + "}"; }

 private:
  std::string text_;
};

/// The playback's times: in order, then a seeded scrub.
std::vector<double> in_order(int frames) {
  std::vector<double> t;
  for (int k = 0; k < frames; ++k) t.push_back(double(k) / (frames - 1));
  return t;
}
std::vector<double> scrubbed(int frames) {
  std::mt19937 rng(15);
  std::vector<double> t;
  for (int k = 0; k < frames; ++k) t.push_back(unit(rng));
  return t;
}

/// Plays `times` with `frame` (returns false when the frame fails its
/// certificate); records fps, mean and worst frame under `prefix`.
template <class Frame>
void play(Fields& fields, const std::string& prefix, const std::vector<double>& times, Frame frame) {
  int defects = 0;
  double worst = 0;
  const auto start = Clock::now();
  for (double t : times) {
    const auto begin = Clock::now();
    if (!frame(t)) ++defects;
    worst = std::max(worst, ms_since(begin));
  }
  const double total = ms_since(start);
  fields.set(prefix + "_fps", 1000.0 * double(times.size()) / total)
      .set(prefix + "_mean_ms", total / double(times.size()))
      .set(prefix + "_worst_ms", worst)
      .set(prefix + "_defects", defects);
}

std::string run_case(const std::string& family, int requested, int frames, bool rigid) {
  Fields fields;
  auto start = Clock::now();
  const RawPair raw = make_pair(family, requested);
  const StickFigure source = make_stick_figure(raw.source, raw.edges);
  const StickFigure target = make_stick_figure(raw.target, raw.edges);
  fields.set("n", int(source.vertices.size())).set("generate_ms", ms_since(start));

  start = Clock::now();
  const FigureTriangulation tri = triangulate_figures(source, target);
  fields.set("triangulate_ms", ms_since(start)).set("steiner", tri.steiner_vertices);
  fields.set("fresh_lu_ms", fresh_lu_ms(tri, 0.5, 1));

  start = Clock::now();
  MorphSolver solver(tri);
  require_figure_edges(tri, source);
  fields.set("solver_setup_ms", ms_since(start)).set("unknowns", solver.unknowns());
  const auto barycentric_frame = [&](double t) {
    return certificate_defect(tri, solver.solve(t)).empty();
  };
  play(fields, "barycentric_in_order", in_order(frames), barycentric_frame);
  const MorphSolverStats in_order_stats = solver.stats();
  play(fields, "barycentric_scrub", scrubbed(frames), barycentric_frame);
  fields.set("barycentric_factorizations_in_order", in_order_stats.factorizations)
      .set("barycentric_iterations_in_order", in_order_stats.iterations)
      .set("barycentric_factorizations_scrub", solver.stats().factorizations - in_order_stats.factorizations)
      .set("barycentric_iterations_scrub", solver.stats().iterations - in_order_stats.iterations);

  if (rigid) {
    start = Clock::now();
    MorphStickFiguresOptions options;
    GuidedMorph morph = prepare_rigid_morph(source, target, options);
    fields.set("rigid_setup_ms", ms_since(start));
    // GuidedMorph::frame throws VerificationError when no candidate passes.
    const auto rigid_frame = [&](double t) {
      morph.frame(t, -1, true, "benchmark: ");
      return true;
    };
    // Where a rigid frame's time goes (GuidedMorphStats, accumulated, so
    // each playback's share is a difference): the guide and its Steiner
    // solve, the blended solves and the exact checks, and the numeric
    // factorizations (issue 29: a scrub iterates on the kept one nearest
    // in time instead of factorizing after every jump).
    const auto rigid_stats = [&](const std::string& prefix, const GuidedMorphStats& before) {
      const GuidedMorphStats& after = morph.stats();
      fields.set(prefix + "_guide_ms", after.guide_ms - before.guide_ms)
          .set(prefix + "_solve_ms", after.solve_ms - before.solve_ms)
          .set(prefix + "_verify_ms", after.verify_ms - before.verify_ms)
          .set(prefix + "_factorizations", after.factorizations - before.factorizations);
    };
    GuidedMorphStats before = morph.stats();
    fields.set("rigid_setup_factorizations", before.factorizations);
    play(fields, "rigid_in_order", in_order(frames), rigid_frame);
    rigid_stats("rigid_in_order", before);
    before = morph.stats();
    play(fields, "rigid_scrub", scrubbed(frames), rigid_frame);
    rigid_stats("rigid_scrub", before);
  }
  return fields.str();
}

std::string field(const ChildResult& r, const std::string& key) {
  if (r.status != "ok") return r.status;
  try {
    const JsonValue value = parse_json(r.body);
    if (const JsonValue* item = value.find(key)) return to_json(*item);
  } catch (const JsonError&) {
    return "unreadable";
  }
  return "-";
}

int run(int argc, char** argv) {
  const Options options = parse_arguments(argc, argv);
  if (options.help) return 0;
  std::ofstream json;
  if (!options.json_path.empty()) {
    json.open(options.json_path);
    if (!json) throw Error("cannot write '" + options.json_path + "'");
  }
  std::cout << "# Scrubbing benchmark\n\n" << options.frames << " frames per playback.\n\n"
            << "| family | requested n | status | n | triangulate ms | fresh LU ms | barycentric fps (in order) | "
               "barycentric fps (scrub) | rigid fps (in order) | rigid fps (scrub) |\n"
               "|---|--:|---|--:|--:|--:|--:|--:|--:|--:|\n";
  const auto run_start = Clock::now();
  for (const std::string& family : options.families) {
    std::string stopped;
    for (int requested : options.sizes) {
      Fields record;
      record.set("family", family).set("requested_n", requested).set("frames", options.frames);
      std::cerr << "[" << int(ms_since(run_start) / 1000) << " s] " << family << " n~" << requested << ": "
                << std::flush;
      if (!stopped.empty()) {
        record.set("status", "not_run").set("reason", stopped);
        std::cerr << "not run (" << stopped << ")\n";
      } else {
        const ChildResult r = run_child([&] { return run_case(family, requested, options.frames, options.rigid); },
                                        options.time_limit_s, options.memory_limit_mib);
        record.set("status", r.status).set("wall_ms", r.wall_ms).set("peak_kib", int(r.peak_kib));
        if (r.status == "ok") {
          record.raw("result", r.body);
        } else {
          record.set("reason", r.body);
          if (r.status == "timeout" || r.status == "out_of_memory")
            stopped = std::string(r.status == "timeout" ? "timed out" : "out of memory") + " at n~" +
                      std::to_string(requested);
        }
        std::cerr << r.status << " in " << int(r.wall_ms) << " ms, peak " << r.peak_kib / 1024 << " MiB"
                  << (r.status == "ok" ? "" : ": " + r.body) << "\n";
        std::cout << "| " << family << " | " << requested << " | " << r.status << " | " << field(r, "n") << " | "
                  << field(r, "triangulate_ms") << " | " << field(r, "fresh_lu_ms") << " | "
                  << field(r, "barycentric_in_order_fps") << " | " << field(r, "barycentric_scrub_fps") << " | "
                  << field(r, "rigid_in_order_fps") << " | " << field(r, "rigid_scrub_fps") << " |\n"
                  << std::flush;
      }
      if (json) json << record.str() << "\n" << std::flush;
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
