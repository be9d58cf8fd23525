// EXPECT: ANGLE_STATES: expected a sequence of state indices, each in parentheses
// Mistake: indices written with commas instead of as a sequence
#define SF_ANGLES_CASE
#include "valid_angles.h"

#define ANGLE_STATES (0, 2)
