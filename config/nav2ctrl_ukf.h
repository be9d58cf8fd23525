// Pioneer 3-AT dead reckoning, model nav2ctrl (wheel encoders and cmd_vel; thesis section
// 5.2.1), with the UNSCENTED_KALMAN_FILTER: transition eqs. 5.8-5.13 with v = cmd_vel.linear.x,
// observation eqs. 5.17-5.18; Q of eq. 5.20 with v in place of a, R of section 5.1.2, known
// start pose. The equations are in pioneer/nav2ctrl_model.h.
#define METHOD UNSCENTED_KALMAN_FILTER
#include "pioneer/nav2ctrl_model.h"
