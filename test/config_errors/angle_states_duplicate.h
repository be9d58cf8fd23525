// EXPECT: ANGLE_STATES entry 1: index 2 is already listed in an earlier entry
// Mistake: the same state listed twice
#define SF_ANGLES_CASE
#include "valid_angles.h"

#define ANGLE_STATES (2)(2)
