#include "sf_estimation/numerical_repairs.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace estimation {
namespace {

/// Up to this many states the LDLT judgement works on stack storage (no allocation in a step
/// whose covariance is only semi-definite, which some models give in every step).
constexpr int kBoundedStates = 16;
using BoundedMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kBoundedStates, kBoundedStates>;

/// True if P has an LDLT pivot below -kCovarianceTolerance times its largest diagonal entry.
template <class MatrixType>
bool indefiniteBeyondRounding(const Eigen::Ref<const Eigen::MatrixXd>& P) {
  const MatrixType value = P;
  const double scale = value.diagonal().cwiseAbs().maxCoeff();
  const Eigen::LDLT<MatrixType> ldlt(value);
  return ldlt.info() != Eigen::Success || ldlt.vectorD().minCoeff() < -kCovarianceTolerance * scale;
}

/// Replaces P by its nearest positive semi-definite matrix (eigenvalues floored at zero). On
/// the heap, for every size: it runs only for a covariance that is indefinite beyond rounding,
/// a fault that is counted, and each eigen-solver instance costs about 10 s of compile time.
bool floorEigenvalues(Eigen::Ref<Eigen::MatrixXd> P) {
  const Eigen::MatrixXd value = P;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(value);
  if (eigen.info() != Eigen::Success) return false;  // leave it to the caller's checks
  const Eigen::VectorXd floored = eigen.eigenvalues().cwiseMax(0.0);
  const Eigen::MatrixXd repaired =
      eigen.eigenvectors() * floored.asDiagonal() * eigen.eigenvectors().transpose();
  P = 0.5 * (repaired + repaired.transpose());
  return true;
}

}  // namespace

bool repairIndefiniteCovariance(Eigen::Ref<Eigen::MatrixXd> P) {
  if (P.rows() == 0) return false;
  const bool indefinite = P.rows() <= kBoundedStates ? indefiniteBeyondRounding<BoundedMatrix>(P)
                                                     : indefiniteBeyondRounding<Eigen::MatrixXd>(P);
  return indefinite && floorEigenvalues(P);
}

}  // namespace estimation
