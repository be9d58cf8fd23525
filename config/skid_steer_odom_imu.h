// Skid-steer planar robot: a four-wheel or tracked base (Pioneer 3-AT, Clearpath Husky,
// Jackal-class) with wheel odometry on /odom (nav_msgs/Odometry) and an IMU on /imu/data
// (sensor_msgs/Imu). The variant of config/diff_drive_odom_imu.h for bases whose wheels
// slip sideways in every turn; doc/generic_robot.md says when to take which and how to
// point it at other topics.
//
//   state x = (x, y, theta, v, omega, b_g, s)
//     x, y, theta  planar pose in the odom frame [m, m, rad], starting at (0, 0, 0)
//     v, omega     forward speed and yaw rate of base_link [m/s, rad/s]
//     b_g          bias of the gyro's yaw rate, in base_link [rad/s]
//     s            the wheels' yaw-rate error of this period (skid slip) [rad/s]: white,
//                  a nuisance state that is never published as an estimate of anything
//   inputs
//     0  /odom     twist.twist.linear.x   = v
//     1  /odom     twist.twist.angular.z  = omega + k(v, omega) s
//     2  /imu/data angular_velocity, rotated by tf2 from the IMU's header.frame_id into
//                  base_link, z component = omega + b_g
//
// Why not the differential-drive header. A skid-steer base turns by dragging its wheels
// sideways: the wheels' yaw rate ((v_r - v_l) / track) is off by a factor that depends on
// the floor and the load (the Husky recording in bags/ reports 2.06 times the gyro's turn,
// doc/real_robot.md), and the error is systematic, always of the sign of the turn. In the
// differential-drive header the wheels' yaw rate is a precise observation of omega and the
// gyro of omega + b_g, so the gyro bias state learns whatever the two disagree on: it
// absorbs the slip, and the heading follows the wheels.
//
// What this header does instead:
// - The gyro carries the yaw rate: it is the only precise observation of omega.
// - The wheels' yaw rate sees omega plus the slip s weighted by
//       k(v, omega) = 1 - exp(-r^2),  r = (v / 0.05 m/s)^2 + (omega / 0.1 rad/s)^2,
//   so 0 at standstill and 1 as soon as the base moves (k = 0.003 at 0.012 m/s or at
//   0.025 rad/s alone, 0.014 at both, 0.63 at 0.05 m/s or 0.1 rad/s, 1.0 at twice that).
//   s is white with a variance of 100 (rad/s)^2 per period: while the base moves the
//   wheels' yaw rate has a variance of about 100 and tells the filter nothing (the slip
//   goes into s, which is redrawn every period, not into b_g); at standstill it is the
//   precise observation omega = 0 (R 4e-4), and the gyro's reading is then its bias.
//   This is the "variance that is huge unless the wheels report standstill", written as
//   an expression of the observation model (the configuration has no state-dependent R).
// - The gyro bias is therefore learned only while the wheels report standstill: slip is
//   never taken for bias. It starts at P0 = (0.005 rad/s)^2: the header assumes a gyro
//   whose turn-on bias was removed by its driver or by a few seconds at rest, because a
//   bias that is uncertain and cannot be observed (a robot that never stops) makes the
//   heading's variance grow with t^2. The UKF takes its predicted mean as f of the mean
//   (UKF_PROPAGATED_MEAN, on with ANGLE_STATES; doc/manifolds.md), so a wide heading no
//   longer shortens its steps as the sigma points' average did (issue 13: that UKF
//   contracted a real track to half); the particle filter's pose mean is taken on SE(2).
//   Raise it for a cold gyro that stands still at start.
// - No standstill assumed at the start. The standstill test k(v, omega) reads the estimate,
//   and an initial v = omega = 0 would be read as standstill: the first period would take the
//   wheels' yaw rate as exact and write the difference to the gyro, all slip on a recording that
//   starts in a turn, into b_g (issue 37: 0.0019 rad/s on a real Husky recording, kept until its
//   first stop 236 s later). So v starts at the first wheel speed and omega at the first gyro
//   reading (INITIAL_STATE_FROM_INPUTS, minus b_g's initial 0; the gyro, not the slipping
//   wheels, carries the yaw rate), their variances of 1 kept: the test then sees measured
//   values from the first step on. Chosen over gating the test on the readings themselves,
//   which an observation model cannot see, and over a "moving" x0, which would move the pose
//   in the first period. The particle filter (config/husky_skid_steer_pf.h) cannot replace
//   its belief and keeps x0; its particles, spread over v and omega by P0, read mostly as
//   moving anyway.
// - Position does not jump. Nothing measures x, y or theta; they are integrated from the
//   velocities of the previous period's estimate (the state transition below uses x[3],
//   x[4] of the last a posteriori estimate). A Kalman update moves a state only through its
//   covariance with the observed ones. In motion no innovation reaches b_g (above), so the
//   only covariances of the pose with observed states are those of the current period's
//   step with v and omega: an innovation moves the pose by at most T times its velocity
//   correction, the dead-reckoning step with the corrected velocity. The large
//   covariances of the differential-drive header on a real bag (x, y with heading and a
//   bias that absorbs slip, position variance 3300 m^2, jumps of 2 m per period) cannot
//   build up. The one exception is a bias update at standstill: it corrects the heading
//   (and through it the position) by what the old bias estimate integrated since the last
//   stop (on the simulated differential-drive bag at most 12 mm in one period, while in
//   motion the position never left its dead-reckoning step by more than 0.011 mm;
//   doc/real_robot.md, which also measures the jumps on the real Husky recording).
//
// Noise (replace with your robot's numbers): odometry speed std 0.01 m/s per message (R
// 1e-4: a skid-steer base also slips along its track); the wheels' yaw rate std 0.02 rad/s
// at standstill (R 4e-4); gyro std 0.005 rad/s per sample, R 1.25e-5 for the mean of the
// IMU samples of a period (set it from the IMU's standstill noise); accelerations up to
// about 0.5 m/s^2 and 1 rad/s^2 (Q of v and omega: 0.25 T and 1 T); gyro bias drift
// 1e-4 rad/s per sqrt(s) (Q 1e-8 T); the pose's own model error 1e-6 T.
//
// Period 20 ms, inputs aligned by header stamp with 20 ms of lag allowed, timeouts 500 ms,
// heading declared an angle: as in config/diff_drive_odom_imu.h. METHOD is the EKF unless
// the including file defines another one first.
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>

