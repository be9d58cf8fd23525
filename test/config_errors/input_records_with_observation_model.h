// EXPECT: INPUTS cannot be combined with OBSERVATION_MODEL, OBSERVATION_MATRIX or OBSERVATION_JACOBIAN
// Mistake: the observation model kept as a macro beside the records
#include "fake_msgs.h"
#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define TOPICS_OUT ((position)(0))((speed)(1))
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(variance, 0.5))
#define OBSERVATION_MODEL (x[0])
