// EXPECT: OK
// valid_quaternion_inputs.h with UNSCENTED_KALMAN_FILTER (UKF-M, UKF_PROPAGATED_MEAN's default 1)
#define METHOD UNSCENTED_KALMAN_FILTER
#include "valid_quaternion_inputs.h"
