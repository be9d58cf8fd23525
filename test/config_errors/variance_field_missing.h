// EXPECT: TOPICS_IN entry 0 (topic 'odom'): message type 'nav_msgs::Odometry' has no variance field 'twist.variance[0]'
// Mistake: misspelled variance field
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define INITIAL_STATE (0)(0)
#define TOPICS_IN \
  ((odom)(nav_msgs::Odometry)(twist.twist.linear.x)(twist.variance[0])) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_OUT ((velocity)(0))((acceleration_estimate)(1))
