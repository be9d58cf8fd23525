// Generic planar robot: a differential-drive or skid-steer base with wheel odometry on
// /odom (nav_msgs/Odometry, e.g. from diff_drive_controller) and an IMU on /imu/data
// (sensor_msgs/Imu). The header to start from for a typical robot: doc/generic_robot.md says
// how to point it at other topics and how to adapt it.
//
//   state x = (x, y, theta, v, omega, b_g)
//     x, y, theta  planar pose in the odom frame [m, m, rad], starting at (0, 0, 0)
//     v, omega     forward speed and yaw rate of base_link [m/s, rad/s]
//     b_g          bias of the gyro's yaw rate, in base_link [rad/s]
//   inputs
//     0  /odom     twist.twist.linear.x   = v          (wheel odometry; twist in base_link)
//     1  /odom     twist.twist.angular.z  = omega
//     2  /imu/data angular_velocity, rotated by tf2 from the IMU's header.frame_id into
//                  base_link, z component = omega + b_g
//
// Transition over one period T: unicycle with the mid-period heading (exact for constant v
// and omega), v and omega random walks (white acceleration), b_g a slow random walk.
// b_g is observable because the odometry measures omega without the gyro's bias: it is what
// gyro and wheels disagree on over time, and learned fastest while the robot stands still.
//
// Noise (replace with your robot's numbers): odometry speed std 0.005 m/s and yaw rate std
// 0.02 rad/s per 50 Hz message (wheel speed noise 0.007 m/s per wheel over a 0.5 m track);
// gyro std 0.005 rad/s per 100 Hz sample, so 0.005^2 / 2 for the mean of the two samples of
// a 20 ms period; accelerations up to about 0.5 m/s^2 and 1 rad/s^2 (Q of v and
// omega: 0.5^2 T and 1 T); gyro bias drift 1e-4 rad/s per sqrt(s) (Q 1e-8 T). The pose has a
// small Q (1e-6 T) for the model's own error; nothing measures it, so it only grows P.
// P0: the pose is the start of odom, exactly 0; v and omega unknown (1); the bias within
// about 0.05 rad/s (3 deg/s, a MEMS gyro's turn-on bias), P0 = 0.05^2.
//
// Period 20 ms: the odometry's 50 Hz (diff_drive_controller's default publish rate), so
// every period has one odometry message and the IMU's samples of that period are averaged.
//
// Output: TOPICS_OUT below (relative names: remap or use a namespace), ~state, and with
// POSE_OUT nav_msgs/Odometry on odometry/filtered plus the tf ~frame_id -> ~child_frame_id.
// The wheel odometry usually broadcasts odom -> base_link itself, so the launch file
// (launch/diff_drive_odom_imu.launch) publishes odom -> base_link_fused by default; see
// doc/generic_robot.md for replacing the wheel odometry's transform instead.
//
// Working first time on a real robot (issue 13):
// - the heading x[2] is declared an angle (ANGLE_STATES): it is wrapped to (-pi, pi] after
//   every step and the UKF and PF average it on the circle;
// - both topics carry header.stamp, so every input is aligned by its stamp, not by its
//   arrival (ALIGN_BY_STAMP), and a period waits MAX_MEASUREMENT_LAG = 20 ms for values
//   stamped in it that are still in transit (a real driver's latency is a few ms);
// - INPUT_TIMEOUT: an input silent for 500 ms is timed out (diagnostics WARN, missing in
//   every period). 500 ms is several periods of any odometry or IMU from 10 Hz up, so the
//   same value fits a slower robot without an edit.
// - METHOD is the EKF unless the including file defines another one first (a UKF variant
//   is then two lines: #define METHOD UNSCENTED_KALMAN_FILTER and #include this header).
//   The header keeps the wheels' yaw rate as a precise observation: on a skid-steer base
//   (four wheels, tracks) use config/skid_steer_odom_imu.h instead.
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>

#ifndef METHOD
#define METHOD EXTENDED_KALMAN_FILTER
#endif
#define ESTIMATION_PERIOD 20
#define STATE_TRANSITION_MODEL \
  (x[0] + x[3] * T * cos(x[2] + 0.5 * x[4] * T)) \
  (x[1] + x[3] * T * sin(x[2] + 0.5 * x[4] * T)) \
  (x[2] + x[4] * T) \
  (x[3]) \
  (x[4]) \
  (x[5])
#define OBSERVATION_MODEL \
  (x[3]) \
  (x[4]) \
  (x[4] + x[5])
#define PROCESS_NOISE_COVARIANCE \
  ((1e-6 * T)(0)(0)(0)(0)(0)) \
  ((0)(1e-6 * T)(0)(0)(0)(0)) \
  ((0)(0)(1e-6 * T)(0)(0)(0)) \
  ((0)(0)(0)(0.25 * T)(0)(0)) \
  ((0)(0)(0)(0)(1.0 * T)(0)) \
  ((0)(0)(0)(0)(0)(1e-8 * T))
#define MEASUREMENT_NOISE_COVARIANCE \
  ((2.5e-5)(0)(0)) \
  ((0)(4e-4)(0)) \
  ((0)(0)(1.25e-5))
// v = omega = 0 at the start is harmless here (unlike config/skid_steer_odom_imu.h, whose
// standstill test reads them): the wheels' yaw rate is an observation of omega in every
// period, so the first period teaches the bias what every other period does.
#define INITIAL_STATE (0)(0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE \
  ((0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(1)(0)(0)) \
  ((0)(0)(0)(0)(1)(0)) \
  ((0)(0)(0)(0)(0)(2.5e-3))
#define TOPICS_IN \
  ((odom)(nav_msgs::Odometry)(twist.twist.linear.x)) \
  ((odom)(nav_msgs::Odometry)(twist.twist.angular.z)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.z))
#define TOPICS_OUT \
  ((fused/x)(0))((fused/y)(1))((fused/heading)(2)) \
  ((fused/linear_velocity)(3))((fused/angular_velocity)(4))((fused/gyro_bias)(5))
#define POSE_OUT (0)(1)(2)
// The Odometry's twist from v and omega (doc/configuration.md, "Outputs").
#define TWIST_OUT (3)(4)
#define BASE_FRAME base_link
#define FRAME_ALIGNED_INPUTS ((2)(angular_velocity)(z))
#define ANGLE_STATES (2)
#define ALIGN_BY_STAMP (0)(1)(2)
#define MAX_MEASUREMENT_LAG 20
#define INPUT_TIMEOUT ((0)(500))((1)(500))((2)(500))
