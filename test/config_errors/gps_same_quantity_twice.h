// EXPECT: DERIVED_INPUTS entry 1 ((1)(EAST)(ABSOLUTE)): an earlier entry already takes this quantity from the same topic's fix
// Mistake: EAST twice from one fix (NORTH meant)
#include <sf_filter/config/diagonal.hpp>
#include "fake_navsat.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[2] * T)(x[1] + x[3] * T)(x[2])(x[3])
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0.01)(0.01)(0.1)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((2)(0))((0)(2))
#define TOPICS_OUT ((x)(0))((y)(1))
#define OBSERVATION_MODEL (x[0])(x[1])
#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(EAST)(ABSOLUTE))
