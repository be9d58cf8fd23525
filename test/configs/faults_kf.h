// Test configuration of test/faults.test (doc/reliability.md): the train of config/train_kf.h
// without control, x = (v, a), a speedometer with its own variance and an accelerometer, both
// stamped, with the fault handling on:
//   INPUT_TIMEOUT  both inputs time out after 0.5 s without a value
//   INPUT_RANGE    speeds outside [-20, 20] m/s are dropped
//   INPUT_GATE     the speed's Mahalanobis gate at 9 (3 sigma)
#include <geometry_msgs/TwistWithCovarianceStamped.h>
#include <geometry_msgs/Vector3Stamped.h>

#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(1))
#define OBSERVATION_MATRIX ((1)(0))((0)(1))
#define PROCESS_NOISE_COVARIANCE ((0.001)(0))((0)(0.01))
#define MEASUREMENT_NOISE_COVARIANCE ((0.25)(0))((0)(0.04))
#define INITIAL_STATE (0)(0)
#define INITIAL_ERROR_COVARIANCE ((1)(0))((0)(1))
#define TOPICS_IN \
  ((faults/speed)(geometry_msgs::TwistWithCovarianceStamped)(twist.twist.linear.x)(twist.covariance[0])) \
  ((faults/acceleration)(geometry_msgs::Vector3Stamped)(vector.x))
#define TOPICS_OUT ((faults/estimate/speed)(0))((faults/estimate/acceleration)(1))
#define INPUT_TIMEOUT ((0)(500))((1)(500))
#define INPUT_RANGE ((0)(-20)(20))
#define INPUT_GATE ((0)(9))
