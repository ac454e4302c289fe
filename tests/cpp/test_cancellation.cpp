// Progress and cancellation of long engine calls (cancellation.h, issue 29):
// a cancel from another thread stops the triangulation and the frame loops
// with CancelledError; a Progress that is not cancelled changes nothing.
#include "catch.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "figures.h"
#include "stickmorph/cancellation.h"
#include "stickmorph/errors.h"
#include "stickmorph/key_pose_morph.h"
#include "stickmorph/morph_stick_figures.h"

using namespace stickmorph;
using namespace stickmorph::test;

namespace {

// Two graphs of functions of x (so both valid polylines, and compatible):
// a wave into another wave. n = 20000 triangulates for about a second,
// long enough for the watcher below to see the stage.
// A pair, not bound with auto [source, target] by the tests: C++17 lambdas may
// not capture structured bindings (clang refuses; the sanitizer build is clang's).
std::pair<StickFigure, StickFigure> waves(int n) {
  std::vector<Vec2> source, target;
  for (int i = 0; i < n; ++i) {
    const double x = 100.0 * i / (n - 1);
    source.push_back({x, 3 * std::sin(0.7 * x) + 1.5 * std::sin(2.3 * x)});
    target.push_back({x, -2 * std::cos(0.3 * x) + 0.5 * std::sin(1.1 * x)});
  }
  return {polyline(source), polyline(target)};
}

// Runs `call` with `progress` installed on this thread while another thread
// cancels `progress` once `ready` says so; returns the CancelledError's
// message, or "finished" when the call ended first.
template <class Call, class Ready>
std::string cancelled_when(Progress& progress, Ready ready, Call call) {
  std::atomic<bool> over{false};
  std::thread watcher([&] {
    while (!over.load() && !ready(progress)) std::this_thread::sleep_for(std::chrono::microseconds(200));
    progress.cancel();
  });
  std::string outcome = "finished";
  try {
    const ProgressScope scope(&progress);
    call();
  } catch (const CancelledError& error) {
    outcome = error.what();
  }
  over = true;
  watcher.join();
  return outcome;
}

}  // namespace

TEST_CASE("a cancel during the triangulation stops the morph there") {
  const auto figures = waves(20000);
  const StickFigure& source = figures.first;
  const StickFigure& target = figures.second;
  for (MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric}) {
    MorphStickFiguresOptions options;
    options.method = method;
    options.frames = 10;
    Progress progress;
    const std::string outcome = cancelled_when(
        progress, [](const Progress& p) { return p.stage() == "triangulate"; },
        [&] { morph_stick_figures(source, target, options); });
    CHECK(outcome == "cancelled while in stage 'triangulate'");
    CHECK(progress.cancelled());
  }
}

TEST_CASE("a cancel during the frames stops the morph between two frames") {
  const auto figures = waves(300);
  const StickFigure& source = figures.first;
  const StickFigure& target = figures.second;
  for (MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric, MorphMethod::Linear}) {
    MorphStickFiguresOptions options;
    options.method = method;
    options.frames = 5000;
    Progress progress;
    long done_when_cancelled = -1;
    const std::string outcome = cancelled_when(
        progress,
        [&](const Progress& p) {
          if (p.stage() != "frames" || p.done() < 2) return false;
          done_when_cancelled = p.done();
          return true;
        },
        [&] { morph_stick_figures(source, target, options); });
    CHECK(outcome == "cancelled while in stage 'frames'");
    CHECK(progress.total() == 5000);
    CHECK(done_when_cancelled >= 2);
    CHECK(progress.done() < 5000);
  }
}

TEST_CASE("a cancel during the key poses' frames stops morph_key_poses") {
  KeyPoseMorphOptions options;
  options.frames = 4000;
  const StickFigure standing = stick_man_standing();
  std::vector<StickFigure> keys;
  for (const std::vector<Vec2>& pose : stick_man_walk(3)) keys.push_back(figure(pose, raw_edges(standing.edges)));
  Progress progress;
  const std::string outcome = cancelled_when(
      progress, [](const Progress& p) { return p.stage() == "frames" && p.done() >= 2; },
      [&] { morph_key_poses(keys, options); });
  CHECK(outcome == "cancelled while in stage 'frames'");
}

TEST_CASE("a Progress cancelled before the call stops it before any work") {
  const auto figures = waves(50);
  const StickFigure& source = figures.first;
  const StickFigure& target = figures.second;
  Progress progress;
  progress.cancel();
  const ProgressScope scope(&progress);
  CHECK_THROWS_AS(morph_stick_figures(source, target, {}), CancelledError);
  CHECK(progress.stage().empty());  // not even the check started
}

TEST_CASE("a Progress that is not cancelled changes nothing and times the stages") {
  const auto figures = waves(400);
  const StickFigure& source = figures.first;
  const StickFigure& target = figures.second;
  for (MorphMethod method : {MorphMethod::Rigid, MorphMethod::Barycentric}) {
    MorphStickFiguresOptions options;
    options.method = method;
    options.frames = 30;
    const MorphStickFiguresResult plain = morph_stick_figures(source, target, options);
    Progress progress;
    MorphStickFiguresResult watched;
    {
      const ProgressScope scope(&progress);
      watched = morph_stick_figures(source, target, options);
    }
    CHECK(watched.frames == plain.frames);  // bit for bit
    CHECK(watched.times == plain.times);
    CHECK(progress.stage() == "frames");
    CHECK(progress.done() == 30);
    CHECK(progress.fraction() == 1.0);
    progress.finish();
    std::vector<std::string> names;
    for (const Progress::StageTime& t : progress.stage_times()) {
      names.push_back(t.name);
      CHECK(t.milliseconds >= 0);
    }
    CHECK(names == std::vector<std::string>{"check", "triangulate", "frames"});
    const std::string summary = progress.summary();
    CHECK(summary.rfind("check ", 0) == 0);
    CHECK(summary.find(" ms, triangulate ") != std::string::npos);
    CHECK(summary.find(" ms, frames ") != std::string::npos);
  }
}

TEST_CASE("ProgressScope installs for its thread only and restores the outer Progress") {
  Progress outer, inner;
  CHECK(current_progress() == nullptr);
  {
    const ProgressScope a(&outer);
    CHECK(current_progress() == &outer);
    {
      const ProgressScope b(&inner);
      CHECK(current_progress() == &inner);
      Progress* seen = &outer;
      std::thread([&] { seen = current_progress(); }).join();
      CHECK(seen == nullptr);
    }
    CHECK(current_progress() == &outer);
  }
  CHECK(current_progress() == nullptr);
  // Nothing installed: the calls report to no one and never throw.
  CHECK_NOTHROW(poll_cancellation());
  CHECK_NOTHROW(report_stage("frames", 3));
  CHECK_NOTHROW(report_progress(1, 3));
}

TEST_CASE("a stage that runs more than once is one entry, its times added") {
  Progress progress;
  CHECK(progress.fraction() < 0);
  progress.begin_stage("triangulate");
  progress.begin_stage("frames", 4);
  progress.set_progress(1, 4);
  CHECK(progress.fraction() == 0.25);
  progress.begin_stage("triangulate");
  progress.finish();
  const std::vector<Progress::StageTime> times = progress.stage_times();
  REQUIRE(times.size() == 2);
  CHECK(times[0].name == "triangulate");
  CHECK(times[1].name == "frames");
  CHECK(progress.stage().empty());
  CHECK(progress.fraction() < 0);
}