#ifndef METHOD
#define METHOD EXTENDED_KALMAN_FILTER
#endif
#define ESTIMATION_PERIOD 20
// The transition has a name of its own so that a header extending the state appends to it
// instead of copying it (config/husky_skid_steer_gps.h).
#define SKID_STEER_TRANSITION \
  (x[0] + x[3] * T * cos(x[2] + 0.5 * x[4] * T)) \
  (x[1] + x[3] * T * sin(x[2] + 0.5 * x[4] * T)) \
  (x[2] + x[4] * T) \
  (x[3]) \
  (x[4]) \
  (x[5]) \
  (0)
#define STATE_TRANSITION_MODEL SKID_STEER_TRANSITION
// k(v, omega): 0 at standstill, 1 in motion (see above).
#define SKID_STEER_MOVING \
  (1 - exp(-pow(pow(x[3] / 0.05, 2) + pow(x[4] / 0.1, 2), 2)))
#define OBSERVATION_MODEL \
  (x[3]) \
  (x[4] + SKID_STEER_MOVING * x[6]) \
  (x[4] + x[5])
#define PROCESS_NOISE_COVARIANCE \
  ((1e-6 * T)(0)(0)(0)(0)(0)(0)) \
  ((0)(1e-6 * T)(0)(0)(0)(0)(0)) \
  ((0)(0)(1e-6 * T)(0)(0)(0)(0)) \
  ((0)(0)(0)(0.25 * T)(0)(0)(0)) \
  ((0)(0)(0)(0)(1.0 * T)(0)(0)) \
  ((0)(0)(0)(0)(0)(1e-8 * T)(0)) \
  ((0)(0)(0)(0)(0)(0)(100))
#define MEASUREMENT_NOISE_COVARIANCE \
  ((1e-4)(0)(0)) \
  ((0)(4e-4)(0)) \
  ((0)(0)(1.25e-5))
#define INITIAL_STATE (0)(0)(0)(0)(0)(0)(0)
// v from the wheels' first speed, omega from the gyro's first yaw rate (see above).
#define INITIAL_STATE_FROM_INPUTS ((3)(0))((4)(2))
#define INITIAL_ERROR_COVARIANCE \
  ((0)(0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(1)(0)(0)(0)) \
  ((0)(0)(0)(0)(1)(0)(0)) \
  ((0)(0)(0)(0)(0)(2.5e-5)(0)) \
  ((0)(0)(0)(0)(0)(0)(100))
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
