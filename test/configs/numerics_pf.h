// Test configuration of test/numerical_faults.test (doc/reliability.md): a particle filter
// of a constant measured directly, without a plausible range, so that a finite but absurd
// value (1e200) reaches the filter. Every particle's squared residual then overflows and
// every weight vanishes; the filter drops that measurement (as if it were missing) and
// counts it (numericalRepairs().weights), which the node must report.
#include <std_msgs/Float64.h>

#define METHOD PARTICLE_FILTER_SIR
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MODEL (x[0])
#define OBSERVATION_MODEL (x[0])
#define PROCESS_NOISE_COVARIANCE ((0.001))
#define MEASUREMENT_NOISE_COVARIANCE ((0.01))
#define INITIAL_STATE (1)
#define INITIAL_ERROR_COVARIANCE ((0.01))
#define NUMBER_OF_PARTICLES 300
#define RANDOM_SEED 11
#define TOPICS_IN ((numerics/level)(std_msgs::Float64)(data))
#define TOPICS_OUT ((numerics/estimate/level)(0))
