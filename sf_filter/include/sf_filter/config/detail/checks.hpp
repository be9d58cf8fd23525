// Stage 2 of the configuration: shape and value checks that do not stop code generation.
// Each check is a namespace-scope static_assert whose message starts with the macro name and
// states what was expected and what was found, with the sizes stringized into the message:
//   PROCESS_NOISE_COVARIANCE: expected 2 rows, found 3 (must be n x n; n = 2 is ...)
// The generated code never depends on these checks holding, so a failed check is the only
// error printed for its mistake. Included by configuration.hpp after validation.hpp succeeded.
#pragma once

#include <type_traits>

#include "sf_filter/config/detail/preprocessor.hpp"
#include "sf_filter/config/detail/validation.hpp"

// clang-format off

#define SF_CFG_NXN_WHY "must be n x n; " SF_CFG_N_WHY
#define SF_CFG_MXM_WHY "must be m x m; " SF_CFG_M_WHY
#define SF_CFG_MXN_WHY \
  "must be m x n, one row per TOPICS_IN entry; " SF_CFG_M_WHY "; " SF_CFG_N_WHY
#define SF_CFG_NXL_WHY \
  "must be n x l, one column per TOPICS_IN_CTRL entry; " SF_CFG_N_WHY "; " SF_CFG_L_WHY

