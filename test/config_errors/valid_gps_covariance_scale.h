// EXPECT: OK
// A GPS fix whose covariance reaches the filter scaled (GPS_COVARIANCE_SCALE: its white part).
#include "gps_filter.inc"

#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
#define GPS_COVARIANCE_SCALE 0.003
