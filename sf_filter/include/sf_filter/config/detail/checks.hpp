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
// Q and P0: over the tangent space with QUATERNION_STATES, n x n otherwise.
#if SF_CFG_HAS_QUATERNION_STATES
#define SF_CFG_COVARIANCE_WHY "must be d x d, over the tangent space; " SF_CFG_D_WHY
#else
#define SF_CFG_COVARIANCE_WHY SF_CFG_NXN_WHY
#endif

namespace sf_config {
namespace checks {

// --- models and matrices ----------------------------------------------------------------------
// The chosen method's own macros first (its traits header, SF_METHOD_PART_CHECKS).
#define SF_METHOD_PART SF_METHOD_PART_CHECKS
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART

#if SF_CFG_IS_MODEL_BASED
SF_PP_CHECK_VECTOR("OBSERVATION_MODEL", SF_CFG_M,
                   "one expression per TOPICS_IN entry; " SF_CFG_M_WHY, "(x[0])(x[1])",
                   OBSERVATION_MODEL)
#endif

// --- covariances and initial values -----------------------------------------------------------
#if !SF_CFG_IS_AVERAGING
SF_PP_CHECK_MATRIX("PROCESS_NOISE_COVARIANCE", SF_CFG_D, SF_CFG_D, SF_CFG_COVARIANCE_WHY,
                   PROCESS_NOISE_COVARIANCE)
#endif
#if defined(MEASUREMENT_NOISE_COVARIANCE) &&                                                       \
    (!SF_CFG_IS_AVERAGING || defined(SF_CFG_METHOD_TAKES_R))
SF_PP_CHECK_MATRIX("MEASUREMENT_NOISE_COVARIANCE", SF_CFG_M, SF_CFG_M, SF_CFG_MXM_WHY,
                   MEASUREMENT_NOISE_COVARIANCE)
#endif
#if defined(INITIAL_STATE) && !SF_CFG_IS_AVERAGING
SF_PP_CHECK_VECTOR("INITIAL_STATE", SF_CFG_N, "one value per state variable; " SF_CFG_N_WHY,
                   "(0)(0)", INITIAL_STATE)
#endif
#if defined(INITIAL_ERROR_COVARIANCE) && !SF_CFG_IS_AVERAGING
SF_PP_CHECK_MATRIX("INITIAL_ERROR_COVARIANCE", SF_CFG_D, SF_CFG_D, SF_CFG_COVARIANCE_WHY,
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
}  // namespace checks
}  // namespace sf_config

// clang-format on
