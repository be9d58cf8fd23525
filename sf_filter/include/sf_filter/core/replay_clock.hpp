// How the offline replay advances the fusion core's clock to the recorded time of each
// message, as the online node's ros::Timer would while `rosbag play --clock` runs: the timer
// estimates every period while the clock runs through a gap between messages, so the core
// runs to the message time (FusionCore::runTo) estimating every period, up to kMaxGapPeriods.
// A longer gap (a recording paused or two recordings in one bag) is crossed by the core's own
// gap rule, as the online node crosses a clock jump: one estimate, the missed periods skipped
// (counted), never millions of empty periods. Shared by the bag replay (bag_replay.hpp) and
// the in-memory replays of the noise identification (tuning/event_log.hpp), so that both
// estimate the same periods.
#pragma once

#include <cstdint>
#include <iomanip>
#include <iostream>

#include "sf_filter/core/fusion_engine.hpp"

namespace sf_filter {

class ReplayClock {
 public:
  /// The longest gap between messages estimated period by period.
  static constexpr std::uint64_t kMaxGapPeriods = 10000;

  /// Advances `core` to the message time `now`, handing every estimate to `write`.
  template <class Write>
  void advance(FusionEngine& core, double now, Write& write) {
    if (core.runTo(now, kMaxGapPeriods, write) == ClockEvent::SkippedGap) {
      // The core counts the gaps (FusionStatistics::skippedGaps); read only on a gap.
      const std::uint64_t skipped = core.statistics().skippedGaps;
      if (skipped == 1 || skipped % 1000 == 0) {
        std::cerr << "warning: a gap of more than " << kMaxGapPeriods
                  << " periods in the bag before " << std::fixed << std::setprecision(3) << now
                  << " s: skipped as the online node skips a clock jump (" << skipped << " so far)"
                  << std::defaultfloat << std::endl;
      }
    }
  }
};

}  // namespace sf_filter
