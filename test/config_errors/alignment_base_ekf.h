// EXPECT: OK
// The model-based configuration that the INPUT_ALIGNMENT, INPUT_GATE, ALIGN_BY_STAMP and
// MAX_MEASUREMENT_LAG cases include and extend: inputs 0 (stamped), 1 (no header), 2, 3.
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])(x[1])(x[0])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE \
  ((0.5)(0)(0)(0))((0)(0.2)(0)(0))((0)(0)(0.3)(0))((0)(0)(0)(0.4))
#define TOPICS_IN \
  ((position)(geometry_msgs::Vector3Stamped)(vector.x)) \
  ((wheel)(std_msgs::Float32)(data)) \
  ((imu)(sensor_msgs::Imu)(linear_acceleration.x)) \
  ((odom)(nav_msgs::Odometry)(pose.pose.position.x))
#define TOPICS_OUT ((position)(0))((speed)(1))
