// Progress and cancellation of long engine calls; see cancellation.h.
#include "stickmorph/cancellation.h"

#include <algorithm>
#include <cstdio>

#include "stickmorph/errors.h"

namespace stickmorph {
namespace {

// One pointer per thread: the engine call and its Progress run on the same
// thread (the Python module releases the GIL, it does not change threads).
thread_local Progress* t_current = nullptr;

}  // namespace

Progress::Progress() : stage_started_(Clock::now()) {}

void Progress::end_stage_locked(Clock::time_point now) {
  if (stage_.empty()) return;
  const double ms = std::chrono::duration<double, std::milli>(now - stage_started_).count();
  const auto same = std::find_if(times_.begin(), times_.end(), [&](const StageTime& t) { return t.name == stage_; });
  if (same != times_.end())
    same->milliseconds += ms;
  else
    times_.push_back({stage_, ms});
}

void Progress::begin_stage(const std::string& name, long total) {
  const Clock::time_point now = Clock::now();
  std::lock_guard<std::mutex> lock(mutex_);
  end_stage_locked(now);
  stage_ = name;
  stage_started_ = now;
  // Total before done, both reset: a reader between the two stores sees a
  // fraction of 0 or an uncounted stage, never the last stage's count
  // against the new total.
  done_.store(0, std::memory_order_relaxed);
  total_.store(total, std::memory_order_relaxed);
}

void Progress::finish() {
  const Clock::time_point now = Clock::now();
  std::lock_guard<std::mutex> lock(mutex_);
  end_stage_locked(now);
  stage_.clear();
  done_.store(0, std::memory_order_relaxed);
  total_.store(0, std::memory_order_relaxed);
}

std::string Progress::stage() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stage_;
}

double Progress::fraction() const noexcept {
  const long total = total_.load(std::memory_order_relaxed);
  if (total <= 0) return -1;
  const long done = done_.load(std::memory_order_relaxed);
  return std::clamp(double(done) / double(total), 0.0, 1.0);
}

std::vector<Progress::StageTime> Progress::stage_times() const {
  const Clock::time_point now = Clock::now();
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<StageTime> times = times_;
  if (!stage_.empty()) {
    const double ms = std::chrono::duration<double, std::milli>(now - stage_started_).count();
    const auto same = std::find_if(times.begin(), times.end(), [&](const StageTime& t) { return t.name == stage_; });
    if (same != times.end())
      same->milliseconds += ms;
    else
      times.push_back({stage_, ms});
  }
  return times;
}

std::string Progress::summary() const {
  std::string text;
  for (const StageTime& t : stage_times()) {
    char ms[32];
    std::snprintf(ms, sizeof ms, " %.0f ms", t.milliseconds);
    text += (text.empty() ? "" : ", ") + t.name + ms;
  }
  return text;
}

Progress* current_progress() noexcept { return t_current; }

ProgressScope::ProgressScope(Progress* progress) noexcept : previous_(t_current) { t_current = progress; }
ProgressScope::~ProgressScope() { t_current = previous_; }

void poll_cancellation() {
  const Progress* progress = t_current;
  if (progress != nullptr && progress->cancelled()) {
    const std::string stage = progress->stage();
    throw CancelledError("cancelled" + (stage.empty() ? std::string() : " while in stage '" + stage + "'"));
  }
}

void report_stage(const char* name, long total) {
  poll_cancellation();
  if (Progress* progress = t_current) progress->begin_stage(name, total);
}

void report_progress(long done, long total) {
  poll_cancellation();
  if (Progress* progress = t_current) progress->set_progress(done, total);
}

}  // namespace stickmorph
