// EXPECT: OK
// Particle filter with all PF parameters; topics given as string literals with namespaces.
#include "fake_msgs.h"

#define METHOD PARTICLE_FILTER_SIR
#define ESTIMATION_PERIOD 20.5
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5))
#define INITIAL_STATE (1)(0)
#define NUMBER_OF_PARTICLES 500
#define RANDOM_SEED 7
#define RESAMPLING_THRESHOLD 0.3
#define TOPICS_IN (("/robot/wheel/velocity")(std_msgs::Float32)(data))
#define TOPICS_OUT ((/robot/velocity)(0))(("~acceleration")(1))
