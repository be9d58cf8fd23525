// Everything one input received in one estimation period, kept in the forms the alignment
// policies read: the running mean (AVERAGE), the newest value (LAST, SAMPLED, HOLD, FILL) and
// the newest samples with their times (shifted into the HOLD and FILL histories once the
// period is estimated). Fixed size, no allocation.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "sf_filter/core/alignment/period_newest.hpp"
#include "sf_filter/core/alignment/sample_history.hpp"
#include "sf_filter/core/period_average.hpp"

namespace sf_filter {

class InputPeriod {
 public:
  /// `samplesKept`: how many of the period's samples the input's policy needs (0: none);
  /// `angle`: the values are angles in radians (averaged on the circle).
  explicit InputPeriod(int samplesKept = 0, bool angle = false)
      : average_(angle), samples_(samplesKept), keepSamples_(samplesKept > 0) {}

  /// `time`: where the value belongs (its stamp or arrival); `arrival`: when it arrived
  /// (default: `time`).
  void add(double value, std::optional<double> variance, double time,
           double arrival = std::numeric_limits<double>::quiet_NaN()) {
    if (std::isnan(arrival)) arrival = time;
    if (!(arrival <= newestArrival_)) newestArrival_ = arrival;
    average_.add(value, variance);
    newest_.add(value, variance, time);
    if (keepSamples_) samples_.push(time, value);
  }

  bool empty() const { return average_.empty(); }
  std::uint32_t count() const { return average_.count(); }
  const PeriodAverage& average() const { return average_; }
  const PeriodNewest& newest() const { return newest_; }
  /// The period's newest samples, oldest first via samples()[size - 1 .. 0].
  const SampleHistory& samples() const { return samples_; }
  /// The latest arrival of the period's values (NaN if none).
  double newestArrival() const { return newestArrival_; }

  void clear() {
    average_.clear();
    newest_.clear();
    samples_.clear();
    newestArrival_ = std::numeric_limits<double>::quiet_NaN();
  }

 private:
  PeriodAverage average_;
  PeriodNewest newest_;
  SampleHistory samples_;
  bool keepSamples_;
  double newestArrival_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace sf_filter
