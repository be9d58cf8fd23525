// EXPECT: CONTROL_INPUT_MATRIX: row 0 has 2 entries, expected 1
// Mistake: B has 2 columns for 1 control
#include "fake_msgs.h"

#define METHOD KALMAN_FILTER
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(1))
#define CONTROL_INPUT_MATRIX ((0)(1))((T)(0))
#define OBSERVATION_MATRIX ((1)(0))((0)(1))
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define INITIAL_STATE (0)(0)
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_IN_CTRL ((velocity_command)(std_msgs::Float32)(data))
#define TOPICS_OUT ((velocity)(0))((acceleration_estimate)(1))
