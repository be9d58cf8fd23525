// EXPECT: QUATERNION_STATES entry 0: the quaternion x[0..+3] overlaps an ANGLE_STATES entry
// Mistake: x[2] declared an angle and a quaternion component
#define SF_QUATERNION_CASE
#include "valid_quaternions.h"

#define QUATERNION_STATES (0)
#define ANGLE_STATES (2)
