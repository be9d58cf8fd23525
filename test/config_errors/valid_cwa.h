// EXPECT: OK
// Confidence-weighted averaging of two velocity sources, one with a variance field.
#include "fake_msgs.h"

#define METHOD CONFIDENCE_WEIGHTED_AVERAGING
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define TOPICS_IN \
  ((odom)(nav_msgs::Odometry)(twist.twist.linear.x)(twist.covariance[0])) \
  ((velocity_wheel_left)(std_msgs::Float32)(data))
#define TOPICS_OUT ((velocity)(0))
