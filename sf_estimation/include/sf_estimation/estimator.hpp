// IEstimator: the one interface every method implements (thesis Figure 4.8).
#pragma once

#include <ostream>
#include <string>

#include "sf_estimation/numerical_repairs.hpp"
#include "sf_estimation/value.hpp"

namespace estimation {

class IEstimator {
 public:
  virtual ~IEstimator() = default;

  /// Runs one estimation step (time update with the last control, then correction with the
  /// present entries of `measurements`) and returns the new estimate. Throws
  /// InvalidInputError or NumericalError and leaves the estimator unchanged on failure.
  virtual Output estimate(const Input& measurements) = 0;

  /// Sets the control vector used by the following time updates. Missing entries keep
  /// their previous value. Throws InvalidInputError on a wrong size or non-finite value.
  virtual void setControlInput(const Input& controls) = 0;

  virtual const Output& getLastEstimate() const = 0;

  /// Method name, sizes and main parameters, one line.
  virtual std::string description() const = 0;

  /// Restores the initial state and covariance.
  virtual void reset() = 0;

  /// What the method repaired so far to keep estimating (numerical_repairs.hpp): counts that
  /// a caller can log. Zero for methods that never need a repair.
  virtual NumericalRepairs numericalRepairs() const { return {}; }
};

inline std::ostream& operator<<(std::ostream& os, const IEstimator& estimator) {
  return os << estimator.description();
}

}  // namespace estimation
