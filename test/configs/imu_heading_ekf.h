// Test configuration of test/spatial_alignment.test: planar dead reckoning whose yaw rate comes
// from gyros mounted in other frames than the robot's base_link (FRAME_ALIGNED_INPUTS).
//   state x = (x, y, heading, omega, v), control u = (v)
//   input 0: IMU in frame imu_link (mounted upside down: rotated 180 deg about x), its
//            angular_velocity rotated into base_link, z component
//   input 1: a second IMU whose frame has no transform (its values are dropped)
//   input 2: a gyro as geometry_msgs/Vector3Stamped in frame gyro_link (rotated -90 deg about
//            y: the sensor's x axis is the robot's z axis), vector rotated, z component
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <sensor_msgs/Imu.h>

#define METHOD EXTENDED_KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MODEL \
  (x[0] + x[4] * cos(x[2]) * T) \
  (x[1] + x[4] * sin(x[2]) * T) \
  (x[2] + x[3] * T) \
  (x[3]) \
  (u[0])
#define OBSERVATION_MODEL (x[3])(x[3])(x[3])
#define PROCESS_NOISE_COVARIANCE \
  ((0.001)(0)(0)(0)(0)) \
  ((0)(0.001)(0)(0)(0)) \
  ((0)(0)(0.001)(0)(0)) \
  ((0)(0)(0)(0.1)(0)) \
  ((0)(0)(0)(0)(0.001))
#define MEASUREMENT_NOISE_COVARIANCE ((0.01)(0)(0))((0)(0.01)(0))((0)(0)(0.02))
#define INITIAL_STATE (0)(0)(0)(0)(0)
#define TOPICS_IN \
  ((imu)(sensor_msgs::Imu)(angular_velocity.z)) \
  ((imu_unmounted)(sensor_msgs::Imu)(angular_velocity.z)) \
  ((gyro)(geometry_msgs::Vector3Stamped)(vector.x))
#define TOPICS_IN_CTRL ((cmd_vel)(geometry_msgs::Twist)(linear.x))
#define TOPICS_OUT ((heading)(2))((yaw_rate)(3))
#define POSE_OUT (0)(1)(2)
#define BASE_FRAME base_link
#define FRAME_ALIGNED_INPUTS \
  ((0)(angular_velocity)(z)) \
  ((1)(angular_velocity)(z)) \
  ((2)(vector)(z))
