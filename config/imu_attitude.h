// IMU-only attitude: the orientation of a body from its gyro and accelerometer
// (sensor_msgs/Imu on /imu/data), the 3D filter on the rotation group (QUATERNION_STATES;
// doc/configuration.md, "Rotations in 3D"; doc/manifolds.md).
//
//   state x = (q, b_g)
//     q    x[0..3]  unit quaternion w, x, y, z of the body (the IMU's frame) in the world frame
//                   (z up), starting at the identity
//     b_g  x[4..6]  the gyro's bias, in the body frame [rad/s]
//   controls   u[0..2] = the gyro's angular velocity x, y, z [rad/s] (the latest reading)
//   inputs     0..2  the accelerometer's linear_acceleration x, y, z [m/s^2] (specific
//                    force) = R(q)^T (0, 0, g): gravity rotated into the body
//
// The gyro drives the transition, q' = q exp((omega - b_g) T), and the accelerometer, read
// as gravity alone, corrects roll and pitch and, through their coupling, the bias; nothing
// observes the yaw, which follows the gyro. Gravity: g = 9.80665 m/s^2 along the world's -z,
// so that a level body at rest reads +g on its z axis (REP 103; tools/sim/rigid_body_sim.py
// and the BROAD bags read so). The accelerometer also reads the body's own acceleration,
// which this model takes for noise: R = 0.05 (m/s^2)^2 per axis (a body that accelerates more
// should raise it). Q: the orientation 1e-4 T rad^2 (the gyro's noise and the one-sample
// control over a period), the bias 1e-8 T (rad/s)^2. P0: 1 rad^2 on roll and pitch, whose
// first accelerometer readings settle them, and on yaw; (0.01 rad/s)^2 on the bias.
// METHOD is the EKF unless the including file defines another one first.
#include <sensor_msgs/Imu.h>
#include <sf_filter/config/diagonal.hpp>

#ifndef METHOD
#define METHOD EXTENDED_KALMAN_FILTER
#endif
#define ESTIMATION_PERIOD 10
#define IMU_ATTITUDE_GRAVITY 9.80665
#define QUATERNION_STATES (0)
// q turned by the bias-corrected gyro rate over the period; the bias constant.
#define STATE_TRANSITION_MODEL \
  (quat_integrate(x, 0, 0, (u[0] - x[4]) * T, (u[1] - x[5]) * T, (u[2] - x[6]) * T)) \
  (quat_integrate(x, 0, 1, (u[0] - x[4]) * T, (u[1] - x[5]) * T, (u[2] - x[6]) * T)) \
  (quat_integrate(x, 0, 2, (u[0] - x[4]) * T, (u[1] - x[5]) * T, (u[2] - x[6]) * T)) \
  (quat_integrate(x, 0, 3, (u[0] - x[4]) * T, (u[1] - x[5]) * T, (u[2] - x[6]) * T)) \
  (x[4])(x[5])(x[6])
#define OBSERVATION_MODEL \
  (quat_rotate_inverse(x, 0, 0, 0.0, 0.0, IMU_ATTITUDE_GRAVITY)) \
  (quat_rotate_inverse(x, 0, 1, 0.0, 0.0, IMU_ATTITUDE_GRAVITY)) \
  (quat_rotate_inverse(x, 0, 2, 0.0, 0.0, IMU_ATTITUDE_GRAVITY))
// Over the tangent space: 3 rows for q (rad^2), 3 for b_g.
#define PROCESS_NOISE_COVARIANCE \
  SF_DIAGONAL((1e-4 * T)(1e-4 * T)(1e-4 * T)(1e-8 * T)(1e-8 * T)(1e-8 * T))
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((0.05)(0.05)(0.05))
#define INITIAL_STATE (1)(0)(0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL((1)(1)(1)(1e-4)(1e-4)(1e-4))
#define TOPICS_IN_CTRL \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.x)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.y)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.z))
#define TOPICS_IN \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.x)) \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.y)) \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.z))
#define TOPICS_OUT \
  ((fused/orientation/w)(0))((fused/orientation/x)(1))((fused/orientation/y)(2)) \
  ((fused/orientation/z)(3)) \
  ((fused/gyro_bias/x)(4))((fused/gyro_bias/y)(5))((fused/gyro_bias/z)(6))
#define INPUT_TIMEOUT ((0)(500))((1)(500))((2)(500))
