// EXPECT: DERIVED_INPUTS entry 1 ((1)(NORTH)(ABSOLUTE)): the input also has an INPUT_COVARIANCE entry; a GPS input takes its variance from the fix's position_covariance
// Mistake: the fix's covariance given twice
#include "gps_filter.inc"

#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
#define INPUT_COVARIANCE ((1)(position_covariance)(4))
