// EXPECT: DERIVED_INPUTS entry 1 ((1)(X)(RELATIVE)): mode 'RELATIVE' is not ABSOLUTE or DIFFERENTIAL
// Mistake: RELATIVE is not a mode
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define TOPICS_OUT ((heading)(0))
#define TOPICS_IN ((imu)(sensor_msgs::Imu)(orientation))((odom)(nav_msgs::Odometry)(pose.pose))
#define DERIVED_INPUTS ((0)(YAW)(ABSOLUTE))((1)(X)(RELATIVE))
