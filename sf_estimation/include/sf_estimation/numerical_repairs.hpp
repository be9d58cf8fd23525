// What the filters repair instead of failing, and the covariance repair itself.
//
// Rules (doc/estimation.md, "Numerical faults"):
//  - a covariance that lost positive semi-definiteness beyond rounding (an LDLT pivot below
//    -1e-9 times its largest diagonal entry) is replaced by its nearest positive
//    semi-definite matrix in the Frobenius norm: eigenvalues below zero are raised to zero
//    (Higham 1988). Counted in NumericalRepairs::covariance.
//  - particle filter: a particle whose likelihood is not a number gets weight zero; a step in
//    which every weight vanished drops its measurement (the weights stay as before it, as
//    for a missing measurement). Counted in NumericalRepairs::weights.
//  - unscented Kalman filter: sigma points too close to a state far from the origin to be
//    resolved in floating point get a larger alpha for that step
//    (UnscentedTransform::alphaFor). Counted in NumericalRepairs::sigmaSpread.
// A failure that cannot be repaired (an innovation covariance that is not positive definite,
// a non-finite prediction) rejects the step with NumericalError and leaves the filter as it
// was.
#pragma once

#include <cstdint>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "sf_estimation/parameter_checks.hpp"
#include "sf_estimation/probability/cholesky.hpp"
#include "sf_estimation/probability/gaussian.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// Counts of repairs since the filter was constructed (reset() keeps them).
struct NumericalRepairs {
  std::uint64_t covariance = 0;   ///< covariances projected back to positive semi-definite
  std::uint64_t weights = 0;      ///< PF steps whose measurement made every weight vanish
  std::uint64_t sigmaSpread = 0;  ///< UKF steps that widened alpha to resolve a badly scaled state

  std::uint64_t total() const { return covariance + weights + sigmaSpread; }

  NumericalRepairs& operator+=(const NumericalRepairs& other) {
    covariance += other.covariance;
    weights += other.weights;
    sigmaSpread += other.sigmaSpread;
    return *this;
  }
};

/// True if Filter counts its repairs (Kalman filters, particle filter).
template <class Filter, class = void>
struct HasNumericalRepairs : std::false_type {};
template <class Filter>
struct HasNumericalRepairs<Filter,
                           std::void_t<decltype(std::declval<const Filter&>().numericalRepairs())>>
    : std::true_type {};

/// Relative tolerance on negative LDLT pivots: rounding in a covariance update stays far
/// below it, a genuinely indefinite matrix (a negative variance) far above. The same value
/// as CovarianceSquareRoot's, so a covariance accepted here can be given sigma points.
constexpr double kCovarianceTolerance = 1e-9;

/// The part of repairCovariance() after a failed Cholesky factorisation: judges P by a
/// pivoted LDLT and, if it is indefinite beyond rounding, floors its eigenvalues. Compiled
/// once in the library (src/numerical_repairs.cpp): an eigen-solver instantiated for every
/// state size cost most of a configuration's compile time. The judgement is allocation-free up
/// to 16 states; the repair itself, a counted fault, works on a heap copy.
bool repairIndefiniteCovariance(Eigen::Ref<Eigen::MatrixXd> P);

/// Makes a finite symmetric P positive semi-definite if it is not (see the rules above).
/// Returns true if P was changed. Costs one square-root-free Cholesky factorisation when P is
/// positive definite (the usual case), one pivoted LDLT more when it is only semi-definite.
template <int N>
bool repairCovariance(Matrix<N, N>& P) {
  if (P.rows() == 0) return false;
  // The unpivoted factorisation exists only for a positive definite matrix; it is much
  // cheaper than the pivoted LDLT, which is needed only to judge a singular P.
  if (probability::positiveDefinite(P)) return false;
  return repairIndefiniteCovariance(P);
}

}  // namespace estimation
