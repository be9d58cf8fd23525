// EXPECT: DERIVED_INPUTS entry 1 ((1)(NORTH)(ABSOLUTE)): the input also has an INPUT_COVARIANCE entry; a GPS input takes its variance from the fix's position_covariance
// Mistake: the fix's covariance given twice
#include <sf_filter/config/diagonal.hpp>
#include "fake_navsat.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[2] * T)(x[1] + x[3] * T)(x[2])(x[3])
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0.01)(0.01)(0.1)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((2)(0))((0)(2))
#define TOPICS_OUT ((x)(0))((y)(1))
#define OBSERVATION_MODEL (x[0])(x[1])
#define TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(latitude))
#define DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
#define INPUT_COVARIANCE ((1)(position_covariance)(4))
