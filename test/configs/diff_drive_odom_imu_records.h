// config/diff_drive_odom_imu.h written with one INPUTS record per input (doc/configuration.md,
// "One record per input"): the same model, noise, topics and per-input options, so the node
// built from it must generate the same tables and replay a bag to the same bytes
// (test/robots/test_input_records_replay.py). The comments of the original explain the numbers.
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>

#ifndef METHOD
#define METHOD EXTENDED_KALMAN_FILTER
#endif
#define ESTIMATION_PERIOD 20
#define STATE_TRANSITION_MODEL \
  (x[0] + x[3] * T * cos(x[2] + 0.5 * x[4] * T)) \
  (x[1] + x[3] * T * sin(x[2] + 0.5 * x[4] * T)) \
  (x[2] + x[4] * T) \
  (x[3]) \
  (x[4]) \
  (x[5])
#define PROCESS_NOISE_COVARIANCE \
  ((1e-6 * T)(0)(0)(0)(0)(0)) \
  ((0)(1e-6 * T)(0)(0)(0)(0)) \
  ((0)(0)(1e-6 * T)(0)(0)(0)) \
  ((0)(0)(0)(0.25 * T)(0)(0)) \
  ((0)(0)(0)(0)(1.0 * T)(0)) \
  ((0)(0)(0)(0)(0)(1e-8 * T))
#define INITIAL_STATE (0)(0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE \
  ((0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(1)(0)(0)) \
  ((0)(0)(0)(0)(1)(0)) \
  ((0)(0)(0)(0)(0)(2.5e-3))
#define INPUTS \
  ((wheel_speed)(odom)(nav_msgs::Odometry)(twist.twist.linear.x) \
     (observe, x[3])(variance, 2.5e-5)(by_stamp)(timeout, 500)) \
  ((wheel_yaw_rate)(odom)(nav_msgs::Odometry)(twist.twist.angular.z) \
     (observe, x[4])(variance, 4e-4)(by_stamp)(timeout, 500)) \
  ((gyro_yaw_rate)(imu/data)(sensor_msgs::Imu)(angular_velocity.z) \
     (observe, x[4] + x[5])(variance, 1.25e-5)(by_stamp)(timeout, 500) \
     (frame_aligned, angular_velocity, z))
#define TOPICS_OUT \
  ((fused/x)(0))((fused/y)(1))((fused/heading)(2)) \
  ((fused/linear_velocity)(3))((fused/angular_velocity)(4))((fused/gyro_bias)(5))
#define POSE_OUT (0)(1)(2)
#define BASE_FRAME base_link
#define ANGLE_STATES (2)
#define MAX_MEASUREMENT_LAG 20
