// EXPECT: OK
// The averaging configuration that the INPUT_ALIGNMENT and INPUT_GATE cases for methods
// without a predicted measurement include and extend: inputs 0 (stamped), 1 (no header).
#include "fake_msgs.h"

#define METHOD MOVING_AVERAGE
#define WINDOW_SIZE 3
#define TOPICS_IN \
  ((position)(geometry_msgs::Vector3Stamped)(vector.x)) \
  ((wheel)(std_msgs::Float32)(data))
#define TOPICS_OUT ((position)(0))
