// EXPECT: ANGLE_STATES entry 1: index '1.5' is out of range, expected an integer
// Mistake: an index that is not an integer
#define SF_ANGLES_CASE
#include "valid_angles.h"

#define ANGLE_STATES (2)(1.5)
