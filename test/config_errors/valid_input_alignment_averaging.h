// EXPECT: OK
// HOLD and LAST need no prediction: allowed for the averaging methods
#include "fake_msgs.h"

#define METHOD MOVING_AVERAGE
#define WINDOW_SIZE 3
#define TOPICS_IN \
  ((position)(geometry_msgs::Vector3Stamped)(vector.x)) \
  ((wheel)(std_msgs::Float32)(data))
#define TOPICS_OUT ((position)(0))
#define INPUT_ALIGNMENT ((0)(LAST))((1)(HOLD)(LAGRANGE)(1)(0.5))
#define ALIGN_BY_STAMP (0)
