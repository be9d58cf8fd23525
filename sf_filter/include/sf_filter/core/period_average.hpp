// Temporal alignment of one input by averaging (thesis section 4.3.4): the values received in
// an estimation period are combined into one observation; no value means the input is missing.
//
// An angle input (ANGLE_INPUTS, a derived ROLL, PITCH or YAW) is averaged on the circle: the
// mean is the direction of the resultant, m = atan2(sum sin a_i, sum cos a_i), so that 3.1 and
// -3.1 rad average to pi, not to 0. Its variance is the linearisation of that m in the
// readings, dm = sum cos(a_i - m) e_i / R with R = |sum (cos a_i, sin a_i)|:
//   var(m) = sum var_i cos^2(a_i - m) / R^2,
// which is sum var_i / k^2 (the linear mean's) when the readings agree and grows as they
// spread. It is kept as running sums, cos^2(a - m) = (1 + cos 2a cos 2m + sin 2a sin 2m) / 2.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include <sf_estimation/angles.hpp>

namespace sf_filter {

class PeriodAverage {
 public:
  /// `angle`: the values are angles in radians, averaged on the circle.
  explicit PeriodAverage(bool angle = false) : angle_(angle) {}

  /// `variance` is the message's own variance, if it has one (else the configured R applies).
  void add(double value, std::optional<double> variance) {
    ++count_;
    double s = 0.0, c = 0.0;
    if (angle_) {
      s = std::sin(value);
      c = std::cos(value);
      sinSum_ += s;
      cosSum_ += c;
    } else {
      sum_ += value;
    }
    if (variance) {
      varianceSum_ += *variance;
      ++varianceCount_;
      if (angle_) {
        varianceCos2_ += *variance * (c * c - s * s);
        varianceSin2_ += *variance * 2.0 * s * c;
      }
    }
  }

  bool empty() const { return count_ == 0; }
  std::uint32_t count() const { return count_; }
  bool angle() const { return angle_; }

  /// False only for angles spread evenly around the circle (0 and pi, say): their resultant
  /// vanishes and they have no mean direction.
  bool hasMean() const {
    return count_ > 0 && (!angle_ || std::hypot(sinSum_, cosSum_) > kMinResultant * count_);
  }
  /// The mean; for angles the circular mean, wrapped to (-pi, pi]. Requires hasMean().
  double mean() const {
    return angle_ ? estimation::wrapAngle(std::atan2(sinSum_, cosSum_)) : sum_ / count_;
  }

  /// The derivative of mean() by the reading `value` of the period: 1 / k, for angles
  /// cos(value - m) / R (the weights of the variance above). Requires hasMean().
  double weightOf(double value) const {
    if (!angle_) return 1.0 / count_;
    return std::cos(value - mean()) / std::hypot(sinSum_, cosSum_);
  }

  /// True when every value of the period carried its own variance.
  bool hasVariance() const { return count_ > 0 && varianceCount_ == count_; }
  /// Variance of the mean of independent values: sum(var_i) / k^2, for angles
  /// sum var_i cos^2(a_i - m) / R^2 (above). Requires hasMean() and hasVariance().
  double meanVariance() const {
    if (!angle_) {
      return varianceSum_ / (static_cast<double>(count_) * static_cast<double>(count_));
    }
    const double m = mean();
    const double weighted = 0.5 * (varianceSum_ + std::cos(2.0 * m) * varianceCos2_ +
                                   std::sin(2.0 * m) * varianceSin2_);
    return weighted / (sinSum_ * sinSum_ + cosSum_ * cosSum_);
  }

  void clear() { *this = PeriodAverage(angle_); }

 private:
  /// Resultant length per value below which the directions cancel (rounding of sin and cos).
  static constexpr double kMinResultant = 1e-9;

  bool angle_;
  double sum_ = 0.0;
  double sinSum_ = 0.0, cosSum_ = 0.0;
  double varianceSum_ = 0.0;
  double varianceCos2_ = 0.0, varianceSin2_ = 0.0;  ///< sum var_i cos 2a_i, sum var_i sin 2a_i
  std::uint32_t count_ = 0;
  std::uint32_t varianceCount_ = 0;
};

}  // namespace sf_filter
