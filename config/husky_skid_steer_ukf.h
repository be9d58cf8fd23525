// The UKF on the Husky recording with config/husky_skid_steer_odom_imu.h (doc/real_robot.md).
#define METHOD UNSCENTED_KALMAN_FILTER
#include "husky_skid_steer_odom_imu.h"
