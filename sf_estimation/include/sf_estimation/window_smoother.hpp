// The common frame of the window filters (moving average, moving median): each measurement
// entry is smoothed separately from the last `windowSize` present values of that entry. A
// filter derives from WindowSmoother<Self> and supplies only how one entry's output is
// computed from its window (updateOutput).
#pragma once

#include <limits>
#include <string>

#include <Eigen/Core>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/sliding_windows.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// Derived provides `static constexpr const char* kName` (for messages) and
/// `void updateOutput(Index i)`, which sets state_(i) and covariance_(i, i) from window i.
///
/// A missing entry does not enter its window (the output keeps its value). Until an entry's
/// output is defined its value is 0 with infinite variance: nothing is known yet. Controls are
/// ignored (ControlSize = 0).
template <class Derived>
class WindowSmoother {
 public:
  static constexpr int StateSize = Dynamic;
  static constexpr int MeasurementSize = Dynamic;
  static constexpr int ControlSize = 0;

  Index stateSize() const { return state_.size(); }
  Index measurementSize() const { return state_.size(); }
  Index controlSize() const { return 0; }
  Index windowSize() const { return windows_.capacity(); }

  /// Controls are ignored; only a size-0 control vector is accepted.
  template <class U>
  void setControl(const Eigen::MatrixBase<U>& u) {
    validateControl(u, 0);
  }

  /// Adds the present entries of z to their windows and recomputes those outputs. Throws
  /// InvalidInputError (nothing changed) on a wrong size or a non-finite present value.
  void estimate(const Measurement<MeasurementSize>& z) {
    z.validate(measurementSize());
    for (Index i = 0; i < measurementSize(); ++i) {
      if (!z.available(i)) continue;
      windows_.push(i, z.value(i));
      static_cast<Derived&>(*this).updateOutput(i);
    }
  }

  const Eigen::VectorXd& state() const { return state_; }
  /// Diagonal: the spread of each window (infinite while an entry's output is undefined).
  const Eigen::MatrixXd& covariance() const { return covariance_; }
  const Vector<ControlSize>& control() const { return control_; }

  /// Empties every window; outputs return to 0 with infinite variance.
  void reset() {
    windows_.clear();
    state_.setZero();
    covariance_.diagonal().setConstant(std::numeric_limits<double>::infinity());
  }

 protected:
  WindowSmoother(Index inputCount, Index windowSize)
      : windows_(checkedInputCount(inputCount), checkedWindowSize(windowSize)),
        state_(Eigen::VectorXd::Zero(inputCount)),
        covariance_(Eigen::MatrixXd::Zero(inputCount, inputCount)) {
    reset();
  }

  /// Upper limits, so that a mistyped size is refused instead of exhausting memory (the
  /// windows hold inputs x window values, the covariance inputs^2): at most 80 MB.
  static constexpr Index kMaxInputCount = 1000;
  static constexpr Index kMaxWindowSize = 10000;

  static Index checkedWindowSize(Index windowSize) {
    if (windowSize < 1 || windowSize > kMaxWindowSize) {
      throw ParameterError(std::string(Derived::kName) +
                           ": parameter 'windowSize' must be from 1 to " +
                           std::to_string(kMaxWindowSize) + ", got " + std::to_string(windowSize));
    }
    return windowSize;
  }

  SlidingWindows windows_;
  Eigen::VectorXd state_;
  Eigen::MatrixXd covariance_;  // diagonal; preallocated so covariance() returns a reference
  Vector<ControlSize> control_;

 private:
  static Index checkedInputCount(Index inputCount) {
    if (inputCount < 1 || inputCount > kMaxInputCount) {
      throw ParameterError(std::string(Derived::kName) +
                           ": parameter 'inputCount' must be from 1 to " +
                           std::to_string(kMaxInputCount) + ", got " + std::to_string(inputCount));
    }
    return inputCount;
  }
};

}  // namespace estimation
