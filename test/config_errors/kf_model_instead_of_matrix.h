// EXPECT: KALMAN_FILTER requires STATE_TRANSITION_MATRIX (n x n) but found STATE_TRANSITION_MODEL
// Mistake: KF given a non-linear model
#include "fake_msgs.h"

#define METHOD KALMAN_FILTER
#define OBSERVATION_MATRIX ((1)(0))((0)(1))
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define INITIAL_STATE (0)(0)
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_OUT ((velocity)(0))((acceleration_estimate)(1))
