// EXPECT: OK
// Derived inputs: the yaw of an IMU orientation (absolute, variance from its covariance array)
// and x, y, yaw of an odometry pose (differential).
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[3] * cos(x[2]) * T)(x[1] + x[3] * sin(x[2]) * T)(x[2])(x[3])
#define OBSERVATION_MODEL (x[2])(x[3] * T)(0)(0)
#define PROCESS_NOISE_COVARIANCE \
  ((0.01)(0)(0)(0))((0)(0.01)(0)(0))((0)(0)(0.01)(0))((0)(0)(0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE \
  ((0.1)(0)(0)(0))((0)(0.1)(0)(0))((0)(0)(0.1)(0))((0)(0)(0)(0.1))
#define ANGLE_STATES (2)
#define TOPICS_IN \
  ((imu)(sensor_msgs::Imu)(orientation)) \
  ((odom)(nav_msgs::Odometry)(pose.pose)) \
  ((odom)(nav_msgs::Odometry)(pose.pose)) \
  ((odom)(nav_msgs::Odometry)(pose.pose.orientation))
#define DERIVED_INPUTS \
  ((0)(YAW)(ABSOLUTE)) \
  ((1)(X)(DIFFERENTIAL)) \
  ((2)(Y)(DIFFERENTIAL)) \
  ((3)(YAW)(DIFFERENTIAL))
#define INPUT_COVARIANCE ((0)(orientation_covariance)(8))((1)(pose.covariance)(0))
#define TOPICS_OUT ((heading)(2))
#include <sf_filter/config/configuration.hpp>

static_assert(sf_config::kAngleInputs[0] && !sf_config::kAngleInputs[1] &&
                  !sf_config::kAngleInputs[2] && sf_config::kAngleInputs[3],
              "derived ROLL, PITCH, YAW inputs are angle inputs");
static_assert(sf_config::Derivation<1>::differential && !sf_config::Derivation<0>::differential,
              "modes");
static_assert(sf_config::CovarianceSource<0>::valid && !sf_config::CovarianceSource<2>::given,
              "covariance sources");
