// Generated default parameters of the configuration (see configuration.hpp for the API).
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"
#include "sf_filter/config/detail/quaternions.hpp"

namespace sf_config {

/// The numeric parameters of the configuration header. defaultParameters() fills them from the
/// macros (or the documented defaults); the node may override them, e.g. from ROS parameters.
/// Members a method does not use keep their defaults.
struct Parameters {
  using StateVector = Eigen::Matrix<double, kStateSize, 1>;
  using StateMatrix = Eigen::Matrix<double, kStateSize, kStateSize>;
  using MeasurementMatrix = Eigen::Matrix<double, kMeasurementSize, kMeasurementSize>;

  double estimation_period_ms = kEstimationPeriodMs;  ///< ESTIMATION_PERIOD (default 100)
  StateMatrix process_noise_covariance;               ///< Q, PROCESS_NOISE_COVARIANCE (default 0)
  MeasurementMatrix measurement_noise_covariance;  ///< R, MEASUREMENT_NOISE_COVARIANCE (default I)
  StateVector initial_state;                       ///< x0, INITIAL_STATE (default 0)
  StateMatrix initial_error_covariance;            ///< P0, INITIAL_ERROR_COVARIANCE (default I)
  // Each method's own parameters (SF_METHOD_PARAMETER in its traits header, config/methods/),
  // with the header's values: number_of_particles, random_seed, resampling_threshold,
  // ukf_alpha, ukf_beta, ukf_kappa, ukf_propagated_mean.
#define SF_METHOD_PARAMETER(type, name, fallback, header_default) \
  type name = static_cast<type>(header_default);
#define SF_METHOD_PART SF_METHOD_PART_PARAMETERS
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART
#undef SF_METHOD_PARAMETER
  int window_size = kWindowSize;           ///< WINDOW_SIZE (default 1, CWA only)
  Eigen::VectorXd weighting_coefficients;  ///< WEIGHTING_COEFFICIENTS (default empty)
};

#if SF_CFG_HAS_QUATERNION_STATES
/// Q and P0 of a header with QUATERNION_STATES: d x d, over the tangent space.
using TangentMatrix = Eigen::Matrix<double, kTangentSize, kTangentSize>;
#endif

/// The parameters of the configuration header. Matrix and vector entries may use T, which is
/// estimation_period_ms / 1000 (seconds), so pass the period actually used by the node.
inline Parameters defaultParameters(double estimation_period_ms = kEstimationPeriodMs) {
  SF_CFG_MATH_USINGS
  const double T = estimation_period_ms / 1000.0;
  static_cast<void>(T);
  Parameters parameters;
  parameters.estimation_period_ms = estimation_period_ms;

  parameters.process_noise_covariance.setZero();
#if SF_CFG_HAS_PROCESS_NOISE_COVARIANCE && !SF_CFG_IS_AVERAGING && SF_CFG_HAS_QUATERNION_STATES
  TangentMatrix tangent_q = TangentMatrix::Zero();
  SF_PP_ASSIGN_MATRIX(tangent_q, PROCESS_NOISE_COVARIANCE)
  parameters.process_noise_covariance = storedCovariance(tangent_q);
#elif SF_CFG_HAS_PROCESS_NOISE_COVARIANCE && !SF_CFG_IS_AVERAGING
  SF_PP_ASSIGN_MATRIX(parameters.process_noise_covariance, PROCESS_NOISE_COVARIANCE)
#endif

  parameters.measurement_noise_covariance.setIdentity();
#if SF_CFG_HAS_MEASUREMENT_NOISE_COVARIANCE
  parameters.measurement_noise_covariance.setZero();
  SF_PP_ASSIGN_MATRIX(parameters.measurement_noise_covariance, MEASUREMENT_NOISE_COVARIANCE)
#endif

  parameters.initial_state.setZero();
#if SF_CFG_HAS_INITIAL_STATE && !SF_CFG_IS_AVERAGING
  SF_PP_ASSIGN_VECTOR(parameters.initial_state, INITIAL_STATE)
#elif SF_CFG_HAS_QUATERNION_STATES
  for (const int q : quaternions_detail::kStarts) parameters.initial_state(q) = 1.0;  // identity
#endif

  parameters.initial_error_covariance.setIdentity();
#if SF_CFG_HAS_INITIAL_ERROR_COVARIANCE && !SF_CFG_IS_AVERAGING && SF_CFG_HAS_QUATERNION_STATES
  TangentMatrix tangent_p0 = TangentMatrix::Zero();
  SF_PP_ASSIGN_MATRIX(tangent_p0, INITIAL_ERROR_COVARIANCE)
  parameters.initial_error_covariance = storedCovariance(tangent_p0);
#elif SF_CFG_HAS_QUATERNION_STATES
  parameters.initial_error_covariance = storedCovariance(TangentMatrix::Identity());
#elif SF_CFG_HAS_INITIAL_ERROR_COVARIANCE && !SF_CFG_IS_AVERAGING
  parameters.initial_error_covariance.setZero();
  SF_PP_ASSIGN_MATRIX(parameters.initial_error_covariance, INITIAL_ERROR_COVARIANCE)
#endif

#if SF_CFG_HAS_WEIGHTING_COEFFICIENTS
  parameters.weighting_coefficients.resize(BOOST_PP_SEQ_SIZE(WEIGHTING_COEFFICIENTS));
  SF_PP_ASSIGN_VECTOR(parameters.weighting_coefficients, WEIGHTING_COEFFICIENTS)
#endif
  return parameters;
}

}  // namespace sf_config
