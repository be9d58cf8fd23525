// EXPECT: TOPICS_IN entry 0 (topic 'imu'): field 'orientation' of message type 'sensor_msgs::Imu' is not a number
// EXPECT: or derive a number from it with DERIVED_INPUTS
// Mistake: a quaternion member without DERIVED_INPUTS
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define TOPICS_OUT ((heading)(0))
#define TOPICS_IN ((imu)(sensor_msgs::Imu)(orientation))((imu)(sensor_msgs::Imu)(angular_velocity.z))
