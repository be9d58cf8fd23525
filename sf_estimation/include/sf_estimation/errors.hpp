// Exception types of sf_estimation. Every error names what was wrong; a step that throws
// leaves the filter exactly as it was before the call.
#pragma once

#include <stdexcept>
#include <string>

namespace estimation {

/// Base of all errors thrown by the library.
class EstimationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A measurement or control value was rejected (NaN, Inf, bad variance, wrong size).
class InvalidInputError : public EstimationError {
 public:
  using EstimationError::EstimationError;
};

/// A parameter given to a filter or to the factory is missing, of the wrong type or size.
class ParameterError : public EstimationError {
 public:
  using EstimationError::EstimationError;
};

/// A numerical operation failed (covariance not positive definite, non-finite result).
class NumericalError : public EstimationError {
 public:
  using EstimationError::EstimationError;
};

/// Throws NumericalError "<method>: <reason>; step rejected" (compiled once in the library,
/// src/errors.cpp, for the filters of every size).
[[noreturn]] void rejectStep(const std::string& method, const char* reason);

}  // namespace estimation
