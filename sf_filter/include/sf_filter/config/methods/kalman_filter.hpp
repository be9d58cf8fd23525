// Traits of METHOD KALMAN_FILTER (thesis Algorithm 3.1): included once per pass by
// config/methods.hpp, which explains the passes. A linear model given as matrices:
// STATE_TRANSITION_MATRIX, OBSERVATION_MATRIX, CONTROL_INPUT_MATRIX (with TOPICS_IN_CTRL).

// clang-format off
#if SF_METHOD_PART == SF_METHOD_PART_DECLARE && METHOD == KALMAN_FILTER
#define SF_CFG_METHOD_NAME "KALMAN_FILTER"
#define SF_CFG_METHOD_KIND SF_METHOD_KIND_LINEAR

#elif SF_METHOD_PART == SF_METHOD_PART_TUNING
// The noise identification (tuning/noise_tuning.hpp) can tune it: no refusal.
SF_METHOD_TUNING(KALMAN_FILTER, "")

#elif SF_METHOD_PART == SF_METHOD_PART_MACROS && METHOD == KALMAN_FILTER
#if !defined(STATE_TRANSITION_MATRIX)
#if defined(STATE_TRANSITION_MODEL)
#error KALMAN_FILTER requires STATE_TRANSITION_MATRIX (n x n) but found STATE_TRANSITION_MODEL: a KALMAN_FILTER is linear, use EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER or PARTICLE_FILTER_SIR for a model given as expressions
#else
#error KALMAN_FILTER requires STATE_TRANSITION_MATRIX: the n x n matrix A of x(k) = A x(k-1) + B u(k), as a sequence of rows, e.g. ((1)(T))((0)(1))
#endif
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#if !defined(OBSERVATION_MATRIX)
#if defined(OBSERVATION_MODEL)
#error KALMAN_FILTER requires OBSERVATION_MATRIX (m x n) but found OBSERVATION_MODEL: a KALMAN_FILTER is linear, use EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER or PARTICLE_FILTER_SIR for a model given as expressions
#else
#error KALMAN_FILTER requires OBSERVATION_MATRIX: the m x n matrix H of z(k) = H x(k) with one row per TOPICS_IN entry, e.g. ((1)(0))((0)(1))
#endif
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#if defined(TOPICS_IN_CTRL) && !defined(CONTROL_INPUT_MATRIX)
#error KALMAN_FILTER with TOPICS_IN_CTRL requires CONTROL_INPUT_MATRIX: the n x l matrix B of x(k) = A x(k-1) + B u(k) with one column per TOPICS_IN_CTRL entry
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#if defined(CONTROL_INPUT_MATRIX) && !defined(TOPICS_IN_CTRL)
#error CONTROL_INPUT_MATRIX is defined but TOPICS_IN_CTRL is not: define one ((topic)(type)(field)) entry of TOPICS_IN_CTRL per column of CONTROL_INPUT_MATRIX, or remove CONTROL_INPUT_MATRIX
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif

#elif SF_METHOD_PART == SF_METHOD_PART_UNUSED && METHOD != KALMAN_FILTER
#if defined(STATE_TRANSITION_MATRIX)
#pragma GCC warning "STATE_TRANSITION_MATRIX is not used by the chosen METHOD and is ignored"
#endif
#if defined(OBSERVATION_MATRIX)
#pragma GCC warning "OBSERVATION_MATRIX is not used by the chosen METHOD and is ignored"
#endif

#elif SF_METHOD_PART == SF_METHOD_PART_CHECKS && METHOD == KALMAN_FILTER
SF_PP_CHECK_MATRIX("STATE_TRANSITION_MATRIX", SF_CFG_N, SF_CFG_N, SF_CFG_NXN_WHY,
                   STATE_TRANSITION_MATRIX)
SF_PP_CHECK_MATRIX("OBSERVATION_MATRIX", SF_CFG_M, SF_CFG_N, SF_CFG_MXN_WHY,
                   OBSERVATION_MATRIX)
#if defined(CONTROL_INPUT_MATRIX)
SF_PP_CHECK_MATRIX("CONTROL_INPUT_MATRIX", SF_CFG_N, SF_CFG_L, SF_CFG_NXL_WHY,
                   CONTROL_INPUT_MATRIX)
#endif
// clang-format on

#elif SF_METHOD_PART == SF_METHOD_PART_BINDING && METHOD == KALMAN_FILTER
#include <sf_estimation/kalman_filter.hpp>

namespace sf_filter {
namespace generated {

using Filter = estimation::KalmanFilter<sf_config::kStateSize, sf_config::kMeasurementSize,
                                        sf_config::kControlSize>;
template <class = void>  // see filter_binding.hpp
Filter makeFilter(const sf_config::Parameters& p) {
  sf_config::Model model;
  model.T = periodSeconds(p);  // matrices may use T
  return Filter(model.transitionMatrix(), model.controlInputMatrix(), model.observationMatrix(),
                p.process_noise_covariance, p.measurement_noise_covariance, p.initial_state,
                p.initial_error_covariance, angularComponents());
}

}  // namespace generated
}  // namespace sf_filter
#endif
