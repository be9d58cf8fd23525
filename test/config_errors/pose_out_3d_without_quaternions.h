// EXPECT: POSE_OUT_3D requires QUATERNION_STATES
// Mistake: a planar state has no quaternion to publish
#include "fake_msgs.h"
#include <sf_filter/config/diagonal.hpp>

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[3] * cos(x[2]) * T)(x[1] + x[3] * sin(x[2]) * T)(x[2] + x[4] * T)(x[3])(x[4])
#define OBSERVATION_MODEL (x[3])(x[4])
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0.01)(0.01)(0.01)(0.1)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define TOPICS_IN ((odom)(nav_msgs::Odometry)(twist.twist.linear.x))((imu)(sensor_msgs::Imu)(angular_velocity.z))
#define TOPICS_OUT ((heading)(2))
#define POSE_OUT_3D (0)(1)(4)(2)
