// Generic 3D robot: IMU (sensor_msgs/Imu on /imu/data), 3D odometry (nav_msgs/Odometry on
// /odom, its body-frame twist) and an absolute position (geometry_msgs/PoseWithCovarianceStamped
// on /vision/pose: a motion-capture or visual pose, a GPS in the odom frame), fused on the
// rotation group (QUATERNION_STATES; doc/configuration.md, "Rotations in 3D"). What
// robot_localization's 15-state filter does with two_d_mode false, with the orientation a
// unit quaternion instead of Euler angles.
//
//   state x (16 stored, 15 tangent)
//     p      x[0..2]    position in the world (odom) frame, z up [m]
//     q      x[3..6]    orientation w, x, y, z of base_link in the world frame
//     v      x[7..9]    linear velocity in base_link [m/s]
//     omega  x[10..12]  angular velocity in base_link [rad/s]
//     a      x[13..15]  linear acceleration in base_link [m/s^2] (of the body, gravity not
//                       included)
//   inputs
//     0..2    /imu/data   angular_velocity           = omega
//     3..5    /imu/data   linear_acceleration        = a + R(q)^T (0, 0, g)
//     6..8    /odom       twist.twist.linear         = v
//     9..11   /odom       twist.twist.angular        = omega
//     12..14  /vision/pose pose.pose.position        = p
//
// Transition over the period T: p' = p + R(q) (v T + a T^2 / 2), q' = q exp(omega T),
// v' = v + (a - omega x v) T (the body frame turns under the velocity), omega and a constant.
// Gravity: g = 9.80665 m/s^2 along the world's -z, so that an accelerometer at rest reads +g on
// the body's up axis (REP 103; tools/sim/rigid_body_sim.py and the BROAD bags read so). The IMU
// is taken to be mounted in base_link (a mounted IMU: rotate its vectors with
// FRAME_ALIGNED_INPUTS). Inputs that never arrive (a robot without odometry, the BROAD bags)
// simply leave their states to the others.
//
// Noise (replace with your robot's numbers): gyro 0.005 rad/s and accelerometer 0.05 m/s^2 per
// sample, odometry 0.02 m/s and 0.01 rad/s, position 0.01 m (tools/sim/rigid_body_sim.py's
// defaults). Q over the tangent space: position and orientation 1e-6 T (m^2, rad^2), velocity
// 1e-4 T, angular acceleration 0.5 T (rad/s)^2 and jerk 2 T (m/s^2)^2 (a body whose motion
// changes within a second). P0: 100 m^2 on the position (the first positions set it), 1 rad^2
// on the orientation, 1 on the rates. METHOD is the EKF unless the including file defines
// another one first. A file that defines IMU_ODOMETRY_3D_POSE_ORIENTATION before including this
// one also reads the vision pose's orientation as a measured quaternion, inputs 15..18
// (QUATERNION_INPUTS; config/imu_odometry_pose_3d.h).
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>
#include <sf_filter/config/diagonal.hpp>

#ifndef METHOD
#define METHOD EXTENDED_KALMAN_FILTER
#endif
#define ESTIMATION_PERIOD 10
#define IMU_ODOMETRY_3D_GRAVITY 9.80665
#define QUATERNION_STATES (3)
#ifdef IMU_ODOMETRY_3D_POSE_ORIENTATION
// The vision pose's orientation w, x, y, z = q, compared on SO(3); R: w row 0, the rotation
// vector's 0.01 rad (1e-4 rad^2) about the world's axes.
#define QUATERNION_INPUTS (15)
#define IMU_ODOMETRY_3D_ORIENTATION_ROWS (x[3])(x[4])(x[5])(x[6])
#define IMU_ODOMETRY_3D_ORIENTATION_NOISE (0)(1e-4)(1e-4)(1e-4)
#define IMU_ODOMETRY_3D_ORIENTATION_INPUTS \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.orientation.w)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.orientation.x)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.orientation.y)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.orientation.z))
#else
#define IMU_ODOMETRY_3D_ORIENTATION_ROWS
#define IMU_ODOMETRY_3D_ORIENTATION_NOISE
#define IMU_ODOMETRY_3D_ORIENTATION_INPUTS
#endif
#define IMU_ODOMETRY_3D_STEP(k) \
  quat_rotate(x, 3, k, x[7] * T + 0.5 * x[13] * T * T, x[8] * T + 0.5 * x[14] * T * T, \
              x[9] * T + 0.5 * x[15] * T * T)
