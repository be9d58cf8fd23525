// Pioneer 3-AT dead reckoning, model nav2 (wheel encoders only; thesis section 5.2.1), with the
// EXTENDED_KALMAN_FILTER: transition eqs. 5.1-5.6 with v = v, observation eqs. 5.17-5.18; Q of
// eq. 5.20 with v in place of a, R of section 5.1.2, known start pose. The equations are in
// pioneer/nav2_model.h.
#define METHOD EXTENDED_KALMAN_FILTER
#include "pioneer/nav2_model.h"
