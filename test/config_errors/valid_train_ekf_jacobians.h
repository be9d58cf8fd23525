// EXPECT: OK
// The train with hand-written Jacobians, a nested field with a variance field, a topic used by two
// inputs, T in matrices and all optional EKF macros.
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define ESTIMATION_PERIOD 50
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])(x[0])
#define STATE_TRANSITION_JACOBIAN ((1)(T))((0)(1))
#define OBSERVATION_JACOBIAN ((1)(0))((0)(1))((1)(0))
#define PROCESS_NOISE_COVARIANCE ((T * T * T / 3)(T * T / 2))((T * T / 2)(T))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0)(0))((0)(0.2)(0))((0)(0)(0.1))
#define INITIAL_STATE (0)(0)
#define INITIAL_ERROR_COVARIANCE ((10)(0))((0)(10))
#define TOPICS_IN \
  ((odom)(nav_msgs::Odometry)(twist.twist.linear.x)(twist.covariance[0])) \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.x)(linear_acceleration_covariance[0])) \
  ((odom)(nav_msgs::Odometry)(pose.pose.position.x))
#define TOPICS_OUT ((velocity)(0))((acceleration)(1))
