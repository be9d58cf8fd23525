#include "sf_estimation/parameter_checks.hpp"

#include "sf_estimation/model.hpp"

#include <algorithm>
#include <cstdio>

#include <Eigen/Cholesky>

namespace estimation {

std::string sizeText(Index rows, Index cols) {
  return std::to_string(rows) + "x" + std::to_string(cols);
}

void requireSize(const std::string& method, const std::string& name,
                 const Eigen::Ref<const Eigen::MatrixXd>& value, Index rows, Index cols) {
  if (value.rows() != rows || value.cols() != cols) {
    throw ParameterError(method + ": parameter '" + name + "' must be " + sizeText(rows, cols) +
                         ", got " + sizeText(value.rows(), value.cols()));
  }
  if (!value.allFinite()) {
    throw ParameterError(method + ": parameter '" + name + "' contains a non-finite value");
  }
}

bool nearlySymmetric(const Eigen::Ref<const Eigen::MatrixXd>& P) {
  if (P.rows() != P.cols() || !P.allFinite()) return false;
  if (P.size() == 0) return true;
  const double scale = std::max(1.0, P.cwiseAbs().maxCoeff());
  return P.isApprox(P.transpose(), kSymmetryTolerance) ||
         (P - P.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale;
}

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
  if (!nearlySymmetric(value)) {
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

void requireFilterParameters(const std::string& method, const Eigen::Ref<const Eigen::MatrixXd>& Q,
                             const Eigen::Ref<const Eigen::MatrixXd>& R,
                             const Eigen::Ref<const Eigen::MatrixXd>& x0,
                             const Eigen::Ref<const Eigen::MatrixXd>& P0) {
  const Index n = Q.rows();
  if (n < 1) {
    throw ParameterError(method + ": the state must have at least one variable (Q is " +
                         sizeText(Q.rows(), Q.cols()) + ")");
  }
  requireCovariance(method, "Q", Q, n, false);
  requireCovariance(method, "R", R, R.rows(), true);
  requireSize(method, "x0", x0, n, 1);
  requireCovariance(method, "P0", P0, n, false);
}

void requireControlSize(const std::string& method, Index controlSize, Index fixedControlSize) {
  if (controlSize < 0 || (fixedControlSize != Dynamic && controlSize != fixedControlSize)) {
    throw ParameterError(method + ": control size must be " + std::to_string(fixedControlSize));
  }
}

std::string filterDescription(const std::string& method, Index n, Index m, Index l,
                              const char* extraName, Index extraValue) {
  std::string text =
      method + "(n=" + std::to_string(n) + ", m=" + std::to_string(m) + ", l=" + std::to_string(l);
  if (extraName) text += std::string(", ") + extraName + "=" + std::to_string(extraValue);
  return text + ")";
}

void checkModelSizes(const std::string& method, Index modelStateSize, Index modelMeasurementSize,
                     Index stateSize, Index measurementSize) {
  if (modelStateSize != stateSize) {
    throw ParameterError(method + ": the model has state size " + std::to_string(modelStateSize) +
                         " but Q is " + sizeText(stateSize, stateSize));
  }
  if (modelMeasurementSize != measurementSize) {
    throw ParameterError(method + ": the model has " + std::to_string(modelMeasurementSize) +
                         " measurements but R is " + sizeText(measurementSize, measurementSize));
  }
}

}  // namespace estimation
