// EXPECT: DERIVED_INPUTS entry 1 ((1)(EAST)(ABSOLUTE)): an earlier entry already takes this quantity from the same topic's fix
// Mistake: EAST twice from one fix (NORTH meant)
#include "gps_filter.inc"

#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(EAST)(ABSOLUTE))
