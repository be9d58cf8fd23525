// EXPECT: OK
// POSE_OUT_3D with the orientation alone: no position in the state
#include "valid_quaternions.h"

#define POSE_OUT_3D (0)
#include <sf_filter/config/configuration.hpp>
static_assert(sf_config::kHasPoseOut3d && sf_config::kPoseOut3d[0] == -1 &&
                  sf_config::kPoseOut3d[1] == -1 && sf_config::kPoseOut3d[2] == -1 &&
                  sf_config::kPoseOut3d[3] == 0 && !sf_config::kHasTwistOut3d,
              "POSE_OUT_3D");
