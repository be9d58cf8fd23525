// The cadence of an input without stamps (FusionCoreOptions::unstampedCadence): when its values
// arrived and where they were placed, so that a value delivered late - a stalled node reading
// its backlog after roscpp's clock already jumped, issue 38 D10 - can be placed where its
// sensor's rhythm says it was sent. Such a value carries no other evidence: its receipt time
// is an upper bound, and the order between its connection and /clock's is lost in a backlog.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sf_filter {

class ArrivalCadence {
 public:
  /// Arrival intervals kept; their median is the cadence (a stall's long and zero intervals,
  /// one pair per stall, do not move it).
  static constexpr int kIntervals = 8;
  /// Intervals needed before the cadence predicts anything.
  static constexpr int kMinIntervals = 4;

  /// The time the cadence predicts for a value arriving at `arrival` (the previous value's
  /// placement plus the median interval) if the value is later than that by more than half an
  /// interval (a late delivery, not jitter); NaN otherwise or while the cadence is unknown.
  double lateExpected(double arrival) const {
    if (count_ < kMinIntervals) return std::numeric_limits<double>::quiet_NaN();
    const double interval = median();
    const double expected = lastTime_ + interval;
    if (!(interval > 0.0) || !(arrival - expected > 0.5 * interval)) {
      return std::numeric_limits<double>::quiet_NaN();
    }
    return expected;
  }

  /// A value that arrived at `arrival` was placed at `time`.
  void note(double arrival, double time) {
    if (arrival > lastArrival_) {  // -inf before the first: no interval
      if (!std::isinf(lastArrival_)) {
        intervals_[static_cast<std::size_t>(next_)] = arrival - lastArrival_;
        next_ = (next_ + 1) % kIntervals;
        count_ = std::min(count_ + 1, kIntervals);
      }
      lastArrival_ = arrival;
    }
    lastTime_ = time;
  }

  void clear() { *this = ArrivalCadence{}; }

 private:
  double median() const {
    std::array<double, kIntervals> sorted = intervals_;
    const auto n = static_cast<std::size_t>(count_);
    std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.begin() + n);
    return sorted[n / 2];
  }

  std::array<double, kIntervals> intervals_{};
  int count_ = 0, next_ = 0;
  double lastArrival_ = -std::numeric_limits<double>::infinity();
  double lastTime_ = 0.0;
};

}  // namespace sf_filter
