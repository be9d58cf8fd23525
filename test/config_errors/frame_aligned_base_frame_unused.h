// EXPECT: WARNING BASE_FRAME is not used without FRAME_ALIGNED_INPUTS and is ignored
// Mistake: BASE_FRAME alone has no effect
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[1])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define TOPICS_IN \
  ((imu)(sensor_msgs::Imu)(angular_velocity.z)) \
  ((gyro)(geometry_msgs::Vector3Stamped)(vector.x))
#define TOPICS_OUT ((heading)(0))((yaw_rate)(1))
#define BASE_FRAME base_link
#include <sf_filter/config/frame_alignment.hpp>
