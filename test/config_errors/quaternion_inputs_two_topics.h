// EXPECT: QUATERNION_INPUTS entry 0: the quaternion of TOPICS_IN entries 3..+3 is not read from one topic
// Mistake: the w of the quaternion read from another topic than its x, y, z
#define SF_QUATERNION_EXTRA_TOPICS \
  ((imu2)(sensor_msgs::Imu)(orientation.w)) \
  ((imu)(sensor_msgs::Imu)(orientation.x)) \
  ((imu)(sensor_msgs::Imu)(orientation.y)) \
  ((imu)(sensor_msgs::Imu)(orientation.z))
#include "valid_quaternion_inputs.h"
