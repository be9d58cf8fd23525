// EXPECT: TOPICS_OUT entry 0 (topic 'velocity'): state index '0.5' is out of range, expected an integer from 0 to 1
// Mistake: a fractional state index
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_OUT ((velocity)(0.5))
