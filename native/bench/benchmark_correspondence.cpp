// Benchmark of automatic correspondence (issue 13, figure_correspondence.h):
// the time correspond_figures takes to match two figures drawn separately,
// against their size, on five deterministic families:
//
//  - polygon: a star-shaped blob sampled at n points, target the same curve
//             sampled at 1.37 n other points, turned, scaled, renumbered (a
//             loop: the cyclic shift search);
//  - spiral:  an open polyline on an Archimedean spiral, target the same
//             spiral resampled at 0.8 n points, turned, renumbered;
//  - tree:    a random spanning tree of a grid (junctions of degree 3 and 4,
//             bends, ends) with every edge subdivided 0-2 times, target the
//             same tree subdivided otherwise, turned, renumbered;
//  - mesh:    a jittered k by k grid with one diagonal per cell: nearly every
//             vertex a junction, so the skeleton is the whole figure (the
//             worst case for the search), target a renumbered, turned copy;
//  - wheel:   a hub with k spokes and a rim with 2 vertices per arc, target
//             the same wheel with 3 per arc, turned by 0.3 of a spoke,
//             renumbered: k symmetric isomorphisms, all compared.
//
// Each case runs in a child process of its own (its peak memory is its own
// ru_maxrss, and a time or memory limit stops one case, not the run); the
// match is timed best of --repeat, the matched pair checked with is_valid
// and check_compatibility (untimed), and where the true partner of a source
// vertex is known (the tree's own vertices, every mesh vertex, the wheel's
// hub and spoke ends, the spiral's ends) the partner found is compared with
// it. stdout gets a Markdown table, the fitted growth exponent per family
// and whether the 1000-vertex pairs match in under a second (the issue's
// requirement); --json FILE writes everything for bench/make_benchmarks.py.
//
//   stickmorph_benchmark_correspondence [--sizes 10,30,100,300,1000,3000,10000]
//       [--families polygon,spiral,tree,mesh,wheel] [--repeat N] [--json FILE]
//       [--time-limit S] [--memory-limit-mib M]
#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <new>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench_child.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/io/json.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The requirement: "Matching a 1000-vertex pair takes under a second".
constexpr int kRequirementSize = 1000;
constexpr double kRequirementMs = 1000;
// Exponents are fitted over these sizes only, as in make_benchmarks.py.
constexpr int kFitMinN = 100;
// A match that takes longer than this is not repeated.
constexpr double kRepeatOnlyBelowMs = 10000;


using RawEdges = std::vector<std::array<std::int64_t, 2>>;

const std::vector<std::string>& family_names() {
  static const std::vector<std::string> names = {"polygon", "spiral", "tree", "mesh", "wheel"};
  return names;
}

constexpr const char* kUsage =
    "usage: stickmorph_benchmark_correspondence [--sizes 10,30,...] [--families LIST] [--repeat N]\n"
    "           [--json FILE] [--time-limit S] [--memory-limit-mib M]\n"
    "\n"
    "Times correspond_figures (automatic correspondence, issue 13) against size on\n"
    "deterministic pairs drawn separately, each case in a child process of its own.\n"
    "\n"
    "  --sizes LIST          requested source vertex counts (default 10,30,100,300,1000,3000,10000)\n"
    "  --families LIST       polygon,spiral,tree,mesh,wheel (default all)\n"
    "  --repeat N            time each match N times and keep the best (default 3; once\n"
    "                        only when one run takes over 10 s)\n"
    "  --json FILE           write the results as one JSON document to FILE\n"
    "  --time-limit S        seconds of wall time per case (default 300)\n"
    "  --memory-limit-mib M  address-space limit of every child (default 4096)\n";

struct Options {
  std::vector<int> sizes = {10, 30, 100, 300, 1000, 3000, 10000};
  std::vector<std::string> families = family_names();
  int repeat = 3;
  std::string json_path;
  int time_limit_s = 300;
  long memory_limit_mib = 4096;
  bool help = false;
};

