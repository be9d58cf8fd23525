// EXPECT: OK
// Two GPS receivers, each giving EAST and NORTH of its own fix (the same quantity from two topics).
#include <sf_filter/config/diagonal.hpp>
#include "fake_navsat.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0.01)(0.01))
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((2)(2)(3)(3))
#define TOPICS_OUT ((x)(0))((y)(1))
#define OBSERVATION_MODEL (x[0])(x[1])(x[0])(x[1])
#define TOPICS_IN \
  ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(latitude)) \
  ((fix2)(sensor_msgs::NavSatFix)(longitude))((fix2)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS \
  ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))((2)(EAST)(ABSOLUTE))((3)(NORTH)(ABSOLUTE))
