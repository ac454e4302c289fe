// stickmorph_random_pairs: the long mode of the random-pair property test
// (random_pairs.h). Runs N pairs through the whole pipeline, saves every
// failing pair as a regression case and exits 1 if anything failed.
#include <CLI/CLI.hpp>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "random_pairs.h"
#include "stickmorph/argument_limits.h"

using namespace stickmorph;
using namespace stickmorph::test;

namespace {

// CTest reports a test that exits with this code as skipped
// (SKIP_RETURN_CODE in tests/cpp/CMakeLists.txt).
constexpr int kSkipExitCode = 77;
constexpr int kLongModePairs = 10000;

const char* kUsage =
    "usage: stickmorph_random_pairs [--pairs N] [--seed S|random] [--kind NAME] [--frames F]\n"
    "                               [--save-failures DIR] [--verbose]\n"
    "       stickmorph_random_pairs --long-if-env [--save-failures DIR]\n"
    "\n"
    "Generates random compatible stick-figure pairs and runs each through the whole\n"
    "pipeline: morph_stick_figures (improved Steiner method), the triangulation verified\n"
    "again, and an exact check of every frame (all triangles counter-clockwise,\n"
    "verify_frame on the figure).\n"
    "\n"
    "Pair i (i = 0..N-1) is (seed S+i, kind i mod 7) in the order polyline, polygon,\n"
    "tree, sparse, dangling, near_touching, near_collinear, or always NAME with --kind.\n"
    "Its placement (scale and distance from the origin) is class (S+i) mod 6. One pair is\n"
    "replayed with: --seed SEED --kind KIND --pairs 1.\n"
    "\n"
    "  --pairs N            number of pairs (default 300)\n"
    "  --seed S|random      first seed (default 1); 'random' draws one and prints it\n"
    "  --kind NAME          only this kind\n"
    "  --frames F           frames per morph (default 12)\n"
    "  --save-failures DIR  write each failing pair as DIR/random_<kind>_seed<seed>.source.json\n"
    "                       and .target.json (figure files; the name field gives seed,\n"
    "                       kind and error); tests/data/regressions is replayed by the suite\n"
    "  --verbose            print every pair\n"
    "  --long-if-env        if the environment has STICKMORPH_LONG=1: 10000 pairs from a\n"
    "                       random seed; otherwise print why and exit 77 (CTest: skipped)\n"
    "\n"
    "Exit status: 0 all pairs passed, 1 a pair failed or could not be generated, 2 bad usage.\n";

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "error: " << what << "\n" << kUsage;
  std::exit(2);
}

std::uint64_t parse_count(const std::string& text, const char* option) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || text[0] == '-' || *end != '\0' || errno != 0)
    usage_error(std::string(option) + " needs a non-negative integer, got '" + text + "'");
  return value;
}

std::vector<std::string> kind_names() {
  std::vector<std::string> names;
  for (const PairKind kind : kAllPairKinds) names.push_back(pair_kind_name(kind));
  return names;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t pairs = 300, first_seed = 1;
  bool random_seed = false, verbose = false, long_if_env = false;
  int frames = 12;
  std::optional<PairKind> only_kind;
  std::string save_dir;
  std::string pairs_text, seed_text, kind_text;
  CLI::App app{"random-pair property test", "stickmorph_random_pairs"};
  app.set_help_flag("-h,--help");
  // Counts as text: parse_count takes the full uint64 range and refuses a
  // sign, which CLI11's integer conversion would wrap or accept.
  app.add_option("--pairs", pairs_text);
  app.add_option("--seed", seed_text);
  app.add_option("--kind", kind_text)->check(CLI::IsMember(kind_names()));
  app.add_option("--frames", frames)->check(CLI::Range(kMinMorphFrames, kMaxMorphFrames));
  app.add_option("--save-failures", save_dir);
  app.add_flag("--verbose", verbose);
  app.add_flag("--long-if-env", long_if_env);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << kUsage;
    return 0;
  } catch (const CLI::ParseError& error) {
    usage_error(error.what());
  }
  if (app.count("--pairs")) pairs = parse_count(pairs_text, "--pairs");
  if (seed_text == "random") random_seed = true;
  else if (app.count("--seed")) first_seed = parse_count(seed_text, "--seed");
  if (app.count("--kind")) only_kind = parse_pair_kind(kind_text);
  if (long_if_env) {
    const char* flag = std::getenv("STICKMORPH_LONG");
    if (flag == nullptr || std::strcmp(flag, "1") != 0) {
      std::cout << "skipped: STICKMORPH_LONG is not 1 (scripts/test.sh --long sets it)\n";
      return kSkipExitCode;
    }
    pairs = kLongModePairs;
    random_seed = true;
  }
  if (random_seed) {
    std::random_device device;
    // Below 2^40, so that seeds are short to type when replaying.
    first_seed = ((std::uint64_t(device()) << 32) | device()) % (std::uint64_t(1) << 40);
  }
  if (!save_dir.empty()) std::filesystem::create_directories(save_dir);

  std::cout << "stickmorph_random_pairs: " << pairs << " pairs from seed " << first_seed
            << (only_kind ? std::string(", kind ") + pair_kind_name(*only_kind) : std::string()) << ", " << frames
            << " frames" << std::endl;
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::uint64_t failed = 0, total_redraws = 0;
  int max_redraws = 0;
  std::map<std::string, int> failures_by_kind;
  for (std::uint64_t i = 0; i < pairs; ++i) {
    const std::uint64_t seed = first_seed + i;
    const PairKind kind = only_kind ? *only_kind : kAllPairKinds[i % kAllPairKinds.size()];
    RandomPair pair;
    try {
      pair = generate_pair(seed, kind);
    } catch (const GeneratorError& e) {
      ++failed;
      ++failures_by_kind[pair_kind_name(kind)];
      std::cout << "FAILED to generate: " << e.what() << std::endl;
      continue;
    }
    total_redraws += std::uint64_t(pair.redraws);
    max_redraws = std::max(max_redraws, pair.redraws);
    const auto pair_start = std::chrono::steady_clock::now();
    const std::string error = morph_and_verify(pair.source, pair.target, frames);
    if (verbose)
      std::cout << (error.empty() ? "ok " : "FAILED ") << pair.description << " "
                << std::chrono::duration<double>(std::chrono::steady_clock::now() - pair_start).count() << " s"
                << std::endl;
    if (!error.empty()) {
      ++failed;
      ++failures_by_kind[pair_kind_name(kind)];
      std::cout << "FAILED " << pair.description << ": " << error << std::endl;
      if (!save_dir.empty()) std::cout << "  saved as " << save_regression_pair(save_dir, pair, error) << ".*.json"
                                       << std::endl;
      std::cout << "  replay: stickmorph_random_pairs --seed " << seed << " --kind " << pair_kind_name(kind)
                << " --pairs 1" << std::endl;
    }
    if ((i + 1) % 500 == 0)
      std::cout << (i + 1) << " pairs, " << failed << " failed, " << elapsed() << " s" << std::endl;
  }
  std::cout << "done: " << pairs << " pairs from seed " << first_seed << ", " << failed << " failed, "
            << total_redraws << " redraws (at most " << max_redraws << " for one pair), " << elapsed() << " s"
            << std::endl;
  for (const auto& [kind, count] : failures_by_kind) std::cout << "  " << kind << ": " << count << " failed\n";
  return failed == 0 ? 0 : 1;
}