Options parse_arguments(int argc, char** argv) {
  Options options;
  CLI::App app{"correspondence benchmark", "stickmorph_benchmark_correspondence"};
  app.set_help_flag("-h,--help");
  constexpr int kMost = std::numeric_limits<int>::max();
  app.add_option("--sizes", options.sizes)->delimiter(',')->check(CLI::Range(3, 10000000));
  app.add_option("--families", options.families)->delimiter(',')->check(CLI::IsMember(family_names()));
  app.add_option("--repeat", options.repeat)->check(CLI::Range(1, 1000));
  app.add_option("--json", options.json_path);
  app.add_option("--time-limit", options.time_limit_s)->check(CLI::Range(1, kMost));
  app.add_option("--memory-limit-mib", options.memory_limit_mib)->check(CLI::Range(64L, long(kMost)));
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
// A JSON object written field by field (one line).

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
  Record& raw(const std::string& key, const std::string& json) {
    text_ += (text_.empty() ? "{" : ",") + quote_json_string(key) + ":" + json;
    return *this;
  }
  std::string str() const { return (text_.empty() ? "{" : text_) + "}"; }

 private:
  std::string text_;
};

// ---------------------------------------------------------------------------
// The pairs. Seeded std::mt19937, its raw output turned into numbers by plain
// arithmetic (the standard distributions differ between libraries), so the
// corpus is the same on every machine.

double unit(std::mt19937& rng) { return double(rng()) / 4294967296.0; }

struct Pair {
  StickFigure source, target;
  /// (source vertex, target vertex) pairs the matching should find.
  std::vector<std::pair<int, int>> known;
};

std::vector<Vec2> similar(std::vector<Vec2> points, double angle, double scale, double dx, double dy) {
  const double c = scale * std::cos(angle), s = scale * std::sin(angle);
  for (Vec2& p : points) p = {c * p[0] - s * p[1] + dx, s * p[0] + c * p[1] + dy};
  return points;
}

/// The target's vertices renumbered and its edges shuffled and turned round
/// (a figure drawn separately agrees on nothing but the shape); `known`'s
/// target indices follow.
void renumber_target(std::vector<Vec2>& points, RawEdges& edges, std::vector<std::pair<int, int>>& known,
                     std::uint32_t seed) {
  std::mt19937 rng(seed);
  const std::size_t n = points.size();
  std::vector<std::int64_t> new_of_old(n);
  std::iota(new_of_old.begin(), new_of_old.end(), 0);
  for (std::size_t i = n; i > 1; --i) std::swap(new_of_old[i - 1], new_of_old[rng() % i]);
  std::vector<Vec2> moved(n);
  for (std::size_t v = 0; v < n; ++v) moved[std::size_t(new_of_old[v])] = points[v];
  points = std::move(moved);
  for (auto& e : edges) {
    e = {new_of_old[std::size_t(e[0])], new_of_old[std::size_t(e[1])]};
    if (rng() % 2) std::swap(e[0], e[1]);
  }
  for (std::size_t i = edges.size(); i > 1; --i) std::swap(edges[i - 1], edges[rng() % i]);
  for (auto& [s, t] : known) t = int(new_of_old[std::size_t(t)]);
}

Pair finish(std::vector<Vec2> source, const RawEdges& source_edges, std::vector<Vec2> target, RawEdges target_edges,
            std::vector<std::pair<int, int>> known, std::uint32_t seed) {
  renumber_target(target, target_edges, known, seed);
  Pair pair;
  pair.source = make_stick_figure(std::move(source), source_edges);
  pair.target = make_stick_figure(std::move(target), target_edges);
  pair.known = std::move(known);
  return pair;
}

