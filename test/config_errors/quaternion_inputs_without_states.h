// EXPECT: QUATERNION_INPUTS needs QUATERNION_STATES
// Mistake: a measured quaternion in a filter whose state holds no rotation
#define SF_QUATERNION_STATES_CASE
#include "valid_quaternion_inputs.h"
