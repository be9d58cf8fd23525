// EXPECT: DERIVED_INPUTS entry 0 ((0)(EAST)(ABSOLUTE)): TOPICS_IN entry 0 has a variance field; a GPS input takes its variance from the fix's position_covariance
// Mistake: a variance field on a GPS input
#include "gps_filter.inc"

#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude)(position_covariance[0]))((fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
