// EXPECT: DERIVED_INPUTS entry 1 ((1)(LATITUDE)(ABSOLUTE)): quantity 'LATITUDE' is not one of X, Y, Z
// EXPECT: or EAST, NORTH, UP (of a NavSatFix)
// Mistake: a GPS component named after the fix's field (NORTH is the position's component)
#include "gps_filter.inc"

#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(LATITUDE)(ABSOLUTE))
