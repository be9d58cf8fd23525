// A position (x, y) held still and measured by a GPS fix (DERIVED_INPUTS EAST, NORTH of a
// sensor_msgs/NavSatFix), for test/gps_covariance.test: the fix's position_covariance, turned
// into the odom frame by ~gps_yaw_offset, reaches the filter with the covariance of x and y.
// Q = 0, so that each period's estimate is one Kalman update computed by hand in the test.
#include <sensor_msgs/NavSatFix.h>

#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MATRIX ((1)(0))((0)(1))
#define OBSERVATION_MATRIX ((1)(0))((0)(1))
#define PROCESS_NOISE_COVARIANCE ((0)(0))((0)(0))
#define MEASUREMENT_NOISE_COVARIANCE ((4)(0))((0)(4))
#define INITIAL_STATE (0)(0)
#define INITIAL_ERROR_COVARIANCE ((1)(0))((0)(1))
#define TOPICS_IN \
  ((fix)(sensor_msgs::NavSatFix)(longitude)) \
  ((fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
#define TOPICS_OUT ((position/x)(0))((position/y)(1))
