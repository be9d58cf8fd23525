// EXPECT: OK
// A magnetometer's heading (DERIVED_INPUTS MAGNETIC_YAW of a MagneticField's vector): an angle
// input read by the extractor kind MagneticHeading, with its parameter ~magnetic_declination.
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define ANGLE_STATES (0)
#define TOPICS_IN \
  ((imu/mag)(sensor_msgs::MagneticField)(magnetic_field)) \
  ((imu/data)(sensor_msgs::Imu)(angular_velocity.z))
#define DERIVED_INPUTS ((0)(MAGNETIC_YAW)(ABSOLUTE))
#define TOPICS_OUT ((heading)(0))
#include <sf_filter/config/configuration.hpp>

static_assert(sf_config::kAngleInputs[0] && !sf_config::kAngleInputs[1],
              "MAGNETIC_YAW is an angle input");
static_assert(std::is_same_v<sf_config::Derivation<0>::Kind, sf_config::extractors::MagneticHeading>,
              "read by the magnetometer's kind");
static_assert(sf_config::Derivation<0>::valid && sf_config::Derivation<0>::kind_quantity == 0,
              "its only quantity");
