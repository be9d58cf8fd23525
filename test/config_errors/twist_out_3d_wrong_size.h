// EXPECT: TWIST_OUT_3D: expected six state indices, (vx)(vy)(vz)(wx)(wy)(wz)
// EXPECT: found '(4)(5)'
// Mistake: the planar twist's two entries
#include "valid_quaternions.h"

#define POSE_OUT_3D (0)
#define TWIST_OUT_3D (4)(5)
