// EXPECT: MOVING_AVERAGE, MOVING_MEDIAN and CONFIDENCE_WEIGHTED_AVERAGING take no control inputs
// Mistake: controls for an average
#include "fake_msgs.h"

#define METHOD MOVING_AVERAGE
#define WINDOW_SIZE 3
#define TOPICS_IN \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((velocity_wheel_right)(std_msgs::Float32)(data))
#define TOPICS_IN_CTRL ((velocity_command)(std_msgs::Float32)(data))
#define TOPICS_OUT ((velocity_left_avg)(0))((velocity_right_avg)(1))
