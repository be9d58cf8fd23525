// Armesto, Tornero and Vincze's 19-state inertial+vision ego-motion model ("Fast ego-motion
// estimation with multi-rate fusion of inertial and vision", doc/armesto.md) as a node: the
// IMU (sensor_msgs/Imu on /imu/data) sampled every 10 ms, a camera's pose
// (geometry_msgs/PoseWithCovarianceStamped on /vision/pose) every 80 ms, the paper's Q and R.
// This file is their MR-EKF; config/armesto_inertial_vision_ukf.h the MR-UKF (UKF-M) of the
// same model. The library-level reproduction on BROAD is sf_estimation's
// models/armesto_inertial_vision.hpp; "The node headers" in doc/armesto.md compares the two.
//
//   state x (19 stored, 18 tangent; the paper's order, eq. 6)
//     p      x[0..2]    position in the world (odom) frame, z up [m]
//     v      x[3..5]    velocity in the world frame [m/s]
//     a      x[6..8]    acceleration in the world frame [m/s^2] (of the body, without gravity)
//     b      x[9..11]   accelerometer bias in the sensor frame [m/s^2]
//     q      x[12..15]  orientation w, x, y, z of the sensor in the world frame
//     omega  x[16..18]  angular velocity in the sensor frame [rad/s]
//   inputs (all SAMPLED: the period's sample, Armesto et al.'s multi-rate sampler)
//     0..2   /imu/data    linear_acceleration       = R(q)^T (a + (0, 0, g)) + b
//     3..5   /imu/data    angular_velocity          = omega
//     6..8   /vision/pose pose.pose.position        = p
//     9..12  /vision/pose pose.pose.orientation     = q (QUATERNION_INPUTS, compared on SO(3))
//
// Transition over the period T, the paper's eqs. 11-21 with the jerk j, the angular
// acceleration alpha and the bias rate b' as the process noise: p' = p + T v + T^2/2 a,
// v' = v + T a, a' = a, b' = b, q' = q exp(omega T), omega' = omega. Like the library model it
// leaves out eq. 13's alpha x v + omega x a (p, v, a are world vectors of one point), reads
// the accelerometer in the sensor frame (nonlinear in q, differentiated by the filter) instead
// of rotating it into the world as the paper does, and keeps q on SO(3).
//
// Gravity: g = 9.80665 m/s^2 along the world's -z, as the other 3D headers (an accelerometer at
// rest reads +g on its up axis; tools/sim/rigid_body_sim.py and the BROAD bags read so). The
// library model uses 9.81 along east-north-up's up: the same direction, 3.3 mm/s^2 apart.
//
// Q, over the tangent (p, v, a, b, the rotation vector of q about the world's axes, omega):
// the paper's eq. 26 for one step's noise w = (j, alpha, b'), diag(0.7447 I3, 0.38 I3,
// 0.19e-6 I3), carried into the state as the library model's transition carries it, G Q G^T
// with G = dx'/dw: per axis, the jerk enters (p, v, a) as (T^3/6, T^2/2, T) (a rank-one 3 x 3
// block), the bias rate b as T, the angular acceleration q as a turn of T^2/2 alpha and omega
// as T alpha. The one term left out is the cross covariance of q's and omega's noise
// (0.38 T^3/2): the node's q is perturbed about the world's axes and omega lives in the sensor
// frame, so that term is 0.38 T^3/2 R(q), which depends on the state, and Q here is a constant.
// R: the paper's eq. 25, diag(1e-3 I3, 1e-4 I3, 1e-7 I3, 1e-6 I4) for the accelerometer, gyro,
// position and the quaternion's four components. On SO(3) the quaternion's rows are the
// rotation vector's (w row 0): a small rotation phi is the quaternion (1, phi / 2), so a
// component variance of 1e-6 is 4e-6 rad^2 per axis (doc/armesto.md; isotropic, so the world's
// axes and the sensor's give the same R).
// Start: at rest (v = a = b = 0), p and q at the first vision pose and omega at the first gyro
// sample (INITIAL_STATE_FROM_INPUTS), as the library's runs start; P0 1 m^2 on p, 0.01 on the
// rest (m/s, m/s^2, rad, rad/s), so that the IMU's periods before the first frame (4.9 s on the
// BROAD bag) cannot run v and a away: with 1 on v, a and q they reached 3 m/s and a 90 deg
// heading there, and the first frame then sets p and q but not v (doc/armesto.md).
// The node publishes the pose (POSE_OUT_3D); not the twist (the state's velocity is in the
// world frame, TWIST_OUT_3D wants the body's). METHOD is the EKF unless the including file
// defines another one first.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <sensor_msgs/Imu.h>
#include <sf_filter/config/diagonal.hpp>

