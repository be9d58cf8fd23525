// LAST and SAMPLED alignment: of the values of an input received in an estimation period only
// the newest is used, with its own variance if the message carried one; no value means the
// input is missing. The thesis (section 4.3.4) suggests it for sensors of a state itself,
// such as a position, where the mean of the period lags behind the newest reading.
#pragma once

#include <cstdint>
#include <optional>

namespace sf_filter {

class PeriodNewest {
 public:
  void add(double value, std::optional<double> variance, double time) {
    value_ = value;
    variance_ = variance;
    time_ = time;
    ++count_;
  }

  bool empty() const { return count_ == 0; }
  /// Values received in the period (count() - 1 of them were superseded by a newer one).
  std::uint32_t count() const { return count_; }
  double value() const { return value_; }
  std::optional<double> variance() const { return variance_; }
  double time() const { return time_; }

  void clear() { *this = PeriodNewest(); }

 private:
  double value_ = 0.0;
  std::optional<double> variance_;
  double time_ = 0.0;
  std::uint32_t count_ = 0;
};

}  // namespace sf_filter
