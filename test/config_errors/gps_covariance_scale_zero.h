// EXPECT: GPS_COVARIANCE_SCALE: expected a finite factor > 0 on each fix's covariance, found '0'
// Mistake: a zero scale (the filter would take every fix as exact)
#include "gps_filter.inc"

#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
#define GPS_COVARIANCE_SCALE 0
