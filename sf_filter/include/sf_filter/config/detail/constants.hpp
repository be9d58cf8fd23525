// Generated compile-time constants of the configuration (see configuration.hpp for the API).
#pragma once

#include "sf_filter/config/detail/validation.hpp"

// clang-format off
#if defined(ESTIMATION_PERIOD)
#define SF_CFG_ESTIMATION_PERIOD (ESTIMATION_PERIOD)
#else
#define SF_CFG_ESTIMATION_PERIOD 100
#endif
// The methods' own macros have their defaults in their traits headers (config/methods/).
#if defined(WINDOW_SIZE)
#define SF_CFG_WINDOW_SIZE (WINDOW_SIZE)
#else
#define SF_CFG_WINDOW_SIZE 1
#endif
// clang-format on

namespace sf_config {

/// The configured method (one of the macros of methods.hpp) and its name (its traits header).
constexpr int kMethod = METHOD;
constexpr const char* kMethodName = SF_CFG_METHOD_NAME;

/// n, m and l (see configuration.hpp for how they are derived).
constexpr int kStateSize = SF_CFG_N;
constexpr int kMeasurementSize = SF_CFG_M;
constexpr int kControlSize = SF_CFG_L;

/// Which optional parts the configuration header gives.
constexpr bool kHasControls = SF_CFG_L > 0;
constexpr bool kHasTransitionJacobian = SF_CFG_HAS_STATE_TRANSITION_JACOBIAN || SF_CFG_IS_LINEAR;
constexpr bool kHasObservationJacobian = SF_CFG_HAS_OBSERVATION_JACOBIAN || SF_CFG_IS_LINEAR;
constexpr bool kHasInitialState = SF_CFG_HAS_INITIAL_STATE;
constexpr bool kHasInitialErrorCovariance = SF_CFG_HAS_INITIAL_ERROR_COVARIANCE;
constexpr bool kHasMeasurementNoiseCovariance = SF_CFG_HAS_MEASUREMENT_NOISE_COVARIANCE;
constexpr bool kHasWeightingCoefficients = SF_CFG_HAS_WEIGHTING_COEFFICIENTS;

/// Defaults of the scalar parameters (the macro's value, or the documented default).
constexpr double kEstimationPeriodMs = static_cast<double>(SF_CFG_ESTIMATION_PERIOD);
constexpr int kWindowSize = static_cast<int>(SF_CFG_WINDOW_SIZE);

}  // namespace sf_config
