// EXPECT: QUATERNION_INPUTS: expected a sequence of TOPICS_IN indices
// Mistake: the index list written with commas instead of parentheses
#define SF_QUATERNION_INPUTS_CASE
#include "valid_quaternion_inputs.h"

#define QUATERNION_INPUTS 3, 4
