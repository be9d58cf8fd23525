// EXPECT: QUATERNION_STATES entry 1: the quaternion x[3..+3] overlaps the quaternion of an earlier entry
// Mistake: two quaternions sharing x[3] (n = 7: x[0..3] and x[3..6]); Q and P0 of the tangent size d = 5
#define SF_QUATERNION_CASE
#define SF_QUATERNION_COVARIANCE_CASE
#include "valid_quaternions.h"

#define QUATERNION_STATES (0)(3)
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((1e-6)(1e-6)(1e-6)(1e-6)(1e-6))
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL((1)(1)(1)(1)(1))
