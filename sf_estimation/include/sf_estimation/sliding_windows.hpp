// One ring buffer per channel holding the last `capacity` values pushed to that channel. The
// storage is allocated at construction, so pushing and reading never allocate; the window
// filters (moving average, moving median) keep one channel per measurement entry.
#pragma once

#include <algorithm>
#include <string>

#include <Eigen/Core>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

class SlidingWindows {
 public:
  SlidingWindows(Index channelCount, Index capacity) {
    if (channelCount < 0) {
      throw ParameterError("SlidingWindows: parameter 'channelCount' must not be negative, got " +
                           std::to_string(channelCount));
    }
    if (capacity < 1) {
      throw ParameterError("SlidingWindows: parameter 'capacity' must be at least 1, got " +
                           std::to_string(capacity));
    }
    values_ = Eigen::MatrixXd::Zero(capacity, channelCount);
    counts_ = IndexVector::Zero(channelCount);
    newest_ = IndexVector::Constant(channelCount, -1);
  }

  Index channelCount() const { return values_.cols(); }
  Index capacity() const { return values_.rows(); }

  /// Number of values held by `channel` (at most capacity()).
  Index count(Index channel) const { return counts_(channel); }

  /// Appends `value` to `channel`, dropping the oldest value when the window is full.
  void push(Index channel, double value) {
    const Index slot = (newest_(channel) + 1) % capacity();
    values_(slot, channel) = value;
    newest_(channel) = slot;
    counts_(channel) = std::min(counts_(channel) + 1, capacity());
  }

  /// The value pushed `age` pushes ago: age 0 is the newest, count(channel) - 1 the oldest.
  double value(Index channel, Index age) const {
    Index slot = newest_(channel) - age;
    if (slot < 0) slot += capacity();
    return values_(slot, channel);
  }

  /// Empties every window.
  void clear() {
    counts_.setZero();
    newest_.setConstant(-1);
  }

 private:
  using IndexVector = Eigen::Matrix<Index, Eigen::Dynamic, 1>;

  Eigen::MatrixXd values_;  // capacity x channelCount, one ring buffer per column
  IndexVector counts_;
  IndexVector newest_;  // slot of the newest value, -1 while empty
};

}  // namespace estimation
