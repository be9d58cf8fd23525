// EXPECT: OK
// A heading as an angle: the unscented Kalman filter of valid_ukf_controls.h with its heading
// x[2] declared in ANGLE_STATES and the compass (TOPICS_IN entry 0) in ANGLE_INPUTS. The
// angle cases include it (n = 3, m = 2); sf_filter/test/test_config_angles.cpp checks that the
// declarations reach the filter.
#include "fake_msgs.h"

#define METHOD UNSCENTED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL \
  (x[0] + u[0] * T * cos(x[2])) \
  (x[1] + u[0] * T * sin(x[2])) \
  (x[2] + u[1] * T)
#define OBSERVATION_MODEL (x[2])(sqrt(pow(x[0], 2) + x[1] * x[1]))
#define PROCESS_NOISE_COVARIANCE ((0.01)(0)(0))((0)(0.01)(0))((0)(0)(0.001))
#define MEASUREMENT_NOISE_COVARIANCE ((0.05)(0))((0)(0.5))
#define TOPICS_IN \
  ((compass)(std_msgs::Float64)(data)) \
  ((range)(std_msgs::Float32)(data))
#define TOPICS_IN_CTRL \
  ((cmd_vel)(geometry_msgs::Twist)(linear.x)) \
  ((cmd_vel)(geometry_msgs::Twist)(angular.z))
#define TOPICS_OUT ((x)(0))((y)(1))((heading)(2))
#if !defined(SF_ANGLES_CASE)
#define ANGLE_STATES (2)
#define ANGLE_INPUTS (0)
#endif
