// A position (x, y) held still and measured by the x and y of a
// geometry_msgs/PoseWithCovarianceStamped with their covariance block, correlation included
// (INPUT_COVARIANCE_BLOCK: rows 0 and 1 of pose.covariance), for test/covariance_block.test.
// Q = 0, so that each period's estimate is one Kalman update computed by hand in the test.
#include <geometry_msgs/PoseWithCovarianceStamped.h>

#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MATRIX ((1)(0))((0)(1))
#define OBSERVATION_MATRIX ((1)(0))((0)(1))
#define PROCESS_NOISE_COVARIANCE ((0)(0))((0)(0))
#define MEASUREMENT_NOISE_COVARIANCE ((4)(0))((0)(4))
#define INITIAL_STATE (0)(0)
#define INITIAL_ERROR_COVARIANCE ((1)(0))((0)(1))
#define TOPICS_IN \
  ((pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.position.x)) \
  ((pose)(geometry_msgs::PoseWithCovarianceStamped)(pose.pose.position.y))
#define INPUT_COVARIANCE_BLOCK (((0)(1))(pose.covariance)((0)(1)))
#define TOPICS_OUT ((position/x)(0))((position/y)(1))
