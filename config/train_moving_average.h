// Moving average of the train's speedometer and accelerometer (window of 5 periods).
#include <geometry_msgs/Vector3Stamped.h>
#include <std_msgs/Float64.h>

#define METHOD MOVING_AVERAGE
#define WINDOW_SIZE 5
#define TOPICS_IN \
  ((train/velocity)(std_msgs::Float64)(data)) \
  ((train/acceleration)(geometry_msgs::Vector3Stamped)(vector.x))
#define TOPICS_OUT ((train/average/velocity)(0))((train/average/acceleration)(1))