#define IMU_ODOMETRY_3D_TURN(k) quat_integrate(x, 3, k, x[10] * T, x[11] * T, x[12] * T)
#define STATE_TRANSITION_MODEL \
  (x[0] + IMU_ODOMETRY_3D_STEP(0)) \
  (x[1] + IMU_ODOMETRY_3D_STEP(1)) \
  (x[2] + IMU_ODOMETRY_3D_STEP(2)) \
  (IMU_ODOMETRY_3D_TURN(0))(IMU_ODOMETRY_3D_TURN(1))(IMU_ODOMETRY_3D_TURN(2)) \
  (IMU_ODOMETRY_3D_TURN(3)) \
  (x[7] + (x[13] - (x[11] * x[9] - x[12] * x[8])) * T) \
  (x[8] + (x[14] - (x[12] * x[7] - x[10] * x[9])) * T) \
  (x[9] + (x[15] - (x[10] * x[8] - x[11] * x[7])) * T) \
  (x[10])(x[11])(x[12]) \
  (x[13])(x[14])(x[15])
#define IMU_ODOMETRY_3D_GRAVITY_IN_BODY(k) \
  quat_rotate_inverse(x, 3, k, 0.0, 0.0, IMU_ODOMETRY_3D_GRAVITY)
#define OBSERVATION_MODEL \
  (x[10])(x[11])(x[12]) \
  (x[13] + IMU_ODOMETRY_3D_GRAVITY_IN_BODY(0)) \
  (x[14] + IMU_ODOMETRY_3D_GRAVITY_IN_BODY(1)) \
  (x[15] + IMU_ODOMETRY_3D_GRAVITY_IN_BODY(2)) \
  (x[7])(x[8])(x[9]) \
  (x[10])(x[11])(x[12]) \
  (x[0])(x[1])(x[2]) \
  IMU_ODOMETRY_3D_ORIENTATION_ROWS
// Over the tangent space: p, q (3 rows, rad^2), v, omega, a.
#define PROCESS_NOISE_COVARIANCE \
  SF_DIAGONAL((1e-6 * T)(1e-6 * T)(1e-6 * T)(1e-6 * T)(1e-6 * T)(1e-6 * T) \
              (1e-4 * T)(1e-4 * T)(1e-4 * T)(0.5 * T)(0.5 * T)(0.5 * T)(2 * T)(2 * T)(2 * T))
#define MEASUREMENT_NOISE_COVARIANCE \
  SF_DIAGONAL((2.5e-5)(2.5e-5)(2.5e-5)(2.5e-3)(2.5e-3)(2.5e-3)(4e-4)(4e-4)(4e-4) \
              (1e-4)(1e-4)(1e-4)(1e-4)(1e-4)(1e-4) IMU_ODOMETRY_3D_ORIENTATION_NOISE)
#define INITIAL_STATE (0)(0)(0)(1)(0)(0)(0)(0)(0)(0)(0)(0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE \
  SF_DIAGONAL((100)(100)(100)(1)(1)(1)(1)(1)(1)(1)(1)(1)(1)(1)(1))
#define TOPICS_IN \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.x)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.y)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.z)) \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.x)) \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.y)) \
  ((imu/data)(sensor_msgs::Imu)(linear_acceleration.z)) \
  ((odom)(nav_msgs::Odometry)(twist.twist.linear.x)) \
  ((odom)(nav_msgs::Odometry)(twist.twist.linear.y)) \
  ((odom)(nav_msgs::Odometry)(twist.twist.linear.z)) \
  ((odom)(nav_msgs::Odometry)(twist.twist.angular.x)) \
  ((odom)(nav_msgs::Odometry)(twist.twist.angular.y)) \
  ((odom)(nav_msgs::Odometry)(twist.twist.angular.z)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.position.x)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.position.y)) \
  ((vision/pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.position.z)) \
  IMU_ODOMETRY_3D_ORIENTATION_INPUTS
#define TOPICS_OUT \
  ((fused/position/x)(0))((fused/position/y)(1))((fused/position/z)(2)) \
  ((fused/orientation/w)(3))((fused/orientation/x)(4))((fused/orientation/y)(5)) \
  ((fused/orientation/z)(6)) \
  ((fused/velocity/x)(7))((fused/velocity/y)(8))((fused/velocity/z)(9)) \
  ((fused/angular_velocity/x)(10))((fused/angular_velocity/y)(11)) \
  ((fused/angular_velocity/z)(12))
// nav_msgs/Odometry on odometry/filtered (pose and body twist with their 6x6 covariances),
// the tf odom -> base_link and the Euler angles on fused/euler (doc/filter_node.md).
#define POSE_OUT_3D (0)(1)(2)(3)
#define TWIST_OUT_3D (7)(8)(9)(10)(11)(12)
#define INPUT_TIMEOUT \
  ((0)(500))((1)(500))((2)(500))((3)(500))((4)(500))((5)(500)) \
  ((6)(500))((7)(500))((8)(500))((9)(500))((10)(500))((11)(500))
