// Test configuration of the load / soak test (sf_filter/bench/soak_node.sh, test/soak): a 1-D
// cart with four sensors at 1 kHz and an acceleration command, estimated every 10 ms, so each
// period averages 10 values of each input.
//   state x = (position, velocity), control u = (acceleration command)
//   inputs: two position sensors, two speed sensors, stamped and unstamped message types
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <std_msgs/Float64.h>

#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 10
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(1))
#define CONTROL_INPUT_MATRIX ((0.5 * T * T))((T))
#define OBSERVATION_MATRIX ((1)(0))((1)(0))((0)(1))((0)(1))
#define PROCESS_NOISE_COVARIANCE ((1e-6)(0))((0)(1e-4))
#define MEASUREMENT_NOISE_COVARIANCE \
  ((0.01)(0)(0)(0)) \
  ((0)(0.04)(0)(0)) \
  ((0)(0)(0.01)(0)) \
  ((0)(0)(0)(0.04))
#define INITIAL_STATE (0)(0)
#define INITIAL_ERROR_COVARIANCE ((1)(0))((0)(1))
#define TOPICS_IN \
  ((soak/position_a)(geometry_msgs::PointStamped)(point.x)) \
  ((soak/position_b)(std_msgs::Float64)(data)) \
  ((soak/velocity_a)(geometry_msgs::Vector3Stamped)(vector.x)) \
  ((soak/velocity_b)(std_msgs::Float64)(data))
#define TOPICS_IN_CTRL ((soak/command)(std_msgs::Float64)(data))
#define TOPICS_OUT ((soak/estimate/position)(0))((soak/estimate/velocity)(1))
