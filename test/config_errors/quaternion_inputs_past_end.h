// EXPECT: QUATERNION_INPUTS entry 0: index '4' does not start a quaternion among the inputs, expected an integer from 0 to 3
// Mistake: the quaternion's first component given one entry too late (m = 7: entries 4..7)
#define SF_QUATERNION_INPUTS_CASE
#include "valid_quaternion_inputs.h"

#define QUATERNION_INPUTS (4)