#ifndef METHOD
#define METHOD EXTENDED_KALMAN_FILTER
#endif
#define ESTIMATION_PERIOD 10
#define ARMESTO_GRAVITY 9.80665
#define QUATERNION_STATES (12)
#define QUATERNION_INPUTS (9)
#define ARMESTO_GRAVITY_AND_ACCELERATION_IN_SENSOR(k) \
  quat_rotate_inverse(x, 12, k, x[6], x[7], x[8] + ARMESTO_GRAVITY)
#define ARMESTO_TURN(k) quat_integrate(x, 12, k, x[16] * T, x[17] * T, x[18] * T)
#define STATE_TRANSITION_MODEL \
  (x[0] + x[3] * T + 0.5 * x[6] * T * T) \
  (x[1] + x[4] * T + 0.5 * x[7] * T * T) \
  (x[2] + x[5] * T + 0.5 * x[8] * T * T) \
  (x[3] + x[6] * T)(x[4] + x[7] * T)(x[5] + x[8] * T) \
  (x[6])(x[7])(x[8]) \
  (x[9])(x[10])(x[11]) \
  (ARMESTO_TURN(0))(ARMESTO_TURN(1))(ARMESTO_TURN(2))(ARMESTO_TURN(3)) \
  (x[16])(x[17])(x[18])
#define OBSERVATION_MODEL \
  (ARMESTO_GRAVITY_AND_ACCELERATION_IN_SENSOR(0) + x[9]) \
  (ARMESTO_GRAVITY_AND_ACCELERATION_IN_SENSOR(1) + x[10]) \
  (ARMESTO_GRAVITY_AND_ACCELERATION_IN_SENSOR(2) + x[11]) \
  (x[16])(x[17])(x[18]) \
  (x[0])(x[1])(x[2]) \
  (x[12])(x[13])(x[14])(x[15])
