// EXPECT: WEIGHTING_COEFFICIENTS: expected 3 entries, found 2 (one weight per measurement of the window, WINDOW_SIZE = 3)
// Mistake: two weights for a window of 3
#include "fake_msgs.h"

#define METHOD MOVING_AVERAGE
#define WINDOW_SIZE 3
#define WEIGHTING_COEFFICIENTS (0.5)(0.5)
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((velocity_wheel_right)(std_msgs::Float32)(data))
#define TOPICS_OUT ((velocity_left_avg)(0))((velocity_right_avg)(1))
