// Moving average: each measurement entry is smoothed separately by the weighted mean of its
// last `windowSize` present values. It has no model of the process, so it serves as a simple
// baseline and as a smoother of a single noisy signal.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/types.hpp"
#include "sf_estimation/window_smoother.hpp"

namespace estimation {

/// Output entry i is the weighted mean of the values held in the window of input entry i, and
/// its variance is the weighted variance of those values around that mean (0 with one value):
/// the spread of the window, not the uncertainty of the mean. The weights are normalised over
/// the values actually held, so a window that is not yet full already averages correctly.
///
/// Missing entries: see WindowSmoother. An entry's output is undefined (0, infinite variance)
/// until its window holds a value with positive weight (e.g. no value yet, or a delay-line
/// weighting {0, 1} after one value).
class MovingAverage : public WindowSmoother<MovingAverage> {
 public:
  static constexpr const char* kName = "MovingAverage";

  /// Equal weights.
  MovingAverage(Index inputCount, Index windowSize)
      : MovingAverage(inputCount, windowSize,
                      Eigen::VectorXd::Ones(WindowSmoother::checkedWindowSize(windowSize)), false) {
  }

  /// weights[0] applies to the newest value, weights[windowSize - 1] to the oldest. They must
  /// be finite, non-negative, with a positive sum; they need not sum to 1.
  MovingAverage(Index inputCount, Index windowSize, const std::vector<double>& weights)
      : MovingAverage(
            inputCount, windowSize,
            Eigen::Map<const Eigen::VectorXd>(weights.data(), static_cast<Index>(weights.size())),
            true) {}

  /// As above; a template so that a braced list {..} unambiguously means std::vector.
  template <class Derived>
  MovingAverage(Index inputCount, Index windowSize, const Eigen::MatrixBase<Derived>& weights)
      : MovingAverage(inputCount, windowSize, Eigen::VectorXd(weights), true) {}

  const Eigen::VectorXd& weights() const { return weights_; }

  std::string description() const {
    std::ostringstream text;
    text << "MovingAverage(inputs=" << measurementSize() << ", window=" << windowSize();
    if (customWeights_) {
      text << ", weights=[";
      for (Index a = 0; a < weights_.size(); ++a) text << (a ? ", " : "") << weights_(a);
      text << "]";
    }
    text << ")";
    return text.str();
  }

 private:
  MovingAverage(Index inputCount, Index windowSize, const Eigen::VectorXd& weights,
                bool customWeights)
      : WindowSmoother(inputCount, windowSize),
        weights_(checkedWeights(weights, windowSize)),
        customWeights_(customWeights) {}

  static const Eigen::VectorXd& checkedWeights(const Eigen::VectorXd& weights, Index windowSize) {
    if (weights.size() != windowSize) {
      throw ParameterError("MovingAverage: parameter 'weights' has " +
                           std::to_string(weights.size()) + " entries, windowSize is " +
                           std::to_string(windowSize));
    }
    for (Index a = 0; a < weights.size(); ++a) {
      if (!std::isfinite(weights(a)) || weights(a) < 0.0) {
        throw ParameterError("MovingAverage: parameter 'weights' entry " + std::to_string(a) +
                             " must be finite and non-negative, got " + std::to_string(weights(a)));
      }
    }
    if (!(weights.sum() > 0.0)) {
      throw ParameterError("MovingAverage: parameter 'weights' must have a positive sum");
    }
    return weights;
  }

  friend class WindowSmoother<MovingAverage>;

  void updateOutput(Index i) {
    const Index held = windows_.count(i);
    double weightSum = 0.0;
    double weightedSum = 0.0;
    for (Index age = 0; age < held; ++age) {
      weightSum += weights_(age);
      weightedSum += weights_(age) * windows_.value(i, age);
    }
    if (!(weightSum > 0.0)) {  // only zero-weight values held so far
      state_(i) = 0.0;
      covariance_(i, i) = std::numeric_limits<double>::infinity();
      return;
    }
    const double mean = weightedSum / weightSum;
    double weightedSquares = 0.0;
    for (Index age = 0; age < held; ++age) {
      const double deviation = windows_.value(i, age) - mean;
      weightedSquares += weights_(age) * deviation * deviation;
    }
    state_(i) = mean;
    covariance_(i, i) = weightedSquares / weightSum;
  }

  Eigen::VectorXd weights_;
  bool customWeights_;
};

}  // namespace estimation
