// stickmorph_random_pairs: the long mode of the random-pair property test
// (random_pairs.h). Runs N pairs through the whole pipeline, saves every
// failing pair as a regression case and exits 1 if anything failed.
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
    "pipeline: triangulate_figures (improved Steiner method), verify_figure_triangulation,\n"
    "morph_triangulation, and an exact check of every frame (all triangles\n"
    "counter-clockwise, verify_frame on the figure).\n"
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

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t pairs = 300, first_seed = 1;
  bool random_seed = false, verbose = false, long_if_env = false;
  int frames = 12;
  std::optional<PairKind> only_kind;
  std::string save_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (arg == "--pairs") {
      pairs = parse_count(next(), "--pairs");
    } else if (arg == "--seed") {
      const std::string value = next();
      if (value == "random") random_seed = true;
      else first_seed = parse_count(value, "--seed");
    } else if (arg == "--kind") {
      const std::string value = next();
      only_kind = parse_pair_kind(value);
      if (!only_kind) usage_error("unknown kind '" + value + "'");
    } else if (arg == "--frames") {
      const std::uint64_t value = parse_count(next(), "--frames");
      if (value < 2 || value > std::uint64_t(kMaxMorphFrames)) usage_error("--frames must be at least 2");
      frames = int(value);
    } else if (arg == "--save-failures") {
      save_dir = next();
    } else if (arg == "--verbose") {
      verbose = true;
    } else if (arg == "--long-if-env") {
      long_if_env = true;
    } else {
      usage_error("unknown argument '" + arg + "'");
    }
  }
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
