// config/husky_skid_steer_odom_imu.h (wheel odometry and the IMU's yaw rate on the real Husky
// recording bags/husky_gps.bag) with the recording's GPS fused as well (doc/real_robot.md,
// "GPS fused at a reduced rate"; the GPS input is documented in doc/configuration.md, "GPS").
//
//   state x = (x, y, theta, v, omega, b_g, s, k): as in config/skid_steer_odom_imu.h, plus
//     k  the wheels' speed scale error: the odometry reports v (1 + k)
//   inputs 0-2 as there (/encoder v and yaw rate, /imu/data gyro z), input 0 now observed as
//   v (1 + k), and
//     3  /fix  sensor_msgs/NavSatFix  EAST:  x of the fix in the odom frame = x[0]
//     4  /fix  sensor_msgs/NavSatFix  NORTH: y of the fix in the odom frame = x[1]
//
// The fix is taken about the datum (the first valid fix, or ~datum) and turned into the odom
// frame by ~gps_yaw_offset: the heading in ENU of the odom frame's x axis, i.e. of the robot
// at start (its odometry heading is 0 there). The odom origin is the start, so the first fix
// is the datum. The recording has no absolute heading (its IMU's orientation covariance is
// 1e6, its magnetometer topic was not kept), so the offset is a parameter; tools/eval/
// gps_holdout.py measures it from the first fused fixes. The covariance of each fix is its
// position_covariance turned into the odom frame (covariance type APPROXIMATED on this
// recording: its diagonal, equal east and north variances of 0.81 to 1.96 m^2, so x and y
// stay uncorrelated at any offset); R's 2.0 m^2 is used only for a fix whose covariance type
// is UNKNOWN.
//
// Why the scale state: the wheels of this robot report about 15 % more distance than the GPS
// track has (27.6 m against 24.0 m, doc/real_robot.md), a systematic error that no white
// process noise of the pose describes: without k the dead-reckoned loop is larger than the
// GPS loop and every fix pulls the estimate back by a little (with k: 0.71 m RMSE on the
// held-out fixes at every 5th fix fused, without: 1.04 m; doc/real_robot.md). Nothing but
// the GPS observes k (the wheels see v (1 + k) only); it starts at 0 with a standard
// deviation of 0.2 and drifts by 1e-3 per sqrt(s).
// Process noise of the pose: the base header models a perfect dead reckoning (1e-6 T), because
// nothing measured the pose there. With the GPS it must admit what dead reckoning gets wrong
// beyond the scale, or the fixes would never move the estimate: slip across the track and the
// gyro's heading drift; 0.02 T m^2 on x and y (0.14 m per sqrt(s)) and 1e-4 T rad^2 on the
// heading (0.6 deg per sqrt(s)). Chosen from these figures, not fitted to the fixes.
#include <sensor_msgs/NavSatFix.h>
#include <sf_filter/config/diagonal.hpp>

#include "husky_skid_steer_odom_imu.h"

#undef TOPICS_IN
#define TOPICS_IN \
  ((/encoder)(nav_msgs::Odometry)(twist.twist.linear.x)) \
  ((/encoder)(nav_msgs::Odometry)(twist.twist.angular.z)) \
  ((/imu/data)(sensor_msgs::Imu)(angular_velocity.z)) \
  ((/fix)(sensor_msgs::NavSatFix)(longitude)) \
  ((/fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((3)(EAST)(ABSOLUTE))((4)(NORTH)(ABSOLUTE))
// The fixes' slow error: first-order Gauss-Markov per axis, time constant and standard
// deviation measured on the recording's fixes (see above).
#define GPS_ERROR_TAU 60.0
#define GPS_ERROR_SIGMA 1.1
#undef STATE_TRANSITION_MODEL
#define STATE_TRANSITION_MODEL \
  SKID_STEER_TRANSITION(x[7])(x[8])(exp(-T / GPS_ERROR_TAU) * x[9])(exp(-T / GPS_ERROR_TAU) * x[10])
#undef OBSERVATION_MODEL
#define OBSERVATION_MODEL \
  (x[3] * (1 + x[7])) \
  (x[4] + SKID_STEER_MOVING * x[6]) \
  (x[4] + x[5]) \
  (cos(x[8]) * x[0] - sin(x[8]) * x[1] + x[9]) \
  (sin(x[8]) * x[0] + cos(x[8]) * x[1] + x[10])
#undef MEASUREMENT_NOISE_COVARIANCE
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((1e-4)(4e-4)(1.25e-5)(0.02)(0.02))
#define GPS_COVARIANCE_SCALE 0.01
#define GPS_ERROR_Q (GPS_ERROR_SIGMA * GPS_ERROR_SIGMA * (1 - exp(-2 * T / GPS_ERROR_TAU)))
#undef PROCESS_NOISE_COVARIANCE
#define PROCESS_NOISE_COVARIANCE \
  SF_DIAGONAL((0.02 * T)(0.02 * T)(1e-4 * T)(0.25 * T)(1.0 * T)(1e-8 * T)(100)(1e-6 * T) \
              (0)(GPS_ERROR_Q)(GPS_ERROR_Q))
#undef INITIAL_STATE
#define INITIAL_STATE (0)(0)(0)(0)(0)(0)(0)(0)(0)(0)(0)
#undef INITIAL_ERROR_COVARIANCE
#define INITIAL_ERROR_COVARIANCE \
  SF_DIAGONAL((0)(0)(0)(1)(1)(2.5e-5)(100)(0.04)(3.29)(GPS_ERROR_SIGMA * GPS_ERROR_SIGMA) \
              (GPS_ERROR_SIGMA * GPS_ERROR_SIGMA))
#undef ANGLE_STATES
#define ANGLE_STATES (2)(8)
#undef ALIGN_BY_STAMP
#define ALIGN_BY_STAMP (0)(1)(2)(3)(4)
// The fixes' gate (doc/configuration.md, "Alignment policies, gates and stamps"): a fix whose
// east or north innovation exceeds 10 of its predicted standard deviations (squared
// Mahalanobis distance above 100, chi-square with 1 degree of freedom) is a jump that no
// motion of the model allows - a multipath reflection, a receiver's reset, a 1000 km error -
// and is treated as missing, counted as gated (diagnostics, replay summary). 10 sigma, not
// 3: a consistent filter passes a fix beyond it once in 1e23, and the dead reckoning must
// be wrong by 10 of its own sigmas before the gate could lock the GPS out. On
// bags/husky_gps.bag the largest squared distance is 3.6 (east; north below 1), so no fix
// is gated and the estimates are those without a gate, byte for byte (doc/real_robot.md).
#define INPUT_GATE ((3)(100))((4)(100))
