// EXPECT: TOPICS_OUT entry 0 (topic 'fused'): state index '1' is out of range, expected an integer from 0 to 0 (n = 1 for CONFIDENCE_WEIGHTED_AVERAGING)
// Mistake: CWA has one output value
#include "fake_msgs.h"

#define METHOD CONFIDENCE_WEIGHTED_AVERAGING
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((velocity_wheel_right)(std_msgs::Float32)(data))
#define TOPICS_OUT ((fused)(1))
