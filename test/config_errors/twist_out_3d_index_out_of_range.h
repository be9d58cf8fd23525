// EXPECT: TWIST_OUT_3D: entry 5 '7' is not a state index, expected an integer from 0 to 6
// Mistake: the state has 7 variables
#include "valid_quaternions.h"

#define POSE_OUT_3D (0)
#define TWIST_OUT_3D (4)(5)(6)(4)(5)(7)
