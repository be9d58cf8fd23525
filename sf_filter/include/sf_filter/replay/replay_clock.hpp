// How the offline replay advances the fusion core's clock to the recorded time of each
// message, as the online node's ros::Timer would while `rosbag play --clock` runs: the timer
// estimates every period while the clock runs through a gap between messages, so a gap longer
// than the core's maxCatchUpPeriods periods (which the core would skip with one estimate) is
// crossed in steps of one period less than that, each estimating every period it ends.
// Shorter gaps take one step. A gap of more than kMaxGapPeriods periods (a recording paused or
// two recordings in one bag) is crossed as the online node crosses a clock jump: one
// estimate, the missed periods skipped (counted), never millions of empty periods. Shared by
// the bag replay (bag_replay.hpp) and the in-memory replays of the noise identification
// (tuning/event_log.hpp), so that both estimate the same periods.
#pragma once

#include <cstdint>
#include <iomanip>
#include <iostream>

#include "sf_filter/core/fusion_engine.hpp"

namespace sf_filter {

class ReplayClock {
 public:
  /// The longest gap between messages estimated period by period.
  static constexpr double kMaxGapPeriods = 10000.0;

  /// Advances `core` to the message time `now`, handing every estimate to `write`.
  template <class Write>
  void advance(FusionEngine& core, double now, Write& write) {
    if (started_ && now - core.clock() <= kMaxGapPeriods * core.period()) {
      const std::uint64_t periods = core.maxCatchUpPeriods();
      const double step = static_cast<double>(periods > 1 ? periods - 1 : 1) * core.period();
      while (now - core.clock() > step) core.advanceTo(core.clock() + step, write);
    }
    if (core.advanceTo(now, write) == ClockEvent::SkippedGap) {
      if (skippedGaps_++ == 0 || skippedGaps_ % 1000 == 0) {
        std::cerr << "warning: a gap of more than " << kMaxGapPeriods
                  << " periods in the bag before " << std::fixed << std::setprecision(3) << now
                  << " s: skipped as the online node skips a clock jump (" << skippedGaps_
                  << " so far)" << std::defaultfloat << std::endl;
      }
    }
    started_ = true;
  }

  /// Gaps crossed with one estimate.
  std::uint64_t skippedGaps() const { return skippedGaps_; }

 private:
  bool started_ = false;  ///< the core's clock has had its first reading
  std::uint64_t skippedGaps_ = 0;
};

}  // namespace sf_filter
