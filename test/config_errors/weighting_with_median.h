// EXPECT: WEIGHTING_COEFFICIENTS is only used by MOVING_AVERAGE
// Mistake: weights for the median
#include "fake_msgs.h"

#define METHOD MOVING_MEDIAN
#define WINDOW_SIZE 3
#define WEIGHTING_COEFFICIENTS (0.5)(0.3)(0.2)
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((velocity_wheel_right)(std_msgs::Float32)(data))
#define TOPICS_OUT ((velocity_left_avg)(0))((velocity_right_avg)(1))
