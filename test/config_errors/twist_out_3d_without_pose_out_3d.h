// EXPECT: TWIST_OUT_3D requires POSE_OUT_3D
// Mistake: the twist is part of the Odometry that POSE_OUT_3D enables
#include "valid_quaternions.h"

#define TWIST_OUT_3D (4)(5)(6)(4)(5)(6)
