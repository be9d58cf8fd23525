// EXPECT: INPUT_COVARIANCE_BLOCK entry 0 (((0)(1))(position_covariance)((0)(1))): a GPS input (DERIVED_INPUTS EAST, NORTH, UP) takes its covariances from the fix's position_covariance
// Mistake: the fix's covariance block configured by hand (ENU, not turned into the odom frame)
#include "gps_filter.inc"

#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
#define INPUT_COVARIANCE_BLOCK (((0)(1))(position_covariance)((0)(1)))
