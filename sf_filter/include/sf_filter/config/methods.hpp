// Estimation methods selectable in a configuration header with
//   #define METHOD <one of the names below>
// (thesis section 4.3.5, "pre_config.h"). Each method is a distinct integer so that the
// configuration machinery and the fusion node can compare METHOD in #if directives.
// The value 0 is deliberately unused: an unknown identifier evaluates to 0 in #if.
#pragma once

#define KALMAN_FILTER 1
#define EXTENDED_KALMAN_FILTER 2
#define UNSCENTED_KALMAN_FILTER 3
#define PARTICLE_FILTER_SIR 4
#define MOVING_AVERAGE 5
#define MOVING_MEDIAN 6
#define CONFIDENCE_WEIGHTED_AVERAGING 7

namespace sf_config {

/// Name of a method value (the macro name), or "unknown".
constexpr const char* methodName(int method) {
  switch (method) {
    case KALMAN_FILTER:
      return "KALMAN_FILTER";
    case EXTENDED_KALMAN_FILTER:
      return "EXTENDED_KALMAN_FILTER";
    case UNSCENTED_KALMAN_FILTER:
      return "UNSCENTED_KALMAN_FILTER";
    case PARTICLE_FILTER_SIR:
      return "PARTICLE_FILTER_SIR";
    case MOVING_AVERAGE:
      return "MOVING_AVERAGE";
    case MOVING_MEDIAN:
      return "MOVING_MEDIAN";
    case CONFIDENCE_WEIGHTED_AVERAGING:
      return "CONFIDENCE_WEIGHTED_AVERAGING";
    default:
      return "unknown";
  }
}

/// True for the state estimators built from a model (KF, EKF, UKF, PF).
constexpr bool isStateEstimator(int method) {
  return method == KALMAN_FILTER || method == EXTENDED_KALMAN_FILTER ||
         method == UNSCENTED_KALMAN_FILTER || method == PARTICLE_FILTER_SIR;
}

}  // namespace sf_config
