#include "sf_estimation/parameter_checks.hpp"

#include <algorithm>
#include <cstdio>

#include <Eigen/Cholesky>

namespace estimation {

void requireCovariance(const std::string& method, const std::string& name,
                       const Eigen::Ref<const Eigen::MatrixXd>& value, Index size, bool strict) {
  requireSize(method, name, value, size, size);
  if (size == 0) return;  // maxCoeff() of an empty matrix is undefined
  const double largest = value.cwiseAbs().maxCoeff();
  if (largest > kMaxCovarianceEntry) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", largest);
    throw ParameterError(method + ": parameter '" + name + "' has an entry of magnitude " + text +
                         ", more than the maximum 1e100 (the filter's products would overflow)");
  }
  const double scale = std::max(1.0, largest);
  if (!value.isApprox(value.transpose(), 1e-9) &&
      (value - value.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
    throw ParameterError(method + ": parameter '" + name + "' must be symmetric");
  }
  Eigen::LDLT<Eigen::MatrixXd> ldlt(value);
  const Eigen::VectorXd d = ldlt.vectorD();
  if (ldlt.info() != Eigen::Success || !d.allFinite() || d.minCoeff() < -1e-12 * scale) {
    throw ParameterError(method + ": parameter '" + name + "' must be positive semi-definite");
  }
  if (strict && d.minCoeff() <= 0.0) {
    throw ParameterError(method + ": parameter '" + name + "' must be positive definite");
  }
}

}  // namespace estimation
