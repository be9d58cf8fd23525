// Test configuration of test/magnetic_heading_test.cpp: a heading filter fusing a
// magnetometer's heading (DERIVED_INPUTS MAGNETIC_YAW of a sensor_msgs/MagneticField, written as
// an INPUTS record) and a gyro's yaw rate.
//   state x = (yaw, omega)
//   input 0 mag_yaw:  the heading of imu/mag's magnetic_field, ~magnetic_declination applied
//   input 1 gyro:     imu/data's angular_velocity.z
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/MagneticField.h>

#define METHOD EXTENDED_KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define PROCESS_NOISE_COVARIANCE ((1e-4)(0))((0)(1e-2))
#define INITIAL_ERROR_COVARIANCE ((10)(0))((0)(1))
#define ANGLE_STATES (0)
#define INPUTS \
  ((mag_yaw)(imu/mag)(sensor_msgs::MagneticField)(magnetic_field) \
     (observe, x[0])(variance, 0.01)(derived, MAGNETIC_YAW, ABSOLUTE)) \
  ((gyro)(imu/data)(sensor_msgs::Imu)(angular_velocity.z)(observe, x[1])(variance, 1e-4))
#define TOPICS_OUT ((yaw)(0))((yaw_rate)(1))
