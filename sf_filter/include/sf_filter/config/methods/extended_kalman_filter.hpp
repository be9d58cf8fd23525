// Traits of METHOD EXTENDED_KALMAN_FILTER (thesis Algorithm 3.2): included once per pass by
// config/methods.hpp, which explains the passes. Its own macros: STATE_TRANSITION_JACOBIAN,
// OBSERVATION_JACOBIAN (optional; automatic differentiation otherwise). The model's macros are
// checked for every model-based method by validation.hpp (SF_METHOD_KIND_MODEL).

// clang-format off
#if SF_METHOD_PART == SF_METHOD_PART_DECLARE && METHOD == EXTENDED_KALMAN_FILTER
#define SF_CFG_METHOD_NAME "EXTENDED_KALMAN_FILTER"
#define SF_CFG_METHOD_KIND SF_METHOD_KIND_MODEL
#define SF_CFG_METHOD_TAKES_JACOBIANS 1

#elif SF_METHOD_PART == SF_METHOD_PART_TUNING
// The noise identification (tuning/noise_tuning.hpp) can tune it: no refusal.
SF_METHOD_TUNING(EXTENDED_KALMAN_FILTER, "")

#elif SF_METHOD_PART == SF_METHOD_PART_UNUSED && METHOD != EXTENDED_KALMAN_FILTER
#if defined(STATE_TRANSITION_JACOBIAN)
#pragma GCC warning "STATE_TRANSITION_JACOBIAN is not used by the chosen METHOD and is ignored"
#endif
#if defined(OBSERVATION_JACOBIAN)
#pragma GCC warning "OBSERVATION_JACOBIAN is not used by the chosen METHOD and is ignored"
#endif

#elif SF_METHOD_PART == SF_METHOD_PART_CHECKS && METHOD == EXTENDED_KALMAN_FILTER
#if defined(STATE_TRANSITION_JACOBIAN)
SF_PP_CHECK_MATRIX("STATE_TRANSITION_JACOBIAN", SF_CFG_N, SF_CFG_N,
                   "must be n x n, row i holding the derivatives of expression i of "
                   "STATE_TRANSITION_MODEL; " SF_CFG_N_WHY,
                   STATE_TRANSITION_JACOBIAN)
#endif
#if defined(OBSERVATION_JACOBIAN)
SF_PP_CHECK_MATRIX("OBSERVATION_JACOBIAN", SF_CFG_M, SF_CFG_N,
                   "must be m x n, row i holding the derivatives of expression i of "
                   "OBSERVATION_MODEL; " SF_CFG_M_WHY "; " SF_CFG_N_WHY,
                   OBSERVATION_JACOBIAN)
#endif
// clang-format on

#elif SF_METHOD_PART == SF_METHOD_PART_BINDING && METHOD == EXTENDED_KALMAN_FILTER
#if SF_CFG_HAS_QUATERNION_STATES
// Rotations: the error-state EKF on the header's layout (doc/manifolds.md).
#include <sf_estimation/layout_extended_kalman_filter.hpp>
#else
#include <sf_estimation/extended_kalman_filter.hpp>
#endif

namespace sf_filter {
namespace generated {

#if SF_CFG_HAS_QUATERNION_STATES
using Filter = estimation::LayoutExtendedKalmanFilter<sf_config::Model, sf_config::StateLayout,
                                                      sf_config::MeasurementLayout>;
// Its AutoDiff Jacobians: the transition's in the node's second unit, the observation's in the
// Jacobians' unit (filter_binding.hpp), as together they took the second unit over 500 MB
// (doc/build_cost.md, "The Jacobians' unit").
#define SF_CFG_SECOND_UNIT_INSTANCES(PREFIX) \
  SF_ESTIMATION_LAYOUT_EKF_TRANSITION_JACOBIAN(PREFIX, sf_filter::generated::Filter)
#define SF_CFG_JACOBIAN_UNIT_INSTANCES(PREFIX) \
  SF_ESTIMATION_LAYOUT_EKF_OBSERVATION_JACOBIAN(PREFIX, sf_filter::generated::Filter)
// Its step (the corrections, a measured rotation's rows) in the third (filter_binding.hpp).
#define SF_CFG_THIRD_UNIT_INSTANCES(PREFIX) \
  SF_ESTIMATION_LAYOUT_EKF_STEP(PREFIX, sf_filter::generated::Filter)
#else
using Filter = estimation::ExtendedKalmanFilter<sf_config::Model>;
// Both of the model's Jacobians in the Jacobians' unit: the EKF's step and the three smoothers
// call them, and compiled in the node's unit and in the smoothers' each they took a 13-state
// header's two units over 500 MB (doc/build_cost.md, "The Jacobians' unit").
#define SF_CFG_JACOBIAN_UNIT_INSTANCES(PREFIX) \
  SF_ESTIMATION_MODEL_JACOBIANS(PREFIX, sf_config::Model)
#endif
template <class = void>  // see filter_binding.hpp
Filter makeFilter(const sf_config::Parameters& p) {
  return makeModelFilter<Filter>(p);
}

}  // namespace generated
}  // namespace sf_filter
#endif
