// EXPECT: UKF_PROPAGATED_MEAN: QUATERNION_STATES needs 1 (UKF-M propagates the mean
// Mistake: the sigma points' weighted mean asked for a state with a quaternion
#define METHOD UNSCENTED_KALMAN_FILTER
#define UKF_PROPAGATED_MEAN 0
#include "valid_quaternions.h"
