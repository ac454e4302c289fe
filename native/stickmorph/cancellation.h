// Progress and cancellation of long engine calls (issue 29): a 10^5-vertex
// morph takes minutes (most of it the compatible triangulation), and a GUI
// that runs it in a worker thread must be able to show how far it is and to
// stop it.
//
// No engine signature carries this. The caller makes a Progress, installs
// it for the current thread with a ProgressScope around the engine call,
// and may read or cancel it from any other thread while the call runs. The
// engine reports its stages (report_stage), counts the steps of the
// counted ones (report_progress) and polls for cancellation in its long
// loops (poll_cancellation); a cancelled call throws CancelledError at the
// next poll and returns nothing. With no Progress installed, or one that is
// not cancelled, a poll is one thread-local read and one relaxed atomic
// load, and nothing else changes: results are bit for bit those of a call
// without a Progress (tests/cpp/test_cancellation.cpp).
//
// The stages the engine reports (names, in the order they run):
//   "check"        validation, Algorithm 1 and the compatibility check
//   "correspond"   matching figures drawn separately (correspond="auto")
//   "triangulate"  Algorithm 3's compatible triangulation (one per key-pose
//                  segment); for the rigid method also the solver's set-up
//                  on it (weights, first factorization, the guide).
//                  Counted in what the engine can count: the interior faces
//                  of a figure of many faces, the corners glued of a face of
//                  1000 corners or more (a polyline's exterior face, nearly
//                  all of a 10^5-vertex triangulation's time); the count
//                  restarts with each face or segment and stays at its end
//                  during the set-up. Not a time estimate.
//   "frames"       the frame loop, counted in frames
// Callers may add stages of their own (the Blender add-on's "read" and
// "build") with begin_stage; stage times are kept for summary().
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace stickmorph {

/// What one engine call (or a caller's sequence of them) is doing, and
/// whether its caller wants it to stop. Every member may be called from any
/// thread at any time; the counters are atomics, the stage name and the
/// stage times are behind a mutex taken only at stage boundaries.
class Progress {
 public:
  Progress();

  /// Asks the engine call to stop: it throws CancelledError at its next
  /// poll. Cannot be undone; a cancelled Progress cancels every later call
  /// it is installed for, before any work.
  void cancel() noexcept { cancelled_.store(true, std::memory_order_relaxed); }
  bool cancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }

  /// Ends the current stage (its time is recorded) and starts `name`, with
  /// `total` steps to count, or 0 when its steps are not counted.
  void begin_stage(const std::string& name, long total = 0);
  /// `done` of `total` steps of the current stage (total 0: not counted).
  void set_progress(long done, long total) noexcept {
    total_.store(total, std::memory_order_relaxed);
    done_.store(done, std::memory_order_relaxed);
  }
  /// Ends the current stage, recording its time; the stage becomes "".
  void finish();

  /// The current stage's name, "" before the first and after finish().
  std::string stage() const;
  long done() const noexcept { return done_.load(std::memory_order_relaxed); }
  long total() const noexcept { return total_.load(std::memory_order_relaxed); }
  /// done / total of the current stage, in [0, 1]; negative when the stage
  /// is not counted.
  double fraction() const noexcept;

  struct StageTime {
    std::string name;
    double milliseconds = 0;
  };
  /// Every stage so far with its wall-clock time, the current one up to
  /// now; a stage that ran more than once (one triangulation per key-pose
  /// segment) is one entry with the times added, in first-started order.
  std::vector<StageTime> stage_times() const;
  /// stage_times() as "check 30 ms, triangulate 3100 ms, frames 900 ms".
  std::string summary() const;

 private:
  using Clock = std::chrono::steady_clock;
  void end_stage_locked(Clock::time_point now);

  std::atomic<bool> cancelled_{false};
  std::atomic<long> done_{0};
  std::atomic<long> total_{0};
  mutable std::mutex mutex_;
  std::string stage_;
  Clock::time_point stage_started_;
  std::vector<StageTime> times_;
};

/// The current thread's Progress, or nullptr.
Progress* current_progress() noexcept;

/// Installs a Progress (or nullptr: none) for the current thread for its
/// lifetime, and restores the one installed before when it ends. The
/// Progress must outlive the scope.
class ProgressScope {
 public:
  explicit ProgressScope(Progress* progress) noexcept;
  ~ProgressScope();
  ProgressScope(const ProgressScope&) = delete;
  ProgressScope& operator=(const ProgressScope&) = delete;

 private:
  Progress* previous_;
};

/// Throws CancelledError when the current thread's Progress is cancelled.
/// Cheap enough for any loop whose body is not a handful of instructions.
void poll_cancellation();
/// Polls, then starts stage `name` on the current thread's Progress, if any.
void report_stage(const char* name, long total = 0);
/// Polls, then sets `done` of `total` steps of the current stage.
void report_progress(long done, long total);

}  // namespace stickmorph
