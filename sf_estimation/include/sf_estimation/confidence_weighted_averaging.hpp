// Confidence-weighted averaging (Elmenreich): fuses redundant measurements of one quantity
// into a single estimate, weighting each by the inverse of its variance. It is the minimum-
// variance unbiased combination of independent measurements and needs no process model.
#pragma once

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <Eigen/Core>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// All present entries of one measurement give one output (state size 1):
///   x = sum(z_i / var_i) / sum(1 / var_i),   var = 1 / sum(1 / var_i).
/// var_i is the measurement's own variance for this step when given, otherwise
/// defaultVariances(i). Each step is independent of the previous ones, except that a step with
/// every entry missing keeps the previous estimate. The initial estimate is 0 with infinite
/// variance. Controls are ignored (ControlSize = 0).
class ConfidenceWeightedAveraging {
 public:
  static constexpr int StateSize = Dynamic;
  static constexpr int MeasurementSize = Dynamic;
  static constexpr int ControlSize = 0;

  /// defaultVariances(i) (finite, > 0) is the variance of input i when a measurement does not
  /// carry its own.
  ConfidenceWeightedAveraging(Index inputCount, const Eigen::VectorXd& defaultVariances)
      : defaultVariances_(checkedDefaultVariances(checkedInputCount(inputCount), defaultVariances)),
        state_(Eigen::VectorXd::Zero(1)),
        covariance_(Eigen::MatrixXd::Zero(1, 1)) {
    reset();
  }

  Index stateSize() const { return 1; }
  Index measurementSize() const { return defaultVariances_.size(); }
  Index controlSize() const { return 0; }
  const Eigen::VectorXd& defaultVariances() const { return defaultVariances_; }

  /// Controls are ignored; only a size-0 control vector is accepted.
  template <class Derived>
  void setControl(const Eigen::MatrixBase<Derived>& u) {
    validateControl(u, 0);
  }

  /// Fuses the present entries of z. Throws InvalidInputError on a wrong size, a non-finite
  /// value or a bad given variance, NumericalError when the fused result is not finite (e.g.
  /// a variance so small that its inverse overflows); the estimate is unchanged on a throw.
  void estimate(const Measurement<MeasurementSize>& z) {
    z.validate(measurementSize());
    if (!z.anyAvailable()) return;  // every entry missing: keep the last estimate
    double inverseVarianceSum = 0.0;
    double weightedSum = 0.0;
    for (Index i = 0; i < measurementSize(); ++i) {
      if (!z.available(i)) continue;
      const double variance = z.varianceGiven(i) ? z.variance(i) : defaultVariances_(i);
      inverseVarianceSum += 1.0 / variance;
      weightedSum += z.value(i) / variance;
    }
    const double fused = weightedSum / inverseVarianceSum;
    const double fusedVariance = 1.0 / inverseVarianceSum;
    if (!std::isfinite(fused) || !std::isfinite(fusedVariance)) {
      throw NumericalError("ConfidenceWeightedAveraging: fused estimate is not finite (" +
                           std::to_string(fused) + ", variance " + std::to_string(fusedVariance) +
                           ")");
    }
    state_(0) = fused;
    covariance_(0, 0) = fusedVariance;
  }

  const Eigen::VectorXd& state() const { return state_; }
  const Eigen::MatrixXd& covariance() const { return covariance_; }
  const Vector<ControlSize>& control() const { return control_; }

  /// Back to the initial estimate: 0 with infinite variance.
  void reset() {
    state_(0) = 0.0;
    covariance_(0, 0) = std::numeric_limits<double>::infinity();
  }

  std::string description() const {
    std::ostringstream text;
    text << "ConfidenceWeightedAveraging(inputs=" << measurementSize() << ", defaultVariances=[";
    for (Index i = 0; i < defaultVariances_.size(); ++i) {
      text << (i ? ", " : "") << defaultVariances_(i);
    }
    text << "])";
    return text.str();
  }

 private:
  static Index checkedInputCount(Index inputCount) {
    if (inputCount < 1) {
      throw ParameterError(
          "ConfidenceWeightedAveraging: parameter 'inputCount' must be at least 1, got " +
          std::to_string(inputCount));
    }
    return inputCount;
  }

  static const Eigen::VectorXd& checkedDefaultVariances(Index inputCount,
                                                        const Eigen::VectorXd& variances) {
    if (variances.size() != inputCount) {
      throw ParameterError("ConfidenceWeightedAveraging: parameter 'defaultVariances' has " +
                           std::to_string(variances.size()) + " entries, inputCount is " +
                           std::to_string(inputCount));
    }
    for (Index i = 0; i < variances.size(); ++i) {
      if (!std::isfinite(variances(i)) || !(variances(i) > 0.0)) {
        throw ParameterError("ConfidenceWeightedAveraging: parameter 'defaultVariances' entry " +
                             std::to_string(i) + " must be finite and positive, got " +
                             std::to_string(variances(i)));
      }
    }
    return variances;
  }

  Eigen::VectorXd defaultVariances_;
  Eigen::VectorXd state_;
  Eigen::MatrixXd covariance_;
  Vector<ControlSize> control_;
};

}  // namespace estimation