// Q = G diag(0.7447 I3, 0.38 I3, 0.19e-6 I3) G^T (above). Its 18 x 18 entries are written
// from the 6 x 6 coefficients of the tangent's blocks of three (p, v, a, b, q, omega): entry
// (i, j) is block (i / 3, j / 3)'s coefficient when i and j are the same axis, else 0. Row by
// row with plain macros, not Boost.Preprocessor's arithmetic over the 324 entries: the
// configuration layer expands the matrix several times, and that arithmetic took 3 s of
// every unit's preprocessing and about 100 MB (doc/build_cost.md).
#define ARMESTO_JERK(g1, g2) (0.7447 * (g1) * (g2))
#define ARMESTO_Q_PP ARMESTO_JERK(T * T * T / 6, T * T * T / 6)
#define ARMESTO_Q_PV ARMESTO_JERK(T * T * T / 6, T * T / 2)
#define ARMESTO_Q_PA ARMESTO_JERK(T * T * T / 6, T)
#define ARMESTO_Q_VP ARMESTO_JERK(T * T / 2, T * T * T / 6)
#define ARMESTO_Q_VV ARMESTO_JERK(T * T / 2, T * T / 2)
#define ARMESTO_Q_VA ARMESTO_JERK(T * T / 2, T)
#define ARMESTO_Q_AP ARMESTO_JERK(T, T * T * T / 6)
#define ARMESTO_Q_AV ARMESTO_JERK(T, T * T / 2)
#define ARMESTO_Q_AA ARMESTO_JERK(T, T)
#define ARMESTO_Q_BB 0.19e-6 * T * T
#define ARMESTO_Q_QQ 0.38 * (T * T / 2) * (T * T / 2)
#define ARMESTO_Q_WW 0.38 * T * T
// Row i of block b = i / 3, axis k = i % 3: block (b, c)'s coefficient on column 3 c + k.
#define ARMESTO_AXIS_0(c) (c)(0)(0)
#define ARMESTO_AXIS_1(c) (0)(c)(0)
#define ARMESTO_AXIS_2(c) (0)(0)(c)
#define ARMESTO_Q_ROW(k, c0, c1, c2, c3, c4, c5)                                       \
  (ARMESTO_AXIS_##k(c0) ARMESTO_AXIS_##k(c1) ARMESTO_AXIS_##k(c2) ARMESTO_AXIS_##k(c3) \
       ARMESTO_AXIS_##k(c4) ARMESTO_AXIS_##k(c5))
#define ARMESTO_Q_BLOCK_ROWS(c0, c1, c2, c3, c4, c5)                        \
  ARMESTO_Q_ROW(0, c0, c1, c2, c3, c4, c5) ARMESTO_Q_ROW(1, c0, c1, c2, c3, c4, c5) \
      ARMESTO_Q_ROW(2, c0, c1, c2, c3, c4, c5)
#define PROCESS_NOISE_COVARIANCE                                              \
  ARMESTO_Q_BLOCK_ROWS(ARMESTO_Q_PP, ARMESTO_Q_PV, ARMESTO_Q_PA, 0, 0, 0)    \
  ARMESTO_Q_BLOCK_ROWS(ARMESTO_Q_VP, ARMESTO_Q_VV, ARMESTO_Q_VA, 0, 0, 0)    \
  ARMESTO_Q_BLOCK_ROWS(ARMESTO_Q_AP, ARMESTO_Q_AV, ARMESTO_Q_AA, 0, 0, 0)    \
  ARMESTO_Q_BLOCK_ROWS(0, 0, 0, ARMESTO_Q_BB, 0, 0)                          \
  ARMESTO_Q_BLOCK_ROWS(0, 0, 0, 0, ARMESTO_Q_QQ, 0)                          \
  ARMESTO_Q_BLOCK_ROWS(0, 0, 0, 0, 0, ARMESTO_Q_WW)
#define MEASUREMENT_NOISE_COVARIANCE \
  SF_DIAGONAL((1e-3)(1e-3)(1e-3)(1e-4)(1e-4)(1e-4)(1e-7)(1e-7)(1e-7)(0)(4e-6)(4e-6)(4e-6))
#define INITIAL_STATE (0)(0)(0)(0)(0)(0)(0)(0)(0)(0)(0)(0)(1)(0)(0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE \
  SF_DIAGONAL((1)(1)(1)(0.01)(0.01)(0.01)(0.01)(0.01)(0.01)(0.01)(0.01)(0.01) \
              (0.01)(0.01)(0.01)(0.01)(0.01)(0.01))
#define INITIAL_STATE_FROM_INPUTS \
  ((0)(6))((1)(7))((2)(8))((12)(9))((13)(10))((14)(11))((15)(12))((16)(3))((17)(4))((18)(5))
#define TOPICS_IN \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.x)) \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.y)) \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.z)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.x)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.y)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.z)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.position.x)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.position.y)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.position.z)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.orientation.w)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.orientation.x)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.orientation.y)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.orientation.z))
#define INPUT_ALIGNMENT \
  ((0)(SAMPLED))((1)(SAMPLED))((2)(SAMPLED))((3)(SAMPLED))((4)(SAMPLED))((5)(SAMPLED)) \
  ((6)(SAMPLED))((7)(SAMPLED))((8)(SAMPLED)) \
  ((9)(SAMPLED))((10)(SAMPLED))((11)(SAMPLED))((12)(SAMPLED))
#define TOPICS_OUT \
  ((fused/position/x)(0))((fused/position/y)(1))((fused/position/z)(2)) \
  ((fused/velocity/x)(3))((fused/velocity/y)(4))((fused/velocity/z)(5)) \
  ((fused/acceleration/x)(6))((fused/acceleration/y)(7))((fused/acceleration/z)(8)) \
  ((fused/accelerometer_bias/x)(9))((fused/accelerometer_bias/y)(10)) \
  ((fused/accelerometer_bias/z)(11)) \
  ((fused/orientation/w)(12))((fused/orientation/x)(13))((fused/orientation/y)(14)) \
  ((fused/orientation/z)(15)) \
  ((fused/angular_velocity/x)(16))((fused/angular_velocity/y)(17)) \
  ((fused/angular_velocity/z)(18))
// nav_msgs/Odometry on odometry/filtered (the pose and its 6x6 covariance; the twist unknown),
// the tf odom -> base_link and the Euler angles on fused/euler (doc/filter_node.md).
#define POSE_OUT_3D (0)(1)(2)(12)
