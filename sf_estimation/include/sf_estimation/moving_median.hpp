// Moving median: each measurement entry is smoothed separately by the median of its last
// `windowSize` present values. Unlike the moving average, a single outlier in the window does
// not move the output.
#pragma once

#include <algorithm>
#include <limits>
#include <string>

#include <Eigen/Core>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/sliding_windows.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// Output entry i is the median of the values held in the window of input entry i (an even
/// count gives the mean of the two middle values). Its variance is the (population) variance
/// of the window values around their mean, 0 with one value: the spread of the window, not
/// the uncertainty of the median.
///
/// A missing entry does not enter its window (the output keeps its value). Before the first
/// value of an entry its output is 0 with infinite variance: nothing is known yet. Controls
/// are ignored (ControlSize = 0).
class MovingMedian {
 public:
  static constexpr int StateSize = Dynamic;
  static constexpr int MeasurementSize = Dynamic;
  static constexpr int ControlSize = 0;

  MovingMedian(Index inputCount, Index windowSize)
      : windows_(checkedInputCount(inputCount), checkedWindowSize(windowSize)),
        scratch_(windowSize),
        state_(Eigen::VectorXd::Zero(inputCount)),
        covariance_(Eigen::MatrixXd::Zero(inputCount, inputCount)) {
    reset();
  }

  Index stateSize() const { return state_.size(); }
  Index measurementSize() const { return state_.size(); }
  Index controlSize() const { return 0; }
  Index windowSize() const { return windows_.capacity(); }

  /// Controls are ignored; only a size-0 control vector is accepted.
  template <class Derived>
  void setControl(const Eigen::MatrixBase<Derived>& u) {
    validateControl(u, 0);
  }

  /// Adds the present entries of z to their windows and recomputes those outputs. Throws
  /// InvalidInputError (nothing changed) on a wrong size or a non-finite present value.
  void estimate(const Measurement<MeasurementSize>& z) {
    z.validate(measurementSize());
    for (Index i = 0; i < measurementSize(); ++i) {
      if (!z.available(i)) continue;
      windows_.push(i, z.value(i));
      updateOutput(i);
    }
  }

  const Eigen::VectorXd& state() const { return state_; }
  /// Diagonal: the variances of the windows (infinite before an entry's first value).
  const Eigen::MatrixXd& covariance() const { return covariance_; }
  const Vector<ControlSize>& control() const { return control_; }

  /// Empties every window; outputs return to 0 with infinite variance.
  void reset() {
    windows_.clear();
    state_.setZero();
    covariance_.diagonal().setConstant(std::numeric_limits<double>::infinity());
  }

  std::string description() const {
    return "MovingMedian(inputs=" + std::to_string(measurementSize()) +
           ", window=" + std::to_string(windowSize()) + ")";
  }

 private:
  static Index checkedInputCount(Index inputCount) {
    if (inputCount < 1) {
      throw ParameterError("MovingMedian: parameter 'inputCount' must be at least 1, got " +
                           std::to_string(inputCount));
    }
    return inputCount;
  }

  static Index checkedWindowSize(Index windowSize) {
    if (windowSize < 1) {
      throw ParameterError("MovingMedian: parameter 'windowSize' must be at least 1, got " +
                           std::to_string(windowSize));
    }
    return windowSize;
  }

  void updateOutput(Index i) {
    const Index held = windows_.count(i);
    double sum = 0.0;
    for (Index age = 0; age < held; ++age) {
      scratch_(age) = windows_.value(i, age);
      sum += scratch_(age);
    }
    const double mean = sum / static_cast<double>(held);
    double squares = 0.0;
    for (Index age = 0; age < held; ++age) {
      squares += (scratch_(age) - mean) * (scratch_(age) - mean);
    }

    // nth_element puts the upper middle value at `middle` and only smaller-or-equal values
    // before it, so for an even count the lower middle value is the largest of those.
    double* first = scratch_.data();
    double* middle = first + held / 2;
    std::nth_element(first, middle, first + held);
    const double median =
        held % 2 == 1 ? *middle : 0.5 * *std::max_element(first, middle) + 0.5 * *middle;

    state_(i) = median;
    covariance_(i, i) = squares / static_cast<double>(held);
  }

  SlidingWindows windows_;
  Eigen::VectorXd scratch_;  // window copy reordered by nth_element, preallocated
  Eigen::VectorXd state_;
  Eigen::MatrixXd covariance_;  // diagonal; preallocated so covariance() returns a reference
  Vector<ControlSize> control_;
};

}  // namespace estimation
