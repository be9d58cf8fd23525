// What a filter expects its next measurement to be: the predicted measurement
// z^ = E[h(x(k|k-1))] and the covariance of h(x(k|k-1)), from the time update of the
// current belief with the current control, plus the configured R. A measurement gate needs
// them for the squared Mahalanobis distance of the innovation (vision/radar paper's gating),
// the gap-filling alignment for z^ as its newest control point (Wang et al., eq. 6).
//
// Filters that can predict (KF, EKF, UKF, SIR PF) provide
//   void predictMeasurement(MeasurementPrediction<M>& out) const;
// which leaves the filter unchanged. The averaging methods have no model and do not.
#pragma once

#include <cmath>
#include <optional>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "sf_estimation/angles.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/measurement_noise.hpp"
#include "sf_estimation/probability/cholesky.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

template <int M>
struct MeasurementPrediction {
  Vector<M> mean;           ///< z^, the predicted measurement
  Matrix<M, M> covariance;  ///< covariance of h(x(k|k-1)): H P(k|k-1) H^T for a Kalman filter
  Matrix<M, M> noise;       ///< R, the configured measurement noise
  Mask<M> angular;          ///< true: the entry is an angle, its innovation is wrapped

  explicit MeasurementPrediction(Index size = (M == Dynamic ? 0 : M))
      : mean(Vector<M>::Zero(size)),
        covariance(Matrix<M, M>::Zero(size, size)),
        noise(Matrix<M, M>::Zero(size, size)),
        angular(Mask<M>::Constant(size, false)) {}

  bool isAngle(Index i) const { return i < angular.size() && angular(i); }

  /// value - z^_i, wrapped to (-pi, pi] for an angle.
  double innovation(Index i, double value) const {
    const double y = value - mean(i);
    return isAngle(i) ? wrapAngle(y) : y;
  }

  Index size() const { return mean.size(); }

  /// S = covariance + R, as the filter's correction with z would use it: z's own variances
  /// replace the diagonal of R, missing entries are decoupled (identity row and column).
  void innovationCovariance(const Measurement<M>& z, Matrix<M, M>& S) const {
    effectiveMeasurementNoise(noise, z, S);
    for (Index i = 0; i < size(); ++i) {
      if (!z.available(i)) continue;
      for (Index j = 0; j < size(); ++j) {
        if (z.available(j)) S(i, j) += covariance(i, j);
      }
    }
  }
};

/// The innovation y = z - z^ (wrapped for angles) of the present entries of z judged by its
/// covariance S (the missing entries take no part): its squared Mahalanobis distance
/// y^T S^-1 y, the normalised innovation squared, chi-square distributed with as many degrees
/// of freedom as entries are present if the filter's model is right; and log det S. Both come
/// from one Cholesky factor of S; together they are the period's term of the innovations'
/// negative log-likelihood, -2 log p(z) = log det S + y^T S^-1 y + m log(2 pi), which the
/// prediction-error method minimises to identify Q and R.
struct InnovationLikelihood {
  double squaredDistance = 0.0;  ///< y^T S^-1 y
  double logDeterminant = 0.0;   ///< log det S over the present entries
};

/// Throws NumericalError when S is not positive definite.
///
/// The factor is Eigen::LLT's bit for bit (CholeskyOrder::sumFirst; checked on 2.7 million
/// random matrices of sizes 1..9 when it replaced Eigen::LLT, doc/build_cost.md), so the NIS
/// values, gates and tuned files are what they were; Eigen::LLT cost 3-4 s of compile time per
/// measurement size.
template <int M>
InnovationLikelihood innovationLikelihood(const MeasurementPrediction<M>& prediction,
                                          const Measurement<M>& z) {
  const Index m = prediction.size();
  Matrix<M, M> factor(m, m);
  prediction.innovationCovariance(z, factor);  // missing entries: identity, log det 0
  Vector<M> y(m);
  for (Index i = 0; i < m; ++i) y(i) = z.available(i) ? prediction.innovation(i, z.value(i)) : 0.0;
  if (!probability::choleskyInPlace<M, probability::CholeskyOrder::sumFirst>(factor)) {
    throw NumericalError("innovation covariance is not positive definite; no Mahalanobis distance");
  }
  InnovationLikelihood result;
  result.squaredDistance = factor.template triangularView<Eigen::Lower>().solve(y).squaredNorm();
  for (Index i = 0; i < m; ++i) result.logDeterminant += 2.0 * std::log(factor(i, i));
  return result;
}

/// y^T S^-1 y alone (innovationLikelihood). Throws NumericalError when S is not positive
/// definite.
template <int M>
double squaredMahalanobisDistance(const MeasurementPrediction<M>& prediction,
                                  const Measurement<M>& z) {
  return innovationLikelihood(prediction, z).squaredDistance;
}

/// (value - z^_i)^2 / S_ii for entry i alone, with S_ii = covariance(i, i) + `variance`
/// (R(i, i) when no variance is given): the one-dimensional case used by a per-input gate.
template <int M>
double squaredMahalanobisDistance(const MeasurementPrediction<M>& prediction, Index entry,
                                  double value, std::optional<double> variance = std::nullopt) {
  const double s =
      prediction.covariance(entry, entry) + (variance ? *variance : prediction.noise(entry, entry));
  if (!(s > 0.0)) {
    throw NumericalError("innovation variance of measurement " + std::to_string(entry) +
                         " is not positive; no Mahalanobis distance");
  }
  const double y = prediction.innovation(entry, value);
  return y * y / s;
}

// The likelihood terms of a whole measurement vector are compiled once in the library for the
// measurement sizes 1..6 and Dynamic (src/mahalanobis_distances.cpp); other sizes are
// instantiated where used. Dynamic is the window filters' size: inline, it brought Eigen's
// run-time-sized kernels into each of their nodes.
#ifndef SF_ESTIMATION_INSTANTIATING_MAHALANOBIS
extern template InnovationLikelihood innovationLikelihood<1>(const MeasurementPrediction<1>&,
                                                             const Measurement<1>&);
extern template InnovationLikelihood innovationLikelihood<2>(const MeasurementPrediction<2>&,
                                                             const Measurement<2>&);
extern template InnovationLikelihood innovationLikelihood<3>(const MeasurementPrediction<3>&,
                                                             const Measurement<3>&);
extern template InnovationLikelihood innovationLikelihood<4>(const MeasurementPrediction<4>&,
                                                             const Measurement<4>&);
extern template InnovationLikelihood innovationLikelihood<5>(const MeasurementPrediction<5>&,
                                                             const Measurement<5>&);
extern template InnovationLikelihood innovationLikelihood<6>(const MeasurementPrediction<6>&,
                                                             const Measurement<6>&);
extern template InnovationLikelihood innovationLikelihood<Dynamic>(
    const MeasurementPrediction<Dynamic>&, const Measurement<Dynamic>&);
#endif

/// True if Filter has predictMeasurement(MeasurementPrediction<MeasurementSize>&) const.
template <class Filter, class = void>
struct HasMeasurementPrediction : std::false_type {};
template <class Filter>
struct HasMeasurementPrediction<
    Filter, std::void_t<decltype(std::declval<const Filter&>().predictMeasurement(
                std::declval<MeasurementPrediction<Filter::MeasurementSize>&>()))>>
    : std::true_type {};

}  // namespace estimation