/// A closed star-shaped curve (radius positive, angle increasing: every
/// sampling of it is a simple counter-clockwise polygon).
Vec2 blob(double angle) {
  const double r = 1 + 0.25 * std::sin(3 * angle) + 0.15 * std::cos(7 * angle + 1);
  return {r * std::cos(angle), r * std::sin(angle)};
}

Pair polygon_pair(int n) {
  const int nt = std::max(3, int(std::lround(1.37 * n)));
  std::vector<Vec2> s, t;
  RawEdges se, te;
  for (int i = 0; i < n; ++i) {
    s.push_back(blob(2 * kPi * i / n));
    se.push_back({i, (i + 1) % n});
  }
  for (int j = 0; j < nt; ++j) {
    t.push_back(blob(2 * kPi * (j + 0.5) / nt));
    te.push_back({j, (j + 1) % nt});
  }
  return finish(std::move(s), se, similar(std::move(t), 35 * kPi / 180, 2.0, 3, -1), std::move(te), {}, 11);
}

/// r = angle, from one turn out, with more turns for more points.
std::vector<Vec2> spiral(int count, double turns, double phase) {
  std::vector<Vec2> points;
  const double start = 2 * kPi, span = 2 * kPi * turns;
  for (int i = 0; i < count; ++i) {
    const double u = (i + (i == 0 || i == count - 1 ? 0.0 : phase)) / (count - 1);
    const double angle = start + span * u;
    points.push_back({angle * std::cos(angle), angle * std::sin(angle)});
  }
  return points;
}

Pair spiral_pair(int n) {
  const double turns = 1 + std::floor(std::sqrt(double(n)) / 4);
  const int nt = std::max(3, int(std::lround(0.8 * n)));
  std::vector<Vec2> s = spiral(n, turns, 0), t = spiral(nt, turns, 0.4);
  RawEdges se, te;
  for (int i = 0; i + 1 < n; ++i) se.push_back({i, i + 1});
  for (int j = 0; j + 1 < nt; ++j) te.push_back({j, j + 1});
  return finish(std::move(s), se, similar(std::move(t), -50 * kPi / 180, 0.5, 0, 0), std::move(te),
                {{0, 0}, {n - 1, nt - 1}}, 12);
}

/// The tree's edges with `counts[e]` extra vertices each, at seeded uneven
/// fractions; the tree's vertices keep their indices.
void subdivide(const std::vector<Vec2>& points, const std::vector<std::array<int, 2>>& tree, std::uint32_t seed,
               int most, std::vector<Vec2>& out, RawEdges& edges) {
  std::mt19937 rng(seed);
  out = points;
  for (const auto& [a, b] : tree) {
    const int k = int(rng() % std::uint32_t(most + 1));
    std::vector<double> gaps;
    double total = 0;
    for (int i = 0; i <= k; ++i) total += gaps.emplace_back(1 + 2 * unit(rng));
    std::int64_t previous = a;
    double run = 0;
    for (int i = 0; i < k; ++i) {
      const double f = (run += gaps[std::size_t(i)]) / total;
      out.push_back({points[std::size_t(a)][0] + f * (points[std::size_t(b)][0] - points[std::size_t(a)][0]),
                     points[std::size_t(a)][1] + f * (points[std::size_t(b)][1] - points[std::size_t(a)][1])});
      const std::int64_t v = std::int64_t(out.size()) - 1;
      edges.push_back({previous, v});
      previous = v;
    }
    edges.push_back({previous, b});
  }
}

