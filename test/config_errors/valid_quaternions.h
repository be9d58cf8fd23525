// EXPECT: OK
// An attitude with a unit quaternion x[0..3] and a gyro bias x[4..6] (QUATERNION_STATES): Q and
// P0 over the tangent space (d = 6), the rotation helpers in the models. The quaternion cases
// include it (n = 7, m = 3; valid_quaternion_inputs.h adds inputs through
// SF_QUATERNION_EXTRA_ROWS, SF_QUATERNION_EXTRA_R and SF_QUATERNION_EXTRA_TOPICS).
#include <sf_filter/config/diagonal.hpp>

#include "fake_msgs.h"

#if !defined(SF_QUATERNION_EXTRA_ROWS)
#define SF_QUATERNION_EXTRA_ROWS
#define SF_QUATERNION_EXTRA_R
#define SF_QUATERNION_EXTRA_TOPICS
#endif
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
  (quat_rotate_inverse(x, 0, 2, 0.0, 0.0, 9.80665)) SF_QUATERNION_EXTRA_ROWS
#if !defined(SF_QUATERNION_COVARIANCE_CASE)
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((1e-6)(1e-6)(1e-6)(1e-10)(1e-10)(1e-10))
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL((1)(1)(1)(1e-4)(1e-4)(1e-4))
#endif
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((0.05)(0.05)(0.05) SF_QUATERNION_EXTRA_R)
#define TOPICS_IN_CTRL \
  ((imu)(sensor_msgs::Imu)(angular_velocity.x)) \
  ((imu)(sensor_msgs::Imu)(angular_velocity.y)) \
  ((imu)(sensor_msgs::Imu)(angular_velocity.z))
#define TOPICS_IN \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.x)) \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.y)) \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.z)) SF_QUATERNION_EXTRA_TOPICS
#define TOPICS_OUT ((qw)(0))((qx)(1))((qy)(2))((qz)(3))
#if !defined(SF_QUATERNION_CASE)
#define QUATERNION_STATES (0)
#endif
