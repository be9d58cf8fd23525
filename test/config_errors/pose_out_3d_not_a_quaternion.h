// EXPECT: POSE_OUT_3D: the q index is not an entry of QUATERNION_STATES ((0)): the orientation is the w of a declared quaternion
// Mistake: q points at the quaternion's x, not its w
#include "valid_quaternions.h"

#define POSE_OUT_3D (4)(5)(6)(1)
