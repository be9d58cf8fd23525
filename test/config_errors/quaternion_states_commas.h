// EXPECT: QUATERNION_STATES: expected a sequence of state indices, each in parentheses
// Mistake: indices written with commas instead of as a sequence
#define SF_QUATERNION_CASE
#define SF_QUATERNION_COVARIANCE_CASE
#include "valid_quaternions.h"

#define QUATERNION_STATES 0, 3
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((1e-6)(1e-6)(1e-6)(1e-6)(1e-6)(1e-6)(1e-6))
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL((1)(1)(1)(1)(1)(1)(1))
