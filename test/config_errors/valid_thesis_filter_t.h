// EXPECT: OK
// The configuration exactly as printed in the thesis (section 4.3.5): a UKF whose model uses a
// user macro FILTER_T for the period, an input with a variance field, default noise values.
#include "fake_msgs.h"

#define METHOD UNSCENTED_KALMAN_FILTER
#define FILTER_T 0.1
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MODEL \
  (x[0] + x[1] * FILTER_T) \
  (x[1])
#define OBSERVATION_MODEL (x[1])
#define PROCESS_NOISE_COVARIANCE \
  ((1)(0)) \
  ((0)(2))
#define MEASUREMENT_NOISE_COVARIANCE ((0.1))
#define INITIAL_STATE (0)(0)
#define TOPICS_IN ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_OUT ((velocity)(0))
