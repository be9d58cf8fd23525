// config/skid_steer_odom_imu.h with its inputs written as INPUTS records, one per input
// (doc/configuration.md, "One record per input"): the model, noise and outputs are the
// original's, the macros of its three inputs are replaced by three records, so the node built
// from it must generate the same tables and replay a bag to the same bytes
// (test/robots/test_input_records_replay.py).
#include "../../config/skid_steer_odom_imu.h"

#undef TOPICS_IN
#undef OBSERVATION_MODEL
#undef MEASUREMENT_NOISE_COVARIANCE
#undef FRAME_ALIGNED_INPUTS
#undef ALIGN_BY_STAMP
#undef INPUT_TIMEOUT
#define INPUTS \
  ((wheel_speed)(odom)(nav_msgs::Odometry)(twist.twist.linear.x) \
     (observe, x[3])(variance, 1e-4)(by_stamp)(timeout, 500)) \
  ((wheel_yaw_rate)(odom)(nav_msgs::Odometry)(twist.twist.angular.z) \
     (observe, x[4] + SKID_STEER_MOVING * x[6])(variance, 4e-4)(by_stamp)(timeout, 500)) \
  ((gyro_yaw_rate)(imu/data)(sensor_msgs::Imu)(angular_velocity.z) \
     (observe, x[4] + x[5])(variance, 1.25e-5)(by_stamp)(timeout, 500) \
     (frame_aligned, angular_velocity, z))
