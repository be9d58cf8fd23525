// Test configuration of test/numerical_faults.test (doc/reliability.md): a UKF whose single
// state is a coordinate far from the origin (1e9 m, known to about 0.3 m). With the default
// alpha = 1e-3 its sigma points lie closer to the mean than 1e9 can resolve after the
// transform's weights amplify the rounding; the filter widens alpha for every such step and
// counts it (numericalRepairs().sigmaSpread), which the node must report.
#include <std_msgs/Float64.h>

#define METHOD UNSCENTED_KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MODEL (x[0])
#define OBSERVATION_MODEL (x[0])
#define PROCESS_NOISE_COVARIANCE ((0.01))
#define MEASUREMENT_NOISE_COVARIANCE ((1))
#define INITIAL_STATE (1e9)
#define INITIAL_ERROR_COVARIANCE ((1))
#define TOPICS_IN ((numerics/far_position)(std_msgs::Float64)(data))
#define TOPICS_OUT ((numerics/estimate/far_position)(0))
