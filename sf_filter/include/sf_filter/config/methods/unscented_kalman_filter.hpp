// Traits of METHOD UNSCENTED_KALMAN_FILTER (thesis Algorithm 3.3): included once per pass by
// config/methods.hpp, which explains the passes. Its own macros: UKF_ALPHA, UKF_BETA,
// UKF_KAPPA, UKF_PROPAGATED_MEAN. The model's macros are checked for every model-based method
// by validation.hpp (SF_METHOD_KIND_MODEL).

// clang-format off
#if SF_METHOD_PART == SF_METHOD_PART_DECLARE
#if METHOD == UNSCENTED_KALMAN_FILTER
#define SF_CFG_METHOD_NAME "UNSCENTED_KALMAN_FILTER"
#define SF_CFG_METHOD_KIND SF_METHOD_KIND_MODEL
#endif
// Defaults of its own macros, for every method: sf_config::Parameters has them all.
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
// The predicted mean (estimation::PredictedMean): f of the mean (UKF-M) for a state with
// angles, whose sigma-point average shortens every dead-reckoned step by the heading's spread
// (doc/manifolds.md); the sigma points' weighted mean (thesis Algorithm 3.3) otherwise.
#if defined(UKF_PROPAGATED_MEAN)
#define SF_CFG_UKF_PROPAGATED_MEAN (UKF_PROPAGATED_MEAN)
#elif defined(ANGLE_STATES) || defined(QUATERNION_STATES)
#define SF_CFG_UKF_PROPAGATED_MEAN 1
#else
#define SF_CFG_UKF_PROPAGATED_MEAN 0
#endif

#elif SF_METHOD_PART == SF_METHOD_PART_PARAMETERS
// Its run-time parameters: type, name (member of sf_config::Parameters and FilterParameters,
// private ROS parameter ~name, entry of the replay's --params file), default without a
// configuration header, default of the header (SF_CFG_* above).
SF_METHOD_PARAMETER(double, ukf_alpha, 1e-3, SF_CFG_UKF_ALPHA)
SF_METHOD_PARAMETER(double, ukf_beta, 2.0, SF_CFG_UKF_BETA)
SF_METHOD_PARAMETER(double, ukf_kappa, 0.0, SF_CFG_UKF_KAPPA)
SF_METHOD_PARAMETER(bool, ukf_propagated_mean, false, (SF_CFG_UKF_PROPAGATED_MEAN) != 0)

#elif SF_METHOD_PART == SF_METHOD_PART_TUNING
// The noise identification (tuning/noise_tuning.hpp) can tune it: no refusal.
SF_METHOD_TUNING(UNSCENTED_KALMAN_FILTER, "")

#elif SF_METHOD_PART == SF_METHOD_PART_UNUSED && METHOD != UNSCENTED_KALMAN_FILTER
#if defined(UKF_ALPHA)
#pragma GCC warning "UKF_ALPHA is not used by the chosen METHOD and is ignored"
#endif
#if defined(UKF_BETA)
#pragma GCC warning "UKF_BETA is not used by the chosen METHOD and is ignored"
#endif
#if defined(UKF_KAPPA)
#pragma GCC warning "UKF_KAPPA is not used by the chosen METHOD and is ignored"
#endif
#if defined(UKF_PROPAGATED_MEAN)
#pragma GCC warning "UKF_PROPAGATED_MEAN is not used by the chosen METHOD and is ignored"
#endif

#elif SF_METHOD_PART == SF_METHOD_PART_CHECKS && METHOD == UNSCENTED_KALMAN_FILTER
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
#if defined(UKF_PROPAGATED_MEAN) && defined(QUATERNION_STATES)
static_assert((UKF_PROPAGATED_MEAN) == 1,
              "UKF_PROPAGATED_MEAN: QUATERNION_STATES needs 1 (UKF-M propagates the mean, a "
              "sigma-point average of quaternions is not a rotation), found '"
              SF_PP_STR(UKF_PROPAGATED_MEAN) "'");
#endif
// clang-format on

#elif SF_METHOD_PART == SF_METHOD_PART_BINDING && METHOD == UNSCENTED_KALMAN_FILTER && \
    SF_CFG_HAS_QUATERNION_STATES
// Rotations: UKF-M on the header's layout (doc/manifolds.md), UKF_ALPHA its three spreads.
#include <sf_estimation/layout_unscented_kalman_filter.hpp>

namespace sf_filter {
namespace generated {

using Filter = estimation::LayoutUnscentedKalmanFilter<sf_config::Model, sf_config::StateLayout,
                                                       sf_config::MeasurementLayout>;
// UKF-M's propagation in the node's second unit, the rest of its step (the corrections, the
// measurement's moments) in the third (filter_binding.hpp).
#define SF_CFG_SECOND_UNIT_INSTANCES(PREFIX) \
  SF_ESTIMATION_MANIFOLD_UKF_PREDICT(PREFIX, sf_filter::generated::Filter::Manifold)
#define SF_CFG_THIRD_UNIT_INSTANCES(PREFIX) \
  SF_ESTIMATION_LAYOUT_UKF_STEP(PREFIX, sf_filter::generated::Filter)
template <class = void>  // see filter_binding.hpp
Filter makeFilter(const sf_config::Parameters& p) {
  if (!p.ukf_propagated_mean) {
    throw estimation::ParameterError(
        "ukf_propagated_mean: false is not possible with QUATERNION_STATES, whose UKF (UKF-M) "
        "propagates the mean itself");
  }
  const estimation::ManifoldUnscentedParameters ut{p.ukf_alpha, p.ukf_alpha, p.ukf_alpha};
  return makeModelFilter<Filter>(p, ut);
}

}  // namespace generated
}  // namespace sf_filter

#elif SF_METHOD_PART == SF_METHOD_PART_BINDING && METHOD == UNSCENTED_KALMAN_FILTER
#include <sf_estimation/unscented_kalman_filter.hpp>

namespace sf_filter {
namespace generated {

using Filter = estimation::UnscentedKalmanFilter<sf_config::Model>;
template <class = void>  // see filter_binding.hpp
Filter makeFilter(const sf_config::Parameters& p) {
  const estimation::UnscentedParameters ut{p.ukf_alpha, p.ukf_beta, p.ukf_kappa,
                                           p.ukf_propagated_mean
                                               ? estimation::PredictedMean::Propagated
                                               : estimation::PredictedMean::SigmaPointAverage};
  return makeModelFilter<Filter>(p, ut);
}

}  // namespace generated
}  // namespace sf_filter
#endif
