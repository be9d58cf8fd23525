// The position (x, y) held still of test/configs/pose_block_kf.h (Q = 0, P0 = I, header
// R = 4 I), measured by a GPS fix instead (DERIVED_INPUTS EAST, NORTH of a
// sensor_msgs/NavSatFix), for test/gps_covariance.test: the fix's position_covariance, turned
// into the odom frame by ~gps_yaw_offset, reaches the filter with the covariance of x and y.
#include <sensor_msgs/NavSatFix.h>

#include "pose_block_kf.h"

#undef TOPICS_IN
#define TOPICS_IN \
  ((fix)(sensor_msgs::NavSatFix)(longitude)) \
  ((fix)(sensor_msgs::NavSatFix)(latitude))
#undef INPUT_COVARIANCE_BLOCK
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
