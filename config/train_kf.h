// The thesis's moving train (section 2.2.1) as a Kalman filter, with a commanded
// acceleration as control: x = (v, a), v' = v + a T, a' = u0 (the command); the sensors
// measure v (speedometer) and a (accelerometer). Used by the rostest and the tutorial.
#include <geometry_msgs/Vector3Stamped.h>
#include <std_msgs/Float64.h>

#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(0))
#define CONTROL_INPUT_MATRIX ((0))((1))
#define OBSERVATION_MATRIX ((1)(0))((0)(1))
#define PROCESS_NOISE_COVARIANCE ((0.001)(0))((0)(0.01))
#define MEASUREMENT_NOISE_COVARIANCE ((0.25)(0))((0)(0.04))
#define INITIAL_STATE (0)(0)
#define INITIAL_ERROR_COVARIANCE ((1)(0))((0)(1))
#define TOPICS_IN \
  ((train/velocity)(std_msgs::Float64)(data)) \
  ((train/acceleration)(geometry_msgs::Vector3Stamped)(vector.x))
#define TOPICS_IN_CTRL ((train/command)(std_msgs::Float64)(data))
#define TOPICS_OUT ((train/estimate/velocity)(0))((train/estimate/acceleration)(1))
