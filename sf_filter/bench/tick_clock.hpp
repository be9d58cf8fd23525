// Fixed-rate publishing for the load drivers (node_load_driver.cpp, soak_driver.cpp): sleeping
// to absolute ticks on CLOCK_MONOTONIC, so that late wake-ups do not accumulate into drift.
#pragma once

#include <cerrno>
#include <ctime>

namespace sf_bench {

/// Advances `next` by `stepNs` and sleeps until then.
inline void sleepToNextTick(timespec& next, long stepNs) {
  next.tv_nsec += stepNs;
  while (next.tv_nsec >= 1000000000) {
    next.tv_nsec -= 1000000000;
    ++next.tv_sec;
  }
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr) == EINTR) {
  }
}

}  // namespace sf_bench
