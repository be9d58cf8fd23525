// EXPECT: WARNING PF_LINEARISED_PROPOSAL is not used by the chosen METHOD and is ignored
// Mistake: the particle filter's linearised proposal for a Kalman filter (a warning, builds)
#include "fake_msgs.h"

#define METHOD KALMAN_FILTER
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(1))
#define OBSERVATION_MATRIX ((1)(0))((0)(1))
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define INITIAL_STATE (0)(0)
#define PF_LINEARISED_PROPOSAL 1
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_OUT ((velocity)(0))((acceleration_estimate)(1))
