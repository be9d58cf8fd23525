// Test configuration of test/derived_inputs_test.cpp: a planar robot fusing the yaw of an IMU's
// orientation (absolute, its variance from orientation_covariance) and an odometry's pose
// (differential: the forward and sideways steps and the turn since the previous message, in
// the robot's frame, their variances from pose.covariance) - DERIVED_INPUTS and
// INPUT_COVARIANCE; its Odometry output carries the twist (v, omega) from the state (TWIST_OUT).
//   state x = (x, y, yaw, v, omega); the odometry publishes at the estimation period (100 ms),
//   so its differential steps are observed as v T, 0 and omega T.
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>

#define METHOD EXTENDED_KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MODEL \
  (x[0] + x[3] * cos(x[2]) * T) \
  (x[1] + x[3] * sin(x[2]) * T) \
  (x[2] + x[4] * T) \
  (x[3]) \
  (x[4])
#define OBSERVATION_MODEL (x[2])(x[3] * T)(0)(x[4] * T)
#define PROCESS_NOISE_COVARIANCE \
  ((1e-4)(0)(0)(0)(0)) \
  ((0)(1e-4)(0)(0)(0)) \
  ((0)(0)(1e-4)(0)(0)) \
  ((0)(0)(0)(0.01)(0)) \
  ((0)(0)(0)(0)(0.01))
#define MEASUREMENT_NOISE_COVARIANCE \
  ((0.01)(0)(0)(0)) \
  ((0)(1e-4)(0)(0)) \
  ((0)(0)(1e-4)(0)) \
  ((0)(0)(0)(1e-4))
#define INITIAL_STATE (0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE \
  ((1)(0)(0)(0)(0)) \
  ((0)(1)(0)(0)(0)) \
  ((0)(0)(10)(0)(0)) \
  ((0)(0)(0)(1)(0)) \
  ((0)(0)(0)(0)(1))
#define ANGLE_STATES (2)
#define TOPICS_IN \
  ((imu/data)(sensor_msgs::Imu)(orientation)) \
  ((odom)(nav_msgs::Odometry)(pose.pose)) \
  ((odom)(nav_msgs::Odometry)(pose.pose)) \
  ((odom)(nav_msgs::Odometry)(pose.pose.orientation))
#define DERIVED_INPUTS \
  ((0)(YAW)(ABSOLUTE)) \
  ((1)(X)(DIFFERENTIAL)) \
  ((2)(Y)(DIFFERENTIAL)) \
  ((3)(YAW)(DIFFERENTIAL))
#define INPUT_COVARIANCE \
  ((0)(orientation_covariance)(8)) \
  ((1)(pose.covariance)(0)) \
  ((2)(pose.covariance)(7)) \
  ((3)(pose.covariance)(35))
#define TOPICS_OUT ((yaw)(2))((speed)(3))
#define POSE_OUT (0)(1)(2)
#define TWIST_OUT (3)(4)
