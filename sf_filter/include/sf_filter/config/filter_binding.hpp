// The only code that depends on the chosen METHOD: which estimator type a configuration
// header selects and how it is built from the (possibly overridden) parameters. Included by
// the generated translation unit after the configuration header and configuration.hpp.
#pragma once

#include <sf_estimation/angles.hpp>
#include <sf_estimation/filters.hpp>

namespace sf_filter {
namespace generated {

constexpr double periodSeconds(const sf_config::Parameters& p) {
  return p.estimation_period_ms / 1000.0;
}

/// ANGLE_STATES and ANGLE_INPUTS of the configuration header, for the model-based filters.
inline estimation::AngularComponents angularComponents() {
  estimation::AngularComponents angles;
  for (std::size_t i = 0; i < sf_config::kAngleStates.size(); ++i) {
    if (sf_config::kAngleStates[i]) angles.states.push_back(static_cast<estimation::Index>(i));
  }
  for (std::size_t i = 0; i < sf_config::kAngleInputs.size(); ++i) {
    if (sf_config::kAngleInputs[i])
      angles.measurements.push_back(static_cast<estimation::Index>(i));
  }
  return angles;
}

#if METHOD == KALMAN_FILTER
using Filter = estimation::KalmanFilter<sf_config::kStateSize, sf_config::kMeasurementSize,
                                        sf_config::kControlSize>;
inline Filter makeFilter(const sf_config::Parameters& p) {
  sf_config::Model model;
  model.T = periodSeconds(p);  // matrices may use T
  return Filter(model.transitionMatrix(), model.controlInputMatrix(), model.observationMatrix(),
                p.process_noise_covariance, p.measurement_noise_covariance, p.initial_state,
                p.initial_error_covariance, angularComponents());
}
#elif METHOD == EXTENDED_KALMAN_FILTER
using Filter = estimation::ExtendedKalmanFilter<sf_config::Model>;
inline Filter makeFilter(const sf_config::Parameters& p) {
  sf_config::Model model;
  model.T = periodSeconds(p);
  return Filter(model, p.process_noise_covariance, p.measurement_noise_covariance, p.initial_state,
                p.initial_error_covariance, angularComponents());
}
#elif METHOD == UNSCENTED_KALMAN_FILTER
using Filter = estimation::UnscentedKalmanFilter<sf_config::Model>;
inline Filter makeFilter(const sf_config::Parameters& p) {
  sf_config::Model model;
  model.T = periodSeconds(p);
  estimation::UnscentedParameters ut;
  ut.alpha = p.ukf_alpha;
  ut.beta = p.ukf_beta;
  ut.kappa = p.ukf_kappa;
  ut.predictedMean = p.ukf_propagated_mean ? estimation::PredictedMean::Propagated
                                           : estimation::PredictedMean::SigmaPointAverage;
  return Filter(model, p.process_noise_covariance, p.measurement_noise_covariance, p.initial_state,
                p.initial_error_covariance, ut, angularComponents());
}
#elif METHOD == PARTICLE_FILTER_SIR
using Filter = estimation::ParticleFilterSIR<sf_config::Model>;
inline Filter makeFilter(const sf_config::Parameters& p) {
  sf_config::Model model;
  model.T = periodSeconds(p);
  estimation::ParticleFilterParameters pf;
  pf.particles = p.number_of_particles;
  pf.seed = p.random_seed;
  pf.resamplingThreshold = p.resampling_threshold;
#if defined(POSE_OUT)
  // A published pose whose heading is an angle: its mean over the particles is taken on SE(2),
  // where poses spread along an arc average to a point of the arc (planar_pose_mean.hpp).
  if (sf_config::kAngleStates[BOOST_PP_SEQ_ELEM(2, POSE_OUT)]) {
    pf.planarPose = estimation::PlanarPoseIndices{BOOST_PP_SEQ_ELEM(0, POSE_OUT),
                                                  BOOST_PP_SEQ_ELEM(1, POSE_OUT),
                                                  BOOST_PP_SEQ_ELEM(2, POSE_OUT)};
  }
#endif
  return Filter(model, p.process_noise_covariance, p.measurement_noise_covariance, p.initial_state,
                p.initial_error_covariance, pf, angularComponents());
}
#elif METHOD == MOVING_AVERAGE
using Filter = estimation::MovingAverage;
inline Filter makeFilter(const sf_config::Parameters& p) {
  if (p.weighting_coefficients.size() > 0) {
    return Filter(sf_config::kMeasurementSize, p.window_size, p.weighting_coefficients);
  }
  return Filter(sf_config::kMeasurementSize, p.window_size);
}
#elif METHOD == MOVING_MEDIAN
using Filter = estimation::MovingMedian;
inline Filter makeFilter(const sf_config::Parameters& p) {
  return Filter(sf_config::kMeasurementSize, p.window_size);
}
#elif METHOD == CONFIDENCE_WEIGHTED_AVERAGING
using Filter = estimation::ConfidenceWeightedAveraging;
inline Filter makeFilter(const sf_config::Parameters& p) {
  return Filter(sf_config::kMeasurementSize, p.measurement_noise_covariance.diagonal());
}
#endif

}  // namespace generated
}  // namespace sf_filter
