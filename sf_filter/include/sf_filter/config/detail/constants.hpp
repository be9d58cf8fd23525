// Generated compile-time constants of the configuration (see configuration.hpp for the API).
#pragma once

#include "sf_filter/config/detail/validation.hpp"

// clang-format off
#if defined(ESTIMATION_PERIOD)
#define SF_CFG_ESTIMATION_PERIOD (ESTIMATION_PERIOD)
#else
#define SF_CFG_ESTIMATION_PERIOD 100
#endif
#if defined(NUMBER_OF_PARTICLES)
#define SF_CFG_NUMBER_OF_PARTICLES (NUMBER_OF_PARTICLES)
#else
#define SF_CFG_NUMBER_OF_PARTICLES 1000
#endif
#if defined(RANDOM_SEED)
#define SF_CFG_RANDOM_SEED (RANDOM_SEED)
#else
#define SF_CFG_RANDOM_SEED 42
#endif
#if defined(RESAMPLING_THRESHOLD)
#define SF_CFG_RESAMPLING_THRESHOLD (RESAMPLING_THRESHOLD)
#else
#define SF_CFG_RESAMPLING_THRESHOLD 0.5
#endif
#if defined(UKF_ALPHA)
#define SF_CFG_UKF_ALPHA (UKF_ALPHA)
#else
#define SF_CFG_UKF_ALPHA 1e-3
#endif
#if defined(UKF_BETA)
#define SF_CFG_UKF_BETA (UKF_BETA)
#else
#define SF_CFG_UKF_BETA 2.0
#endif
#if defined(UKF_KAPPA)
#define SF_CFG_UKF_KAPPA (UKF_KAPPA)
#else
#define SF_CFG_UKF_KAPPA 0.0
#endif
// The UKF's predicted mean (estimation::PredictedMean): f of the mean (UKF-M) for a state with
// angles, whose sigma-point average shortens every dead-reckoned step by the heading's spread
// (doc/manifolds.md); the sigma points' weighted mean (thesis Algorithm 3.3) otherwise.
#if defined(UKF_PROPAGATED_MEAN)
#define SF_CFG_UKF_PROPAGATED_MEAN (UKF_PROPAGATED_MEAN)
#elif defined(ANGLE_STATES)
#define SF_CFG_UKF_PROPAGATED_MEAN 1
#else
#define SF_CFG_UKF_PROPAGATED_MEAN 0
#endif
#if defined(WINDOW_SIZE)
#define SF_CFG_WINDOW_SIZE (WINDOW_SIZE)
#else
#define SF_CFG_WINDOW_SIZE 1
#endif
// clang-format on

namespace sf_config {

/// The configured method (one of the macros of methods.hpp) and its name.
constexpr int kMethod = METHOD;
constexpr const char* kMethodName = SF_CFG_METHOD_NAME;

/// n, m and l (see configuration.hpp for how they are derived).
constexpr int kStateSize = SF_CFG_N;
constexpr int kMeasurementSize = SF_CFG_M;
constexpr int kControlSize = SF_CFG_L;

/// Which optional parts the configuration header gives.
constexpr bool kHasControls = SF_CFG_L > 0;
constexpr bool kHasTransitionJacobian =
    SF_CFG_HAS_STATE_TRANSITION_JACOBIAN || METHOD == KALMAN_FILTER;
constexpr bool kHasObservationJacobian = SF_CFG_HAS_OBSERVATION_JACOBIAN || METHOD == KALMAN_FILTER;
constexpr bool kHasInitialState = SF_CFG_HAS_INITIAL_STATE;
constexpr bool kHasInitialErrorCovariance = SF_CFG_HAS_INITIAL_ERROR_COVARIANCE;
constexpr bool kHasMeasurementNoiseCovariance = SF_CFG_HAS_MEASUREMENT_NOISE_COVARIANCE;
constexpr bool kHasWeightingCoefficients = SF_CFG_HAS_WEIGHTING_COEFFICIENTS;

/// Defaults of the scalar parameters (the macro's value, or the documented default).
constexpr double kEstimationPeriodMs = static_cast<double>(SF_CFG_ESTIMATION_PERIOD);
constexpr int kNumberOfParticles = static_cast<int>(SF_CFG_NUMBER_OF_PARTICLES);
constexpr unsigned kRandomSeed = static_cast<unsigned>(SF_CFG_RANDOM_SEED);
constexpr double kResamplingThreshold = static_cast<double>(SF_CFG_RESAMPLING_THRESHOLD);
constexpr double kUkfAlpha = static_cast<double>(SF_CFG_UKF_ALPHA);
constexpr double kUkfBeta = static_cast<double>(SF_CFG_UKF_BETA);
constexpr double kUkfKappa = static_cast<double>(SF_CFG_UKF_KAPPA);
constexpr bool kUkfPropagatedMean = (SF_CFG_UKF_PROPAGATED_MEAN) != 0;
constexpr int kWindowSize = static_cast<int>(SF_CFG_WINDOW_SIZE);

}  // namespace sf_config
