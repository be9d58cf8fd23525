// A fixed-rate schedule of estimation periods: period k ends at start + k * period, whenever
// the previous estimate happened to run, so the rate never drifts (the original node started
// the next period when the last estimate finished).
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

namespace sf_filter {

class PeriodSchedule {
 public:
  explicit PeriodSchedule(double period) : period_(period) {}

  double period() const { return period_; }
  bool started() const { return started_; }

  /// Starts the schedule at `time`; the first period ends at time + period.
  void start(double time) {
    start_ = time;
    grid_.reset();
    index_ = 1;
    started_ = true;
  }
  /// Starts the schedule on the clock grid at the last multiple of the period at or before
  /// `time`; period ends are then (g + k) * period for that multiple g, the same numbers
  /// whatever reading within the grid's period started it.
  void startOnGrid(double time) {
    start(time);
    grid_ = std::floor(time / period_);
    start_ = *grid_ * period_;
  }
  void stop() { started_ = false; }

  /// Index of the current (not yet estimated) period; the first period is 1.
  std::uint64_t index() const { return index_; }
  /// End time of period k: start + k * period (on the clock grid (g + k) * period).
  double endOf(std::uint64_t k) const { return endAt(static_cast<std::int64_t>(k)); }
  /// End time of the current (not yet estimated) period.
  double currentEnd() const { return endOf(index_); }

  /// Index of the period containing time t, by the convention of due(): a time within the
  /// tolerance of a period's end belongs to the next period. Times before the start give
  /// indices below 1.
  std::int64_t indexOf(double t) const {
    auto k = static_cast<std::int64_t>(std::floor((t + kTolerance - start_) / period_)) + 1;
    // Correct the floor's rounding against the end times the schedule itself uses.
    while (endAt(k) <= t + kTolerance) ++k;
    while (endAt(k - 1) > t + kTolerance) --k;
    return k;
  }
  /// Start of the current period: the previous period's end, computed like every end (not
  /// as currentEnd() - period, which rounds differently: by 2.4e-7 s at 1.7e9 s).
  double currentStart() const { return endOf(index_ - 1); }
  bool due(double now) const { return started_ && now + kTolerance >= currentEnd(); }
  /// Whether time t lies in the current period (by the convention of indexOf()).
  bool inCurrent(double t) const {
    return t + kTolerance < currentEnd() && t + kTolerance >= currentStart();
  }
  /// Whether `time` lies before the current period by more than the tolerance: the clock ran
  /// backwards. This is the negation of due() for the previous period, with the same
  /// expression for its end, so a reading that made a period due - the same reading passed
  /// again by the next callback, or one within the tolerance below the end - never counts as
  /// running backwards.
  bool before(double time) const { return started_ && time + kTolerance < currentStart(); }
  void advance() { ++index_; }

  /// Number of periods that have ended by `now` and are not estimated yet (0 when not due):
  /// after advancing by them, `now` lies in the current period. Counted against the end
  /// times themselves (indexOf), never by dividing the time since the current end by the
  /// period, whose rounding can count a period that due() would not.
  std::uint64_t periodsDue(double now) const {
    if (!due(now)) return 0;
    return static_cast<std::uint64_t>(indexOf(now)) - index_;
  }

  /// Moves the schedule forward by whole periods so that `now` lies in the current period,
  /// keeping the phase (used after a long gap instead of estimating every missed period).
  void skipTo(double now) { index_ += periodsDue(now); }

 private:
  /// endOf() for any (also negative) index.
  double endAt(std::int64_t k) const {
    if (grid_) return (*grid_ + static_cast<double>(k)) * period_;
    return start_ + static_cast<double>(k) * period_;
  }

  /// Period ends are sums of doubles; a clock reading within a microsecond of an end counts
  /// as reaching it (ROS times near 1.7e9 s resolve to about 0.2 us).
  static constexpr double kTolerance = 1e-6;

  double period_;
  double start_ = 0.0;
  std::optional<double> grid_;  ///< the first period's start / period, on the clock grid
  std::uint64_t index_ = 1;
  bool started_ = false;
};

}  // namespace sf_filter
