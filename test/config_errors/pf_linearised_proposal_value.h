// EXPECT: PF_LINEARISED_PROPOSAL: expected 1 (draw each particle from the Kalman posterior
// Mistake: the linearised proposal is a switch, 0 or 1
#include "fake_msgs.h"

#define METHOD PARTICLE_FILTER_SIR
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define INITIAL_STATE (0)(0)
#define PF_LINEARISED_PROPOSAL 2
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_OUT ((velocity)(0))((acceleration_estimate)(1))
