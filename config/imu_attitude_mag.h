// IMU-only attitude with the magnetometer: config/imu_attitude.h with IMU_ATTITUDE_MAGNETOMETER
// (gyro as control, accelerometer on /imu/data measuring gravity, magnetometer on /imu/mag
// measuring the Earth's field), so that the heading is observed about magnetic north.
// The orientation error of the BROAD benchmark, in the earth frame without alignment, needs
// that heading (doc/broad.md, "The node's attitude header").
#define IMU_ATTITUDE_MAGNETOMETER
#include "imu_attitude.h"
