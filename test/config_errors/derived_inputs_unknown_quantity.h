// EXPECT: DERIVED_INPUTS entry 0 ((0)(HEADING)(ABSOLUTE)): quantity 'HEADING' is not one of X, Y, Z
// Mistake: HEADING is not a quantity (YAW is)
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define TOPICS_OUT ((heading)(0))
#define TOPICS_IN ((imu)(sensor_msgs::Imu)(orientation))((odom)(nav_msgs::Odometry)(pose.pose))
#define DERIVED_INPUTS ((0)(HEADING)(ABSOLUTE))((1)(X)(ABSOLUTE))
