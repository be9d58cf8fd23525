// EXPECT: INPUT_ALIGNMENT entry 0 ((1)(FILL)(0.001)(5)): FILL needs the filter's predicted measurement h(x(k|k-1)), which MOVING_AVERAGE does not give
// Mistake: a moving average has no model to predict the measurement
#include "fake_msgs.h"

#define METHOD MOVING_AVERAGE
#define WINDOW_SIZE 3
#define TOPICS_IN \
  ((position)(geometry_msgs::Vector3Stamped)(vector.x)) \
  ((wheel)(std_msgs::Float32)(data))
#define TOPICS_OUT ((position)(0))
#define INPUT_ALIGNMENT ((1)(FILL)(0.001)(5))
