// config/husky_skid_steer_odom_imu.h (wheel odometry and the IMU's yaw rate on the real Husky
// recording bags/husky_gps.bag) with the recording's GPS fused as well (doc/real_robot.md,
// "GPS fused at a reduced rate"; the GPS input is documented in doc/configuration.md, "GPS").
//
//   state x = (x, y, theta, v, omega, b_g, s, k, psi, e_E, e_N, c_E, c_N): as in
//     config/skid_steer_odom_imu.h, plus
//     k         the wheels' speed scale error: the odometry reports v (1 + k)
//     psi       the yaw between ENU and the odom frame: the heading in ENU of the odom x axis
//               (counter-clockwise from east), i.e. of the robot at start
//     e_E, e_N  the receiver's slowly changing error, east and north [m]
//     c_E, c_N  the start (the odom origin) about the datum, east and north [m]
//   inputs 0-2 as there (/encoder v and yaw rate, /imu/data gyro z), input 0 now observed as
//   v (1 + k), and
//     3  /fix  sensor_msgs/NavSatFix  EAST:  east of the fix  = cos psi x - sin psi y + c_E + e_E
//     4  /fix  sensor_msgs/NavSatFix  NORTH: north of the fix = sin psi x + cos psi y + c_N + e_N
//
// The fixes go to the filter in ENU about the datum (~gps_yaw_offset 0, the default; the
// first valid fix, or ~datum), and the model turns the odom pose into ENU by psi: no
// hand-fitted offset (doc/real_robot.md, "GPS fused at a reduced rate", why a state and not
// navsat_transform's heading from the first motion). psi starts at 0 with the variance of a
// heading uniform on the circle, pi^2 / 3: nothing is known. While the robot has not moved
// (x = y = 0) the fixes do not depend on psi (its Jacobian is 0): psi keeps its variance and
// the fix sets c, whose P0 of 1e4 m^2 takes any datum; psi is learnt as the robot moves. A
// given ~gps_yaw_offset (an initial guess) turns the fixes and their covariance, and psi
// estimates the rest.
//
// The receiver's error changes slowly (doc/real_robot.md: a held fix is within 0.29 m of the
// next, 0.4 s later): e is a first-order Gauss-Markov process per axis, e' = -e / tau + w,
// with the standard deviation GPS_ERROR_SIGMA and time constant GPS_ERROR_TAU measured on the
// recording's fixes (tools/eval/gps_error_model.py: their residual against the dead reckoning
// diffuses by 0.04 m^2/s per axis over lags of 0.4 to 12 s, with no white part visible;
// sigma^2 = 1.21 m^2 is the receiver's declared horizontal variance (0.81 to 1.96 m^2) and
// tau = 2 sigma^2 / 0.04 = 60 s; the 38 s recording does not identify a longer tau). The fix's
// own covariance is the receiver's total error; with e a state only its white part is left,
// GPS_COVARIANCE_SCALE 0.003 of it (0.05 to 0.08 m). c and e are told apart by e's decay: c is
// constant. Each fix's covariance is its position_covariance (covariance type APPROXIMATED on
// this recording: its diagonal, equal east and north variances); R's 0.02 m^2 is used only
// for a fix whose covariance type is UNKNOWN.
//
// Why the scale state: the wheels of this robot report about 15 % more distance than the GPS
// track has (27.6 m against 24.0 m, doc/real_robot.md), a systematic error that no white
// process noise of the pose describes. Nothing but the GPS observes k (the wheels see
// v (1 + k) only); it starts at 0 with a standard deviation of 0.2 and drifts by 1e-3 per
// sqrt(s).
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
// The fixes' slow error e: first-order Gauss-Markov per axis (see above).
#define GPS_ERROR_TAU 60.0
#define GPS_ERROR_SIGMA 1.1
#undef STATE_TRANSITION_MODEL
#define STATE_TRANSITION_MODEL \
  SKID_STEER_TRANSITION(x[7])(x[8])(exp(-T / GPS_ERROR_TAU) * x[9]) \
  (exp(-T / GPS_ERROR_TAU) * x[10])(x[11])(x[12])
#undef OBSERVATION_MODEL
#define OBSERVATION_MODEL \
  (x[3] * (1 + x[7])) \
  (x[4] + SKID_STEER_MOVING * x[6]) \
  (x[4] + x[5]) \
  (cos(x[8]) * x[0] - sin(x[8]) * x[1] + x[11] + x[9]) \
  (sin(x[8]) * x[0] + cos(x[8]) * x[1] + x[12] + x[10])
#undef MEASUREMENT_NOISE_COVARIANCE
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((1e-4)(4e-4)(1.25e-5)(0.02)(0.02))
#define GPS_COVARIANCE_SCALE 0.003
#define GPS_ERROR_Q (GPS_ERROR_SIGMA * GPS_ERROR_SIGMA * (1 - exp(-2 * T / GPS_ERROR_TAU)))
#undef PROCESS_NOISE_COVARIANCE
#define PROCESS_NOISE_COVARIANCE \
  SF_DIAGONAL((0.02 * T)(0.02 * T)(1e-4 * T)(0.25 * T)(1.0 * T)(1e-8 * T)(100)(1e-6 * T) \
              (0)(GPS_ERROR_Q)(GPS_ERROR_Q)(0)(0))
#undef INITIAL_STATE
#define INITIAL_STATE (0)(0)(0)(0)(0)(0)(0)(0)(0)(0)(0)(0)(0)
#undef INITIAL_ERROR_COVARIANCE
#define INITIAL_ERROR_COVARIANCE \
  SF_DIAGONAL((0)(0)(0)(1)(1)(2.5e-5)(100)(0.04)(3.29)(GPS_ERROR_SIGMA * GPS_ERROR_SIGMA) \
              (GPS_ERROR_SIGMA * GPS_ERROR_SIGMA)(1e4)(1e4))
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
// bags/husky_gps.bag the largest squared distance is between 5 and 6 (north), so no fix
// is gated and the estimates are those without a gate, byte for byte (doc/real_robot.md).
#define INPUT_GATE ((3)(100))((4)(100))
