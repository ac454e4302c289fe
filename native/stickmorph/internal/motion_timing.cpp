// The timing of a motion from its cumulative motion table; see
// motion_timing.h.
#include "stickmorph/internal/motion_timing.h"

#include <algorithm>
#include <utility>

#include "stickmorph/errors.h"

namespace stickmorph {
namespace internal {
namespace {

// Steps of time at which the speed is compared with its mean: finer than
// the frames of any animation, whose steps average several of these, so the
// frames' unevenness is at most what is measured here (up to the table's
// own resolution).
constexpr int kTimingSteps = 200;

}  // namespace

MotionTiming::MotionTiming(std::vector<double> times, std::vector<double> motion, double still, double bound)
    : times_(std::move(times)), motion_(std::move(motion)) {
  if (times_.size() < 2 || times_.size() != motion_.size())
    throw InternalError("MotionTiming: the times and the motion must be tables of the same length >= 2");
  moves_ = motion_.back() > still;
  if (!moves_ || unevenness(0, kTimingSteps) <= bound) return;
  // Bisection: the unevenness falls from the motion's own at 0 to about 1
  // at full evening.
  double low = 0, high = 1;
  for (int k = 0; k < 30; ++k) {
    const double mid = 0.5 * (low + high);
    (unevenness(mid, kTimingSteps) > bound ? low : high) = mid;
  }
  evening_ = high;
}

double MotionTiming::even(double t) const {
  const double goal = t * motion_.back();
  // The first sample at or beyond the goal; linear in between.
  const int last = int(motion_.size()) - 1;
  const auto it = std::lower_bound(motion_.begin(), motion_.end(), goal);
  const int j = std::clamp(int(it - motion_.begin()), 1, last);
  const double lo = motion_[j - 1], hi = motion_[j];
  const double f = hi > lo ? std::clamp((goal - lo) / (hi - lo), 0.0, 1.0) : 0.0;
  return std::clamp((1 - f) * times_[j - 1] + f * times_[j], 0.0, 1.0);
}

double MotionTiming::motion_at(double tau) const {
  const int last = int(times_.size()) - 1;
  const auto it = std::lower_bound(times_.begin(), times_.end(), tau);
  const int j = std::clamp(int(it - times_.begin()), 1, last);
  const double span = times_[j] - times_[j - 1];
  const double f = span > 0 ? std::clamp((tau - times_[j - 1]) / span, 0.0, 1.0) : 1.0;
  return (1 - f) * motion_[j - 1] + f * motion_[j];
}

double MotionTiming::timed(double t, double a) const {
  if (t <= 0 || t >= 1 || !moves_) return std::clamp(t, 0.0, 1.0);
  if (a == 0) return t;
  return std::clamp((1 - a) * t + a * even(t), 0.0, 1.0);
}

double MotionTiming::at(double t) const { return timed(t, evening_); }

double MotionTiming::unevenness(double a, int steps) const {
  const double mean = motion_.back() / steps;
  if (!(mean > 0)) return 1;
  double largest = 0, previous = 0;
  for (int k = 1; k <= steps; ++k) {
    const double here = motion_at(timed(double(k) / steps, a));
    largest = std::max(largest, here - previous);
    previous = here;
  }
  return largest / mean;
}

}  // namespace internal
}  // namespace stickmorph
