// EXPECT: FRAME_ALIGNED_INPUTS entry 1 ((1)(data)(x)): the message type of TOPICS_IN entry 1 has no header
// Mistake: std_msgs/Float64 has no frame to rotate from
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[1])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define TOPICS_IN \
  ((imu)(sensor_msgs::Imu)(angular_velocity.z)) \
  ((speed)(std_msgs::Float64)(data))
#define TOPICS_OUT ((heading)(0))((yaw_rate)(1))
#define BASE_FRAME base_link
#define FRAME_ALIGNED_INPUTS ((0)(angular_velocity)(z))((1)(data)(x))
#include <sf_filter/config/frame_alignment.hpp>
