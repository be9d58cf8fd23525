// EXPECT: T is defined as a macro, but T is the estimation period in seconds that the expressions use
// Mistake: the period defined as T (the thesis used FILTER_T; T is generated from ESTIMATION_PERIOD)
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define T 0.1
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_OUT ((velocity)(0))((acceleration_estimate)(1))
