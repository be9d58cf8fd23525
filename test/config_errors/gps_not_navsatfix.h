// EXPECT: DERIVED_INPUTS entry 1 ((1)(NORTH)(ABSOLUTE)): EAST, NORTH and UP are the position of a GPS fix, but the message type of TOPICS_IN entry 1 is not a sensor_msgs::NavSatFix
// Mistake: NORTH of an odometry's pose (Y is its position)
#include "gps_filter.inc"

#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((odom)(nav_msgs::Odometry)(pose.pose))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
