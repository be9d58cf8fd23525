// EXPECT: DERIVED_INPUTS entry 0 ((0)(YAW)(ABSOLUTE)): ROLL, PITCH and YAW are angle inputs, used by KALMAN_FILTER
// Mistake: a moving average averages a yaw linearly
#include "fake_msgs.h"

#define METHOD MOVING_AVERAGE
#define WINDOW_SIZE 3
#define TOPICS_IN ((imu)(sensor_msgs::Imu)(orientation))
#define TOPICS_OUT ((yaw)(0))
#define DERIVED_INPUTS ((0)(YAW)(ABSOLUTE))
