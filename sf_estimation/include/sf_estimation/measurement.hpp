// A measurement vector for one estimation step: values, which entries are present, and
// optional per-entry variances that replace the diagonal of R for this step only, and
// optional covariances between entries (a sensor's covariance block: x with y of a pose)
// that replace the off-diagonal entries of R for this step only.
#pragma once

#include <cmath>
#include <string>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/probability/cholesky.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

namespace detail {
// The refusals of validate() and validateControl(), compiled once in the library
// (src/measurement_checks.cpp): the checks stay inline in each size's step, their texts not.
[[noreturn]] void refuseInputSize(const char* what, Index size, Index expected);
[[noreturn]] void refuseNonFiniteInput(const char* what, Index i, double value);
[[noreturn]] void refuseMeasurementVariance(Index i, double variance);
}  // namespace detail

template <int M>
struct Measurement {
  Vector<M> value;
  Mask<M> available;      ///< false: the entry is missing this step
  Mask<M> varianceGiven;  ///< true: variance(i) replaces R(i,i) this step
  Vector<M> variance;
  /// true (symmetric, off the diagonal): covariance(i, j) replaces R(i, j) this step. Only
  /// between present entries that carry their own variance, so that the block of R they
  /// replace comes from one source.
  PairMask<M> covarianceGiven;
  Matrix<M, M> covariance;

  explicit Measurement(Index size = (M == Dynamic ? 0 : M))
      : value(Vector<M>::Zero(size)),
        available(Mask<M>::Constant(size, true)),
        varianceGiven(Mask<M>::Constant(size, false)),
        variance(Vector<M>::Zero(size)),
        covarianceGiven(PairMask<M>::Constant(size, size, false)),
        covariance(Matrix<M, M>::Zero(size, size)) {}

  /// A measurement with every entry present and the configured noise.
  static Measurement complete(const Vector<M>& values) {
    Measurement result(values.size());
    result.value = values;
    return result;
  }

  /// A measurement with every entry missing (the step is a pure time update).
  static Measurement missing(Index size = (M == Dynamic ? 0 : M)) {
    Measurement result(size);
    result.available.setConstant(false);
    return result;
  }

  Index size() const { return value.size(); }
  /// Whether covariance(i, j) is used this step (given, both entries present).
  bool covarianceUsed(Index i, Index j) const {
    return covarianceGiven(i, j) && available(i) && available(j);
  }
  Index availableCount() const { return available.count(); }
  bool anyAvailable() const { return available.any(); }

  /// Throws InvalidInputError naming the first bad entry; ignores missing entries.
  void validate(Index expectedSize) const {
    if (value.size() != expectedSize || available.size() != expectedSize ||
        varianceGiven.size() != expectedSize || variance.size() != expectedSize ||
        covarianceGiven.rows() != expectedSize || covarianceGiven.cols() != expectedSize ||
        covariance.rows() != expectedSize || covariance.cols() != expectedSize) {
      detail::refuseInputSize("measurement", value.size(), expectedSize);
    }
    for (Index i = 0; i < expectedSize; ++i) {
      if (!available(i)) continue;
      if (!std::isfinite(value(i))) detail::refuseNonFiniteInput("measurement", i, value(i));
      if (varianceGiven(i) && !(std::isfinite(variance(i)) && variance(i) > 0.0)) {
        detail::refuseMeasurementVariance(i, variance(i));
      }
    }
    if (covarianceGiven.any()) validateCovariances();
  }

 private:
  /// The given covariances: off the diagonal, symmetric, finite, between entries with their
  /// own variance, and the block they form with those variances positive definite (else the
  /// step would fail in the filter's factorisation, or worse, pass with a wrong gain).
  void validateCovariances() const;
};

template <int M>
void Measurement<M>::validateCovariances() const {
  const Index m = size();
  Mask<M> inBlock = Mask<M>::Constant(m, false);
  for (Index i = 0; i < m; ++i) {
    for (Index j = 0; j < m; ++j) {
      if (!covarianceUsed(i, j)) continue;
      const std::string pair =
          "covariance of measurements " + std::to_string(i) + " and " + std::to_string(j);
      if (i == j) throw InvalidInputError(pair + " is on the diagonal: give it as a variance");
      if (!std::isfinite(covariance(i, j))) throw InvalidInputError(pair + " is not finite");
      if (!covarianceGiven(j, i) || covariance(i, j) != covariance(j, i)) {
        throw InvalidInputError(pair + " is not symmetric");
      }
      if (!varianceGiven(i) || !varianceGiven(j)) {
        throw InvalidInputError(pair + " is given without both their variances");
      }
      inBlock(i) = true;
    }
  }
  // The block with the identity on the rows outside it: positive definite iff the block is.
  Matrix<M, M> block = Matrix<M, M>::Identity(m, m);
  std::string entries;
  for (Index i = 0; i < m; ++i) {
    if (!inBlock(i)) continue;
    entries += (entries.empty() ? "" : ", ") + std::to_string(i);
    block(i, i) = variance(i);
    for (Index j = 0; j < m; ++j) {
      if (j != i && covarianceUsed(i, j)) block(i, j) = covariance(i, j);
    }
  }
  if (!probability::choleskyInPlace(block)) {
    throw InvalidInputError("covariance block of measurements " + entries +
                            " is not positive definite");
  }
}

// The check of given covariances (a Cholesky factorisation of the block) is compiled once in
// the library for the dynamic size and the measurement sizes 1..6 (src/measurement_checks.cpp);
// other sizes instantiate it where they use it.
#define SF_ESTIMATION_FOR_CHECKED_MEASUREMENT_SIZES(X) X(Dynamic) X(1) X(2) X(3) X(4) X(5) X(6)
#ifndef SF_ESTIMATION_INSTANTIATING_MEASUREMENT_CHECKS
#define SF_ESTIMATION_EXTERN_MEASUREMENT_CHECK(M) \
  extern template void Measurement<M>::validateCovariances() const;
SF_ESTIMATION_FOR_CHECKED_MEASUREMENT_SIZES(SF_ESTIMATION_EXTERN_MEASUREMENT_CHECK)
#undef SF_ESTIMATION_EXTERN_MEASUREMENT_CHECK
#endif

/// Throws InvalidInputError unless the control vector has the right size and is finite.
template <class Derived>
void validateControl(const Eigen::MatrixBase<Derived>& u, Index expectedSize) {
  if (u.size() != expectedSize) detail::refuseInputSize("control", u.size(), expectedSize);
  for (Index i = 0; i < u.size(); ++i) {
    if (!std::isfinite(u(i))) detail::refuseNonFiniteInput("control", i, u(i));
  }
}

}  // namespace estimation
