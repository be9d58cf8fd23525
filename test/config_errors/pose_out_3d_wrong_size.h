// EXPECT: POSE_OUT_3D: expected four state indices, (x index)(y index)(z index)(q index)
// EXPECT: found '(4)(0)'
// Mistake: a planar position and the quaternion
#include "valid_quaternions.h"

#define POSE_OUT_3D (4)(0)
