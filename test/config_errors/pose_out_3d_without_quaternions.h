// EXPECT: POSE_OUT_3D requires QUATERNION_STATES
// Mistake: without QUATERNION_STATES there is no quaternion to publish
#define SF_QUATERNION_CASE
#include "valid_quaternions.h"

#define POSE_OUT_3D (0)
