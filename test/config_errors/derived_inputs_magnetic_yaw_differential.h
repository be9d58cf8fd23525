// EXPECT: DERIVED_INPUTS entry 0 ((0)(MAGNETIC_YAW)(DIFFERENTIAL)): quantity 'MAGNETIC_YAW' is ABSOLUTE only
// Mistake: a magnetometer's heading has no differential form (fuse a gyro for the turn rate)
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5))
#define ANGLE_STATES (0)
#define TOPICS_IN ((imu/mag)(sensor_msgs::MagneticField)(magnetic_field))
#define DERIVED_INPUTS ((0)(MAGNETIC_YAW)(DIFFERENTIAL))
#define TOPICS_OUT ((heading)(0))
