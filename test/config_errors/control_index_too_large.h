// EXPECT: STATE_TRANSITION_MODEL: expression 1 'u[1]' uses u[i] with i >= 1, but TOPICS_IN_CTRL declares only the control inputs u[0] .. u[0]
// Mistake: u[1] with one control
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + u[0] * T)(u[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define INITIAL_STATE (0)(0)
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_IN_CTRL ((velocity_command)(std_msgs::Float32)(data))
#define TOPICS_OUT ((velocity)(0))((acceleration_estimate)(1))
