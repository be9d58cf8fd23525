// EXPECT: OK
// REQUIRES: /usr/include/std_msgs/Float32.h
// REQUIRES: /usr/include/geometry_msgs/Vector3Stamped.h
// REQUIRES: /usr/include/nav_msgs/Odometry.h
// The train of the thesis with the real ROS message headers (as in the thesis's robot setup).
#include <geometry_msgs/Vector3Stamped.h>
#include <nav_msgs/Odometry.h>
#include <std_msgs/Float32.h>

#define METHOD EXTENDED_KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])(x[0])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0)(0))((0)(0.2)(0))((0)(0)(0.3))
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y)) \
  ((odom)(nav_msgs::Odometry)(twist.twist.linear.x)(twist.covariance[0]))
#define TOPICS_OUT ((velocity)(0))
