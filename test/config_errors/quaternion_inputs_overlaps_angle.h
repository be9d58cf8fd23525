// EXPECT: QUATERNION_INPUTS entry 0: the quaternion of TOPICS_IN entries 3..+3 overlaps an ANGLE_INPUTS entry
// Mistake: a quaternion component also declared a measured angle
#include "valid_quaternion_inputs.h"

#define ANGLE_INPUTS (5)
