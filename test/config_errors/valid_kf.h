// EXPECT: OK
// Linear Kalman filter of the train with the commanded acceleration as control input.
#include "fake_msgs.h"

#define METHOD KALMAN_FILTER
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(0))
#define CONTROL_INPUT_MATRIX ((0))((1))
#define OBSERVATION_MATRIX ((1)(0))((0)(1))
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define INITIAL_ERROR_COVARIANCE ((1)(0))((0)(1))
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_IN_CTRL ((acceleration_command)(std_msgs::Float64)(data))
#define TOPICS_OUT ((velocity)(0))
