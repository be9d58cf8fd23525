// EXPECT: OK
// The model that the input_records_* cases include, then give their own INPUTS: two states,
// two inputs written as records.
#include "fake_msgs.h"
#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define TOPICS_OUT ((position)(0))((speed)(1))
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5)) \
  ((wheel)(wheel)(std_msgs::Float32)(data)(observe, x[1])(variance, 0.2))
