// EXPECT: OBSERVATION_MATRIX: expected 2 rows, found 1 (must be m x n, one row per TOPICS_IN entry; m = 2 is the number of TOPICS_IN entries
// Mistake: H has one row for two inputs
#include "fake_msgs.h"

#define METHOD KALMAN_FILTER
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(1))
#define OBSERVATION_MATRIX ((1)(0))
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define INITIAL_STATE (0)(0)
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_OUT ((velocity)(0))((acceleration_estimate)(1))
