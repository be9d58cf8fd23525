// EXPECT: QUATERNION_INPUTS entry 0: the quaternion of TOPICS_IN entries 3..+3 is not read from one topic
// Mistake: the w of the quaternion read from another topic than its x, y, z
#define SF_QUATERNION_INPUT_TOPICS_CASE
#include "valid_quaternion_inputs.h"

#define TOPICS_IN \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.x)) \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.y)) \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.z)) \
  ((imu2)(sensor_msgs::Imu)(orientation.w)) \
  ((imu)(sensor_msgs::Imu)(orientation.x)) \
  ((imu)(sensor_msgs::Imu)(orientation.y)) \
  ((imu)(sensor_msgs::Imu)(orientation.z))
