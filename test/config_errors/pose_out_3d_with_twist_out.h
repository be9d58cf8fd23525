// EXPECT: TWIST_OUT is the planar twist (v, omega) of POSE_OUT; with POSE_OUT_3D declare TWIST_OUT_3D
// Mistake: the planar twist with a 3D pose
#include "valid_quaternions.h"

#define POSE_OUT_3D (0)
#define TWIST_OUT (4)(6)
