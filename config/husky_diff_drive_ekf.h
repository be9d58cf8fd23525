// The EKF on the Husky recording with config/husky_diff_drive_odom_imu.h (doc/real_robot.md).
#define METHOD EXTENDED_KALMAN_FILTER
#include "husky_diff_drive_odom_imu.h"
