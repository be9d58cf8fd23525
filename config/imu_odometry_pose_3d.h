// config/imu_odometry_3d.h with the vision pose's orientation as well as its position: inputs
// 15..18 are /vision/pose's pose.pose.orientation w, x, y, z, one measured quaternion
// (QUATERNION_INPUTS (15)) compared with the state's q on SO(3), q and -q alike, its innovation
// the rotation vector z [-] q about the world's axes with R 1e-4 rad^2 per axis (the simulated
// vision's 0.01 rad; R's w row is zero). Aligned LAST: a period takes its last pose. The IMU's
// gyro only integrates the heading and the accelerometer sees tilt alone; this pins the heading
// too (doc/configuration.md, "Rotations in 3D").
#define IMU_ODOMETRY_3D_POSE_ORIENTATION
#include "imu_odometry_3d.h"
