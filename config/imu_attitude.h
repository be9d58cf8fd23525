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
// Optional magnetometer (sensor_msgs/MagneticField on /imu/mag, in tesla): define
// IMU_ATTITUDE_MAGNETOMETER before including this header. The state then gains the Earth's
// field in the world frame, its horizontal (north, along the world's y) and vertical (up)
// components m_n, m_u [uT] (x[7], x[8], starting at 20 and -40 uT, P0 (20 uT)^2, drifting by
// 0.01 uT/sqrt(s)), and inputs 3..5 read magnetic_field x, y, z = R(q)^T (0, m_n, m_u) 1e-6
// (R 1e-11 T^2, (3.2 uT)^2: searched on 11 BROAD trials, where (1 uT)^2 let a field bent by a
// nearby magnet pull the tilt; doc/broad.md): the heading is then observed, about magnetic
// north, and the world's y axis points there. Without tilt compensation of its own: the whole vector is compared, so roll
// and pitch need no level sensor. Hard- and soft-iron calibration are the driver's.
// METHOD is the EKF unless the including file defines another one first.
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/MagneticField.h>
#include <sf_filter/config/diagonal.hpp>

#ifndef METHOD
#define METHOD EXTENDED_KALMAN_FILTER
#endif
#define ESTIMATION_PERIOD 10
#define IMU_ATTITUDE_GRAVITY 9.80665
#define QUATERNION_STATES (0)
// q turned by the bias-corrected gyro rate over the period; the bias constant.
#define IMU_ATTITUDE_TURN(k) \
  quat_integrate(x, 0, k, (u[0] - x[4]) * T, (u[1] - x[5]) * T, (u[2] - x[6]) * T)
#define IMU_ATTITUDE_TRANSITION \
  (IMU_ATTITUDE_TURN(0))(IMU_ATTITUDE_TURN(1))(IMU_ATTITUDE_TURN(2))(IMU_ATTITUDE_TURN(3)) \
  (x[4])(x[5])(x[6])
#define IMU_ATTITUDE_OBSERVATION \
  (quat_rotate_inverse(x, 0, 0, 0.0, 0.0, IMU_ATTITUDE_GRAVITY)) \
  (quat_rotate_inverse(x, 0, 1, 0.0, 0.0, IMU_ATTITUDE_GRAVITY)) \
  (quat_rotate_inverse(x, 0, 2, 0.0, 0.0, IMU_ATTITUDE_GRAVITY))
// Over the tangent space: 3 rows for q (rotations about the world's x, y, z; rad^2), 3 for b_g.
#define IMU_ATTITUDE_Q (1e-6 * T)(1e-6 * T)(1e-6 * T)(1e-10 * T)(1e-10 * T)(1e-10 * T)
#define IMU_ATTITUDE_P0 (1)(1)(1)(1e-5)(1e-5)(1e-5)
#define TOPICS_IN_CTRL \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.x)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.y)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.z))
#define IMU_ATTITUDE_INPUTS \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.x)) \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.y)) \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.z))
#define TOPICS_OUT \
  ((fused/orientation/w)(0))((fused/orientation/x)(1))((fused/orientation/y)(2)) \
  ((fused/orientation/z)(3)) \
  ((fused/gyro_bias/x)(4))((fused/gyro_bias/y)(5))((fused/gyro_bias/z)(6))
// The orientation alone as nav_msgs/Odometry on odometry/filtered (position zero, variance
// 1e6), the tf odom -> base_link and the Euler angles on fused/euler (doc/filter_node.md).
#define POSE_OUT_3D (0)

#if defined(IMU_ATTITUDE_MAGNETOMETER)
#define IMU_ATTITUDE_FIELD(k) quat_rotate_inverse(x, 0, k, 0.0, x[7] * 1e-6, x[8] * 1e-6)
#define STATE_TRANSITION_MODEL IMU_ATTITUDE_TRANSITION(x[7])(x[8])
#define OBSERVATION_MODEL \
  IMU_ATTITUDE_OBSERVATION(IMU_ATTITUDE_FIELD(0))(IMU_ATTITUDE_FIELD(1))(IMU_ATTITUDE_FIELD(2))
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL(IMU_ATTITUDE_Q(1e-4 * T)(1e-4 * T))
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((0.5)(0.5)(0.5)(1e-11)(1e-11)(1e-11))
#define INITIAL_STATE (1)(0)(0)(0)(0)(0)(0)(20)(-40)
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL(IMU_ATTITUDE_P0(400)(400))
#define TOPICS_IN \
  IMU_ATTITUDE_INPUTS \
  ((imu/mag)(sensor_msgs::MagneticField)(magnetic_field.x)) \
  ((imu/mag)(sensor_msgs::MagneticField)(magnetic_field.y)) \
  ((imu/mag)(sensor_msgs::MagneticField)(magnetic_field.z))
#define INPUT_TIMEOUT ((0)(500))((1)(500))((2)(500))((3)(500))((4)(500))((5)(500))
#else
#define STATE_TRANSITION_MODEL IMU_ATTITUDE_TRANSITION
#define OBSERVATION_MODEL IMU_ATTITUDE_OBSERVATION
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL(IMU_ATTITUDE_Q)
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((0.5)(0.5)(0.5))
#define INITIAL_STATE (1)(0)(0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL(IMU_ATTITUDE_P0)
#define TOPICS_IN IMU_ATTITUDE_INPUTS
#define INPUT_TIMEOUT ((0)(500))((1)(500))((2)(500))
#endif
