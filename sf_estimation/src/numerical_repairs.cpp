#include "sf_estimation/numerical_repairs.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace estimation {
namespace {

/// Up to this many states the repair works on stack storage (no allocation in a step).
constexpr int kBoundedStates = 16;
using BoundedMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kBoundedStates,
                                    kBoundedStates>;

template <class MatrixType>
bool repairWith(Eigen::Ref<Eigen::MatrixXd> P) {
  const MatrixType value = P;
  const double scale = value.diagonal().cwiseAbs().maxCoeff();
  const Eigen::LDLT<MatrixType> ldlt(value);
  if (ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() >= -kCovarianceTolerance * scale) {
    return false;
  }
  const Eigen::SelfAdjointEigenSolver<MatrixType> eigen(value);
  if (eigen.info() != Eigen::Success) return false;  // leave it to the caller's checks
  const auto floored = eigen.eigenvalues().cwiseMax(0.0).eval();
  const MatrixType repaired =
      eigen.eigenvectors() * floored.asDiagonal() * eigen.eigenvectors().transpose();
  P = 0.5 * (repaired + repaired.transpose());
  return true;
}

}  // namespace

bool repairIndefiniteCovariance(Eigen::Ref<Eigen::MatrixXd> P) {
  if (P.rows() == 0) return false;
  if (P.rows() <= kBoundedStates) return repairWith<BoundedMatrix>(P);
  return repairWith<Eigen::MatrixXd>(P);
}

}  // namespace estimation
