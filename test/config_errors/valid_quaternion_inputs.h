// EXPECT: OK
// An attitude (QUATERNION_STATES (0), a gyro bias x[4..6]) that also reads the IMU's orientation
// as a measured quaternion (QUATERNION_INPUTS (3): TOPICS_IN entries 3..6 are its w, x, y, z,
// compared on SO(3); R's w row zero, the rotation vector's rad^2 on x, y, z). The quaternion
// input cases include it (n = 7, m = 7).
#include <sf_filter/config/diagonal.hpp>

#include "fake_msgs.h"

#if !defined(METHOD)
#define METHOD EXTENDED_KALMAN_FILTER
#endif
#define STATE_TRANSITION_MODEL \
  (quat_integrate(x, 0, 0, (u[0] - x[4]) * T, (u[1] - x[5]) * T, (u[2] - x[6]) * T)) \
  (quat_integrate(x, 0, 1, (u[0] - x[4]) * T, (u[1] - x[5]) * T, (u[2] - x[6]) * T)) \
  (quat_integrate(x, 0, 2, (u[0] - x[4]) * T, (u[1] - x[5]) * T, (u[2] - x[6]) * T)) \
  (quat_integrate(x, 0, 3, (u[0] - x[4]) * T, (u[1] - x[5]) * T, (u[2] - x[6]) * T)) \
  (x[4])(x[5])(x[6])
#define OBSERVATION_MODEL \
  (quat_rotate_inverse(x, 0, 0, 0.0, 0.0, 9.80665)) \
  (quat_rotate_inverse(x, 0, 1, 0.0, 0.0, 9.80665)) \
  (quat_rotate_inverse(x, 0, 2, 0.0, 0.0, 9.80665)) \
  (x[0])(x[1])(x[2])(x[3])
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((1e-6)(1e-6)(1e-6)(1e-10)(1e-10)(1e-10))
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL((1)(1)(1)(1e-4)(1e-4)(1e-4))
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((0.05)(0.05)(0.05)(0)(1e-3)(1e-3)(1e-3))
#define TOPICS_IN_CTRL \
  ((imu)(sensor_msgs::Imu)(angular_velocity.x)) \
  ((imu)(sensor_msgs::Imu)(angular_velocity.y)) \
  ((imu)(sensor_msgs::Imu)(angular_velocity.z))
#if !defined(SF_QUATERNION_INPUT_TOPICS_CASE)
#define TOPICS_IN \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.x)) \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.y)) \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.z)) \
  ((imu)(sensor_msgs::Imu)(orientation.w)) \
  ((imu)(sensor_msgs::Imu)(orientation.x)) \
  ((imu)(sensor_msgs::Imu)(orientation.y)) \
  ((imu)(sensor_msgs::Imu)(orientation.z))
#endif
#define TOPICS_OUT ((qw)(0))((qx)(1))((qy)(2))((qz)(3))
#if !defined(SF_QUATERNION_STATES_CASE)
#define QUATERNION_STATES (0)
#endif
#if !defined(SF_QUATERNION_INPUTS_CASE)
#define QUATERNION_INPUTS (3)
#endif
