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
// which this model takes for noise: R = 0.5 (m/s^2)^2 per axis, far above the sensor's own
// noise (0.05 m/s^2), so that a moving body's accelerations tilt the estimate little (on the
// fast BROAD trial 0.05 gave 16 deg of tilt error, 0.5 gave 2.6 deg; doc/manifolds.md). Q: the
// orientation 1e-6 T rad^2 (a gyro noise of 0.005 rad/s over one sample per period), the bias
// 1e-10 T (rad/s)^2. P0: 1 rad^2 about each world axis (roll and pitch settle on the first
// readings; the heading, about the world's z, is not observed and stays where it starts: the
// orientation error is about the world's axes, so its variance never leaks into roll and
// pitch), 1e-5 (rad/s)^2 on the bias (about a MEMS gyro's turn-on bias of 0.003 rad/s).
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
// Over the tangent space: 3 rows for q (rotations about the world's x, y, z; rad^2), 3 for b_g.
#define PROCESS_NOISE_COVARIANCE \
  SF_DIAGONAL((1e-6 * T)(1e-6 * T)(1e-6 * T)(1e-10 * T)(1e-10 * T)(1e-10 * T))
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((0.5)(0.5)(0.5))
#define INITIAL_STATE (1)(0)(0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL((1)(1)(1)(1e-5)(1e-5)(1e-5))
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