namespace sf_config {
namespace checks {

// --- models and matrices ----------------------------------------------------------------------
#if METHOD == KALMAN_FILTER
SF_PP_CHECK_MATRIX("STATE_TRANSITION_MATRIX", SF_CFG_N, SF_CFG_N, SF_CFG_NXN_WHY,
                   STATE_TRANSITION_MATRIX)
SF_PP_CHECK_MATRIX("OBSERVATION_MATRIX", SF_CFG_M, SF_CFG_N, SF_CFG_MXN_WHY,
                   OBSERVATION_MATRIX)
#if defined(CONTROL_INPUT_MATRIX)
SF_PP_CHECK_MATRIX("CONTROL_INPUT_MATRIX", SF_CFG_N, SF_CFG_L, SF_CFG_NXL_WHY,
                   CONTROL_INPUT_MATRIX)
#endif
#endif

#if SF_CFG_IS_MODEL_BASED
SF_PP_CHECK_VECTOR("OBSERVATION_MODEL", SF_CFG_M,
                   "one expression per TOPICS_IN entry; " SF_CFG_M_WHY, "(x[0])(x[1])",
                   OBSERVATION_MODEL)
#endif

#if METHOD == EXTENDED_KALMAN_FILTER && defined(STATE_TRANSITION_JACOBIAN)
SF_PP_CHECK_MATRIX("STATE_TRANSITION_JACOBIAN", SF_CFG_N, SF_CFG_N,
                   "must be n x n, row i holding the derivatives of expression i of "
                   "STATE_TRANSITION_MODEL; " SF_CFG_N_WHY,
                   STATE_TRANSITION_JACOBIAN)
#endif
#if METHOD == EXTENDED_KALMAN_FILTER && defined(OBSERVATION_JACOBIAN)
SF_PP_CHECK_MATRIX("OBSERVATION_JACOBIAN", SF_CFG_M, SF_CFG_N,
                   "must be m x n, row i holding the derivatives of expression i of "
                   "OBSERVATION_MODEL; " SF_CFG_M_WHY "; " SF_CFG_N_WHY,
                   OBSERVATION_JACOBIAN)
#endif

// --- covariances and initial values -----------------------------------------------------------
#if METHOD == KALMAN_FILTER || SF_CFG_IS_MODEL_BASED
SF_PP_CHECK_MATRIX("PROCESS_NOISE_COVARIANCE", SF_CFG_N, SF_CFG_N, SF_CFG_NXN_WHY,
                   PROCESS_NOISE_COVARIANCE)
#endif
#if defined(MEASUREMENT_NOISE_COVARIANCE) &&                                                       \
    (METHOD == KALMAN_FILTER || SF_CFG_IS_MODEL_BASED || METHOD == CONFIDENCE_WEIGHTED_AVERAGING)
SF_PP_CHECK_MATRIX("MEASUREMENT_NOISE_COVARIANCE", SF_CFG_M, SF_CFG_M, SF_CFG_MXM_WHY,
                   MEASUREMENT_NOISE_COVARIANCE)
#endif
#if defined(INITIAL_STATE) && !SF_CFG_IS_AVERAGING
SF_PP_CHECK_VECTOR("INITIAL_STATE", SF_CFG_N, "one value per state variable; " SF_CFG_N_WHY,
                   "(0)(0)", INITIAL_STATE)
#endif
#if defined(INITIAL_ERROR_COVARIANCE) && !SF_CFG_IS_AVERAGING
SF_PP_CHECK_MATRIX("INITIAL_ERROR_COVARIANCE", SF_CFG_N, SF_CFG_N, SF_CFG_NXN_WHY,
                   INITIAL_ERROR_COVARIANCE)
#endif

// --- scalars ----------------------------------------------------------------------------------
#if defined(ESTIMATION_PERIOD)
static_assert((ESTIMATION_PERIOD) > 0,
              "ESTIMATION_PERIOD: expected a positive period in milliseconds, found '"
              SF_PP_STR(ESTIMATION_PERIOD) "'");
#endif

#if defined(WINDOW_SIZE) && SF_CFG_IS_AVERAGING
static_assert(std::is_integral<decltype(WINDOW_SIZE)>::value && (WINDOW_SIZE) >= 1,
              "WINDOW_SIZE: expected a positive integer, found '" SF_PP_STR(WINDOW_SIZE) "'");
#endif
#if defined(WEIGHTING_COEFFICIENTS) && METHOD == MOVING_AVERAGE
SF_PP_CHECK_VECTOR("WEIGHTING_COEFFICIENTS", WINDOW_SIZE,
                   "one weight per measurement of the window, WINDOW_SIZE = "
                   SF_PP_STR(WINDOW_SIZE), "(0.5)(0.3)(0.2)", WEIGHTING_COEFFICIENTS)
#endif

#if METHOD == PARTICLE_FILTER_SIR
#if defined(NUMBER_OF_PARTICLES)
static_assert(std::is_integral<decltype(NUMBER_OF_PARTICLES)>::value && (NUMBER_OF_PARTICLES) >= 1,
              "NUMBER_OF_PARTICLES: expected a positive integer, found '"
              SF_PP_STR(NUMBER_OF_PARTICLES) "'");
#endif
#if defined(RANDOM_SEED)
static_assert(std::is_integral<decltype(RANDOM_SEED)>::value && (RANDOM_SEED) >= 0,
              "RANDOM_SEED: expected a non-negative integer, found '" SF_PP_STR(RANDOM_SEED) "'");
#endif
#if defined(RESAMPLING_THRESHOLD)
static_assert((RESAMPLING_THRESHOLD) >= 0 && (RESAMPLING_THRESHOLD) <= 1,
              "RESAMPLING_THRESHOLD: expected a fraction of NUMBER_OF_PARTICLES between 0 and 1 "
              "(resample when the effective sample size drops below it), found '"
              SF_PP_STR(RESAMPLING_THRESHOLD) "'");
#endif
#endif

#if METHOD == UNSCENTED_KALMAN_FILTER
#if defined(UKF_ALPHA)
static_assert((UKF_ALPHA) > 0 && (UKF_ALPHA) <= 1,
              "UKF_ALPHA: expected a value in (0, 1], found '" SF_PP_STR(UKF_ALPHA) "'");
#endif
#if defined(UKF_BETA)
static_assert((UKF_BETA) >= 0, "UKF_BETA: expected a non-negative value, found '"
              SF_PP_STR(UKF_BETA) "'");
#endif
#if defined(UKF_KAPPA)
static_assert(SF_CFG_N + (UKF_KAPPA) > 0,
              "UKF_KAPPA: n + kappa must be positive (" SF_CFG_N_WHY "), found kappa = '"
              SF_PP_STR(UKF_KAPPA) "'");
#endif
#if defined(UKF_PROPAGATED_MEAN)
static_assert((UKF_PROPAGATED_MEAN) == 0 || (UKF_PROPAGATED_MEAN) == 1,
              "UKF_PROPAGATED_MEAN: expected 1 (f of the mean, UKF-M) or 0 (the sigma points' "
              "weighted mean), found '" SF_PP_STR(UKF_PROPAGATED_MEAN) "'");
#endif
#endif

}  // namespace checks
}  // namespace sf_config

// clang-format on
