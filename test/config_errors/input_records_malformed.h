// EXPECT: INPUTS: expected a sequence of records, each written as ((name)(topic)(type)(field)(option, arguments)...)
// Mistake: single parentheses around a record
#include "fake_msgs.h"
#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define TOPICS_OUT ((position)(0))((speed)(1))
#define INPUTS \
  (position)(position)(geometry_msgs::Vector3Stamped)(vector.x)
