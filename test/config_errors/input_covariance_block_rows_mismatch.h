// EXPECT: INPUT_COVARIANCE_BLOCK entry 0 (((0)(1))(pose.covariance)((0)(1)(5))): expected 1 to 6 inputs and one row of the message's covariance per input
// Mistake: three rows for two inputs
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0])(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.01))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.5))
#define TOPICS_OUT ((x)(0))
#define TOPICS_IN ((odom)(nav_msgs::Odometry)(pose.pose.position.x))((odom)(nav_msgs::Odometry)(pose.pose.position.y))
#define INPUT_COVARIANCE_BLOCK (((0)(1))(pose.covariance)((0)(1)(5)))
