// EXPECT: MOVING_AVERAGE and MOVING_MEDIAN require WINDOW_SIZE
// Mistake: moving average without window
#include "fake_msgs.h"

#define METHOD MOVING_AVERAGE
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((velocity_wheel_right)(std_msgs::Float32)(data))
#define TOPICS_OUT ((velocity_left_avg)(0))((velocity_right_avg)(1))
