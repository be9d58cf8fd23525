// Pioneer 3-AT dead reckoning, model nav3ctrl (thesis section 5.2.1) with the EXTENDED_KALMAN_FILTER:
// transition eqs. 5.8-5.14 (cmd_vel as control), observation eqs. 5.15-5.18 (gyro,
// accelerometer's y axis = robot x, wheel speeds in mm/s, effective radius R = 0.3 m),
// Q of eq. 5.20 and R of section 5.1.2. T is the period, so changing ESTIMATION_PERIOD
// needs no edit of the model.
//   state x = (x, y, theta, omega, delta_s, v, a)
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <std_msgs/Float32.h>

#define METHOD EXTENDED_KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MODEL \
  (x[0] + x[4] * cos(x[2])) \
  (x[1] + x[4] * sin(x[2])) \
  (x[2] + x[3] * T) \
  (u[1]) \
  (x[5] * T) \
  (x[5] + x[6] * T) \
  ((u[0] - x[5]) / T)
#define OBSERVATION_MODEL \
  (x[3]) \
  (x[6]) \
  ((x[5] - x[3] * 0.3) * 1000) \
  ((x[5] + x[3] * 0.3) * 1000)
#define PROCESS_NOISE_COVARIANCE \
  ((0)(0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0.5)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)(0)) \
  ((0)(0)(0)(0)(0)(0)(0.3))
#define MEASUREMENT_NOISE_COVARIANCE \
  ((0.00017)(0)(0)(0)) \
  ((0)(0.25)(0)(0)) \
  ((0)(0)(2)(0)) \
  ((0)(0)(0)(2))
#define INITIAL_STATE (0)(0)(0)(0)(0)(0)(0)
// The robot starts on a marked position (section 5.1): x, y and theta are known almost
// exactly. With the default P0 = I the heading, which no sensor measures, would keep a
// variance of 1 rad^2 and a UKF would average cos(theta) over +-1 rad, shrinking the path.
#define INITIAL_ERROR_COVARIANCE \
  ((1e-4)(0)(0)(0)(0)(0)(0)) \
  ((0)(1e-4)(0)(0)(0)(0)(0)) \
  ((0)(0)(1e-4)(0)(0)(0)(0)) \
  ((0)(0)(0)(1)(0)(0)(0)) \
  ((0)(0)(0)(0)(1)(0)(0)) \
  ((0)(0)(0)(0)(0)(1)(0)) \
  ((0)(0)(0)(0)(0)(0)(1))
#define TOPICS_IN \
  ((angular_velocity)(geometry_msgs::Vector3Stamped)(vector.z)) \
  ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y)) \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((velocity_wheel_right)(std_msgs::Float32)(data))
#define TOPICS_IN_CTRL \
  ((cmd_vel)(geometry_msgs::Twist)(linear.x)) \
  ((cmd_vel)(geometry_msgs::Twist)(angular.z))
#define TOPICS_OUT ((pose/x)(0))((pose/y)(1))((pose/theta)(2))((velocity/linear)(5))((velocity/angular)(3))
#define POSE_OUT (0)(1)(2)
