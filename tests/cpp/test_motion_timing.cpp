// internal::MotionTiming (motion_timing.h): time kept where the speed is
// even enough, evened no more than the bound needs elsewhere.
#include "catch.h"

#include <algorithm>
#include <vector>

#include "stickmorph/internal/motion_timing.h"

using stickmorph::internal::MotionTiming;

namespace {

// Times j / m and the cumulative motion of a speed that grows linearly from
// 1 to `last` in the motion's own time.
MotionTiming growing_speed(double last, double bound, int m = 100) {
  std::vector<double> times(m + 1), motion(m + 1);
  for (int j = 0; j <= m; ++j) {
    const double tau = double(j) / m;
    times[j] = tau;
    motion[j] = tau + 0.5 * (last - 1) * tau * tau;
  }
  return MotionTiming(times, motion, 1e-12, bound);
}

}  // namespace

TEST_CASE("MotionTiming keeps time when the speed is within the bound", "[motion_timing]") {
  const MotionTiming timing = growing_speed(1.2, 1.15);  // largest speed 1.2 / 1.1 of the mean
  CHECK(timing.evening() == 0);
  for (int k = 0; k <= 20; ++k) CHECK(timing.at(k / 20.0) == k / 20.0);
}

TEST_CASE("MotionTiming evens an uneven speed only down to the bound", "[motion_timing]") {
  const MotionTiming timing = growing_speed(4, 1.15);  // linear time: 4 / 2.5 = 1.6 of the mean
  CHECK(timing.unevenness(0, 200) == Approx(1.6).epsilon(0.01));
  CHECK(timing.evening() > 0);
  CHECK(timing.evening() < 1);
  CHECK(timing.unevenness(timing.evening(), 200) == Approx(1.15).epsilon(0.001));
  CHECK(timing.unevenness(1, 200) == Approx(1).epsilon(0.01));
  CHECK(timing.at(0) == 0);
  CHECK(timing.at(1) == 1);
  double previous = 0;
  for (int k = 1; k <= 1000; ++k) {
    const double tau = timing.at(k / 1000.0);
    CHECK(tau > previous);
    previous = tau;
  }
  // Slow at first, so the motion's time runs ahead of the animation's.
  CHECK(timing.at(0.5) > 0.5);
}

TEST_CASE("MotionTiming keeps time for a motion that does not move", "[motion_timing]") {
  const MotionTiming timing({0, 0.5, 1}, {0, 1e-15, 2e-15}, 1e-12, 1.15);
  CHECK(timing.evening() == 0);
  CHECK(timing.at(0.3) == 0.3);
}
