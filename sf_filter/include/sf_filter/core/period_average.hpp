// Temporal alignment of one input by averaging (thesis section 4.3.4): the values received in
// an estimation period are combined into one observation; no value means the input is missing.
#pragma once

#include <cstdint>
#include <optional>

namespace sf_filter {

class PeriodAverage {
 public:
  /// `variance` is the message's own variance, if it has one (else the configured R applies).
  void add(double value, std::optional<double> variance) {
    sum_ += value;
    ++count_;
    if (variance) {
      varianceSum_ += *variance;
      ++varianceCount_;
    }
  }

  bool empty() const { return count_ == 0; }
  std::uint32_t count() const { return count_; }
  double mean() const { return sum_ / count_; }

  /// True when every value of the period carried its own variance.
  bool hasVariance() const { return count_ > 0 && varianceCount_ == count_; }
  /// Variance of the mean of independent values: sum(var_i) / k^2.
  double meanVariance() const {
    return varianceSum_ / (static_cast<double>(count_) * static_cast<double>(count_));
  }

  void clear() { *this = PeriodAverage(); }

 private:
  double sum_ = 0.0;
  double varianceSum_ = 0.0;
  std::uint32_t count_ = 0;
  std::uint32_t varianceCount_ = 0;
};

}  // namespace sf_filter
