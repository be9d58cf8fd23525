// EXPECT: OK
// POSE_OUT_3D with TWIST_OUT_3D on the attitude of valid_quaternions.h (any state indices do
// for the checks: the bias x[4..6] stands for a position and a velocity here)
#include "valid_quaternions.h"

#define POSE_OUT_3D (4)(5)(6)(0)
#define TWIST_OUT_3D (4)(5)(6)(6)(5)(4)
#include <sf_filter/config/configuration.hpp>
static_assert(sf_config::kHasPoseOut3d && sf_config::kPoseOut3d[0] == 4 &&
                  sf_config::kPoseOut3d[2] == 6 && sf_config::kPoseOut3d[3] == 0,
              "POSE_OUT_3D");
static_assert(sf_config::kHasTwistOut3d && sf_config::kTwistOut3d[3] == 6 &&
                  sf_config::kTwistOut3d[5] == 4,
              "TWIST_OUT_3D");
