// EXPECT: INPUTS and TOPICS_IN are both defined: a header gives its inputs either as INPUTS records
// Mistake: both syntaxes in one header
#include "fake_msgs.h"
#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define TOPICS_OUT ((position)(0))((speed)(1))
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5))
#define TOPICS_IN ((wheel)(std_msgs::Float32)(data))