Pair tree_pair(int n) {
  // About half the vertices are the grid's, half subdivision (1 per edge on
  // average).
  const int k = std::max(2, int(std::lround(std::sqrt(n / 2.0))));
  std::mt19937 rng(5000 + std::uint32_t(n));
  std::vector<Vec2> points;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) points.push_back({j + 0.2 * (unit(rng) - 0.5), i + 0.2 * (unit(rng) - 0.5)});
  std::vector<std::array<int, 2>> all, tree;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      if (j + 1 < k) all.push_back({i * k + j, i * k + j + 1});
      if (i + 1 < k) all.push_back({i * k + j, (i + 1) * k + j});
    }
  for (std::size_t i = all.size(); i > 1; --i) std::swap(all[i - 1], all[rng() % i]);
  std::vector<int> parent(std::size_t(k * k));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int v) {
    while (parent[std::size_t(v)] != v) v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
    return v;
  };
  for (const auto& [a, b] : all)
    if (root(a) != root(b)) {
      parent[std::size_t(root(a))] = root(b);
      tree.push_back({a, b});
    }
  std::vector<Vec2> s, t;
  RawEdges se, te;
  subdivide(points, tree, 1, 2, s, se);
  subdivide(points, tree, 2, 2, t, te);
  std::vector<std::pair<int, int>> known;
  for (int v = 0; v < k * k; ++v) known.emplace_back(v, v);
  return finish(std::move(s), se, similar(std::move(t), 25 * kPi / 180, 1.5, 0, 0), std::move(te), std::move(known),
                13);
}

Pair mesh_pair(int n) {
  const int k = std::max(2, int(std::lround(std::sqrt(double(n)))));
  std::mt19937 rng(6000 + std::uint32_t(n));
  std::vector<Vec2> points;
  RawEdges edges;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) points.push_back({j + 0.2 * (unit(rng) - 0.5), i + 0.2 * (unit(rng) - 0.5)});
  auto id = [k](int i, int j) { return std::int64_t(i) * k + j; };
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      if (j + 1 < k) edges.push_back({id(i, j), id(i, j + 1)});
      if (i + 1 < k) edges.push_back({id(i, j), id(i + 1, j)});
      if (i + 1 < k && j + 1 < k) edges.push_back({id(i, j), id(i + 1, j + 1)});
    }
  std::vector<std::pair<int, int>> known;
  for (int v = 0; v < k * k; ++v) known.emplace_back(v, v);
  return finish(points, edges, similar(points, 0.5, 1.0, 2, 2), edges, std::move(known), 14);
}

/// Hub 0, spoke ends 1..k on the unit circle, `per_arc` rim vertices between
/// consecutive spoke ends.
void wheel(int k, int per_arc, double turn, std::vector<Vec2>& points, RawEdges& edges) {
  points = {{0, 0}};
  for (int i = 0; i < k; ++i) {
    const double a = turn + 2 * kPi * i / k;
    points.push_back({std::cos(a), std::sin(a)});
    edges.push_back({0, i + 1});
  }
  for (int i = 0; i < k; ++i) {
    std::int64_t previous = i + 1;
    for (int r = 1; r <= per_arc; ++r) {
      const double a = turn + 2 * kPi * (i + double(r) / (per_arc + 1)) / k;
      points.push_back({std::cos(a), std::sin(a)});
      const std::int64_t v = std::int64_t(points.size()) - 1;
      edges.push_back({previous, v});
      previous = v;
    }
    edges.push_back({previous, (i + 1) % k + 1});
  }
}

Pair wheel_pair(int n) {
  const int k = std::max(3, (n - 1) / 3);
  std::vector<Vec2> s, t;
  RawEdges se, te;
  wheel(k, 2, 0, s, se);
  wheel(k, 3, 0.3 * 2 * kPi / k, t, te);
  std::vector<std::pair<int, int>> known;
  for (int v = 0; v <= k; ++v) known.emplace_back(v, v);
  return finish(std::move(s), se, similar(std::move(t), 0, 3.0, 1, 1), std::move(te), std::move(known), 15);
}

Pair make_pair(const std::string& family, int n) {
  if (family == "polygon") return polygon_pair(n);
  if (family == "spiral") return spiral_pair(n);
  if (family == "tree") return tree_pair(n);
  if (family == "mesh") return mesh_pair(n);
  if (family == "wheel") return wheel_pair(n);
  throw InvalidArgumentError("unknown family '" + family + "'");
}

