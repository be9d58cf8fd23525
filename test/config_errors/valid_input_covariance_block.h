// EXPECT: OK
// x, y and yaw of an odometry with their covariance block (rows 0, 1, 5 of pose.covariance),
// and a speed from another topic.
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[3] * T * cos(x[2]))(x[1] + x[3] * T * sin(x[2]))(x[2])(x[3])
#define OBSERVATION_MODEL (x[0])(x[1])(x[2])(x[3])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0)(0)(0))((0)(0.01)(0)(0))((0)(0)(0.01)(0))((0)(0)(0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0)(0)(0))((0)(0.5)(0)(0))((0)(0)(0.1)(0))((0)(0)(0)(0.2))
#define TOPICS_OUT ((x)(0))
#define TOPICS_IN ((odom)(nav_msgs::Odometry)(pose.pose.position.x))((odom)(nav_msgs::Odometry)(pose.pose.position.y))((odom)(nav_msgs::Odometry)(pose.pose.orientation))((speed)(std_msgs::Float64)(data))
#define DERIVED_INPUTS ((2)(YAW)(ABSOLUTE))
#define ANGLE_STATES (2)
#define INPUT_COVARIANCE_BLOCK (((0)(1)(2))(pose.covariance)((0)(1)(5)))
