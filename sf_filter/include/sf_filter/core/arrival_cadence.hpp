// The cadence of an input without stamps (FusionCoreOptions::unstampedCadence): when its values
// arrived and where they were placed, so that a value delivered late - a stalled node reading
// its backlog after roscpp's clock already jumped, issue 38 D10 - can be placed where its
// sensor's rhythm says it was sent. Such a value carries no other evidence: its receipt time
// is an upper bound, and the order between its connection and /clock's is lost in a backlog.
// Every input keeps its deliveries too: other inputs silent since the predicted time are what
// tells a stalled delivery from a sensor that skipped a value.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sf_filter {

class ArrivalCadence {
 public:
  /// Intervals between the times values were sent (as noted) kept; their median is the
  /// cadence. Not the arrival intervals: a stall's value arrives late and the next one on time,
  /// a long and a short interval, and the median of eight (the upper one of the middle two)
  /// rose to the shortest of the long ones after four stalls (issue 38 D10, round eight).
  static constexpr int kIntervals = 8;
  /// Intervals needed before the cadence predicts anything.
  static constexpr int kMinIntervals = 4;

  /// The time the cadence predicts for a value arriving at `arrival` (the time the previous
  /// value was sent, as noted, plus the median interval) if the value is later than that by
  /// more than half an interval (a late delivery, not jitter); NaN otherwise, while the
  /// cadence is unknown, and when the previous value arrived less than half an interval before
  /// the prediction and not in the same backlog (the same arrival): then the input is on time
  /// again, and a prediction from a value placed early (a skipped value taken for a late one)
  /// would carry the error on.
  double lateExpected(double arrival) const {
    if (count_ < kMinIntervals) return std::numeric_limits<double>::quiet_NaN();
    const double interval = median();
    const double expected = lastTime_ + interval;
    const bool onTimeAgain = lastArrival_ != arrival && lastArrival_ > expected - 0.5 * interval;
    if (!(interval > 0.0) || !(arrival - expected > 0.5 * interval) || onTimeAgain) {
      return std::numeric_limits<double>::quiet_NaN();
    }
    return expected;
  }

  /// A value of this input that arrived at `arrival` was sent at `time` (its placement, or the
  /// cadence's prediction where its period was estimated already). A value predicted adds the
  /// cadence itself; values of one backlog kept at its arrival add none.
  void note(double arrival, double time) {
    if (time > lastTime_ && !std::isinf(lastArrival_)) {  // -inf before the first: no interval
      intervals_[static_cast<std::size_t>(next_)] = time - lastTime_;
      next_ = (next_ + 1) % kIntervals;
      count_ = std::min(count_ + 1, kIntervals);
    }
    if (arrival > lastArrival_) lastArrival_ = arrival;
    lastTime_ = time;
  }

  /// A value of this input (stamped or not) was received at the clock reading `now`.
  void noteDelivery(double now) {
    if (now <= newestDelivery_) return;
    priorDelivery_ = newestDelivery_;
    newestDelivery_ = now;
  }
  /// Whether this input delivered anything yet.
  bool delivered() const { return !std::isinf(newestDelivery_); }
  /// The newest delivery before `now` (one at `now` is part of the same backlog); -inf if none.
  double deliveredBefore(double now) const {
    return newestDelivery_ == now ? priorDelivery_ : newestDelivery_;
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
  double newestDelivery_ = -std::numeric_limits<double>::infinity();
  double priorDelivery_ = -std::numeric_limits<double>::infinity();
};

}  // namespace sf_filter
