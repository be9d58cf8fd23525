// EXPECT: QUATERNION_INPUTS entry 1: the quaternion of TOPICS_IN entries 2..+3 overlaps the quaternion of an earlier entry
// Mistake: two quaternions sharing inputs 3..5
#define SF_QUATERNION_INPUTS_CASE
#include "valid_quaternion_inputs.h"

#define QUATERNION_INPUTS (3)(2)
