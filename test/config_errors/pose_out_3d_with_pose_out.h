// EXPECT: POSE_OUT_3D and POSE_OUT: a node publishes one odometry
// Mistake: both the planar and the 3D pose
#include "valid_quaternions.h"

#define POSE_OUT (4)(5)(6)
#define POSE_OUT_3D (0)
