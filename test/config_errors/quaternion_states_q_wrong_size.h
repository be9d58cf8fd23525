// EXPECT: PROCESS_NOISE_COVARIANCE: expected 6 rows, found 7 (must be d x d, over the tangent space; d = 6 is the tangent size: n = 7 less one per QUATERNION_STATES entry
// Mistake: Q over the stored entries (7 x 7) instead of the tangent space (a quaternion has 3 rows)
#define SF_QUATERNION_COVARIANCE_CASE
#include "valid_quaternions.h"

#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((1e-6)(1e-6)(1e-6)(1e-6)(1e-10)(1e-10)(1e-10))
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL((1)(1)(1)(1e-4)(1e-4)(1e-4))
