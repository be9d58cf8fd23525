// Pioneer 3-AT dead reckoning, model nav3 (all sensors, no controls; thesis section 5.2.1),
// with the EXTENDED_KALMAN_FILTER: transition eqs. 5.1-5.7, observation eqs. 5.15-5.18; Q of
// eq. 5.20, R of section 5.1.2, known start pose. The equations are in pioneer/nav3_model.h.
#define METHOD EXTENDED_KALMAN_FILTER
#include "pioneer/nav3_model.h"
