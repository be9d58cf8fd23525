// EXPECT: OK
// Moving median of an integer sensor.
#include "fake_msgs.h"

#define METHOD MOVING_MEDIAN
#define WINDOW_SIZE 5
#define TOPICS_IN ((ticks)(std_msgs::Int32)(data))
#define TOPICS_OUT ((ticks_median)(0))
