// EXPECT: INPUT_GATE needs the predicted measurement and innovation covariance of the filter
// Mistake: an averaging method has no innovation covariance
#include "fake_msgs.h"

#define METHOD MOVING_AVERAGE
#define WINDOW_SIZE 3
#define TOPICS_IN \
  ((position)(geometry_msgs::Vector3Stamped)(vector.x)) \
  ((wheel)(std_msgs::Float32)(data))
#define TOPICS_OUT ((position)(0))
#define INPUT_GATE ((0)(9))
