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

std::string sizeText(Index rows, Index cols);

/// A parameter must have the given shape and finite entries; the refusal names the method and
/// the parameter. Not a template, like requireCovariance below: the filters of every size call
/// the one copy in the library (src/parameter_checks.cpp).
void requireSize(const std::string& method, const std::string& name,
                 const Eigen::Ref<const Eigen::MatrixXd>& value, Index rows, Index cols);

/// The relative asymmetry a covariance may have: ||P - P^T|| <= 1e-9 ||P|| (Frobenius norms),
/// or at most 1e-12 max(1, largest |entry|) in every entry (the rounding of a matrix near 0).
/// A covariance computed in floating point (a localiser's, a rotated one) is rarely symmetric
/// to the bit; an asymmetry above this is a fault, not rounding. The one rule of the filters'
/// parameters and beliefs, and of the fusion node's covariance blocks, GPS fixes and set_pose:
/// a matrix that passes is used symmetrised (symmetrize below), one that fails is refused.
constexpr double kSymmetryTolerance = 1e-9;

/// Whether the finite square matrix P is symmetric to kSymmetryTolerance (false for a
/// non-finite P). Compiled once in the library (src/parameter_checks.cpp).
bool nearlySymmetric(const Eigen::Ref<const Eigen::MatrixXd>& P);

/// A covariance must be finite with entries of magnitude at most kMaxCovarianceEntry,
/// symmetric (to kSymmetryTolerance, nearlySymmetric) and positive semi-definite (positive definite
/// when `strict`, e.g. the measurement noise R, whose inverse the Kalman-type filters use). Each
/// refusal names the method and the matrix. Not a template:
/// compiled once in the library, whatever the filters' sizes (src/parameter_checks.cpp).
void requireCovariance(const std::string& method, const std::string& name,
                       const Eigen::Ref<const Eigen::MatrixXd>& value, Index size, bool strict);

/// The model filters' (Kalman family, particle filter) common refusals: an empty state, and
/// Q, R (positive definite), x0 and P0 of the wrong shape or not covariances.
void requireFilterParameters(const std::string& method, const Eigen::Ref<const Eigen::MatrixXd>& Q,
                             const Eigen::Ref<const Eigen::MatrixXd>& R,
                             const Eigen::Ref<const Eigen::MatrixXd>& x0,
                             const Eigen::Ref<const Eigen::MatrixXd>& P0);

/// A control size must be non-negative, and `fixedControlSize` unless that is Dynamic.
void requireControlSize(const std::string& method, Index controlSize, Index fixedControlSize);

/// "method(n=.., m=.., l=..)", with ", <extraName>=<extraValue>" before the ")" when
/// extraName is given: what the filters' description() return.
std::string filterDescription(const std::string& method, Index n, Index m, Index l,
                              const char* extraName = nullptr, Index extraValue = 0);

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

/// symmetrize(P), returning whether every entry of the result is finite: the test is fused into
/// the pass that writes the entries (a separate pass over P cost as much as the averaging).
template <class Derived>
bool symmetrizeFinite(Eigen::MatrixBase<Derived>& P) {
  bool finite = true;
  for (Index j = 0; j < P.cols(); ++j) {
    finite &= P(j, j) - P(j, j) == 0.0;  // false for an infinity or a NaN
    for (Index i = j + 1; i < P.rows(); ++i) {
      const double mean = 0.5 * (P(i, j) + P(j, i));
      P(i, j) = mean;
      P(j, i) = mean;
      finite &= mean - mean == 0.0;
    }
  }
  return finite;
}

}  // namespace estimation