// ---------------------------------------------------------------------------
// The measured work, run inside a child.

std::string run_case(const std::string& family, int requested, int repeat) {
  Record record;
  auto start = Clock::now();
  const Pair pair = make_pair(family, requested);
  record.set("generate_ms", ms_since(start));
  std::vector<double> runs;
  FigureCorrespondence c;
  for (int r = 0; r < repeat; ++r) {
    start = Clock::now();
    c = correspond_figures(pair.source, pair.target);
    runs.push_back(ms_since(start));
    // A match this slow is measured well enough once; repeating it would
    // only spend the time limit.
    if (runs.back() > kRepeatOnlyBelowMs) break;
  }
  std::string runs_json = "[";
  for (std::size_t r = 0; r < runs.size(); ++r) runs_json += (r ? "," : "") + format_json_number(runs[r]);
  runs_json += "]";
  start = Clock::now();
  const bool valid = is_valid(c, pair.source, pair.target) && check_compatibility(c.source, c.target).compatible();
  const double check_ms = ms_since(start);
  int correct = 0;
  for (const auto& [s, t] : pair.known)
    if (c.target_places[std::size_t(s)].vertex == t) ++correct;
  int source_dummies = 0, target_dummies = 0;
  for (const MatchedPlace& p : c.source_places) source_dummies += p.vertex < 0;
  for (const MatchedPlace& p : c.target_places) target_dummies += p.vertex < 0;
  record.set("n_source", int(pair.source.vertices.size()))
      .set("n_target", int(pair.target.vertices.size()))
      .set("m", int(c.source.vertices.size()))
      .set("source_dummies", source_dummies)
      .set("target_dummies", target_dummies)
      .set("nodes", c.skeleton_nodes)
      .set("chains", c.skeleton_chains)
      .set("candidates", c.candidates)
      .set("residual", c.residual)
      .set("rotation_deg", c.rotation_degrees)
      .set("ms", *std::min_element(runs.begin(), runs.end()))
      .raw("runs_ms", runs_json)
      .set("runs", int(runs.size()))
      .set("engine_ms", c.milliseconds)
      .set("valid", valid)
      .set("check_ms", check_ms)
      .set("known_partners", int(pair.known.size()))
      .set("correct_partners", correct);
  return record.str();
}


// ---------------------------------------------------------------------------
// The report

struct Case {
  std::string family;
  int requested = 0;
  ChildResult child;
  JsonValue result;  ///< the child's fields when ok
  std::string not_run;

  bool ok() const { return child.status == "ok" && result.is_object(); }
  double number(const std::string& key) const {
    if (!result.is_object()) return std::nan("");
    const JsonValue* v = result.find(key);
    return v && v->is_number() ? v->as_number() : std::nan("");
  }
  int integer(const std::string& key) const {
    const double v = number(key);
    return std::isfinite(v) ? int(std::lround(v)) : -1;
  }
};

/// Least-squares slope of log ms against log n_source over the requested
/// sizes >= kFitMinN (a generated n may fall just short of the requested);
/// NaN with fewer than three sizes.
std::pair<double, int> fit_exponent(const std::vector<const Case*>& cases) {
  std::vector<std::pair<double, double>> used;
  for (const Case* c : cases) {
    const double n = c->number("n_source"), ms = c->number("ms");
    if (c->ok() && c->requested >= kFitMinN && ms > 0) used.emplace_back(std::log(n), std::log(ms));
  }
  if (used.size() < 3) return {std::nan(""), int(used.size())};
  double mx = 0, my = 0;
  for (const auto& [x, y] : used) mx += x / double(used.size()), my += y / double(used.size());
  double sxx = 0, sxy = 0;
  for (const auto& [x, y] : used) sxx += (x - mx) * (x - mx), sxy += (x - mx) * (y - my);
  return {sxy / sxx, int(used.size())};
}

