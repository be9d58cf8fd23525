// Checks of filter parameters done once at construction; each failure names the method,
// the parameter and the expected size, so a bad configuration is refused at start.
#pragma once

#include <cmath>
#include <string>

#include <Eigen/Core>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// The largest magnitude of a covariance entry (Q, R, P0): beyond it a filter's products
/// (P + Q, H P H^T, the Cholesky factor's squares) overflow to infinity and every step fails.
/// 1e100 is far beyond any physical variance and still leaves 1e200 of headroom.
constexpr double kMaxCovarianceEntry = 1e100;

inline std::string sizeText(Index rows, Index cols) {
  return std::to_string(rows) + "x" + std::to_string(cols);
}

template <class Derived>
void requireSize(const std::string& method, const std::string& name,
                 const Eigen::MatrixBase<Derived>& value, Index rows, Index cols) {
  if (value.rows() != rows || value.cols() != cols) {
    throw ParameterError(method + ": parameter '" + name + "' must be " + sizeText(rows, cols) +
                         ", got " + sizeText(value.rows(), value.cols()));
  }
  if (!value.allFinite()) {
    throw ParameterError(method + ": parameter '" + name + "' contains a non-finite value");
  }
}

/// A covariance must be finite with entries of magnitude at most kMaxCovarianceEntry,
/// symmetric (to a relative tolerance) and positive semi-definite (positive definite when
/// `strict`, e.g. the measurement noise R, whose inverse the Kalman-type filters use). Each
/// refusal names the method and the matrix. Not a template:
/// compiled once in the library, whatever the filters' sizes (src/parameter_checks.cpp).
void requireCovariance(const std::string& method, const std::string& name,
                       const Eigen::Ref<const Eigen::MatrixXd>& value, Index size, bool strict);

/// P <- (P + P^T) / 2, in place (a loop: the expression form cost a temporary and its own
/// instantiations per size).
template <class Derived>
void symmetrize(Eigen::MatrixBase<Derived>& P) {
  for (Index j = 0; j < P.cols(); ++j) {
    for (Index i = j + 1; i < P.rows(); ++i) {
      const double mean = 0.5 * (P(i, j) + P(j, i));
      P(i, j) = mean;
      P(j, i) = mean;
    }
  }
}

}  // namespace estimation
