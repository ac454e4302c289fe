// Golden Steiner counts: the numbers the README reports, pinned.
//
// Steiner counts are the paper's measure of a compatible triangulation
// (Surazhsky & Gotsman, "Morphing Stick Figures Using Optimized Compatible
// Triangulations", Figure 7 and section 5). Every other test only checks
// that a triangulation is valid, so a change that made `improved` keep twice
// as many Steiner vertices would pass them all. This test recomputes
//  - per polygon pair of tests/data/polygon_pairs and per method, the
//    section 4 triangulation's Steiner count (as stickmorph_benchmark
//    measures it), and the corpus totals;
//  - per figure pair (the paper's S -> U) and per method, the Steiner count
//    of the whole figure pipeline (triangulate_figures, default options,
//    as `stickmorph triangulate` reports it);
// and compares them exactly with tests/data/golden/steiner_counts.json.
//
// An intended change is one command: scripts/update_golden.sh (or
// STICKMORPH_UPDATE_GOLDEN=1 build/stickmorph_tests "[golden]") rewrites the
// file from the current engine; review and commit the diff.
#include "catch.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/figure_io.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/json.h"

using namespace stickmorph;

namespace {

namespace fs = std::filesystem;

const fs::path kData = STICKMORPH_TEST_DATA;
const fs::path kGoldenFile = kData / "golden" / "steiner_counts.json";
const char* const kRegenerate =
    "if the change is intended, regenerate with scripts/update_golden.sh and commit the diff";

const SteinerMethod kMethods[] = {SteinerMethod::Aronov, SteinerMethod::Sg2001, SteinerMethod::Improved};

// The figure pairs run through the whole pipeline: name, then paths relative
// to tests/data. The README quotes S -> U's counts.
struct FigurePairInput {
  const char* name;
  const char* source;
  const char* target;
};
const FigurePairInput kFigurePairs[] = {
    {"s_to_u", "paper/s_to_u.source.json", "paper/s_to_u.target.json"},
};

using MethodCounts = std::map<std::string, long long>;  // method name -> Steiner vertices

struct PolygonPairCounts {
  std::string name;
  long long corners = 0;
  MethodCounts steiner;
};

struct Counts {
  std::vector<PolygonPairCounts> polygon_pairs;  // sorted by name
  std::map<std::string, MethodCounts> figure_pairs;
};

// The polygon pair of two compatible single-polygon figures, as
// stickmorph_benchmark builds it: Algorithm 1's one interior sequence lists
// the corners counter-clockwise, and by compatibility the same order is the
// target's interior sequence.
PolygonPair polygon_pair_of(const std::string& name, const StickFigure& source, const StickFigure& target) {
  const CompatibilityReport report = check_compatibility(source, target);
  INFO("polygon pair " << name << ": " << report.reason);
  REQUIRE(report.compatible());
  const Decomposition decomposition = decompose(source);
  std::vector<const CyclicSequence*> interior;
  for (const CyclicSequence& sequence : decomposition.sequences)
    if (!sequence.exterior) interior.push_back(&sequence);
  INFO("polygon pair " << name << " must be one polygon");
  REQUIRE(interior.size() == 1);
  PolygonPair pair;
  pair.corners = interior.front()->vertices;
  pair.source_positions = source.vertices;
  pair.target_positions = target.vertices;
  return pair;
}

std::vector<fs::path> corpus_sources() {
  std::vector<fs::path> sources;
  const std::string suffix = ".source.json";
  for (const fs::directory_entry& entry : fs::directory_iterator(kData / "polygon_pairs")) {
    const std::string file = entry.path().filename().string();
    if (file.size() > suffix.size() && file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0)
      sources.push_back(entry.path());
  }
  // Directory order is unspecified; the golden file lists pairs by name.
  std::sort(sources.begin(), sources.end());
  return sources;
}

Counts compute_counts() {
  Counts counts;
  for (const fs::path& source_path : corpus_sources()) {
    const std::string file = source_path.filename().string();
    PolygonPairCounts pair_counts;
    pair_counts.name = file.substr(0, file.size() - std::string(".source.json").size());
    const fs::path target_path = source_path.parent_path() / (pair_counts.name + ".target.json");
    const PolygonPair pair = polygon_pair_of(pair_counts.name, read_figure_file(source_path.string()),
                                             read_figure_file(target_path.string()));
    pair_counts.corners = (long long)pair.corners.size();
    for (SteinerMethod method : kMethods) {
      CompatibleTriangulationOptions options;  // the benchmark's: defaults
      options.method = method;
      options.label = pair_counts.name;
      pair_counts.steiner[steiner_method_name(method)] = compatible_triangulation(pair, options).steiner_count();
    }
    counts.polygon_pairs.push_back(pair_counts);
  }
  for (const FigurePairInput& input : kFigurePairs) {
    const StickFigure source = read_figure_file((kData / input.source).string());
    const StickFigure target = read_figure_file((kData / input.target).string());
    for (SteinerMethod method : kMethods) {
      FigureTriangulationOptions options;  // the CLI's defaults but for the method
      options.method = method;
      counts.figure_pairs[input.name][steiner_method_name(method)] =
          triangulate_figures(source, target, options).steiner_vertices;
    }
  }
  return counts;
}

MethodCounts totals(const std::vector<PolygonPairCounts>& pairs, long long* corners) {
  MethodCounts sum;
  *corners = 0;
  for (const PolygonPairCounts& pair : pairs) {
    *corners += pair.corners;
    for (const auto& [method, steiner] : pair.steiner) sum[method] += steiner;
  }
  return sum;
}

void write_method_counts(JsonWriter& out, const MethodCounts& counts) {
  out.begin_object();
  for (SteinerMethod method : kMethods) {
    out.key(steiner_method_name(method));
    out.value(counts.at(steiner_method_name(method)));
  }
  out.end_object();
}

std::string golden_json(const Counts& counts) {
  JsonWriter out(true);
  out.begin_object();
  out.key("about");
  out.value(
      "Steiner vertices per method, pinned by tests/cpp/test_golden_steiner_counts.cpp. polygon_pairs: "
      "compatible_triangulation (paper section 4, default options) of each pair in tests/data/polygon_pairs, "
      "as stickmorph_benchmark measures it. figure_pairs: triangulate_figures (Algorithm 3, default options), "
      "as 'stickmorph triangulate --steiner METHOD' reports it. Regenerate with scripts/update_golden.sh.");
  out.key("polygon_pairs");
  out.begin_array();
  for (const PolygonPairCounts& pair : counts.polygon_pairs) {
    out.begin_object();
    out.key("name");
    out.value(pair.name);
    out.key("corners");
    out.value(pair.corners);
    out.key("steiner");
    write_method_counts(out, pair.steiner);
    out.end_object();
  }
  out.end_array();
  long long corners = 0;
  const MethodCounts sum = totals(counts.polygon_pairs, &corners);
  out.key("polygon_pair_totals");
  out.begin_object();
  out.key("pairs");
  out.value(counts.polygon_pairs.size());
  out.key("corners");
  out.value(corners);
  out.key("steiner");
  write_method_counts(out, sum);
  out.end_object();
  out.key("figure_pairs");
  out.begin_array();
  for (const FigurePairInput& input : kFigurePairs) {
    out.begin_object();
    out.key("name");
    out.value(input.name);
    out.key("source");
    out.value(input.source);
    out.key("target");
    out.value(input.target);
    out.key("steiner");
    write_method_counts(out, counts.figure_pairs.at(input.name));
    out.end_object();
  }
  out.end_array();
  out.end_object();
  return out.finish();
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  INFO("cannot read " << path.string() << "; " << kRegenerate);
  REQUIRE(in);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

long long integer(const JsonValue& object, const char* key) {
  const JsonValue* value = object.find(key);
  INFO("golden file: missing \"" << key << "\" at " << describe_location(object.location()));
  REQUIRE(value != nullptr);
  return (long long)value->as_number();
}

const JsonValue& member(const JsonValue& object, const char* key) {
  const JsonValue* value = object.find(key);
  INFO("golden file: missing \"" << key << "\" at " << describe_location(object.location()));
  REQUIRE(value != nullptr);
  return *value;
}

// One exact comparison per method; the message names the case that drifted.
void compare_methods(const std::string& where, const MethodCounts& current, const JsonValue& golden) {
  for (SteinerMethod method : kMethods) {
    const std::string name = steiner_method_name(method);
    const long long expected = integer(golden, name.c_str());
    const long long actual = current.at(name);
    INFO(where << ", method " << name << ": now " << actual << " Steiner vertices, golden " << expected << " ("
               << kGoldenFile.string() << "; " << kRegenerate << ")");
    CHECK(actual == expected);
  }
}

}  // namespace

TEST_CASE("golden Steiner counts of the polygon-pair corpus and of S -> U", "[golden]") {
  const Counts counts = compute_counts();
  // The corpus must not be silently empty: a wrong data path would otherwise
  // compare nothing against nothing.
  REQUIRE(counts.polygon_pairs.size() >= 1);

  const char* update = std::getenv("STICKMORPH_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    fs::create_directories(kGoldenFile.parent_path());
    std::ofstream out(kGoldenFile, std::ios::binary | std::ios::trunc);
    out << golden_json(counts);
    out.close();
    REQUIRE(out.good());
    WARN("STICKMORPH_UPDATE_GOLDEN=1: wrote " << kGoldenFile.string() << "; review the diff before committing");
  }

  const JsonValue golden = parse_json(read_text(kGoldenFile));

  // Per polygon pair: the golden file and the corpus must list the same
  // pairs, so that adding or removing a pair is a deliberate update too.
  std::map<std::string, const JsonValue*> golden_pairs;
  for (const JsonValue& pair : member(golden, "polygon_pairs").as_array())
    golden_pairs[member(pair, "name").as_string()] = &pair;
  for (const PolygonPairCounts& pair : counts.polygon_pairs) {
    const auto found = golden_pairs.find(pair.name);
    if (found == golden_pairs.end()) {
      FAIL_CHECK("polygon pair " << pair.name << " is in tests/data/polygon_pairs but not in the golden file; "
                                 << kRegenerate);
      continue;
    }
    const std::string where = "polygon pair " + pair.name;
    {
      INFO(where << ": corner count");
      CHECK(pair.corners == integer(*found->second, "corners"));
    }
    compare_methods(where, pair.steiner, member(*found->second, "steiner"));
    golden_pairs.erase(found);
  }
  for (const auto& [name, pair] : golden_pairs) {
    FAIL_CHECK("polygon pair " << name << " is in the golden file but no longer in tests/data/polygon_pairs; "
                               << kRegenerate);
  }

  // Corpus totals: the README's headline figures.
  long long corners = 0;
  const MethodCounts sum = totals(counts.polygon_pairs, &corners);
  const JsonValue& golden_totals = member(golden, "polygon_pair_totals");
  {
    INFO("polygon-pair corpus: number of pairs");
    CHECK((long long)counts.polygon_pairs.size() == integer(golden_totals, "pairs"));
  }
  {
    INFO("polygon-pair corpus: total corners");
    CHECK(corners == integer(golden_totals, "corners"));
  }
  compare_methods("polygon-pair corpus total", sum, member(golden_totals, "steiner"));

  // Figure pairs through the whole pipeline.
  std::map<std::string, const JsonValue*> golden_figures;
  for (const JsonValue& pair : member(golden, "figure_pairs").as_array())
    golden_figures[member(pair, "name").as_string()] = &pair;
  {
    INFO("figure pairs in the golden file; " << kRegenerate);
    CHECK(golden_figures.size() == counts.figure_pairs.size());
  }
  for (const auto& [name, steiner] : counts.figure_pairs) {
    const auto found = golden_figures.find(name);
    if (found == golden_figures.end()) {
      FAIL_CHECK("figure pair " << name << " is missing from the golden file; " << kRegenerate);
      continue;
    }
    compare_methods("figure pair " + name + " (triangulate_figures)", steiner, member(*found->second, "steiner"));
  }
}