std::string fixed(double value, int digits) {
  if (!std::isfinite(value)) return "-";
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

std::string ms_text(double ms) { return fixed(ms, ms >= 100 ? 0 : ms >= 1 ? 1 : 3); }

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
  std::vector<Case> cases;
  const int total = int(options.families.size() * options.sizes.size());
  const auto run_start = Clock::now();
  for (const std::string& family : options.families) {
    std::string stopped;  // once a case hit a limit, larger ones would too
    for (int requested : options.sizes) {
      Case c;
      c.family = family;
      c.requested = requested;
      std::cerr << "[" << cases.size() + 1 << "/" << total << ", " << int(ms_since(run_start) / 1000) << " s] "
                << family << " n~" << requested << ": " << std::flush;
      if (!stopped.empty()) {
        c.not_run = stopped;
        std::cerr << "not run (" << stopped << ")\n";
        cases.push_back(std::move(c));
        continue;
      }
      c.child = run_child([&] { return run_case(family, requested, options.repeat); }, options.time_limit_s,
                          options.memory_limit_mib);
      if (c.child.status == "ok") {
        try {
          c.result = parse_json(c.child.body);
        } catch (const JsonError& error) {
          c.child.status = "failed";
          c.child.body = std::string("unreadable child output: ") + error.what();
        }
      } else if (c.child.status == "timeout" || c.child.status == "out_of_memory") {
        stopped = std::string(c.child.status == "timeout" ? "timed out" : "out of memory") + " at n~" +
                  std::to_string(requested);
      }
      std::cerr << c.child.status << " in " << int(c.child.wall_ms) << " ms, peak " << c.child.peak_kib / 1024
                << " MiB" << (c.child.status == "ok" ? "" : ": " + c.child.body) << "\n";
      cases.push_back(std::move(c));
    }
  }

  // The table.
  std::cout << "# Correspondence benchmark\n\n"
            << "correspond_figures on pairs drawn separately; milliseconds are the best of " << options.repeat
            << " runs (one where a run takes over 10 s) in a child process per case. `valid`: is_valid and check_compatibility of the matched "
               "pair; `partners`: source vertices whose true partner is known, found / known.\n\n"
            << "| family | requested n | status | n_source | n_target | m | nodes | chains | candidates | ms | "
               "peak MiB | valid | partners |\n|---|--:|---|--:|--:|--:|--:|--:|--:|--:|--:|---|--:|\n";
  auto row = [](const std::vector<std::string>& cells) {
    std::string line = "|";
    for (const std::string& cell : cells) line += " " + cell + " |";
    return line + "\n";
  };
  for (const Case& c : cases) {
    std::vector<std::string> cells = {c.family, std::to_string(c.requested)};
    if (!c.ok()) {
      cells.push_back(!c.not_run.empty() ? "not run: " + c.not_run : c.child.status + ": " + c.child.body.substr(0, 80));
      cells.resize(13, "");
      std::cout << row(cells);
      continue;
    }
    const int known = c.integer("known_partners");
    const JsonValue* valid = c.result.find("valid");
    cells.insert(cells.end(), {"ok", std::to_string(c.integer("n_source")), std::to_string(c.integer("n_target")),
                               std::to_string(c.integer("m")), std::to_string(c.integer("nodes")),
                               std::to_string(c.integer("chains")), std::to_string(c.integer("candidates")),
                               ms_text(c.number("ms")) + (c.integer("runs") == 1 && options.repeat > 1 ? " (1 run)" : ""),
                               std::to_string(c.child.peak_kib / 1024),
                               valid && valid->is_bool() && valid->as_bool() ? "yes" : "NO",
                               known ? std::to_string(c.integer("correct_partners")) + "/" + std::to_string(known)
                                     : std::string("-")});
    std::cout << row(cells);
  }

  // Growth per family.
  std::cout << "\nFitted growth exponent of the time against n_source (least squares on log-log, requested n >= "
            << kFitMinN << "; in brackets the sizes used):\n\n| family | exponent |\n|---|--:|\n";
  std::string exponents_json = "{";
  for (const std::string& family : options.families) {
    std::vector<const Case*> mine;
    for (const Case& c : cases)
      if (c.family == family) mine.push_back(&c);
    const auto [slope, count] = fit_exponent(mine);
    std::cout << "| " << family << " | " << (std::isfinite(slope) ? fixed(slope, 2) : "n/a") << " (" << count
              << ") |\n";
    exponents_json += (exponents_json.size() > 1 ? "," : "") + quote_json_string(family) + ":" +
                      Record().set("exponent", slope).set("sizes", count).str();
  }
  exponents_json += "}";

  // The requirement.
  const Case* worst = nullptr;
  int at_size = 0, failed_at_size = 0;
  for (const Case& c : cases) {
    if (c.requested != kRequirementSize) continue;
    ++at_size;
    if (!c.ok()) {
      ++failed_at_size;
      continue;
    }
    if (!worst || c.number("ms") > worst->number("ms")) worst = &c;
  }
  Record requirement;
  requirement.set("requested_n", kRequirementSize).set("limit_ms", kRequirementMs).set("cases", at_size);
  std::cout << "\n";
  if (at_size == 0) {
    std::cout << "Requirement (\"matching a 1000-vertex pair takes under a second\"): not measured (no size "
              << kRequirementSize << " in --sizes).\n";
    requirement.raw("pass", "null");
  } else {
    const bool pass = failed_at_size == 0 && worst && worst->number("ms") < kRequirementMs;
    std::cout << "Requirement (\"matching a 1000-vertex pair takes under a second\"): " << (pass ? "MET" : "NOT MET")
              << ": ";
    if (worst)
      std::cout << "the slowest of the " << at_size << " cases at n~" << kRequirementSize << " is " << worst->family
                << " with " << ms_text(worst->number("ms")) << " ms";
    if (failed_at_size) std::cout << (worst ? "; " : "") << failed_at_size << " did not finish";
    std::cout << ".\n";
    requirement.set("pass", pass);
    if (worst) requirement.set("worst_family", worst->family).set("worst_ms", worst->number("ms"));
    requirement.set("unfinished", failed_at_size);
  }
  std::cerr << "done in " << int(ms_since(run_start) / 1000) << " s\n";

  if (json.is_open()) {
    std::string sizes = "[", families = "[";
    for (std::size_t i = 0; i < options.sizes.size(); ++i) sizes += (i ? "," : "") + std::to_string(options.sizes[i]);
    for (std::size_t i = 0; i < options.families.size(); ++i)
      families += (i ? "," : "") + quote_json_string(options.families[i]);
    std::string command;
    for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
    json << "{\"program\":\"stickmorph_benchmark_correspondence\",\"command\":" << quote_json_string(command)
         << ",\"repeat\":" << options.repeat
         << ",\"time_limit_s\":" << options.time_limit_s << ",\"memory_limit_mib\":" << options.memory_limit_mib
         << ",\"fit_min_n\":" << kFitMinN << ",\"sizes\":" << sizes << "],\"families\":" << families
         << "],\n\"cases\":[";
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const Case& c = cases[i];
      Record record;
      record.set("family", c.family).set("requested_n", c.requested);
      if (!c.not_run.empty()) {
        record.set("status", "not_run").set("reason", c.not_run);
      } else {
        record.set("status", c.child.status).set("wall_ms", c.child.wall_ms).set("peak_kib", c.child.peak_kib);
        if (c.ok())
          record.raw("result", c.child.body);
        else
          record.set("reason", c.child.body);
      }
      json << (i ? ",\n" : "\n") << record.str();
    }
    json << "\n],\n\"exponents\":" << exponents_json << ",\n\"requirement\":" << requirement.str() << "}\n";
    if (!json.good()) throw Error("writing '" + options.json_path + "' failed");
  }
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
