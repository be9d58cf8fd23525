// EXPECT: QUATERNION_STATES entry 0: index '4' does not start a quaternion inside the state, expected an integer from 0 to 3 (the quaternion is x[i..i+3]; n = 7
// Mistake: a quaternion x[4..7] past the end of a state of 7 variables
#define SF_QUATERNION_CASE
#include "valid_quaternions.h"

#define QUATERNION_STATES (4)
