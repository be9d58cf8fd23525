// EXPECT: OK
// Unscented Kalman filter with non-linear expressions and two control inputs (dead reckoning of a
// differential-drive robot: state (x, y, heading), controls (v, omega)).
#include "fake_msgs.h"

#define METHOD UNSCENTED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL \
  (x[0] + u[0] * T * cos(x[2])) \
  (x[1] + u[0] * T * sin(x[2])) \
  (atan2(sin(x[2] + u[1] * T), cos(x[2] + u[1] * T)))
#define OBSERVATION_MODEL (x[2])(sqrt(pow(x[0], 2) + x[1] * x[1]))
#define PROCESS_NOISE_COVARIANCE ((0.01)(0)(0))((0)(0.01)(0))((0)(0)(0.001))
#define MEASUREMENT_NOISE_COVARIANCE ((0.05)(0))((0)(0.5))
#define UKF_ALPHA 0.5
#define UKF_BETA 2
#define UKF_KAPPA 1
#define TOPICS_IN \
  ((compass)(std_msgs::Float64)(data)) \
  ((range)(std_msgs::Float32)(data))
#define TOPICS_IN_CTRL \
  ((cmd_vel)(geometry_msgs::Twist)(linear.x)) \
  ((cmd_vel)(geometry_msgs::Twist)(angular.z))
#define TOPICS_OUT ((x)(0))((y)(1))((heading)(2))
