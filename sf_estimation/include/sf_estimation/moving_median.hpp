// Moving median: each measurement entry is smoothed separately by the median of its last
// `windowSize` present values. Unlike the moving average, a single outlier in the window does
// not move the output.
#pragma once

#include <algorithm>
#include <string>

#include <Eigen/Core>

#include "sf_estimation/types.hpp"
#include "sf_estimation/window_smoother.hpp"

namespace estimation {

/// Output entry i is the median of the values held in the window of input entry i (an even
/// count gives the mean of the two middle values). Its variance is the (population) variance
/// of the window values around their mean, 0 with one value: the spread of the window, not
/// the uncertainty of the median.
///
/// Missing entries and the output before an entry's first value: see WindowSmoother.
class MovingMedian : public WindowSmoother<MovingMedian> {
 public:
  static constexpr const char* kName = "MovingMedian";

  MovingMedian(Index inputCount, Index windowSize)
      : WindowSmoother(inputCount, windowSize), scratch_(windowSize) {}

  std::string description() const {
    return "MovingMedian(inputs=" + std::to_string(measurementSize()) +
           ", window=" + std::to_string(windowSize()) + ")";
  }

 private:
  friend class WindowSmoother<MovingMedian>;

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

  Eigen::VectorXd scratch_;  // window copy reordered by nth_element, preallocated
};

}  // namespace estimation
