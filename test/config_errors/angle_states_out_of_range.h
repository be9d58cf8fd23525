// EXPECT: ANGLE_STATES entry 0: index '3' is out of range, expected an integer from 0 to 2 (a state variable x[i]; n = 3 is the number of expressions in STATE_TRANSITION_MODEL)
// Mistake: state indices start at 0 (the heading of a 3-state model is x[2])
#define SF_ANGLES_CASE
#include "valid_angles.h"

#define ANGLE_STATES (3)
