// EXPECT: DERIVED_INPUTS entry 0 ((0)(MAGNETIC_YAW)(ABSOLUTE)): the field of TOPICS_IN entry 0 is not a pose
// EXPECT: for another kind's quantity the member its fits() accepts
// Mistake: the field is one component of the vector, not the vector
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5))
#define ANGLE_STATES (0)
#define TOPICS_IN ((imu/mag)(sensor_msgs::MagneticField)(magnetic_field.x))
#define DERIVED_INPUTS ((0)(MAGNETIC_YAW)(ABSOLUTE))
#define TOPICS_OUT ((heading)(0))
