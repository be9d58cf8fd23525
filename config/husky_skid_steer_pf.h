// The particle filter on the Husky recording with config/husky_skid_steer_odom_imu.h
// (doc/real_robot.md): the header's defaults (1000 particles, seed 42), nothing tuned.
#define METHOD PARTICLE_FILTER_SIR
#include "husky_skid_steer_odom_imu.h"
