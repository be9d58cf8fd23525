// Pioneer 3-AT: the inputs of model nav2 (the wheel speeds) only averaged, for the comparison
// "from averaging to estimation" (thesis section 5.2.2): plain wheel odometry, the path
// "rosaria" of Fig. 5.6. Every period already averages the wheel speeds received in it
// (temporal alignment, section 4.3.4); a window of 1 publishes that average as it is. The
// path is computed offline from v = (left + right) / 2 and omega = (right - left) / (2 R)
// (eqs. 5.17-5.18 solved for v and omega; tools/eval/evaluate.py
// --dead-reckoning wheels=x0,x1).
#define METHOD MOVING_AVERAGE
#include "pioneer/common.h"

#define WINDOW_SIZE 1
#define TOPICS_IN PIONEER_WHEEL_INPUTS
#define TOPICS_OUT ((average/velocity_wheel_left)(0))((average/velocity_wheel_right)(1))
