// EXPECT: TOPICS_IN entry 1 (topic 'fix'): message type 'sensor_msgs::NavSatFix' has no field 'lat'
// Mistake: a GPS input whose field is not a member of the fix
#include "gps_filter.inc"

#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(lat))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
